// Periodic boundaries in x by ghost particles (fluid/periodic.hpp, coupling/simulation.cpp), against exact answers:
// a periodic lattice fills the plane in x (number density n0 and exact Laplacians next to both ends), a uniform flow
// in a periodic channel keeps going through several wraps, the ghosts are exactly the expected images and outputs
// leave them out, and 1 and 2 threads give bit-identical results.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "coupling/advance.hpp"
#include "coupling/rigid_bodies.hpp"
#include "coupling/simulation.hpp"
#include "fluid/laplacian.hpp"
#include "fluid/parallel.hpp"
#include "fluid/ghosts.hpp"
#include "fluid/walls.hpp"
#include "tools/run_outputs.hpp"

namespace slide {
namespace {

constexpr double dp = 0.01;
constexpr double rho = 1000.0;

// A channel periodic in x over [0, nx dp): nx x ny fluid particles on the square lattice at ((i + 1/2) dp,
// (j + 1/2) dp) moving at u, with or without a floor (face y = 0) and a ceiling (face y = ny dp). The walls' faces
// run from dp/2 to L - dp/2, so their particles sit at the same x as the fluid columns, each once in the period.
struct PeriodicChannel {
  Simulation<2> sim;
  double L = 0.0, H = 0.0;

  PeriodicChannel(int nx, int ny, const Vec<2>& u, bool walls, WallSlip slip = WallSlip::free_slip, double mu = 1e-3) {
    L = nx * dp;
    H = ny * dp;
    auto& o = sim.options;
    o.dp = dp;
    o.lattice = LatticeKind::square;  // the particles below are laid on it
    o.wall_slip = slip;
    o.gravity = Vec<2>::Zero();
    const double re = o.re_over_dp * dp;
    o.domain_lo = Vec<2>(0.0, -4 * re);
    o.domain_hi = Vec<2>(L, H + 4 * re);
    o.periodic_x = PeriodicX{0.0, L};
    auto& P = sim.particles();
    if (walls) {
      const int layers = boundary_layers(o.re_over_dp);
      auto add = [&](const std::vector<BoundaryPoint>& points) {
        for (const auto& b : points) {
          const std::size_t i = P.add(b.position, b.layer == 0 ? Kind::wall : Kind::dummy, 0, rho, mu);
          P.wall_normal[i] = b.normal;
          P.wall_depth[i] = b.depth;
        }
      };
      add(polyline_boundary({Vec<2>(0.5 * dp, 0.0), Vec<2>(L - 0.5 * dp, 0.0)}, true, dp, layers));
      add(polyline_boundary({Vec<2>(L - 0.5 * dp, H), Vec<2>(0.5 * dp, H)}, true, dp, layers));
    }
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::size_t k = P.add(Vec<2>((i + 0.5) * dp, (j + 0.5) * dp), Kind::fluid, 0, rho, mu);
        P.velocity[k] = u;
      }
  }
};

// Rows whose kernel support lies inside the strip (no free surface or wall within re).
bool interior_row(double y, double H, double re) { return y - re > 0.0 && y + re < H; }

TEST(Periodic, WrapBringsXIntoThePeriod) {
  const PeriodicX p{-0.5, 1.5};
  EXPECT_EQ(p.wrap(0.25), 0.25);
  EXPECT_EQ(p.wrap(-0.5), -0.5);
  EXPECT_DOUBLE_EQ(p.wrap(1.5), -0.5);
  EXPECT_DOUBLE_EQ(p.wrap(1.75), -0.25);
  EXPECT_DOUBLE_EQ(p.wrap(-0.75), 1.25);
  EXPECT_DOUBLE_EQ(p.wrap(7.0), 1.0);
  EXPECT_DOUBLE_EQ(p.wrap(-6.0), 0.0);
  const double just_below = std::nextafter(-0.5, -1.0);  // x + L rounds onto x_max
  EXPECT_GE(p.wrap(just_below), -0.5);
  EXPECT_LT(p.wrap(just_below), 1.5);
  EXPECT_TRUE(std::isnan(p.wrap(std::nan(""))));
}

// A periodic strip of fluid fills the plane in x: every particle of the interior rows, the first and last columns
// included, has the lattice's number density, and the MPS Laplacian of u = (U + G y, c y^2) is (0, 2 c) exactly
// there (the lattice sums that define n0 and lambda make it exact for quadratic fields).
TEST(Periodic, LatticeFillsThePlaneInX) {
  PeriodicChannel ch(16, 12, Vec<2>::Zero(), false);
  auto& sim = ch.sim;
  sim.initialise();
  const auto& P = sim.particles();
  const double re = sim.re();
  const LatticeConstants lc = lattice_constants<2>(dp, re);
  ASSERT_GT(P.ghost_count(), 0u);
  int checked = 0, at_ends = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    if (!interior_row(P.position[i][1], ch.H, re)) continue;
    EXPECT_NEAR(P.number_density[i], lc.n0, 1e-12) << "particle at x = " << P.position[i][0];
    ++checked;
    if (P.position[i][0] < dp || P.position[i][0] > ch.L - dp) ++at_ends;
  }
  EXPECT_EQ(checked, 16 * 8);
  EXPECT_EQ(at_ends, 2 * 8);
  for (std::size_t g = 0; g < P.ghost_count(); ++g)
    EXPECT_EQ(P.number_density[P.real_count() + g], P.number_density[P.ghost_source[g]]);

