#pragma once
// The domain seam (DESIGN.md, "One domain seam"): the particles this process owns, their ghost copies, the halo each
// stage declares its neighbours read, and every reduction over particles. A stage computes the owned particles only
// (owned_count()), then refreshes the fields the next stage reads of its neighbours; the time-step limits, the checks
// and the largest speed reduce over the owned particles here.
//
// Today the ghosts are the periodic images and the mirror images across planes of symmetry (fluid/ghosts.hpp: behind
// the owned particles in every array, rebuilt with the neighbour list, refreshed between). Particles owned by another process will be a second kind of ghost
// behind the same calls: refresh() becomes a halo exchange, the reductions combine across processes, and the stages
// do not change. Maxima are exact in any order; sums over particles are to be taken in an order that does not depend
// on the split (global ids), so that results stay the same to the bit for any number of threads and processes.
#include <array>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <vector>

#include "fluid/exact_sum.hpp"
#include "fluid/parallel.hpp"
#include "fluid/particles.hpp"
#include "fluid/ghosts.hpp"

namespace slide {

// What a stage's neighbours read beyond the motion: each is one per-particle array carried to the ghosts. `motion` is
// position (the ghost's image of it), velocity and acceleration, which every stage that moves particles changes (and
// the owned particles on a plane of symmetry are first held on it: fluid/ghosts.hpp, hold_on_planes);
// `wall_normal` turns with a body.
enum class HaloField {
  motion,
  velocity,
  number_density,
  pressure,
  gradient_correction,
  viscosity,
  wall_fraction,
  wall_fill,
  wall_normal
};

template <int D>
class Domain {
 public:
  // The owned particles, then their ghosts (Particles::real_count() are owned).
  Particles<D> particles;

  // The period along x, if any (fluid/periodic.hpp), and the planes of symmetry (fluid/mirror_plane.hpp); set before
  // the first rebuild of the ghosts.
  void set_ghost_layout(const GhostLayout& layout) { layout_ = layout; }
  const GhostLayout& ghost_layout() const { return layout_; }

  std::size_t owned_count() const { return particles.real_count(); }

  // The axes (bit a: axis a) of the planes of symmetry that owned particle i lies on (fluid/mirror_plane.hpp, holds,
  // within the last make_ghosts' depth): it is its own image across them, and its velocity across them is zero.
  std::uint8_t planes_holding(std::size_t i) const {
    std::uint8_t axes = 0;
    for (const MirrorPlane& m : layout_.mirrors)
      if (m.holds(particles.position[i][m.axis], ghost_depth_)) axes = static_cast<std::uint8_t>(axes | (1u << m.axis));
    return axes;
  }

  // Before the owned particles are re-sorted or removed: the ghosts go (every array back to the owned particles).
  void drop_ghosts() {
    if (layout_.any()) remove_ghosts(particles);
  }
  // Owned particles that crossed an end of the period come back into it, those that crossed a plane of symmetry come
  // back as their image (no ghosts present).
  void bring_inside() {
    if (layout_.period) wrap_positions(particles, *layout_.period);
    reflect_into_mirrors(particles, layout_.mirrors);
  }
  // After a re-sort: ghosts afresh for the owned particles within `depth` (the neighbour list's radius) of the
  // period's ends and the planes of symmetry. Returns whether there are any.
  bool make_ghosts(double depth) {
    ghost_depth_ = depth;
    if (layout_.any()) add_ghosts(particles, layout_, depth);
    return particles.ghost_count() != 0;
  }

  // The owned particles' `fields` carried to their ghosts: what the next stage reads of its neighbours.
  void refresh(std::initializer_list<HaloField> fields) {
    if (particles.ghost_count() == 0) return;
    for (const HaloField f : fields) refresh(f);
  }

  // The largest f(i) over the owned particles, from `init` (exact: max does not depend on the order).
  template <class F>
  double max_over_owned(double init, F&& f) const {
    return parallel_max(owned_count(), init, f);
  }
  // Several maxima in one pass (component k of f(i) into component k).
  template <std::size_t K, class F>
  std::array<double, K> max_each_over_owned(const std::array<double, K>& init, F&& f) const {
    return parallel_max_each<K>(owned_count(), init, f);
  }
  // Sums by group over the owned particles (a rigid body's force and torque over its boundary particles): entry g
  // of the result is the sum of values(i) over every owned i with group_of(i) == g (component by component; i with
  // group_of(i) < 0 count nowhere). Each sum is exact and rounded once (fluid/exact_sum.hpp), so it does not depend on
  // the order of the terms: the same bits for any storage order, thread count and, combined across processes, split.
  template <std::size_t K, class GroupOf, class Values>
  std::vector<std::array<double, K>> sum_by_group(std::size_t groups, GroupOf&& group_of, Values&& values) const {
    std::vector<std::array<ExactSum, K>> sums(groups);
    for (std::size_t i = 0; i < owned_count(); ++i) {
      const int g = group_of(i);
      if (g < 0) continue;
      const std::array<double, K> v = values(i);
      for (std::size_t k = 0; k < K; ++k) sums[static_cast<std::size_t>(g)][k].add(v[k]);
    }
    std::vector<std::array<double, K>> out(groups);
    for (std::size_t g = 0; g < groups; ++g)
      for (std::size_t k = 0; k < K; ++k) out[g][k] = sums[g][k].value();
    return out;
  }

 private:
  void refresh(HaloField f) {
    auto& P = particles;
    switch (f) {
      case HaloField::motion:
        hold_on_planes(P, layout_.mirrors, ghost_depth_);  // before its images are placed from it
        sync_ghost_motion(P);
        return;
      case HaloField::velocity: copy_to_ghosts(P, P.velocity); return;
      case HaloField::number_density: copy_to_ghosts(P, P.number_density); return;
      case HaloField::pressure: copy_to_ghosts(P, P.pressure); return;
      case HaloField::gradient_correction: copy_to_ghosts(P, P.gradient_correction); return;
      case HaloField::viscosity: copy_to_ghosts(P, P.viscosity); return;
      case HaloField::wall_fraction: copy_to_ghosts(P, P.wall_fraction); return;
      case HaloField::wall_fill: copy_to_ghosts(P, P.wall_fill); return;
      case HaloField::wall_normal: copy_to_ghosts(P, P.wall_normal); return;
    }
  }

  GhostLayout layout_;
  double ghost_depth_ = 0.0;  // the depth of the last make_ghosts
};

}  // namespace slide
