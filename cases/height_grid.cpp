// Steps: terrains from height grids (cases/height_grid.hpp).
#include "cases/height_grid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "cases/csv_table.hpp"

namespace slide::cases {
namespace {

double number_in(const std::string& cell, const std::string& where) {
  try {
    std::size_t used = 0;
    const double v = std::stod(cell, &used);
    if (cell.find_first_not_of(" \t\r", used) != std::string::npos || !std::isfinite(v)) throw std::invalid_argument("");
    return v;
  } catch (const std::exception&) {
    throw std::runtime_error(fmt::format("{}: '{}' is not a number", where, cell));
  }
}

void check_increasing(const std::vector<double>& v, const char* axis) {
  if (v.size() < 2) throw std::runtime_error(fmt::format("a grid needs at least two {} values", axis));
  for (std::size_t k = 1; k < v.size(); ++k)
    if (!(v[k] > v[k - 1]))
      throw std::runtime_error(fmt::format("the {} values must increase ({} {} after {})", axis, axis, v[k], v[k - 1]));
}

HeightGrid read_csv_grid(const std::filesystem::path& file) {
  const CsvTable t = read_csv(file);
  HeightGrid g;
  for (std::size_t c = 1; c < t.header.size(); ++c) g.x.push_back(number_in(t.header[c], fmt::format("header, column {}", c + 1)));
  check_increasing(g.x, "x");
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto& row = t.rows[r];
    const std::string line = fmt::format("line {}", t.line_numbers[r]);
    if (row.size() != g.x.size() + 1)
      throw std::runtime_error(fmt::format("{} has {} cells, the header {}", line, row.size(), g.x.size() + 1));
    g.y.push_back(number_in(row[0], line + ", column 1"));
    for (std::size_t c = 1; c < row.size(); ++c) g.z.push_back(number_in(row[c], fmt::format("{}, column {}", line, c + 1)));
  }
  check_increasing(g.y, "y");
  return g;
}

HeightGrid read_esri_grid(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::map<std::string, double> head;
  std::string key;
  // The header: keys and values, until the first token that is a number.
  std::streampos data = in.tellg();
  while (in >> key) {
    std::string lower = key;
    for (auto& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (!std::isalpha(static_cast<unsigned char>(lower[0]))) break;
    std::string value;
    if (!(in >> value)) throw std::runtime_error(fmt::format("the header key {} has no value", key));
    head[lower] = number_in(value, "the header's " + key);
    data = in.tellg();
  }
  for (const char* needed : {"ncols", "nrows", "cellsize"})
    if (!head.count(needed)) throw std::runtime_error(fmt::format("the header lacks {}", needed));
  const bool corner = head.count("xllcorner") && head.count("yllcorner");
  if (!corner && !(head.count("xllcenter") && head.count("yllcenter")))
    throw std::runtime_error("the header needs xllcorner and yllcorner, or xllcenter and yllcenter");
  const long nx = std::lround(head["ncols"]), ny = std::lround(head["nrows"]);
  const double h = head["cellsize"];
  if (nx < 2 || ny < 2 || !(h > 0.0)) throw std::runtime_error("a grid needs ncols and nrows of at least 2 and a positive cellsize");
  if (double(nx) * double(ny) > 1e8) throw std::runtime_error(fmt::format("{} x {} values: more than 1e8", nx, ny));
  const double x0 = corner ? head["xllcorner"] + 0.5 * h : head["xllcenter"];
  const double y0 = corner ? head["yllcorner"] + 0.5 * h : head["yllcenter"];
  HeightGrid g;
  for (long i = 0; i < nx; ++i) g.x.push_back(x0 + double(i) * h);
  for (long j = 0; j < ny; ++j) g.y.push_back(y0 + double(j) * h);
  g.z.assign(std::size_t(nx * ny), 0.0);
  in.clear();
  in.seekg(data);
  const bool has_nodata = head.count("nodata_value") > 0;
  for (long r = 0; r < ny; ++r)
    for (long i = 0; i < nx; ++i) {
      std::string cell;
      if (!(in >> cell)) throw std::runtime_error(fmt::format("{} rows of {} values expected; the file ends at row {}", ny, nx, r + 1));
      const double v = number_in(cell, fmt::format("row {}, value {}", r + 1, i + 1));
      if (has_nodata && v == head["nodata_value"])
        throw std::runtime_error(fmt::format("row {}, value {} is no data: a terrain needs every elevation", r + 1, i + 1));
      g.z[std::size_t((ny - 1 - r) * nx + i)] = v;  // the first row is the northernmost
    }
  std::string extra;
  if (in >> extra) throw std::runtime_error(fmt::format("more than {} rows of {} values", ny, nx));
  return g;
}

}  // namespace

HeightGrid read_height_grid(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw std::runtime_error("no such file");
  std::string ext = file.extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".csv") return read_csv_grid(file);
  if (ext == ".asc") return read_esri_grid(file);
  throw std::runtime_error("a height grid must be .csv or .asc (ESRI ASCII grid)");
}

rigid::TriangleSurface terrain_surface(const HeightGrid& g) {
  rigid::TriangleSurface s;
  const std::size_t nx = g.x.size(), ny = g.y.size();
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) s.vertices.push_back(rigid::Vec3(g.x[i], g.y[j], g.at(i, j)));
  const auto v = [nx](std::size_t i, std::size_t j) { return int(j * nx + i); };
  for (std::size_t j = 0; j + 1 < ny; ++j)
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      s.triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      s.triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  return s;
}

namespace {

// v moved onto [lo, hi]'s nearer end when it lies outside by at most `slack`.
double onto_edge(double v, double lo, double hi, double slack) {
  if (v < lo && v >= lo - slack) return lo;
  if (v > hi && v <= hi + slack) return hi;
  return v;
}

}  // namespace

double terrain_height(const HeightGrid& g, double x, double y, double edge_slack) {
  x = onto_edge(x, g.x.front(), g.x.back(), edge_slack);
  y = onto_edge(y, g.y.front(), g.y.back(), edge_slack);
  if (x < g.x.front() || x > g.x.back() || y < g.y.front() || y > g.y.back()) return NAN;
  const std::size_t i = std::min<std::size_t>(std::upper_bound(g.x.begin(), g.x.end(), x) - g.x.begin(), g.x.size() - 1) - 1;
  const std::size_t j = std::min<std::size_t>(std::upper_bound(g.y.begin(), g.y.end(), y) - g.y.begin(), g.y.size() - 1) - 1;
  const double u = (x - g.x[i]) / (g.x[i + 1] - g.x[i]), w = (y - g.y[j]) / (g.y[j + 1] - g.y[j]);
  const double z00 = g.at(i, j), z10 = g.at(i + 1, j), z11 = g.at(i + 1, j + 1), z01 = g.at(i, j + 1);
  // Below the diagonal (u >= w): the triangle (00, 10, 11); above it: (00, 11, 01).
  return u >= w ? z00 + u * (z10 - z00) + w * (z11 - z10) : z00 + w * (z01 - z00) + u * (z11 - z01);
}

}  // namespace slide::cases