  // Laplacian of a field linear in y (x component) and quadratic in y (y component), set on the real particles and
  // copied into the ghosts.
  const double U = 0.7, G = 3.0, c = 5.0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    const double y = P.position[i][1];
    sim.particles().velocity[i] = Vec<2>(U + G * y, c * y * y);
  }
  sync_ghosts(sim.particles());
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    if (!interior_row(P.position[i][1], ch.H, re)) continue;
    const Vec<2> lap = mps_laplacian<2>(i, P.position, P.velocity, sim.neighbors(), re, lc.n0, lc.lambda);
    EXPECT_NEAR(lap[0], 0.0, 1e-9) << "particle at x = " << P.position[i][0];
    EXPECT_NEAR(lap[1], 2.0 * c, 1e-9) << "particle at x = " << P.position[i][0];
  }
}

// A uniform flow in a periodic strip (free surfaces above and below, no gravity) is unchanged by steps: no pressure
// (n <= n0, negative pressure clamped), no viscous force, no collision.
TEST(Periodic, UniformFlowInStripIsUnchangedBySteps) {
  const double U = 1.5;
  PeriodicChannel ch(16, 12, Vec<2>(U, 0.0), false);
  auto& sim = ch.sim;
  sim.initialise();
  const auto& P = sim.particles();
  std::vector<Vec<2>> start(P.real_count());
  for (std::size_t i = 0; i < P.real_count(); ++i) start[P.id[i]] = P.position[i];
  for (int s = 0; s < 20; ++s) {
    const auto [dt, limit] = sim.allowed_time_step();
    ASSERT_FALSE(sim.step(dt, limit));
  }
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    EXPECT_NEAR(P.velocity[i][0], U, 1e-12 * U);
    EXPECT_NEAR(P.velocity[i][1], 0.0, 1e-12 * U);
    const Vec<2> expected(sim.options.periodic_x->wrap(start[P.id[i]][0] + U * sim.time()), start[P.id[i]][1]);
    // Not yet wrapped (no rebuild since crossing x_max) counts as the same place.
    double dx = P.position[i][0] - expected[0];
    dx -= ch.L * std::round(dx / ch.L);
    EXPECT_NEAR(dx, 0.0, 1e-12);
    EXPECT_NEAR(P.position[i][1], expected[1], 1e-12);
  }
}

