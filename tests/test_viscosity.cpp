// The Newtonian viscous term of fluid/viscosity.hpp as it stands, on both lattices, through the fluid/ operators
// alone (no Simulation, so that the test outlives changes to the step loop):
//  * plane Couette: the exact linear profile has zero viscous acceleration; interior particles give zero, and the
//    figures of the rows beside the walls (where the mirror clips d_i at dp / 2) are pinned;
//  * plane Poiseuille: the steady state of du/dt = a_visc + g against the closed form;
//  * free_slip: walls exert no shear;
//  * two viscosities: the harmonic mean across a pair.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/lattice.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"
#include "fluid/viscosity.hpp"
#include "fluid/walls.hpp"

namespace slide {
namespace {

constexpr double rho = 1000.0;  // kg/m^3
constexpr double mu = 0.1;      // Pa s, nu = 1e-4 m^2/s

// A channel between a floor face y = 0 and a ceiling face y = H = 20 dp, 60 dp long, with no periodic ends. The wall
// faces run 2.5 to 3 dp beyond both ends of the fluid, so every fluid particle sees a full wall beneath and above it.
// Square lattice: wall layers at (k + 1/2) dp behind the faces (polyline_boundary, ceil(re / dp) layers), fluid at
// ((i + 1/2) dp, (j + 1/2) dp): 20 rows. Hexagonal lattice: walls cut from the lattice (lattice_boundary), fluid the
// lattice points strictly between the faces: 21 rows (row spacing 0.9306 dp), the lowest 0.465 dp above the floor,
// the highest 0.922 dp below the ceiling, whose first wall row lies only 0.0077 dp behind its face.
struct WallChannel {
  LatticeKind kind;
  double dp = 0.01;
  double re = 2.1 * dp;
  double H = 20 * dp;
  double L = 60 * dp;
  Particles<2> P;
  NeighborList list;
  LatticeConstants c;
  std::vector<std::size_t> fluid, floor_walls, ceiling_walls;

  explicit WallChannel(LatticeKind k) : kind(k) {
    const double ext = 3 * dp;
    // Square lattice: the open faces' wall points are anchored at the face's start, so the start is put on the
    // lattice's column x = -5/2 dp.
    const double x0 = kind == LatticeKind::square ? -2.5 * dp : -ext, x1 = L + ext;
    const std::vector<Vec<2>> floor_face{Vec<2>(x0, 0.0), Vec<2>(x1, 0.0)};
    const std::vector<Vec<2>> ceiling_face{Vec<2>(x0, H), Vec<2>(x1, H)};
    auto add_walls = [&](const std::vector<Vec<2>>& face, bool fluid_on_left, std::vector<std::size_t>& out) {
      const auto pts = kind == LatticeKind::square
                           ? polyline_boundary(face, fluid_on_left, dp, boundary_layers(re / dp))
                           : lattice_boundary(face, fluid_on_left, dp, re, kind);
      for (const auto& b : pts) {
        const std::size_t i = P.add(b.position, b.layer == 0 ? Kind::wall : Kind::dummy, 0, rho, mu);
        P.wall_normal[i] = b.normal;
        P.wall_depth[i] = b.depth;
        out.push_back(i);
      }
    };
    add_walls(floor_face, true, floor_walls);
    add_walls(ceiling_face, false, ceiling_walls);
    const double eps = 1e-9 * dp;
    for_each_lattice_point(kind, dp, Vec<2>(0.0, 0.0), Vec<2>(L, H), [&](const Vec<2>& p) {
      if (p[0] > 0.0 && p[0] < L && p[1] > eps && p[1] < H - eps) fluid.push_back(P.add(p, Kind::fluid, 0, rho, mu));
    });
    NeighborGrid<2> grid(Vec<2>(x0 - re, -2 * re), Vec<2>(x1 + re, H + 2 * re), re);
    grid.bin(P.position);
    build_neighbor_list(grid, P.position, re, list);
    c = lattice_constants<2>(dp, re, kind);
  }

