#pragma once
// Points spread evenly over a surface, one per spacing^2 of its area (the density of a flat wall's layer): a body's
// boundary particles on a curved or meshed face. CGAL's samplers give random points or a grid per triangle, neither
// spaced evenly across triangles, so the spreading is ours: candidates at random (a fixed seed: the same points on
// every machine) thinned by weighted sample elimination (Yuksel, "Sample Elimination for Generating Poisson Disk
// Sample Sets", Computer Graphics Forum 34(2), 2015).
#include <vector>

#include "rigid/polyhedron.hpp"

namespace slide::mesh {

struct SurfaceSample {
  rigid::Vec3 point;
  int triangle = 0;  // the one it lies on
  bool operator==(const SurfaceSample&) const = default;
};

// round(area / spacing^2) points (at least one per surface with any area) on the surface's triangles. Another `seed`
// gives another such set (layers behind a surface each take their own, so that their gaps do not line up).
std::vector<SurfaceSample> even_surface_samples(const rigid::TriangleSurface& surface, double spacing,
                                                unsigned long seed = 20071215);

}  // namespace slide::mesh