// A uniform flow u = (U, 0) between a free-slip floor and ceiling, periodic in x, keeps going through several
// wraps: every particle keeps speed U, the count of real particles is unchanged, positions are back in the period
// after every rebuild, and every particle is where x0 + U t, wrapped, puts it.
TEST(Periodic, UniformChannelFlowKeepsGoingThroughWraps) {
  const double U = 2.0;
  const int nx = 16, ny = 8;
  PeriodicChannel ch(nx, ny, Vec<2>(U, 0.0), true);
  auto& sim = ch.sim;
  sim.initialise();
  const auto& P = sim.particles();
  const std::size_t real = P.real_count();
  const double half_skin = 0.5 * sim.options.skin_over_dp * dp;
  std::vector<Vec<2>> start(real);
  for (std::size_t i = 0; i < real; ++i) start[P.id[i]] = P.position[i];
  long rebuilds = sim.neighbor_rebuilds(), rebuild_steps = 0;
  double worst_speed_error = 0.0, worst_beyond = 0.0;
  bool all_in_period_after_rebuild = true, count_kept = true;
  AfterEveryStep<2, std::function<void(const Simulation<2>&)>> observer([&](const Simulation<2>& s) {
    const auto& Q = s.particles();
    count_kept = count_kept && Q.real_count() == real;
    const bool rebuilt = s.neighbor_rebuilds() != rebuilds;
    rebuilds = s.neighbor_rebuilds();
    rebuild_steps += rebuilt;
    // The step after a rebuild moved the particles by U dt at most (dt <= dt_max).
    const double slack = U * s.options.dt_max * (1.0 + 1e-9);
    for (std::size_t i = 0; i < Q.real_count(); ++i) {
      const double x = Q.position[i][0];
      if (rebuilt && (x < 0.0 || x >= ch.L + slack)) all_in_period_after_rebuild = false;
      worst_beyond = std::max(worst_beyond, x - ch.L);
      if (Q.kind[i] == Kind::fluid)
        worst_speed_error = std::max(worst_speed_error, (Q.velocity[i] - Vec<2>(U, 0.0)).norm());
    }
  });
  const double end_time = 3.5 * ch.L / U;  // three and a half wraps
  const AdvanceResult result = advance<2>(sim, end_time, {&observer});
  ASSERT_EQ(result.outcome, AdvanceResult::Outcome::reached_end)
      << (result.instability ? result.instability->reason : std::string());
  EXPECT_GT(sim.step_count(), 1000);
  EXPECT_GT(rebuild_steps, 100);
  EXPECT_TRUE(count_kept);
  EXPECT_TRUE(all_in_period_after_rebuild);
  EXPECT_LT(worst_beyond, half_skin + U * sim.options.dt_max);
  EXPECT_LT(worst_speed_error, 1e-12 * U);
  std::printf("periodic channel: %ld steps, %ld rebuilds, largest speed error %.3g m/s\n", sim.step_count(),
              rebuild_steps, worst_speed_error);
  std::size_t fluid = 0;
  for (std::size_t i = 0; i < real; ++i) {
    if (P.kind[i] != Kind::fluid) {
      EXPECT_EQ(P.position[i], start[P.id[i]]);  // walls stay put
      continue;
    }
    ++fluid;
    double dx = P.position[i][0] - (start[P.id[i]][0] + U * sim.time());
    dx -= ch.L * std::round(dx / ch.L);
    EXPECT_NEAR(dx, 0.0, 1e-9);
    EXPECT_NEAR(P.position[i][1], start[P.id[i]][1], 1e-12);
  }
  EXPECT_EQ(fluid, std::size_t(nx * ny));
}

