#pragma once
// A tank at rest should start at rest. In WC-MPS the pressure follows from the number density (seed eq. 7), so a
// hydrostatic pressure field needs particles packed slightly closer with depth. Starting from an uncompressed
// lattice instead, the water falls under its own weight and rings for a long time.
//
// Each vertical run of fluid particles (same lattice column, consecutive spacing dp) is compressed along gravity:
// the gap between two neighbours at depth z is shrunk to the vertical spacing at which the lattice's number density
// gives the hydrostatic pressure rho g z through the equation of state. The run's bottom gap (to the wall or floor
// below it) is compressed the same way, its top is the free surface at half a spacing above the top particle.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <unordered_map>
#include <vector>

#include "fluid/communicator.hpp"
#include "fluid/equation_of_state.hpp"
#include "fluid/exact_sum.hpp"
#include "fluid/kernel.hpp"
#include "fluid/particles.hpp"

namespace slide {

// Number density (relative to n0) of the regular lattice with vertical spacing stretch * dp (last axis).
template <int D>
double stretched_lattice_density_ratio(double dp, double re, double stretch) {
  const int m = static_cast<int>(std::ceil(re / (dp * std::min(1.0, stretch)))) + 1;
  auto sum = [&](double s) {
    double n = 0.0;
    const int kmin = D == 3 ? -m : 0, kmax = D == 3 ? m : 0;
    for (int i = -m; i <= m; ++i)
      for (int j = -m; j <= m; ++j)
        for (int k = kmin; k <= kmax; ++k) {
          if (i == 0 && j == 0 && k == 0) continue;
          // The last axis is vertical: j in 2-D, k in 3-D.
          const double v = D == 2 ? j * s : k * s;
          const double h2 = D == 2 ? double(i) * i : double(i) * i + double(j) * j;
          n += kernel_weight(dp * std::sqrt(h2 + v * v), re);
        }
    return n;
  };
  return sum(stretch) / sum(1.0);
}

// Vertical stretch (< 1 is compression) at which the lattice number density ratio equals target (bisection).
template <int D>
double stretch_for_density_ratio(double dp, double re, double target) {
  double lo = 0.8, hi = 1.0;
  if (target <= 1.0) return 1.0;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (stretched_lattice_density_ratio<D>(dp, re, mid) > target)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

// Compresses the fluid particles' vertical positions as described above, and moves boundary particles beside a
// compressed run by the same vertical shift as the nearest run at their height: the symmetric pressure gradient
// feels any misalignment between the fluid's rows and the wall's as a force, so the wall lattice must continue the
// fluid's. g is the magnitude of gravity, which points along -(last axis). Returns the deepest water (m) of any
// run, nominal (uncompressed) height. With apply = false only the depth is measured.
// gap_from_top, when not empty, gives the equilibrium gaps by depth index (entry k: below the k-th particle from
// the top of a run, the last one of a run being its gap to the support), which replace the equation-of-state
// estimate for runs no deeper than it covers (coupling/equilibrium_column.hpp computes them).
// capped_surface: the still-water level for runs capped by a body's boundary particles (water under a floating
// block): their depth counts from that level, not from their own top; NaN for none.
// Boundary particles of bodies are never shifted: bodies keep the shape they were given.
// share: several processes, each holding the particles of its own lattice columns and of those within re around
// them (cases/build_share.hpp): a body's shift is the mean over the runs of every process's own columns. The mean is
// an exact sum (fluid/exact_sum.hpp) either way, so that it does not depend on how the columns are shared.
template <int D>
struct ColumnShare {
  std::function<bool(const Vec<D>&)> owns;  // whether a run at this horizontal position is this process's
  const Communicator* processes = nullptr;
};
template <int D>
double compress_hydrostatically(Particles<D>& P, double dp, double re, const EquationOfState& eos, double g,
                                bool apply, const std::vector<double>& gap_from_top,
                                double capped_surface = std::numeric_limits<double>::quiet_NaN(),
                                std::vector<double>* body_shift = nullptr, const ColumnShare<D>* share = nullptr) {
  std::vector<ExactSum> cap_shift_sum;  // per body: the top shifts of the runs it caps, and their count
  std::vector<std::int64_t> cap_count;
  constexpr int up = D - 1;
  struct Run {
    Vec<D> base;                    // horizontal position (vertical component unused)
    std::vector<double> y_nominal;  // bottom to top
    std::vector<double> shift;      // new minus nominal
  };
  std::vector<Run> runs;
  // The stretch for each pressure met: the lattice's rows repeat from column to column, so the bisection (thousands
  // of kernel sums in 3-D) runs once per depth, not once per particle (29 s of a 200 k particle 3-D setup before).
  std::unordered_map<double, double> stretch_for_target;
  auto stretch_for = [&](double target) {
    auto [it, fresh] = stretch_for_target.try_emplace(target, 0.0);
    if (fresh) it->second = stretch_for_density_ratio<D>(dp, re, target);
    return it->second;
  };
  // Items (particles, runs) binned by their horizontal cell `width` wide; those in the cells beside x's (within
  // `width` horizontally of it) by index, so that a loop over them meets them in the order of a scan over all.
  using Cells = std::map<std::array<long, 2>, std::vector<std::size_t>>;
  auto cell_of = [&](const Vec<D>& x, int k, double width) {
    return k < up ? std::lround(std::floor(x[k] / width)) : 0L;
  };
  auto bin = [&](Cells& cells, const Vec<D>& x, double width, std::size_t item) {
    cells[{cell_of(x, 0, width), cell_of(x, 1, width)}].push_back(item);
  };
  auto items_near = [&](const Cells& cells, const Vec<D>& x, double width,
                        std::vector<std::size_t>& out) -> const std::vector<std::size_t>& {
    out.clear();
    const long cx = cell_of(x, 0, width), cy = cell_of(x, 1, width), ry = D == 3 ? 1 : 0;
    for (long a = cx - 1; a <= cx + 1; ++a)
      for (long c = cy - ry; c <= cy + ry; ++c)
        if (const auto found = cells.find({a, c}); found != cells.end())
          out.insert(out.end(), found->second.begin(), found->second.end());
    std::sort(out.begin(), out.end());
    return out;
  };
  // Bodies' boundary particles, for the test of a run capped by a body (within dp / 2 horizontally of its top).
  Cells body_particles_in_cell;
  if (apply && std::isfinite(capped_surface))
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.body_frame[i] >= 0) bin(body_particles_in_cell, P.position[i], dp, i);
  std::vector<std::size_t> candidates;
  // Group fluid particles by lattice column.
  std::map<std::array<long, 2>, std::vector<std::size_t>> columns;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    std::array<long, 2> key{std::lround(P.position[i][0] / dp * 4.0),
                            D == 3 ? std::lround(P.position[i][1] / dp * 4.0) : 0L};
    columns[key].push_back(i);
  }
  double deepest = 0.0;
  for (auto& [key, members] : columns) {
    std::sort(members.begin(), members.end(),
              [&](std::size_t a, std::size_t b) { return P.position[a][up] < P.position[b][up]; });
    std::size_t start = 0;
    while (start < members.size()) {
      std::size_t end = start + 1;  // one past the run's top
      while (end < members.size() &&
             P.position[members[end]][up] - P.position[members[end - 1]][up] < 1.5 * dp)
        ++end;
      double surface = P.position[members[end - 1]][up] + 0.5 * dp;
      std::size_t top_offset = 0;  // rows of missing water between a cap and the still-water level
      int cap_body = -1;
      if (apply && std::isfinite(capped_surface) && capped_surface > surface + 0.5 * dp) {
        const Vec<D>& top = P.position[members[end - 1]];
        bool capped = false;
        for (const std::size_t i : items_near(body_particles_in_cell, top, dp, candidates)) {
          double h2 = 0.0;
          for (int k = 0; k < up; ++k) h2 += (P.position[i][k] - top[k]) * (P.position[i][k] - top[k]);
          const double above = P.position[i][up] - top[up];
          capped = h2 < 0.25 * dp * dp && above > 0.0 && above < 1.5 * dp;
          if (capped) {
            cap_body = P.body_of(i);
            break;
          }
        }
        if (capped) {
          top_offset = static_cast<std::size_t>(std::lround((capped_surface - surface) / dp));
          surface = capped_surface;
        }
      }
      const double bottom = P.position[members[start]][up] - 0.5 * dp;
      deepest = std::max(deepest, surface - bottom);
      if (apply) {
        Run run{P.position[members[start]], {}, {}};
        // Walk up from the support one spacing below the bottom particle, shrinking each gap.
        double below_nominal = P.position[members[start]][up] - dp;
        double below_new = below_nominal;
        for (std::size_t m = start; m < end; ++m) {
          const double y = P.position[members[m]][up];
          const double depth_mid = surface - 0.5 * (y + below_nominal);
          const double rho = P.density[members[m]];
          // Under layers of other densities (water over sediment) the pressure is their weight plus this phase's:
          // rho g depth + g sum_{above} (rho_k - rho) dp, each particle above standing for dp of height.
          double heavier_above = 0.0;
          for (std::size_t k = m + 1; k < end; ++k) heavier_above += P.density[members[k]] - rho;
          const double target = eos.number_density_ratio(rho * g * depth_mid + g * heavier_above * dp, rho);
          const std::size_t from_top = end - 1 - m + top_offset;
          const double gap = from_top < gap_from_top.size()
                                 ? gap_from_top[from_top] * (y - below_nominal) / dp
                                 : (y - below_nominal) * stretch_for(target);
          below_nominal = y;
          below_new += gap;
          P.position[members[m]][up] = below_new;
          run.y_nominal.push_back(y);
          run.shift.push_back(below_new - y);
        }
        if (cap_body >= 0 && (!share || share->owns(run.base))) {
          if (cap_shift_sum.size() <= std::size_t(cap_body)) cap_shift_sum.resize(cap_body + 1), cap_count.resize(cap_body + 1, 0);
          // The body sits on the top particle at the gap the missing water row above it would have.
          const double cap_gap = top_offset >= 1 && top_offset - 1 < gap_from_top.size() ? gap_from_top[top_offset - 1] : dp;
          cap_shift_sum[cap_body].add(run.shift.back() + (cap_gap - dp));
          cap_count[cap_body] += 1;
        }
        runs.push_back(std::move(run));
      }
      start = end;
    }
  }
  if (!apply) return deepest;
  // A body resting on compressed water goes down with it: by the mean top shift of the runs it caps.
  if (share && share->processes) {  // (every process as many bodies as the most capped)
    std::int64_t bodies = static_cast<std::int64_t>(cap_count.size());
    share->processes->max(&bodies, 1);
    cap_shift_sum.resize(static_cast<std::size_t>(bodies)), cap_count.resize(static_cast<std::size_t>(bodies), 0);
    sum_across(*share->processes, cap_shift_sum.data(), cap_shift_sum.size());
    share->processes->sum(cap_count.data(), cap_count.size());
  }
  if (body_shift) {
    body_shift->assign(cap_count.size(), 0.0);
    for (std::size_t b = 0; b < cap_count.size(); ++b)
      if (cap_count[b] > 0) (*body_shift)[b] = cap_shift_sum[b].value() / double(cap_count[b]);
  }
  // Boundary particles: the shift of the horizontally nearest run that spans their height (within re
  // horizontally); above a run's top they take its top shift. One in a run's own column below its bottom (the floor,
  // a step the run stands on, and beside a step the layers of its side face, which lie in the columns of the water
  // on the step) is that run's support and keeps its place: each run is compressed up from its support, so the gap
  // between them is already the compressed one. Measured with a 0.2 m step in 0.5 m of water (square lattice,
  // dp = 0.01, symmetric gradient, mirror walls), at the water on the step beside its corner, t = 0:
  //  * every boundary particle taking the nearest spanning run's shift (before): the step's top rows took the deeper
  //    run's, dropped 0.9 mm from the water on them, which started at n = 0.943 n0 and zero pressure; the corner
  //    collapsed at t = 0.089 s;
  //  * only an upward-facing face's particles kept in place, the side face following the deep run beside it: the
  //    corner's two faces then part by 1.09 dp, the water beside the corner starts at n = 0.990 n0 and zero pressure,
  //    and the corner collapsed at 0.040 s;
  //  * this rule: the water on the step starts at its depth's number density (tests/test_hydrostatic_start.cpp); the
  //    side face stands up to 0.09 dp off the rows of the deep run beside it, whose water there starts below its
  //    hydrostatic pressure (2456 Pa against 2947 Pa one column further out); the corner collapsed at 0.39 s, the rest
  //    being the symmetric gradient's (fluid/gradient.hpp).
  // Only runs within re horizontally count: they are looked up in cells re wide (over all runs, the 3-D bench case of
  // 5 M particles took 112 s here), in the runs' order, so the nearest and the first support are those of the scan.
  Cells runs_in_cell;
  for (std::size_t r = 0; r < runs.size(); ++r) bin(runs_in_cell, runs[r].base, re, r);
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] == Kind::fluid || P.body_frame[i] >= 0) continue;
    const Vec<D>& x = P.position[i];
    double best_h2 = re * re, shift = 0.0;
    for (const std::size_t r : items_near(runs_in_cell, x, re, near)) {
      const Run& run = runs[r];
      double h2 = 0.0;
      for (int k = 0; k < up; ++k) h2 += (run.base[k] - x[k]) * (run.base[k] - x[k]);
      if (x[up] < run.y_nominal.front() - 0.5 * dp) {
        if (h2 < 0.25 * dp * dp) {  // below the bottom of a run in its own column: that run's support
          shift = 0.0;
          break;
        }
        continue;
      }
      if (h2 >= best_h2 - 1e-12 * dp * dp) continue;
      best_h2 = h2;
      const auto& yn = run.y_nominal;
      const std::size_t above = std::upper_bound(yn.begin(), yn.end(), x[up]) - yn.begin();
      if (above == 0) shift = run.shift.front();
      else if (above == yn.size()) shift = run.shift.back();
      else {
        const double t = (x[up] - yn[above - 1]) / (yn[above] - yn[above - 1]);
        shift = (1 - t) * run.shift[above - 1] + t * run.shift[above];
      }
    }
    P.position[i][up] += shift;
  }
  return deepest;
}

// Deepest water of any vertical run of fluid particles, for lattices whose columns are `pitch` apart vertically
// (dp on the square lattice, two row spacings on the hexagonal one, whose alternate rows are offset): particles of
// one column whose consecutive gaps are below 1.5 pitch form a run, and each stands for one pitch of height.
template <int D>
double deepest_water(const Particles<D>& P, double dp, double pitch) {
  constexpr int up = D - 1;
  std::map<std::array<long, 2>, std::vector<double>> columns;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    columns[{std::lround(P.position[i][0] / dp * 8.0), D == 3 ? std::lround(P.position[i][1] / dp * 8.0) : 0L}]
        .push_back(P.position[i][up]);
  }
  double deepest = 0.0;
  for (auto& [key, ys] : columns) {
    std::sort(ys.begin(), ys.end());
    std::size_t start = 0;
    for (std::size_t k = 1; k <= ys.size(); ++k)
      if (k == ys.size() || ys[k] - ys[k - 1] >= 1.5 * pitch) {
        deepest = std::max(deepest, ys[k - 1] - ys[start] + pitch);
        start = k;
      }
  }
  return deepest;
}

}  // namespace slide
