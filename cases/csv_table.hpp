#pragma once
// The one reader of the CSV files slide writes and reads back (bodies.csv as a prescribed motion, the outputs that
// the error measures and tests compare): a header line, then rows of comma-separated cells; empty lines and lines
// starting with '#' are skipped (the units lines).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace slide {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<long> line_numbers;  // of each row in the file, from 1

  // Index of a named column, or -1.
  int find_column(const std::string& name) const {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return static_cast<int>(k);
    return -1;
  }
  std::size_t column(const std::string& name) const {
    const int c = find_column(name);
    if (c < 0) throw std::out_of_range("no column " + name);
    return static_cast<std::size_t>(c);
  }
  // A column's cells as numbers (std::invalid_argument where one is not, std::out_of_range where a row is short).
  std::vector<double> numbers(const std::string& name) const {
    const std::size_t c = column(name);
    std::vector<double> out;
    out.reserve(rows.size());
    for (const auto& r : rows) out.push_back(std::stod(r.at(c)));
    return out;
  }
};

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();  // getline drops a last, empty cell
  return out;
}

// std::runtime_error naming the file when it cannot be read.
inline CsvTable read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  CsvTable t;
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // a file with Windows line ends
    if (line.empty() || line[0] == '#') continue;
    if (t.header.empty()) {
      t.header = split_csv_line(line);
    } else {
      t.rows.push_back(split_csv_line(line));
      t.line_numbers.push_back(number);
    }
  }
  return t;
}

}  // namespace slide