// The ghosts of a given configuration are exactly the images of the particles within the margin of each end, in the
// order of their sources, each equal to its source but for its x and id; removing them restores the arrays; an
// id-ordered snapshot copy leaves them out.
TEST(Periodic, GhostsAreTheExpectedImages) {
  Particles<2> P;
  const PeriodicX period{-0.1, 0.3};
  const double margin = 0.05;
  unsigned state = 12345;
  auto next = [&] {
    state = state * 1103515245u + 12345u;
    return ((state >> 8) & 0xffff) / 65536.0;
  };
  for (int k = 0; k < 300; ++k) {
    const Vec<2> x(period.x_min + period.length() * next(), 0.2 * next());
    const std::size_t i = P.add(x, k % 5 == 0 ? Kind::wall : Kind::fluid, std::uint8_t(k % 3), 1000.0 + k, 1e-3 * k);
    P.velocity[i] = Vec<2>(next(), next());
    P.acceleration[i] = Vec<2>(next(), next());
    P.pressure[i] = 100.0 * next();
    P.number_density[i] = next();
    P.wall_normal[i] = Vec<2>(0.0, k % 5 == 0 ? 1.0 : 0.0);
    P.wall_depth[i] = next();
    P.wall_fill[i] = next();
  }
  // Particles exactly at the ends and the margins.
  for (double x : {period.x_min, period.x_min + margin, period.x_max - margin, std::nextafter(period.x_max, 0.0)})
    P.add(Vec<2>(x, 0.1), Kind::fluid, 0, 1000.0, 1e-3);
  const std::size_t real = P.size();
  std::vector<std::uint32_t> expected_source;
  std::vector<double> expected_shift;
  for (std::size_t i = 0; i < real; ++i) {
    const double x = P.position[i][0];
    if (x - period.x_min < margin) expected_source.push_back(std::uint32_t(i)), expected_shift.push_back(period.length());
    if (period.x_max - x < margin) expected_source.push_back(std::uint32_t(i)), expected_shift.push_back(-period.length());
  }
  const Particles<2> before = P;
  add_ghosts(P, period, margin);
  EXPECT_EQ(P.ghost_source, expected_source);
  ASSERT_EQ(P.ghost_offset.size(), expected_shift.size());
  for (std::size_t g = 0; g < P.ghost_count(); ++g) {
    EXPECT_EQ(P.ghost_offset[g], Vec<2>(expected_shift[g], 0.0));
    EXPECT_EQ(P.ghost_flip[g], 0u);
  }
  ASSERT_EQ(P.real_count(), real);
  ASSERT_EQ(P.size(), real + expected_source.size());
  EXPECT_GT(P.ghost_count(), 40u);
  for (std::size_t g = 0; g < P.ghost_count(); ++g) {
    const std::size_t t = real + g, s = P.ghost_source[g];
    EXPECT_EQ(P.position[t][0], P.position[s][0] + expected_shift[g]);
    EXPECT_EQ(P.position[t][1], P.position[s][1]);
    EXPECT_EQ(P.velocity[t], P.velocity[s]);
    EXPECT_EQ(P.acceleration[t], P.acceleration[s]);
    EXPECT_EQ(P.pressure[t], P.pressure[s]);
    EXPECT_EQ(P.number_density[t], P.number_density[s]);
    EXPECT_EQ(P.density[t], P.density[s]);
    EXPECT_EQ(P.viscosity[t], P.viscosity[s]);
    EXPECT_EQ(P.phase[t], P.phase[s]);
    EXPECT_EQ(P.kind[t], P.kind[s]);
    EXPECT_EQ(P.wall_normal[t], P.wall_normal[s]);
    EXPECT_EQ(P.wall_depth[t], P.wall_depth[s]);
    EXPECT_EQ(P.wall_fill[t], P.wall_fill[s]);
    EXPECT_EQ(P.id[t], P.id[s]);  // its source's: the order key tells them apart
    EXPECT_NE(P.order_key(t), P.order_key(s));
    EXPECT_EQ(P.real_index(t), s);
  }
  EXPECT_THROW(P.add(Vec<2>::Zero(), Kind::fluid, 0, 1000.0, 1e-3), std::logic_error);
  EXPECT_THROW(add_ghosts(P, period, margin), std::logic_error);

  // A snapshot's id-ordered copy holds the real particles only.
  const tools::IdOrdered<2> snapshot(P);
  ASSERT_EQ(snapshot.id.size(), real);
  ASSERT_EQ(snapshot.position.size(), 2 * real);
  for (std::size_t k = 0; k < real; ++k) {
    EXPECT_EQ(snapshot.id[k], k);
    EXPECT_EQ(snapshot.position[2 * k], before.position[k][0]);
    EXPECT_EQ(snapshot.pressure[k], before.pressure[k]);
  }

  // Sync after the sources changed; removal restores the real arrays exactly.
  for (std::size_t i = 0; i < real; ++i) P.position[i][1] += 1.0, P.pressure[i] *= 2.0;
  sync_ghosts(P);
  for (std::size_t g = 0; g < P.ghost_count(); ++g) {
    EXPECT_EQ(P.position[real + g][1], P.position[P.ghost_source[g]][1]);
    EXPECT_EQ(P.pressure[real + g], P.pressure[P.ghost_source[g]]);
  }
  for (std::size_t i = 0; i < real; ++i) P.position[i] = before.position[i], P.pressure[i] = before.pressure[i];
  remove_ghosts(P);
  EXPECT_EQ(P.size(), real);
  EXPECT_EQ(P.ghost_count(), 0u);
  for (std::size_t i = 0; i < real; ++i) {
    EXPECT_EQ(P.position[i], before.position[i]);
    EXPECT_EQ(P.pressure[i], before.pressure[i]);
    EXPECT_EQ(P.id[i], before.id[i]);
  }
  EXPECT_THROW(add_ghosts(P, PeriodicX{0.0, 0.09}, margin), std::invalid_argument);  // shorter than 2 margins
}

