#pragma once
// Ghost particles: images of real particles that complete the neighbourhoods at the domain's edges, so that no
// operator needs to know about them. Every MPS operator takes its pair vectors as x[j] - x[i] from the neighbour list;
// a ghost is one more j.
//  * Periodic images (fluid/periodic.hpp): a real particle within the list radius of one end of the period gets an
//    image shifted by the period beyond the other end.
//  * Mirror images (fluid/mirror_plane.hpp): a real particle within the list radius of a plane of symmetry gets its
//    mirror image beyond it (two near planes: three images, across each and across both).
//
// Ghosts live at the end of the particle arrays (fluid/particles.hpp: ghost_source, ghost_flip, ghost_offset,
// real_count()). Ghost g is the image of real particle s = ghost_source[g]: its position is the source's with the
// components along the axes in ghost_flip[g] negated, plus ghost_offset[g] (a periodic shift L e_x; a mirror across
// x[a] = c: -x[a] + 2 c); its vectors (velocity, acceleration, wall normal) are the source's with those components
// negated, its corrective matrix L(a, b) times the signs of a and b; every other array is the source's, its id
// included. On every neighbour-list rebuild the simulation (coupling/simulation.cpp through fluid/domain.hpp)
// removes them, brings the real particles back into the domain (wrapped into the period, reflected back across a
// plane), re-sorts the real particles and creates them afresh (add_ghosts); between rebuilds it copies into them what
// each stage changes that neighbours read (sync_ghost_motion after a move, copy_to_ghosts for one array). A real
// particle that drifts past an end or a plane between rebuilds keeps correct neighbours: it and the images near it have
// moved less than half the skin since the list was built, the same argument as for any pair.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/mirror_plane.hpp"
#include "fluid/parallel.hpp"
#include "fluid/particles.hpp"
#include "fluid/periodic.hpp"

namespace slide {

// What makes the ghosts: the period along x, if any, and the planes of symmetry.
struct GhostLayout {
  std::optional<PeriodicX> period;
  std::vector<MirrorPlane> mirrors;
  bool any() const { return period.has_value() || !mirrors.empty(); }
};

// The image of a point, a vector and a corrective matrix for a ghost with flip mask `flip` and offset `offset`.
template <int D>
Vec<D> image_point(const Vec<D>& x, std::uint8_t flip, const Vec<D>& offset) {
  Vec<D> y = x;
  for (int a = 0; a < D; ++a)
    if (flip >> a & 1u) y[a] = -y[a];
  return y + offset;
}
template <int D>
Vec<D> image_vector(const Vec<D>& v, std::uint8_t flip) {
  Vec<D> y = v;
  for (int a = 0; a < D; ++a)
    if (flip >> a & 1u) y[a] = -y[a];
  return y;
}
template <int D>
Mat<D> image_matrix(const Mat<D>& m, std::uint8_t flip) {
  Mat<D> y = m;
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b)
      if ((flip >> a & 1u) != (flip >> b & 1u)) y(a, b) = -y(a, b);
  return y;
}

// Drops the ghosts: every array back to the real particles.
template <int D>
void remove_ghosts(Particles<D>& P) {
  const std::size_t n = P.real_count();
  P.for_each_array([&](auto& v) { v.resize(n); });
  P.ghost_source.clear();
  P.ghost_flip.clear();
  P.ghost_offset.clear();
}

// Copies every array of each ghost's source into the ghost (its id too), then takes the image of its position and
// vectors.
template <int D>
void sync_ghosts(Particles<D>& P) {
  const std::size_t r = P.real_count();
  parallel_for(P.ghost_count(), [&](std::size_t g) {
    const std::size_t s = P.ghost_source[g], t = r + g;
    P.for_each_array([&](auto& v) { v[t] = v[s]; });
    const std::uint8_t flip = P.ghost_flip[g];
    P.position[t] = image_point<D>(P.position[s], flip, P.ghost_offset[g]);
    if (flip != 0) {
      P.velocity[t] = image_vector<D>(P.velocity[s], flip);
      P.acceleration[t] = image_vector<D>(P.acceleration[s], flip);
      P.wall_normal[t] = image_vector<D>(P.wall_normal[s], flip);
    }
  });
}

