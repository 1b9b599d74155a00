#pragma once
// Water at rest in a tank under any constant gravity (gx, gy), gy < 0: a still tank (gx = 0), or, in the tank's
// frame, a tank accelerated sideways at the constant rate a (gx = -a). The exact answer wall models are tested
// against (tests/test_wall_models.cpp).
#include "fluid/vec.hpp"

namespace slide {

// Rigid-body equilibrium of an incompressible fluid: grad p = rho G, so p is constant on planes normal to G and the
// free surface is one of them, tilted by atan(gx / gy) from the horizontal. In a tank of vertical walls x = left and
// x = left + width, the surface passes through the tank's middle at the water's mass level L (the level of the same
// water at rest under gx = 0: area over width), since the tilted plane moves as much water up on one side as down on
// the other (while it meets both walls above the floor: |gx / gy| width / 2 < L). Then
//   surface y_s(x) = L - (gx / gy) (x - x_c),   p(x, y) = rho G . ((x, y) - (x_c, L)),   x_c = left + width / 2
// (elementary hydrostatics in the tank's frame: the textbook "liquid in a uniformly accelerated tank").
struct TiltedHydrostatic {
  Vec<2> gravity;       // m/s^2, (gx, gy) with gy < 0
  double left = 0.0;    // m, the left wall's face
  double width = 1.0;   // m
  double mass_level = 0.0;  // m, L
  double density = 1000.0;  // kg/m^3

  double centre_x() const { return left + 0.5 * width; }
  // dy_s / dx of the free surface.
  double surface_slope() const { return -gravity[0] / gravity[1]; }
  double surface_y(double x) const { return mass_level + surface_slope() * (x - centre_x()); }
  double pressure(const Vec<2>& at) const {
    return density * gravity.dot(at - Vec<2>(centre_x(), mass_level));
  }
};

}  // namespace slide