// In a simulation the ghosts after a rebuild are the images of the real particles within re + skin of the ends.
TEST(Periodic, SimulationGhostsAreTheRealParticlesNearTheEnds) {
  PeriodicChannel ch(20, 6, Vec<2>(0.3, 0.0), true);
  auto& sim = ch.sim;
  sim.initialise();
  const auto& P = sim.particles();
  const double margin = sim.re() + sim.options.skin_over_dp * dp;
  std::size_t expected = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    expected += P.position[i][0] < margin;
    expected += ch.L - P.position[i][0] < margin;
  }
  // Columns at (i + 1/2) dp within 2.4 dp of each end: 2 columns of 6 fluid rows and 2 x 3 wall layers, each end.
  EXPECT_EQ(expected, std::size_t(2 * 2 * (6 + 6)));
  EXPECT_EQ(P.ghost_count(), expected);
  EXPECT_EQ(P.real_count(), std::size_t(20 * 6 + 2 * 3 * 20));
  for (std::size_t g = 0; g < P.ghost_count(); ++g) {
    const std::size_t s = P.ghost_source[g];
    EXPECT_EQ(P.position[P.real_count() + g][0], P.position[s][0] + P.ghost_offset[g][0]);
  }
  EXPECT_EQ(tools::IdOrdered<2>(P).id.size(), P.real_count());
}

// What periodic boundaries refuse: rigid bodies (their force would count ghost images twice), a period shorter than
// twice re + skin, and wall particles outside the period.
TEST(Periodic, RefusesBodiesShortPeriodsAndWallsOutsideThePeriod) {
  {
    PeriodicChannel ch(16, 4, Vec<2>::Zero(), true);
    ch.sim.attach_bodies(std::make_shared<RigidBodies<2>>(Vec<2>::Zero(), 0.001));
    EXPECT_THROW(ch.sim.initialise(), std::invalid_argument);
  }
  {
    PeriodicChannel ch(4, 4, Vec<2>::Zero(), false);
    EXPECT_THROW(ch.sim.initialise(), std::invalid_argument);
  }
  {
    PeriodicChannel ch(16, 4, Vec<2>::Zero(), false);
    const std::size_t i = ch.sim.particles().add(Vec<2>(ch.L, -0.5 * dp), Kind::wall, 0, rho, 1e-3);
    ch.sim.particles().wall_normal[i] = Vec<2>(0.0, 1.0);
    ch.sim.particles().wall_depth[i] = 0.5 * dp;
    EXPECT_THROW(ch.sim.initialise(), std::invalid_argument);
  }
}

