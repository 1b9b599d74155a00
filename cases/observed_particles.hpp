#pragma once
// What a scene's CSVs read of the particles (tools/run_outputs.hpp), so that the first process's observers' copy of a
// run on several processes (tools/observer_copy.hpp) takes in those particles alone rather than the whole scene:
//  * gauges and profiles (coupling/free_surface_gauge.hpp): the fluid particles within reach of the vertical through
//    a gauge, or through a profile's segment, or whose periodic or mirror image is (the images are the copy's ghosts);
//  * the surge front and the velocity profile (2-D): all the fluid;
//  * the slides' fronts, outlines and shapes (coupling/slide_front.hpp): the fluid of the slides' phases; in 3-D a
//    rigid body's outline reads its wall particles.
// The outputs then read the same numbers in the same order as on one process: the copy stores its particles by cell,
// by id within a cell (Simulation::store_as_one_process), so those it leaves out do not change the others' order,
// and they add nothing to what is read: a gauge's kernel sums add +0.0 for a particle beyond re.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cases/scene.hpp"

namespace slide::cases {

template <int D>
class ObservedParticles {
 public:
  // reach_m: how far from a gauge's vertical a fluid particle is read (at least the kernel's radius re).
  ObservedParticles(const Scene<D>& scene, const GhostLayout& images, double reach_m)
      : images_(images), reach_m_(reach_m) {
    all_fluid_ = D == 2 && (scene.surge_front.enabled || scene.velocity_profile.enabled);
    for (const auto& s : scene.slides) phases_.push_back(s.phase);
    body_walls_ = D == 3 && !scene.slide_outline_times.empty();
    for (const auto& g : scene.gauges) {
      const std::array<double, 2> at{g.x, g.y};
      segments_.push_back({at, at});
    }
    if (!scene.profiles.times.empty()) segments_.push_back({scene.profiles.from, scene.profiles.to});
  }

  // Whether the outputs read particle i (a real particle).
  bool operator()(const Particles<D>& P, std::size_t i) const {
    if (P.kind[i] == Kind::wall) return body_walls_ && P.body_of(i) >= 0;
    if (P.kind[i] != Kind::fluid) return false;
    if (all_fluid_ || std::find(phases_.begin(), phases_.end(), P.phase[i]) != phases_.end()) return true;
    return !segments_.empty() && near_a_segment(P.position[i]);
  }

 private:
  struct Segment {
    std::array<double, 2> from, to;  // m, (x, y) of the plan; y unused in 2-D
  };

  // Whether x, or one of the images the copy may give it (shifted by the period, mirrored across the planes of
  // symmetry), lies within reach of a segment in the plan.
  bool near_a_segment(const Vec<D>& x) const {
    const std::size_t planes = images_.mirrors.size();
    const int shifts = images_.period ? 1 : 0;
    for (std::size_t across = 0; across < (std::size_t{1} << planes); ++across)
      for (int shift = -shifts; shift <= shifts; ++shift) {
        Vec<D> image = x;
        for (std::size_t m = 0; m < planes; ++m) {
          const MirrorPlane& plane = images_.mirrors[m];
          if (across >> m & 1u) image[plane.axis] = plane.twice_at() - image[plane.axis];
        }
        if (shift != 0) image[0] += shift * images_.period->length();
        for (const Segment& s : segments_)
          if (plan_distance_squared(image, s) < reach_m_ * reach_m_) return true;
      }
    return false;
  }

  // The squared distance in the plan (x in 2-D; x and y in 3-D) from a point to a segment.
  static double plan_distance_squared(const Vec<D>& p, const Segment& s) {
    constexpr int axes = D - 1;
    double along = 0.0, length2 = 0.0;
    for (int a = 0; a < axes; ++a) {
      along += (p[a] - s.from[a]) * (s.to[a] - s.from[a]);
      length2 += (s.to[a] - s.from[a]) * (s.to[a] - s.from[a]);
    }
    const double t = length2 > 0.0 ? std::clamp(along / length2, 0.0, 1.0) : 0.0;
    double d2 = 0.0;
    for (int a = 0; a < axes; ++a) {
      const double c = s.from[a] + t * (s.to[a] - s.from[a]);
      d2 += (p[a] - c) * (p[a] - c);
    }
    return d2;
  }

  GhostLayout images_;
  double reach_m_;
  bool all_fluid_ = false, body_walls_ = false;
  std::vector<std::uint8_t> phases_;
  std::vector<Segment> segments_;
};

}  // namespace slide::cases
