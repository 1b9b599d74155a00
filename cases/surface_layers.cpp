// Steps: boundary particles in layers along a triangle surface (cases/surface_layers.hpp).
#include "cases/surface_layers.hpp"

#include "mesh/even_surface_samples.hpp"

namespace slide::cases {

std::vector<BoundaryPointOf<3>> surface_layers(const rigid::TriangleSurface& surface, const mesh::MeshDistance& distance,
                                               const std::function<bool(const Vec<3>&)>& solid_side, double dp,
                                               int layers) {
  std::vector<BoundaryPointOf<3>> out;
  for (int l = 0; l < layers; ++l) {
    const double depth = (l + 0.5) * dp;
    const auto samples = mesh::even_surface_samples(surface, dp, 20071215 + static_cast<unsigned long>(l));
    for (const auto& sample : samples) {
      const auto& t = surface.triangles[std::size_t(sample.triangle)];
      const Vec<3> p = sample.point - depth * rigid::outward_normal(surface, t);
      if (!solid_side(p)) continue;
      const double d = distance.distance(p);
      if (d < depth - 0.25 * dp || d > depth + 0.25 * dp) continue;
      out.push_back({p, Vec<3>((distance.nearest_point(p) - p).normalized()), d, l});
    }
  }
  return out;
}

}  // namespace slide::cases
