#pragma once
// A plane of symmetry across which the scene continues as its mirror image (a tank's side walls[].symmetry): the
// half (or quarter) of a symmetric scene is modelled, and the particles within the neighbour list's radius of the
// plane get mirror images beyond it (fluid/ghosts.hpp), so that every particle near it sees the whole neighbourhood
// the symmetric scene gives it. The plane is perpendicular to an axis: x[axis] = at.
#include <cmath>

namespace slide {

struct MirrorPlane {
  int axis = 0;
  double at = 0.0;
  // The modelled side: x[axis] >= at (a min face) when true, x[axis] <= at (a max face) otherwise.
  bool keeps_above = true;

  // How far x lies inside the modelled side (negative beyond the plane).
  double inside(double x) const { return keeps_above ? x - at : at - x; }
  // The mirror image of the coordinate x: 2 at - x, written -x + 2 at so that a ghost's offset adds it.
  double twice_at() const { return 2.0 * at; }
  // Whether x lies on the plane, to a billionth of `margin` (the ghosts' depth): a particle there is its own mirror
  // image, gets none across it (fluid/ghosts.hpp: it would sit on itself) and is held on it (hold_on_planes).
  bool holds(double x, double margin) const { return std::abs(x - at) <= 1e-9 * margin; }
};

}  // namespace slide