  double y(std::size_t i) const { return P.position[i][1]; }
  // At least 3 re from the open ends.
  bool tested(std::size_t i) const { return P.position[i][0] >= 3 * re && P.position[i][0] <= L - 3 * re; }
  // The whole kernel support lies in the fluid.
  bool interior(std::size_t i) const { return y(i) >= re && y(i) <= H - re; }
  Vec<2> accel(std::size_t i, WallSlip slip) const {
    return viscous_acceleration<2>(i, P, list, re, c.n0, c.lambda, ViscousWall{slip, 0.5 * dp});
  }
  // Rows: the row index of a fluid particle, counted from the floor.
  long row(std::size_t i) const { return std::lround(y(i) / row_spacing(kind, dp) - 0.5); }
};

// ---------------------------------------------------------------------------------------------------------------
// 1. Plane Couette. u = U y / H in the fluid, floor walls at rest, ceiling walls moving with (U, 0). The exact
// viscous acceleration is zero everywhere. With the exact mirror u_j = u_b - (d_j / d_i)(u_i - u_b) the wall
// particles would carry the linear profile continued behind the face and every particle would give zero; the clip
// of d_i at dp / 2 (fluid/viscosity.hpp, no_slip_mirror_factor) breaks that for a row nearer the face than dp / 2,
// which then gets
//   a_i = 2d / (lambda n0 rho) mu sum_{wall j} (d_j / (dp/2) - d_j / d_i) W(r_ij) (u_b - u_i),
// checked below against an independent sum over the wall neighbours, and pinned as a number a_x H dp / (nu U) per
// row. (Morris et al.'s cap of the factor at 1.5, used until this test was written, gave the square lattice's first
// rows +-0.2501 and the hexagonal floor's +0.2703.)

// Measured; d = distance of the row from its face in dp.
struct RowFigure {
  bool ceiling;
  double d;       // distance from the face / dp
  double figure;  // a_x H dp / (nu U)
};

void couette(LatticeKind kind, const std::vector<RowFigure>& pinned) {
  WallChannel ch(kind);
  auto& P = ch.P;
  const double U = 0.5, nu = mu / rho;
  for (auto i : ch.fluid) P.velocity[i] = Vec<2>(U * ch.y(i) / ch.H, 0.0);
  for (auto i : ch.ceiling_walls) P.velocity[i] = Vec<2>(U, 0.0);
  const double unit = nu * U / (ch.H * ch.dp);  // a_x / unit is the figure
  const double scale = 2.0 * 2 / (ch.c.lambda * ch.c.n0 * rho);

  std::map<std::pair<bool, long>, std::vector<double>> rows;  // (ceiling?, distance in 1e-6 dp) -> figures
  std::size_t interior = 0;
  for (auto i : ch.fluid) {
    if (!ch.tested(i)) continue;
    const Vec<2> a = ch.accel(i, WallSlip::no_slip);
    EXPECT_EQ(a[1], 0.0);
    if (ch.interior(i)) {
      ++interior;
      ASSERT_NEAR(a[0] / unit, 0.0, 1e-11) << "interior particle at y = " << ch.y(i) / ch.dp << " dp";
      continue;
    }
    // The cap's deficit, summed here independently of viscous_pair_term.
    const double yi = ch.y(i);
    double deficit = 0.0;
    for (const std::uint32_t* q = ch.list.begin(i); q != ch.list.end(i); ++q) {
      const std::uint32_t j = *q;
      if (P.kind[j] == Kind::fluid) continue;
      const double r = (P.position[j] - P.position[i]).norm();
      const bool ceiling_wall = P.position[j][1] > 0.5 * ch.H;
      const double d_i = ceiling_wall ? ch.H - yi : yi, d_j = P.wall_depth[j];
      const double exact = 1.0 + d_j / d_i, clipped = 1.0 + d_j / std::max(d_i, 0.5 * ch.dp);
      deficit += (clipped - exact) * kernel_weight(r, ch.re) * (P.velocity[j][0] - P.velocity[i][0]);
    }
    EXPECT_NEAR(a[0] / unit, scale * mu * deficit / unit, 1e-11) << "y = " << yi / ch.dp << " dp";
    const bool ceiling = yi > 0.5 * ch.H;
    const double d = (ceiling ? ch.H - yi : yi) / ch.dp;
    rows[{ceiling, std::lround(d * 1e6)}].push_back(a[0] / unit);
  }
  EXPECT_GT(interior, 0u);

  std::printf("[ Couette, %s lattice ] a_x H dp / (nu U) by row (distance from face / dp):\n",
              std::string(to_string(kind)).c_str());
  std::size_t matched = 0;
  for (const auto& [key, figs] : rows) {
    const auto [lo, hi] = std::minmax_element(figs.begin(), figs.end());
    const double d = key.second * 1e-6;
    std::printf("    %-7s d = %.4f: %.15g (%zu particles)\n", key.first ? "ceiling" : "floor", d, *lo, figs.size());
    // Every particle of a row alike (translation along x).
    EXPECT_NEAR(*hi, *lo, 1e-11);
    for (const auto& p : pinned)
      if (p.ceiling == key.first && std::abs(p.d - d) < 1e-3) {
        ++matched;
        EXPECT_NEAR(*lo, p.figure, std::max(1e-9 * std::abs(p.figure), 1e-11)) << (key.first ? "ceiling" : "floor") << " row d = " << d;
      }
  }
  EXPECT_EQ(matched, pinned.size());
  EXPECT_EQ(rows.size(), pinned.size());
}

// Square lattice: every row lies at least dp/2 from its face, so the mirror is exact and every row gives zero.
TEST(Viscosity, CouetteSquare) {
  couette(LatticeKind::square, {{false, 0.5, 0.0}, {false, 1.5, 0.0}, {true, 0.5, 0.0}, {true, 1.5, 0.0}});
}
// Hexagonal lattice: the floor's first row lies 0.4653 dp from its face, under the clip, so its mirror factors are
// 1 + d_j / (dp/2) instead of 1 + d_j / 0.4653 dp: the wall brakes it slightly too little, +0.0371. Every other row
// is exact.
TEST(Viscosity, CouetteHexagonal) {
  couette(LatticeKind::hexagonal,
          {{false, 0.4653, 0.0370581430427264}, {false, 1.3959, 0.0}, {true, 0.9226, 0.0}, {true, 1.8532, 0.0}});
}

// ---------------------------------------------------------------------------------------------------------------
// 2. Plane Poiseuille. Both walls at rest, a body force g along x, particles fixed in place: the steady state of
// du/dt = a_visc(u) + g for an infinitely long channel, whose velocity depends on the row alone. (The open ends of
// the 60 dp channel would disturb a steady state of the whole set of particles over a decay length H / pi = 6.4 dp
// and more: its rows differed by up to 3 % of u_max along x.) The viscous term is linear in the velocities (walls
// at rest), so for a particle far enough from the ends (the tested ones, whose whole support lies in the channel)
// a_visc = sum over rows r of A(row, r) u_r; A is read off viscous_acceleration, setting one row after another to
// unit speed, and A u = -g is solved. The solution is checked by evaluating viscous_acceleration on it.
// Closed form: u(y) = g / (2 nu) y (H - y), u_max = g H^2 / (8 nu).
struct PoiseuilleErrors {
  double centreline;  // (u - u_exact) / u_exact at the row nearest y = H / 2
  double l2;          // rms of u - u_exact over the tested particles, / u_max
};

PoiseuilleErrors poiseuille(LatticeKind kind) {
  WallChannel ch(kind);
  auto& P = ch.P;
  const double nu = mu / rho, g = 8.0 * nu / (ch.H * ch.H);  // u_max = 1 m/s
  std::map<long, int> row_of;  // lattice row -> unknown
  for (auto i : ch.fluid) row_of.emplace(ch.row(i), 0);
  int n = 0;
  for (auto& [r, k] : row_of) k = n++;
  Eigen::MatrixXd A = Eigen::MatrixXd::Constant(n, n, std::nan(""));
  const double diagonal = 4.0 * nu / ch.c.lambda;  // |A(k, k)| in the bulk: 2d / (lambda n0) nu sum_j W
  for (const auto& [r, k] : row_of) {
    for (auto i : ch.fluid) P.velocity[i] = Vec<2>(ch.row(i) == r ? 1.0 : 0.0, 0.0);
    for (auto i : ch.fluid) {
      if (!ch.tested(i)) continue;
      const double a = ch.accel(i, WallSlip::no_slip)[0];
      double& e = A(row_of.at(ch.row(i)), k);
      if (std::isnan(e)) e = a;
      EXPECT_NEAR(a, e, 1e-12 * diagonal) << "every tested particle of a row alike";
    }
  }
  const Eigen::VectorXd u = A.fullPivLu().solve(Eigen::VectorXd::Constant(n, -g));
  for (auto i : ch.fluid) P.velocity[i] = Vec<2>(u[row_of.at(ch.row(i))], 0.0);

  // The steady state: viscous_acceleration balances g on every tested particle.
  for (auto i : ch.fluid) {
    if (!ch.tested(i)) continue;
    const Vec<2> a = ch.accel(i, WallSlip::no_slip);
    EXPECT_NEAR(a[0] + g, 0.0, 1e-9 * g);
    EXPECT_EQ(a[1], 0.0);
  }
  auto exact = [&](double y) { return g / (2.0 * nu) * y * (ch.H - y); };
  double nearest = ch.H;
  for (auto i : ch.fluid) nearest = std::min(nearest, std::abs(ch.y(i) - 0.5 * ch.H));
  double sum2 = 0.0, centre = 0.0, centre_y = 0.0;
  std::size_t count = 0, centre_count = 0;
  for (auto i : ch.fluid) {
    if (!ch.tested(i)) continue;
    const double e = P.velocity[i][0] - exact(ch.y(i));
    sum2 += e * e;
    ++count;
    if (std::abs(std::abs(ch.y(i) - 0.5 * ch.H) - nearest) < 1e-9 * ch.dp) {
      centre += e / exact(ch.y(i));
      centre_y = ch.y(i);
      ++centre_count;
    }
  }
  const PoiseuilleErrors out{centre / centre_count, std::sqrt(sum2 / count) / (g * ch.H * ch.H / (8.0 * nu))};
  std::printf("[ Poiseuille, %s lattice ] centreline row y = %.4f dp: error %+.9f %%; L2 error / u_max %.9f %%\n",
              std::string(to_string(kind)).c_str(), centre_y / ch.dp, 100 * out.centreline, 100 * out.l2);
  return out;
}

// Measured (20 rows across on the square lattice, 21 on the hexagonal one):
//   square:    centreline (row 10.5 dp)  +0.2516 %, L2 0.2510 % of u_max;
//   hexagonal: centreline (row 9.771 dp) +0.2950 %, L2 0.3319 % of u_max.
// Before the mirror's distance was clipped at dp / 2 in place of Morris et al.'s cap of the factor at 1.5, the same
// test gave square +3.5966 % / 3.5878 % and hexagonal +1.7449 % / 1.9736 %: the capped factor (1.5 where 1 + d_j / d_i
// is 2 to 4 in the first row) braked the first row too little, which put the effective no-slip plane behind the
// face. Wall particles at zero velocity, no mirror (measured on an edited copy): square +10.3 %, hexagonal +5.0 %.
// DESIGN.md's prototype figures for a Bingham Poiseuille at 20 particles across (square) were 0.3 % mirrored and
// +12 % not mirrored.
TEST(Viscosity, PoiseuilleSquare) {
  const auto e = poiseuille(LatticeKind::square);
  EXPECT_GT(e.centreline, 0.0);
  EXPECT_LT(std::abs(e.centreline), 0.002516 * 1.1 + 1e-4);
  EXPECT_LT(e.l2, 0.002510 * 1.1 + 1e-4);
}
TEST(Viscosity, PoiseuilleHexagonal) {
  const auto e = poiseuille(LatticeKind::hexagonal);
  EXPECT_GT(e.centreline, 0.0);
  EXPECT_LT(std::abs(e.centreline), 0.002950 * 1.1 + 1e-4);
  EXPECT_LT(e.l2, 0.003319 * 1.1 + 1e-4);
}

// ---------------------------------------------------------------------------------------------------------------
// 3. free_slip: boundary particles exert no shear. A uniform flow u = (U, 0) between a resting floor and a ceiling
// moving at (U, 0) has zero viscous acceleration everywhere (exactly: every fluid pair has u_j - u_i = 0), whereas
// no_slip brakes the rows beside the resting floor. With the Couette profile, the ceiling's velocity changes nothing.
void free_slip(LatticeKind kind) {
  WallChannel ch(kind);
  auto& P = ch.P;
  const double U = 0.5;
  for (auto i : ch.fluid) P.velocity[i] = Vec<2>(U, 0.0);
  for (auto i : ch.ceiling_walls) P.velocity[i] = Vec<2>(U, 0.0);
  std::size_t braked = 0;
  for (auto i : ch.fluid) {
    const Vec<2> a = ch.accel(i, WallSlip::free_slip);
    EXPECT_EQ(a[0], 0.0);
    EXPECT_EQ(a[1], 0.0);
    const Vec<2> b = ch.accel(i, WallSlip::no_slip);
    if (ch.y(i) < ch.re) {
      EXPECT_LT(b[0], 0.0) << "no_slip beside the resting floor, y = " << ch.y(i) / ch.dp << " dp";
      ++braked;
    } else {
      EXPECT_EQ(b[0], 0.0);  // the moving ceiling and the fluid agree
    }
  }
  EXPECT_GT(braked, 0u);

  // The Couette profile: the accelerations do not depend on the ceiling's velocity.
  for (auto i : ch.fluid) P.velocity[i] = Vec<2>(U * ch.y(i) / ch.H, 0.0);
  std::vector<Vec<2>> moving, other;
  for (auto i : ch.fluid) moving.push_back(ch.accel(i, WallSlip::free_slip));
  for (auto i : ch.ceiling_walls) P.velocity[i] = Vec<2>(-3.0 * U, 0.7 * U);
  for (auto i : ch.floor_walls) P.velocity[i] = Vec<2>(2.0 * U, 0.0);
  for (auto i : ch.fluid) other.push_back(ch.accel(i, WallSlip::free_slip));
  for (std::size_t k = 0; k < moving.size(); ++k) {
    EXPECT_EQ(moving[k][0], other[k][0]);
    EXPECT_EQ(moving[k][1], other[k][1]);
  }
}
TEST(Viscosity, FreeSlipSquare) { free_slip(LatticeKind::square); }
TEST(Viscosity, FreeSlipHexagonal) { free_slip(LatticeKind::hexagonal); }

// ---------------------------------------------------------------------------------------------------------------
// 4. Two viscosities: across a pair the term uses the harmonic mean mu_ij = 2 mu_i mu_j / (mu_i + mu_j)
// (Shakibaeinia & Jin 2011), the same seen from either side, so the pair exchanges equal and opposite momentum;
// equal viscosities give mu itself. Pairs at each lattice's nearest spacing and further apart.
void two_viscosities(LatticeKind kind) {
  const double dp = 0.01, re = 2.1 * dp;
  const LatticeConstants c = lattice_constants<2>(dp, re, kind);
  const double a = nearest_spacing(kind, dp);
  for (double r : {a, 1.3 * a, 1.9 * dp}) {
    for (auto [mu_i, mu_j] : {std::pair{0.1, 2.5}, std::pair{1e-3, 40.0}, std::pair{0.3, 0.3}}) {
      Particles<2> P;
      const double rho_i = 1000.0, rho_j = 1800.0;
      const std::size_t i = P.add(Vec<2>(0.2, 0.1), Kind::fluid, 0, rho_i, mu_i);
      const std::size_t j = P.add(Vec<2>(0.2, 0.1) + r * Vec<2>(0.6, 0.8), Kind::fluid, 1, rho_j, mu_j);
      P.velocity[i] = Vec<2>(0.3, -0.2);
      P.velocity[j] = Vec<2>(-0.1, 0.7);
      const double r2 = distance_squared<2>(P.position[i], P.position[j]);
      const double w = kernel_weight(std::sqrt(r2), re);
      const double mean = 2.0 * mu_i * mu_j / (mu_i + mu_j);
      const Vec<2> expected = mean * w * (P.velocity[j] - P.velocity[i]);
      const Vec<2> ij = viscous_pair_term<2>(i, static_cast<std::uint32_t>(j), r2, P, re, ViscousWall{WallSlip::no_slip, 0.5 * dp});
      const Vec<2> ji = viscous_pair_term<2>(j, static_cast<std::uint32_t>(i), r2, P, re, ViscousWall{WallSlip::no_slip, 0.5 * dp});
      for (int k = 0; k < 2; ++k) {
        EXPECT_DOUBLE_EQ(ij[k], expected[k]) << "r = " << r / dp << " dp, mu " << mu_i << " / " << mu_j;
        EXPECT_DOUBLE_EQ(ji[k], -expected[k]);
      }
      if (mu_i == mu_j) {
        EXPECT_DOUBLE_EQ(mean, mu_i);
      }
      // Through viscous_acceleration: the pair's accelerations, 2d / (lambda n0 rho) times the pair term.
      NeighborGrid<2> grid(Vec<2>(0.0, 0.0), Vec<2>(0.4, 0.4), re);
      grid.bin(P.position);
      NeighborList list;
      build_neighbor_list(grid, P.position, re, list);
      const Vec<2> ai = viscous_acceleration<2>(i, P, list, re, c.n0, c.lambda, ViscousWall{WallSlip::no_slip, 0.5 * dp});
      const Vec<2> aj = viscous_acceleration<2>(j, P, list, re, c.n0, c.lambda, ViscousWall{WallSlip::no_slip, 0.5 * dp});
      for (int k = 0; k < 2; ++k) {
        EXPECT_DOUBLE_EQ(ai[k], 4.0 / (c.lambda * c.n0 * rho_i) * expected[k]);
        EXPECT_NEAR(rho_i * ai[k] + rho_j * aj[k], 0.0, 1e-14 * rho_i * std::abs(ai[k]));  // momentum
      }
    }
  }
}
TEST(Viscosity, HarmonicMeanSquare) { two_viscosities(LatticeKind::square); }
TEST(Viscosity, HarmonicMeanHexagonal) { two_viscosities(LatticeKind::hexagonal); }

}  // namespace
}  // namespace slide
