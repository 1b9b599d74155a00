#pragma once
// Everything the fluid solver is told by a scene, split by concern: the method, the time step, the checks, the
// domain's periodic directions, and gravity. The parts are bases so that each is read, printed and tested on its
// own while the step reads one object.
#include "fluid/check_options.hpp"
#include "fluid/domain_options.hpp"
#include "fluid/method_options.hpp"
#include "fluid/time_step_options.hpp"

namespace slide {

template <int D>
struct FluidOptions : MethodOptions, TimeStepOptions, CheckOptions<D>, DomainOptions {
  Vec<D> gravity = Vec<D>::Zero();  // m/s^2
};

}  // namespace slide
