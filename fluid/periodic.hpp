#pragma once
// Periodic boundaries in x by ghost particles. Every MPS operator takes its pair vectors as x[j] - x[i] from the
// neighbour list, so instead of a minimum-image rule in each operator the real particles near one end of the period
// get images (ghosts) beyond the other end, and the operators see a full neighbourhood without knowing it.
//
// Ghosts live at the end of the particle arrays (fluid/particles.hpp: ghost_source, ghost_shift, real_count()):
// ghost g is a copy of real particle ghost_source[g] with x shifted by ghost_shift[g] = +L or -L (L the period).
// On every neighbour-list rebuild the simulation (coupling/simulation.cpp) removes them, wraps the real particles
// into [x_min, x_max), re-sorts the real particles, and creates them afresh (add_ghosts); between rebuilds it copies
// into them what each stage changes that neighbours read (sync_ghost_motion after a move, copy_to_ghosts for one
// array). A real
// particle that drifts past an end between rebuilds keeps correct neighbours: it and the images near it have moved
// less than half the skin since the list was built, the same argument as for any pair.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/parallel.hpp"
#include "fluid/particles.hpp"

namespace slide {

// The period [x_min, x_max) in x; L = x_max - x_min.
struct PeriodicX {
  double x_min = 0.0, x_max = 0.0;

  double length() const { return x_max - x_min; }

  // x brought into [x_min, x_max) by a whole number of periods; a value already inside is returned unchanged, bit
  // for bit. Non-finite values are returned as they are (the stability check reports them).
  double wrap(double x) const {
    if ((x >= x_min && x < x_max) || !std::isfinite(x)) return x;
    const double L = length();
    x -= L * std::floor((x - x_min) / L);
    // Rounding can leave x just outside; one more period, and x_min for a value that x + L rounded up onto x_max.
    if (x >= x_max) x -= L;
    if (x < x_min) x += L;
    if (x >= x_max || x < x_min) x = x_min;
    return x;
  }
};

// Wraps every real particle's x into the period (ghosts must have been removed).
template <int D>
void wrap_positions(Particles<D>& P, const PeriodicX& period) {
  parallel_for(P.real_count(), [&](std::size_t i) { P.position[i][0] = period.wrap(P.position[i][0]); });
}

// Drops the ghosts: every array back to the real particles.
template <int D>
void remove_ghosts(Particles<D>& P) {
  const std::size_t n = P.real_count();
  P.for_each_array([&](auto& v) { v.resize(n); });
  P.ghost_source.clear();
  P.ghost_shift.clear();
}

// Copies every array of each ghost's source into the ghost, then shifts its x and gives it its own id.
template <int D>
void sync_ghosts(Particles<D>& P) {
  const std::size_t r = P.real_count(), first_ghost_id = P.id_end();
  parallel_for(P.ghost_count(), [&](std::size_t g) {
    const std::size_t s = P.ghost_source[g], t = r + g;
    P.for_each_array([&](auto& v) { v[t] = v[s]; });
    P.position[t][0] += P.ghost_shift[g];
    P.id[t] = static_cast<std::uint32_t>(first_ghost_id + g);
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
    P.position[t] = P.position[s];
    P.position[t][0] += P.ghost_shift[g];
    P.velocity[t] = P.velocity[s];
    P.acceleration[t] = P.acceleration[s];
  });
}

// Copies one per-particle array (one that holds no position) from each ghost's source into the ghost.
template <int D, class T>
void copy_to_ghosts(const Particles<D>& P, std::vector<T>& v) {
  const std::size_t r = P.real_count();
  parallel_for(P.ghost_count(), [&](std::size_t g) { v[r + g] = v[P.ghost_source[g]]; });
}

// The margin within which a real particle gets an image: a real particle in the period has every neighbour it can
// have before the next rebuild, if the images reach `margin` = re + skin (the list radius) beyond each end.
// Each real particle (fluid and boundary alike: walls along a periodic channel are periodic too) with
// x - x_min < margin gets a ghost at x + L; with x_max - x < margin, one at x - L. Ghosts are appended in the
// order of their sources, left image before right, so their order is fixed by the real particles' order alone.
// Needs L >= 2 margin (one image per side suffices) and no ghosts present; real particles must lie in the period.
template <int D>
void add_ghosts(Particles<D>& P, const PeriodicX& period, double margin) {
  if (P.ghost_count() != 0) throw std::logic_error("add_ghosts: ghosts are already present");
  const double L = period.length();
  if (!(L >= 2.0 * margin))
    throw std::invalid_argument("periodic_x: the period (" + std::to_string(L) +
                                " m) must be at least twice the kernel radius plus the neighbour skin (" +
                                std::to_string(2.0 * margin) + " m)");
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double x = P.position[i][0];
    if (x - period.x_min < margin) {
      P.ghost_source.push_back(static_cast<std::uint32_t>(i));
      P.ghost_shift.push_back(L);
    }
    if (period.x_max - x < margin) {
      P.ghost_source.push_back(static_cast<std::uint32_t>(i));
      P.ghost_shift.push_back(-L);
    }
  }
  const std::size_t total = n + P.ghost_source.size();
  P.for_each_array([&](auto& v) { v.resize(total); });
  sync_ghosts(P);
}

}  // namespace slide
