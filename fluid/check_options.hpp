#pragma once
// The stability checks' settings (scene keys `checks.*` and `domain`): a failed check stops a run with exit 3.
#include "fluid/vec.hpp"

namespace slide {

template <int D>
struct CheckOptions {
  double max_number_density_ratio = 1.5;  // n / n0 above this is a collapse
  double max_speed_over_c0 = 1.0;         // a fluid particle faster than this many c0 is a blow-up
  Vec<D> domain_lo = Vec<D>::Zero(), domain_hi = Vec<D>::Zero();  // a fluid particle outside has left the domain
};

}  // namespace slide
