#pragma once
// A box solid for rigid-body tests: its surface, centre, mass and inertia tensor from rigid/polyhedron.hpp.
#include "rigid/polyhedron.hpp"
#include "rigid/rigid_world.hpp"

namespace slide::testing {

inline rigid::SolidSpec solid_box(const rigid::Vec3& centre, const rigid::Vec3& size, double density,
                                  const rigid::Mat3& axes = rigid::Mat3::Identity()) {
  const rigid::TriangleSurface s = rigid::box_surface(centre, size, axes);
  const rigid::MassProperties m = rigid::mass_properties(s);
  rigid::SolidSpec spec;
  spec.hulls = {s};
  spec.centre_of_mass = m.centroid;
  spec.mass = density * m.volume;
  spec.inertia = density * m.inertia;
  return spec;
}

}  // namespace slide::testing