// Copies what the step's stages move (position, velocity, acceleration) from each ghost's source into the ghost. The
// other arrays stay as sync_ghosts left them between rebuilds, or are copied by the stage that sets them
// (copy_to_ghosts): copying all of them after every stage was 9 % of the equilibrium column's time (perf).
template <int D>
void sync_ghost_motion(Particles<D>& P) {
  const std::size_t r = P.real_count();
  parallel_for(P.ghost_count(), [&](std::size_t g) {
    const std::size_t s = P.ghost_source[g], t = r + g;
    const std::uint8_t flip = P.ghost_flip[g];
    P.position[t] = image_point<D>(P.position[s], flip, P.ghost_offset[g]);
    P.velocity[t] = image_vector<D>(P.velocity[s], flip);
    P.acceleration[t] = image_vector<D>(P.acceleration[s], flip);
  });
}

// Copies one per-particle array from each ghost's source into the ghost: numbers as they are, vectors (velocity, wall
// normal) and corrective matrices as their images. Not for positions (sync_ghost_motion).
template <int D, class T>
void copy_to_ghosts(const Particles<D>& P, std::vector<T>& v) {
  const std::size_t r = P.real_count();
  parallel_for(P.ghost_count(), [&](std::size_t g) {
    const T& source = v[P.ghost_source[g]];
    if constexpr (std::is_same_v<T, Vec<D>>) v[r + g] = image_vector<D>(source, P.ghost_flip[g]);
    else if constexpr (std::is_same_v<T, Mat<D>>) v[r + g] = image_matrix<D>(source, P.ghost_flip[g]);
    else v[r + g] = source;
  });
}

// The images one real particle at x gets, in a fixed order: for each shift (none, +L near x_min, -L near x_max) and
// each set of the planes it lies near (by their order in the layout; the empty set only with a shift), one image.
// A particle on a plane (within a billionth of the margin) is its own image there and gets none across it (it would
// sit on itself or next to it).
template <int D, class Add>
void images_of(const Vec<D>& x, const GhostLayout& layout, double margin, Add&& add) {
  // Fixed-size lists: this runs for every particle at every rebuild (no allocation per particle, found in review).
  std::array<double, 3> shifts{0.0, 0.0, 0.0};
  std::size_t shift_count = 1;
  if (layout.period) {
    if (x[0] - layout.period->x_min < margin) shifts[shift_count++] = layout.period->length();
    if (layout.period->x_max - x[0] < margin) shifts[shift_count++] = -layout.period->length();
  }
  std::array<std::size_t, 8> near{};  // a plane per side of each axis: at most 6
  std::size_t near_count = 0;
  for (std::size_t k = 0; k < layout.mirrors.size() && near_count < near.size(); ++k) {
    const double d = layout.mirrors[k].inside(x[layout.mirrors[k].axis]);
    if (d < margin && !layout.mirrors[k].holds(x[layout.mirrors[k].axis], margin)) near[near_count++] = k;
  }
  const std::size_t subsets = std::size_t(1) << near_count;
  for (std::size_t h = 0; h < shift_count; ++h)
    for (std::size_t set = 0; set < subsets; ++set) {
      const double shift = shifts[h];
      if (set == 0 && shift == 0.0) continue;
      std::uint8_t flip = 0;
      Vec<D> offset = Vec<D>::Zero();
      offset[0] = shift;
      bool twice_on_one_axis = false;
      for (std::size_t b = 0; b < near_count; ++b) {
        if (!(set >> b & 1u)) continue;
        const MirrorPlane& m = layout.mirrors[near[b]];
        twice_on_one_axis = twice_on_one_axis || (flip >> m.axis & 1u);
        flip = static_cast<std::uint8_t>(flip | (1u << m.axis));
        offset[m.axis] += m.twice_at();
      }
      if (!twice_on_one_axis) add(flip, offset);
    }
}