// A pressure-driven-like periodic channel flow (no-slip walls, body force along x, a vertical velocity wave that
// compresses the water) with more than 4096 particles, so that the loops run in parallel: 1 and 2 threads give
// bit-identical states after steps that include rebuilds and wraps.
TEST(Periodic, OneAndTwoThreadsGiveIdenticalStates) {
  auto run = [](int threads) {
    set_thread_count(threads);
    PeriodicChannel ch(64, 64, Vec<2>::Zero(), true, WallSlip::no_slip, 0.01);
    auto& sim = ch.sim;
    sim.options.gravity = Vec<2>(2.0, 0.0);
    auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::fluid)
        P.velocity[i] = Vec<2>(1.0, 0.05 * std::sin(2.0 * M_PI * P.position[i][0] / ch.L));
    sim.initialise();
    EXPECT_GT(P.real_count(), std::size_t(parallel_threshold));
    for (int s = 0; s < 120; ++s) {
      const auto [dt, limit] = sim.allowed_time_step();
      EXPECT_FALSE(sim.step(dt, limit));
    }
    EXPECT_GT(sim.neighbor_rebuilds(), 10);
    return std::move(sim.particles());
  };
  const int saved = thread_count();
  const Particles<2> one = run(1), two = run(2);
  set_thread_count(saved);
  ASSERT_EQ(one.size(), two.size());
  ASSERT_EQ(one.ghost_source, two.ghost_source);
  EXPECT_EQ(0, std::memcmp(one.position.data(), two.position.data(), one.size() * sizeof(Vec<2>)));
  EXPECT_EQ(0, std::memcmp(one.velocity.data(), two.velocity.data(), one.size() * sizeof(Vec<2>)));
  EXPECT_EQ(0, std::memcmp(one.pressure.data(), two.pressure.data(), one.size() * sizeof(double)));
  EXPECT_EQ(one.id, two.id);
  // The flow did something: it crossed the ends and the pressure is not uniform.
  double p_min = 1e300, p_max = -1e300;
  for (std::size_t i = 0; i < one.real_count(); ++i)
    if (one.kind[i] == Kind::fluid) p_min = std::min(p_min, one.pressure[i]), p_max = std::max(p_max, one.pressure[i]);
  EXPECT_GT(p_max - p_min, 1.0);
}

// The semi-implicit viscous stage with enough unknowns (4608 stiff particles, mu = 50 Pa s, beside water that is
// advanced explicitly, fluid/implicit_viscosity.hpp) for its row loops to run in parallel: 1 and 2 threads give
// bit-identical states.
TEST(Periodic, ImplicitViscosityOneAndTwoThreadsGiveIdenticalStates) {
  auto run = [](int threads) {
    set_thread_count(threads);
    PeriodicChannel ch(96, 64, Vec<2>::Zero(), true, WallSlip::no_slip, 1e-3);
    auto& sim = ch.sim;
    sim.options.gravity = Vec<2>(2.0, 0.0);
    sim.options.viscous_scheme = ViscousScheme::implicit;
    auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::fluid) {
        P.velocity[i] = Vec<2>(0.0, 0.05 * std::sin(2.0 * M_PI * P.position[i][0] / ch.L));
        if (P.position[i][0] < 0.75 * ch.L) P.viscosity[i] = 50.0;
      }
    sim.initialise();
    for (int s = 0; s < 40; ++s) {
      const auto [dt, limit] = sim.allowed_time_step();
      EXPECT_FALSE(sim.step(dt, limit));
    }
    EXPECT_GT(sim.last_viscous_solve().iterations, 0);
    return std::move(sim.particles());
  };
  const int saved = thread_count();
  const Particles<2> one = run(1), two = run(2);
  set_thread_count(saved);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(0, std::memcmp(one.position.data(), two.position.data(), one.size() * sizeof(Vec<2>)));
  EXPECT_EQ(0, std::memcmp(one.velocity.data(), two.velocity.data(), one.size() * sizeof(Vec<2>)));
  EXPECT_EQ(0, std::memcmp(one.pressure.data(), two.pressure.data(), one.size() * sizeof(double)));
}

