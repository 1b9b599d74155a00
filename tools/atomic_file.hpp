#pragma once
// Crash-safe output files: every file is written under a temporary name in the same folder,
// flushed to disk (fsync) and then renamed over the final name, so readers (and a crash at any
// moment) only ever see the old complete file or the new complete file.

#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace slide::tools {

// Temporary name used for `path` while it is being written: "<path>.tmp.<pid>" (same folder, so
// the final rename stays within one file system).
std::filesystem::path temporary_path_for(const std::filesystem::path& path);

// fsync()s the file at `tmp`, renames it over `path` and fsync()s the containing folder.
// On failure removes `tmp` and throws std::runtime_error naming the paths and the errno text.
void commit_temporary_file(const std::filesystem::path& tmp, const std::filesystem::path& path);

// A file written in parts under temporary_path_for(path); commit() fsync()s it and renames it over `path`. Destroyed
// uncommitted (a failure on the way), the temporary file is removed and an existing `path` is left untouched. Throws
// std::runtime_error (with the path and the errno text) on failure.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(std::filesystem::path path);
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;
  ~AtomicFileWriter();
  void append(std::string_view bytes);
  void commit();

 private:
  [[noreturn]] void fail(const char* what, int err);
  std::filesystem::path path_, tmp_;
  int fd_ = -1;
};

// Writes `content` to temporary_path_for(path), fsync()s it and renames it over `path`.
// Throws std::runtime_error (with the path and the errno text) on failure; the temporary file
// is removed and an existing `path` is left untouched.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// Comma-separated table kept in memory as text; flush() rewrites the whole file atomically, so
// the file on disk is always complete (header plus every row added before the last flush()).
class CsvWriter {
 public:
  CsvWriter(std::filesystem::path path, std::vector<std::string> columns);

  // Appends one row; values are written with full round-trip precision ("{:.17g}").
  // Throws std::invalid_argument if values.size() != number of columns.
  void add_row(std::span<const double> values);
  void add_row(std::initializer_list<double> values) {
    add_row(std::span<const double>(values.begin(), values.size()));
  }

  // Appends a row whose second column is a label (a name) and whose other columns are `values` (time first).
  void add_labelled_row(double first, std::string_view label, std::span<const double> values);

  // Rewrites the file (header + all rows) atomically.
  void flush() const;

  const std::filesystem::path& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }
  size_t row_count() const { return rows_; }
  // Full file content as flush() would write it.
  const std::string& text() const { return text_; }

  // Continues a table written before (a resumed run): its first `length` bytes on disk, which hold `rows` rows, become
  // the content; what the file holds beyond them (written after a checkpoint) is dropped at the next flush. Throws
  // std::runtime_error naming the file when it is missing, shorter, or starts with another header.
  void continue_from_file(std::size_t length, std::size_t rows);

 private:
  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::string text_;
  size_t rows_ = 0;
};

}  // namespace slide::tools
