#include "tools/measures/wave_signature.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slide::tools {

WaveSignature wave_signature(const CsvTable& gauges, const CsvTable* slide_front, const CsvTable* bodies) {
  WaveSignature s;
  for (std::size_t c = 0; c < gauges.header.size(); ++c) {
    if (gauges.header[c] == "time") continue;
    const std::vector<double> eta = gauges.numbers(gauges.header[c]);
    double still = std::numeric_limits<double>::quiet_NaN(), crest = 0.0, trough = 0.0;
    for (const double e : eta) {
      if (std::isnan(e)) continue;
      if (std::isnan(still)) still = e;
      crest = std::max(crest, e - still);
      trough = std::min(trough, e - still);
    }
    s.gauges.push_back(gauges.header[c]);
    s.crest.push_back(crest);
    s.trough.push_back(trough);
  }
  if (slide_front && !slide_front->rows.empty()) {
    const auto slide = slide_front->rows.front()[slide_front->column("slide")];
    const auto along = slide_front->numbers("front_along");
    double first = std::numeric_limits<double>::quiet_NaN(), last = first;
    for (std::size_t k = 0; k < along.size(); ++k) {
      if (slide_front->rows[k][slide_front->column("slide")] != slide) continue;
      if (std::isnan(first)) first = along[k];
      last = along[k];
    }
    s.slide_travel = last - first;
  } else if (bodies && !bodies->rows.empty()) {
    const int body = bodies->find_column("body");
    const auto x = bodies->numbers("x"), y = bodies->numbers("y");
    std::size_t last = 0;
    for (std::size_t k = 0; k < x.size(); ++k)
      if (body < 0 || bodies->rows[k][body] == bodies->rows[0][body]) last = k;
    s.slide_travel = std::hypot(x[last] - x[0], y[last] - y[0]);
  }
  return s;
}

WaveSignature wave_signature(const std::filesystem::path& run_folder) {
  const CsvTable gauges = read_csv(run_folder / "gauges.csv");
  if (std::filesystem::exists(run_folder / "slide_front.csv")) {
    const CsvTable front = read_csv(run_folder / "slide_front.csv");
    return wave_signature(gauges, &front, nullptr);
  }
  if (std::filesystem::exists(run_folder / "bodies.csv")) {
    const CsvTable bodies = read_csv(run_folder / "bodies.csv");
    return wave_signature(gauges, nullptr, &bodies);
  }
  return wave_signature(gauges, nullptr, nullptr);
}

double wave_signature_error(const WaveSignature& run, const WaveSignature& ref) {
  if (run.gauges != ref.gauges) throw std::invalid_argument("the runs have different gauges");
  double height = 0.0;
  for (std::size_t g = 0; g < ref.gauges.size(); ++g) height = std::max(height, ref.crest[g] - ref.trough[g]);
  if (!(height > 0.0)) throw std::invalid_argument("the reference run has no wave at its gauges");
  double e = 0.0;
  for (std::size_t g = 0; g < ref.gauges.size(); ++g)
    e = std::max({e, std::abs(run.crest[g] - ref.crest[g]) / height, std::abs(run.trough[g] - ref.trough[g]) / height});
  if (!std::isnan(run.slide_travel) && !std::isnan(ref.slide_travel) && ref.slide_travel > 0.0)
    e = std::max(e, std::abs(run.slide_travel - ref.slide_travel) / ref.slide_travel);
  return e;
}

}  // namespace slide::tools