// Ghosts afresh for every real particle within `margin` = re + skin (the list radius) of an end of the period or a
// plane of symmetry: then every real particle has every neighbour it can have before the next rebuild. Ghosts are
// appended in the order of their sources, each source's in images_of's order, so their order is fixed by the real
// particles' order alone. Needs a period of at least 2 margin (one image per side suffices), planes on one axis at
// least 2 margin apart (Simulation::check_mirror_setup), and no ghosts present.
template <int D>
void add_ghosts(Particles<D>& P, const GhostLayout& layout, double margin) {
  if (P.ghost_count() != 0) throw std::logic_error("add_ghosts: ghosts are already present");
  if (layout.period && !(layout.period->length() >= 2.0 * margin))
    throw std::invalid_argument("periodic_x: the period (" + std::to_string(layout.period->length()) +
                                " m) must be at least twice the kernel radius plus the neighbour skin (" +
                                std::to_string(2.0 * margin) + " m)");
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i)
    images_of<D>(P.position[i], layout, margin, [&](std::uint8_t flip, const Vec<D>& offset) {
      P.ghost_source.push_back(static_cast<std::uint32_t>(i));
      P.ghost_flip.push_back(flip);
      P.ghost_offset.push_back(offset);
    });
  const std::size_t total = n + P.ghost_source.size();
  P.for_each_array([&](auto& v) { v.resize(total); });
  sync_ghosts(P);
}

// The periodic images alone (the layout of a period and no planes).
template <int D>
void add_ghosts(Particles<D>& P, const PeriodicX& period, double margin) {
  add_ghosts(P, GhostLayout{period, {}}, margin);
}

// Real fluid particles that crossed a plane of symmetry come back as their mirror image (position reflected, the
// velocity's and acceleration's normal components negated), as the image that crossed the other way would have.
// Boundary particles do not cross (fixed, or on a body that moves along the plane). No ghosts may be present.
template <int D>
void reflect_into_mirrors(Particles<D>& P, const std::vector<MirrorPlane>& mirrors) {
  if (mirrors.empty()) return;
  parallel_for(P.real_count(), [&](std::size_t i) {
    if (P.kind[i] != Kind::fluid) return;
    for (const MirrorPlane& m : mirrors) {
      const int a = m.axis;
      if (!(m.inside(P.position[i][a]) < 0.0)) continue;
      P.position[i][a] = -P.position[i][a] + m.twice_at();
      P.velocity[i][a] = -P.velocity[i][a];
      P.acceleration[i][a] = -P.acceleration[i][a];
    }
  });
}

// Real fluid particles on a plane of symmetry (MirrorPlane::holds) put back on it, with no velocity or acceleration
// across it: the symmetric scene's particle there is its own image, so it has none. Why: its pairs with the images of
// its neighbours cancel across the plane only to rounding, and that rounding, summed over tens of thousands of steps,
// carried particles on the second plane of an axis (coordinates near 0.05 m, not 0) 7e-11 m off it, past the
// on-plane tolerance (2.4e-11 m at dp 0.01): at the next rebuild each got an image 1.5e-10 m away and a number
// density of 1.96 n0 (measured, a column between four planes after 6 s of settling), and the run stopped.
template <int D>
void hold_on_planes(Particles<D>& P, const std::vector<MirrorPlane>& mirrors, double margin) {
  if (mirrors.empty()) return;
  parallel_for(P.real_count(), [&](std::size_t i) {
    if (P.kind[i] != Kind::fluid) return;
    for (const MirrorPlane& m : mirrors) {
      const int a = m.axis;
      if (!m.holds(P.position[i][a], margin)) continue;
      P.position[i][a] = m.at;
      P.velocity[i][a] = 0.0;
      P.acceleration[i][a] = 0.0;
    }
  });
}

}  // namespace slide
