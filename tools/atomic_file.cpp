#include "tools/atomic_file.hpp"

#include <fstream>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

namespace slide::tools {

namespace {

std::string errno_text(int err) { return std::generic_category().message(err); }

// Closes a POSIX file descriptor on scope exit unless released.
struct Fd {
  int fd = -1;
  explicit Fd(int f) : fd(f) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
  // Closes now and reports the error code (0 on success).
  int close_now() {
    int rc = 0;
    if (fd >= 0 && ::close(fd) != 0) rc = errno;
    fd = -1;
    return rc;
  }
};

void remove_quietly(const std::filesystem::path& p) {
  std::error_code ec;
  std::filesystem::remove(p, ec);
}

void fsync_directory(const std::filesystem::path& dir) {
  // Best effort: makes the rename durable; some file systems refuse fsync on folders.
  Fd d(::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (d.fd >= 0) (void)::fsync(d.fd);
}

}  // namespace

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  std::filesystem::path tmp = path;
  tmp += fmt::format(".tmp.{}", static_cast<long>(::getpid()));
  return tmp;
}

void commit_temporary_file(const std::filesystem::path& tmp, const std::filesystem::path& path) {
  {
    Fd f(::open(tmp.c_str(), O_RDONLY | O_CLOEXEC));
    if (f.fd < 0) {
      const int err = errno;
      remove_quietly(tmp);
      throw std::runtime_error(
          fmt::format("cannot open '{}' for fsync: {}", tmp.string(), errno_text(err)));
    }
    if (::fsync(f.fd) != 0) {
      const int err = errno;
      f.close_now();
      remove_quietly(tmp);
      throw std::runtime_error(
          fmt::format("cannot fsync '{}': {}", tmp.string(), errno_text(err)));
    }
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    remove_quietly(tmp);
    throw std::runtime_error(fmt::format("cannot rename '{}' to '{}': {}", tmp.string(),
                                         path.string(), errno_text(err)));
  }
  fsync_directory(path.parent_path());
}

AtomicFileWriter::AtomicFileWriter(std::filesystem::path path)
    : path_(std::move(path)), tmp_(temporary_path_for(path_)) {
  fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int err = errno;
    throw std::runtime_error(fmt::format("cannot create '{}' (writing '{}'): {}", tmp_.string(), path_.string(),
                                         errno_text(err)));
  }
}

AtomicFileWriter::~AtomicFileWriter() {
  if (fd_ >= 0) {
    ::close(fd_);
    remove_quietly(tmp_);
  }
}

void AtomicFileWriter::fail(const char* what, int err) {
  ::close(fd_);
  fd_ = -1;
  remove_quietly(tmp_);
  throw std::runtime_error(
      fmt::format("cannot {} '{}' (writing '{}'): {}", what, tmp_.string(), path_.string(), errno_text(err)));
}

void AtomicFileWriter::append(std::string_view bytes) {
  if (fd_ < 0) throw std::logic_error("AtomicFileWriter::append after commit");
  const char* p = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    const ssize_t w = ::write(fd_, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      fail("write", errno);
    }
    p += w;
    left -= static_cast<size_t>(w);
  }
}

void AtomicFileWriter::commit() {
  if (fd_ < 0) throw std::logic_error("AtomicFileWriter::commit twice");
  if (::fsync(fd_) != 0) fail("fsync", errno);
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0) {
    const int err = errno;
    remove_quietly(tmp_);
    throw std::runtime_error(
        fmt::format("cannot close '{}' (writing '{}'): {}", tmp_.string(), path_.string(), errno_text(err)));
  }
  if (::rename(tmp_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    remove_quietly(tmp_);
    throw std::runtime_error(
        fmt::format("cannot rename '{}' to '{}': {}", tmp_.string(), path_.string(), errno_text(err)));
  }
  fsync_directory(path_.parent_path());
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  AtomicFileWriter file(path);
  file.append(content);
  file.commit();
}

CsvWriter::CsvWriter(std::filesystem::path path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)) {
  for (size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0) text_ += ',';
    text_ += columns_[i];
  }
  text_ += '\n';
}

void CsvWriter::add_row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument(fmt::format("CsvWriter '{}': row has {} values, expected {}",
                                            path_.string(), values.size(), columns_.size()));
  }
  auto out = std::back_inserter(text_);
  for (size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text_ += ',';
    fmt::format_to(out, "{:.17g}", values[i]);
  }
  text_ += '\n';
  ++rows_;
}

void CsvWriter::add_labelled_row(double first, std::string_view label, std::span<const double> values) {
  if (values.size() + 2 != columns_.size()) {
    throw std::invalid_argument(fmt::format("CsvWriter '{}': row has {} values, expected {}", path_.string(),
                                            values.size() + 2, columns_.size()));
  }
  auto out = std::back_inserter(text_);
  fmt::format_to(out, "{:.17g},{}", first, label);
  for (double v : values) fmt::format_to(out, ",{:.17g}", v);
  text_ += '\n';
  ++rows_;
}

void CsvWriter::flush() const { write_file_atomically(path_, text_); }

void CsvWriter::continue_from_file(std::size_t length, std::size_t rows) {
  std::ifstream in(path_, std::ios::binary);
  std::string text(length, '\0');
  if (!in || !in.read(text.data(), static_cast<std::streamsize>(length)))
    throw std::runtime_error(fmt::format("'{}' is missing or shorter than at the checkpoint ({} bytes)", path_.string(),
                                         length));
  if (!text.starts_with(text_))
    throw std::runtime_error(fmt::format("'{}' does not start with this run's header", path_.string()));
  text_ = std::move(text);
  rows_ = rows;
}

}  // namespace slide::tools
