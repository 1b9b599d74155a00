#include "tools/measures/dam_break_front.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "tools/measures/series.hpp"

namespace slide::tools {

FrontError dam_break_front_error(const CsvTable& surge_front, const CsvTable& reference, double T_max) {
  const std::vector<double> T = surge_front.numbers("T"), Z = surge_front.numbers("Z");
  if (T.empty()) throw std::runtime_error("surge_front.csv has no rows");
  if (T.back() < T_max)
    throw std::runtime_error(fmt::format("the run ends at T = {:.4g}, before T = {:.4g}", T.back(), T_max));
  const std::vector<double> T_ref = reference.numbers("T_dimless_t_sqrt_2g_over_a"),
                            Z_ref = reference.numbers("Z_dimless_xfront_over_a");
  FrontError e;
  double sum = 0.0;
  for (std::size_t k = 0; k < T_ref.size(); ++k) {
    if (T_ref[k] <= 0.0 || T_ref[k] > T_max) continue;
    sum += std::abs(interpolate(T, Z, T_ref[k]) - Z_ref[k]) / Z_ref[k];
    ++e.points;
  }
  if (e.points == 0) throw std::runtime_error(fmt::format("no reference point with 0 < T <= {:.4g}", T_max));
  e.mean_relative = sum / e.points;
  return e;
}

}  // namespace slide::tools