// Body-force-driven plane Poiseuille flow between no-slip walls (the square lattice's method: mirror wall pressure,
// symmetric gradient, zero free-surface pressure), periodic in
// x, from rest over six decay times: every row is uniform in x to round-off (the particles next to the ends see the
// same neighbourhood as the middle ones), the profile is symmetric about the centreline, and it follows
// u = g y (H - y) / (2 nu) within 0.9 % of the centreline speed. Measured 0.81 %: the discrete steady state's own
// error is 0.25 % (tests/test_viscosity.cpp, the same wall model), the rest is what is left of the start from rest
// after six decay times (the slowest mode's e^-6 ~ 0.25 %); with Morris et al.'s cap of the mirror factor at 1.5,
// replaced since, it was 4.1 %.
TEST(Periodic, PoiseuilleFlowIsUniformInX) {
  const int nx = 8, ny = 20;
  const double mu = 10.0, g = 0.2;
  PeriodicChannel ch(nx, ny, Vec<2>::Zero(), true, WallSlip::no_slip, mu);
  auto& sim = ch.sim;
  sim.options.gravity = Vec<2>(g, 0.0);
  sim.options.sound_speed = 1.0;
  sim.options.wall_pressure = WallPressure::mirror;
  sim.options.gradient = GradientModel::symmetric;
  sim.options.surface_pressure = SurfacePressure::zero;
  sim.initialise();
  const double nu = mu / rho, H = ch.H, u_max = g * H * H / (8 * nu);
  const AdvanceResult result = advance<2>(sim, 6.0 * H * H / (M_PI * M_PI * nu));
  ASSERT_EQ(result.outcome, AdvanceResult::Outcome::reached_end);
  const auto& P = sim.particles();
  std::vector<double> row_min(ny, 1e300), row_max(ny, -1e300);
  double worst_profile = 0.0, worst_v = 0.0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    const double y = P.position[i][1], u = P.velocity[i][0];
    const int j = static_cast<int>(std::floor(y / dp));
    ASSERT_TRUE(j >= 0 && j < ny);
    row_min[j] = std::min(row_min[j], u);
    row_max[j] = std::max(row_max[j], u);
    worst_profile = std::max(worst_profile, std::abs(u - g / (2 * nu) * y * (H - y)) / u_max);
    worst_v = std::max(worst_v, std::abs(P.velocity[i][1]));
  }
  double spread = 0.0, asymmetry = 0.0;
  for (int j = 0; j < ny; ++j) {
    spread = std::max(spread, row_max[j] - row_min[j]);
    asymmetry = std::max(asymmetry, std::abs(row_max[j] - row_max[ny - 1 - j]));
  }
  std::printf("periodic Poiseuille, %d across: profile error %.2f %% of u_max, spread in x %.2g, asymmetry %.2g m/s\n",
              ny, 100 * worst_profile, spread, asymmetry);
  EXPECT_LT(spread, 1e-12 * u_max);
  EXPECT_LT(asymmetry, 1e-9 * u_max);
  EXPECT_LT(worst_v, 1e-12 * u_max);
  EXPECT_LT(worst_profile, 0.0081 * 1.1 + 1e-4);
}

}  // namespace
}  // namespace slide
