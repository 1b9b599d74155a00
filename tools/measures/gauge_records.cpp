#include "tools/measures/gauge_records.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tools/measures/series.hpp"

namespace slide::tools {
namespace {

// The lower and upper extreme of the samples (t, e) with t in [from, to]; NaN elevations skipped.
void extremes_in(const std::vector<double>& t, const std::vector<double>& e, double from, double to,
                 GaugeExtreme& lowest, GaugeExtreme& highest) {
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < from || t[k] > to || std::isnan(e[k])) continue;
    if (std::isnan(lowest.elevation) || e[k] < lowest.elevation) lowest = {t[k], e[k]};
    if (std::isnan(highest.elevation) || e[k] > highest.elevation) highest = {t[k], e[k]};
  }
}

}  // namespace

std::vector<GaugeRecordComparison> compare_gauge_records(const CsvTable& gauges, const cases::GaugeRecordsSpec& spec) {
  const std::vector<double> t_model = gauges.numbers("time");
  if (t_model.empty() || spec.time_measured.empty()) throw std::invalid_argument("no gauge samples to compare");
  std::vector<double> t_record = spec.time_measured;
  for (double& t : t_record) t += spec.time_offset;
  std::vector<GaugeRecordComparison> out;
  for (const auto& measured : spec.gauges) {
    if (gauges.find_column(measured.name) < 0) throw std::invalid_argument("gauges.csv has no gauge " + measured.name);
    std::vector<double> eta = gauges.numbers(measured.name);
    const auto first_wet = std::find_if(eta.begin(), eta.end(), [](double e) { return !std::isnan(e); });
    const double still = first_wet == eta.end() ? 0.0 : *first_wet;
    for (double& e : eta) e -= still;

    GaugeRecordComparison c;
    c.gauge = measured.name;
    c.from = std::max(t_model.front(), t_record.front());
    c.to = std::min(t_model.back(), t_record.back());
    if (spec.until > 0.0) c.to = std::min(c.to, spec.until);
    // Sample times are sums of steps: 2.0000000000000004 is the sample at 2 s.
    const double slack = 1e-9 * std::max(1.0, std::abs(c.to)), from = c.from - slack, to = c.to + slack;
    if (!(c.to >= c.from))
      throw std::invalid_argument("gauge " + measured.name + ": the run and the record share no time");
    double sum = 0.0;
    for (std::size_t k = 0; k < t_model.size(); ++k) {
      if (t_model[k] < from || t_model[k] > to || std::isnan(eta[k])) continue;
      const double d = eta[k] - interpolate(t_record, measured.elevation, t_model[k]);
      sum += d * d;
      ++c.samples;
    }
    if (c.samples) c.rms = std::sqrt(sum / static_cast<double>(c.samples));
    extremes_in(t_model, eta, from, to, c.trough, c.crest);
    extremes_in(t_record, measured.elevation, from, to, c.measured_trough, c.measured_crest);
    c.measured_height = c.measured_crest.elevation - c.measured_trough.elevation;
    out.push_back(c);
  }
  return out;
}

double gauge_records_error(const std::vector<GaugeRecordComparison>& comparisons) {
  double rms = 0.0, height = 0.0;
  for (const auto& c : comparisons) {
    if (std::isnan(c.rms)) return c.rms;  // a gauge dry all the window: no figure
    rms = std::max(rms, c.rms);
    height = std::max(height, c.measured_height);
  }
  if (!(height > 0.0)) throw std::invalid_argument("the measured records have no height");
  return rms / height;
}

double gauge_records_error(const std::filesystem::path& run_folder) {
  const auto file = run_folder / "gauge_records.csv";
  if (!std::filesystem::exists(file))
    throw std::runtime_error("no gauge_records.csv: the scene needs diagnostics.gauge_records");
  const CsvTable t = read_csv(file);
  std::vector<GaugeRecordComparison> comparisons(t.rows.size());
  const auto rms = t.numbers("rms"), height = t.numbers("measured_height");
  for (std::size_t k = 0; k < comparisons.size(); ++k)
    comparisons[k].rms = rms[k], comparisons[k].measured_height = height[k];
  return gauge_records_error(comparisons);
}

}  // namespace slide::tools
