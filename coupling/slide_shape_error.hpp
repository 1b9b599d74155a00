#pragma once
// How far a deformable slide's shape is from a measured one (diagnostics.slide_shapes, slide_shapes.csv): the
// front's position error in per cent of the measured front's travel, and the rms vertical distance between the two
// upper surfaces. The same functions serve the run's output, the tests and the plots' titles.
//
// The measured shape is a set of digitized points (x, y) of the slide's upper surface at one time, in no particular
// order (a digitizer's strokes may double back). Its front is its largest x (where the surface meets the bed); its
// surface as a function of x is the upper envelope of the points, linearly interpolated between them in x.
// The model's upper surface is slide_upper_surface's or polygon_upper_surface's (coupling/slide_front.hpp): a column's
// centre and the material's top there; its front is the largest x the material reaches (the caller's: the furthest
// particle plus half a spacing, or a rigid outline's furthest vertex).
// The rms distance is taken at the model's columns whose centres lie within both surfaces' x ranges.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "fluid/vec.hpp"

namespace slide {

struct SlideShapeError {
  double front_measured = std::numeric_limits<double>::quiet_NaN();  // m, largest x of the measured surface
  double front_model = std::numeric_limits<double>::quiet_NaN();     // m
  double travel_measured = std::numeric_limits<double>::quiet_NaN(); // m, from the measured front at the start
  double front_error_percent = std::numeric_limits<double>::quiet_NaN();  // (model - measured) / travel, %
  double surface_rms_m = std::numeric_limits<double>::quiet_NaN();   // m
  std::size_t compared = 0;  // model columns in the rms
};

// The upper envelope of scattered points as increasing x with the highest y at each x.
inline std::vector<Vec<2>> upper_envelope(std::vector<Vec<2>> points) {
  std::sort(points.begin(), points.end(), [](const Vec<2>& a, const Vec<2>& b) {
    return a[0] < b[0] || (a[0] == b[0] && a[1] > b[1]);
  });
  std::vector<Vec<2>> out;
  for (const auto& p : points)
    if (out.empty() || p[0] > out.back()[0]) out.push_back(p);
  return out;
}

// y of an envelope (upper_envelope) at x, linear between its points; NaN outside its x range.
inline double envelope_at(const std::vector<Vec<2>>& envelope, double x) {
  if (envelope.empty() || x < envelope.front()[0] || x > envelope.back()[0])
    return std::numeric_limits<double>::quiet_NaN();
  const auto hi = std::lower_bound(envelope.begin(), envelope.end(), x,
                                   [](const Vec<2>& p, double v) { return p[0] < v; });
  if (hi == envelope.begin()) return hi->operator[](1);
  const auto lo = hi - 1;
  const double f = (x - (*lo)[0]) / ((*hi)[0] - (*lo)[0]);
  return (*lo)[1] + f * ((*hi)[1] - (*lo)[1]);
}

// measured: the digitized points at one time; measured_front_at_start: the measured front at the start (its travel's
// origin); model: the model's upper surface in increasing x, and its front.
inline SlideShapeError slide_shape_error(const std::vector<Vec<2>>& measured, double measured_front_at_start,
                                         const std::vector<Vec<2>>& model, double model_front) {
  SlideShapeError e;
  if (measured.empty() || model.empty()) return e;
  const std::vector<Vec<2>> envelope = upper_envelope(measured);
  e.front_measured = envelope.back()[0];
  e.front_model = model_front;
  e.travel_measured = e.front_measured - measured_front_at_start;
  if (e.travel_measured > 0.0) e.front_error_percent = 100.0 * (e.front_model - e.front_measured) / e.travel_measured;
  double sum = 0.0;
  for (const auto& c : model) {
    const double y = envelope_at(envelope, c[0]);
    if (std::isnan(y)) continue;
    sum += (c[1] - y) * (c[1] - y);
    ++e.compared;
  }
  if (e.compared > 0) e.surface_rms_m = std::sqrt(sum / e.compared);
  return e;
}

}  // namespace slide
