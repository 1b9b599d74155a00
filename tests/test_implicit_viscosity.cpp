// The semi-implicit viscous stage (fluid/implicit_viscosity.hpp) against the explicit operator it implicitises
// (fluid/viscosity.hpp): its solution u* satisfies u* - dt a_visc(u*) = u + dt a to the solver's tolerance, for a
// disordered patch with two viscosities (harmonic mean), a no-slip floor and a moving no-slip wall; fluid-fluid
// terms conserve momentum; a huge viscosity at a huge dt stays bounded (the explicit step would blow up); only the
// stiff particles are unknowns, and the step's result then still matches the full solve.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fluid/implicit_viscosity.hpp"
#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/viscosity.hpp"
#include "fluid/walls.hpp"

namespace slide {
namespace {

// Fluid on a square lattice above a floor face y = 0 (at rest) and beside a left wall face x = 0 moving upwards,
// positions jittered by up to 0.1 dp, two phases: water (1000 kg/m^3, 1e-3 Pa s) and a viscous sediment (1950,
// 20 Pa s) in the right half; velocities random.
struct Patch {
  double dp = 0.01, re = 0.021;
  Domain<2> domain;
  Particles<2>& P = domain.particles;
  NeighborList list;
  LatticeConstants c = lattice_constants<2>(dp, re);
  std::vector<Vec<2>> accel;

  explicit Patch(bool walls) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1), speed(-0.5, 0.5);
    if (walls) {
      for (const auto& b : polyline_boundary({Vec<2>(-0.1, 0.0), Vec<2>(0.3, 0.0)}, true, dp, 3)) {
        const std::size_t i = P.add(b.position, b.layer == 0 ? Kind::wall : Kind::dummy, 0, 1000.0, 0.0);
        P.wall_normal[i] = b.normal;
        P.wall_depth[i] = b.depth;
      }
      for (const auto& b : polyline_boundary({Vec<2>(0.0, 0.2), Vec<2>(0.0, 0.0)}, true, dp, 3)) {
        const std::size_t i = P.add(b.position, b.layer == 0 ? Kind::wall : Kind::dummy, 0, 1000.0, 0.0);
        P.wall_normal[i] = b.normal;
        P.wall_depth[i] = b.depth;
        P.velocity[i] = Vec<2>(0.0, 0.3);
      }
    }
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 24; ++i) {
        const Vec<2> x((i + 0.5 + jitter(rng)) * dp, (j + 0.5 + jitter(rng)) * dp);
        const bool sediment = i >= 12;
        const std::size_t k = P.add(x, Kind::fluid, sediment ? 1 : 0, sediment ? 1950.0 : 1000.0, sediment ? 20.0 : 1e-3);
        P.velocity[k] = Vec<2>(speed(rng), speed(rng));
      }
    NeighborGrid<2> grid(Vec<2>(-0.2, -0.2), Vec<2>(0.4, 0.4), re);
    grid.bin(P.position);
    build_neighbor_list(grid, P.position, re, list);
    accel.assign(P.size(), Vec<2>(0.0, -9.81));
  }
};

TEST(ImplicitViscosity, SolutionSatisfiesTheExplicitOperatorAtTheNewVelocities) {
  for (WallSlip slip : {WallSlip::no_slip, WallSlip::free_slip}) {
    Patch patch(true);
    auto& P = patch.P;
    const std::vector<Vec<2>> u0 = P.velocity;
    const double dt = 1e-3;  // 50x the explicit limit of the sediment (0.1 dp^2 / nu = 1e-4 * 1950 / 20 s)
    ImplicitViscosity solver;
    solver.tolerance = 1e-12;
    std::vector<Vec<2>> a_visc;
    const ViscousSolveReport report = solver.solve<2>(patch.domain, patch.list, patch.re, patch.c.n0, patch.c.lambda, ViscousWall{slip, 0.5 * patch.dp}, dt,
                                                      patch.accel, a_visc);
    EXPECT_TRUE(report.converged);
    EXPECT_GT(report.iterations, 0);
    double worst = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.kind[i] != Kind::fluid) {
        EXPECT_EQ(P.velocity[i], u0[i]);  // boundaries keep their velocities
        continue;
      }
      const Vec<2> a = viscous_acceleration<2>(i, P, patch.list, patch.re, patch.c.n0, patch.c.lambda, ViscousWall{slip, 0.5 * patch.dp});
      EXPECT_EQ(a_visc[i], a);  // the solve's viscous acceleration at u~ is the explicit operator's
      const Vec<2> r = P.velocity[i] - dt * a - (u0[i] + dt * patch.accel[i]);
      worst = std::max(worst, r.norm());
      scale = std::max(scale, (u0[i] + dt * patch.accel[i]).norm());
    }
    // The residual of the rho-weighted system is below 1e-12 of its right-hand side; per particle that is ~1e-11.
    EXPECT_LT(worst / scale, 1e-9) << to_string(slip);
  }
}

// Without walls and body forces, the fluid-fluid terms are antisymmetric: sum m_i u*_i = sum m_i u_i.
TEST(ImplicitViscosity, ConservesMomentumBetweenFluidParticles) {
  Patch patch(false);
  auto& P = patch.P;
  std::fill(patch.accel.begin(), patch.accel.end(), Vec<2>::Zero());
  Vec<2> before = Vec<2>::Zero(), after = Vec<2>::Zero();
  for (std::size_t i = 0; i < P.size(); ++i) before += P.density[i] * P.velocity[i];
  ImplicitViscosity solver;
  solver.tolerance = 1e-13;
  std::vector<Vec<2>> a_visc;
  solver.solve<2>(patch.domain, patch.list, patch.re, patch.c.n0, patch.c.lambda, ViscousWall{WallSlip::no_slip, 0.5 * patch.dp}, 1e-2, patch.accel,
                  a_visc);
  double scale = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    after += P.density[i] * P.velocity[i];
    scale += P.density[i] * P.velocity[i].norm();
  }
  EXPECT_LT((after - before).norm() / scale, 1e-10);
}

// The implicit step is a weighted average (its matrix is an M-matrix): no fluid speed component grows beyond the
// largest one it started with, even for a viscosity and step at which the explicit term multiplies speeds by ~1e6.
TEST(ImplicitViscosity, StaysBoundedWhereTheExplicitStepWouldExplode) {
  Patch patch(false);
  auto& P = patch.P;
  std::fill(patch.accel.begin(), patch.accel.end(), Vec<2>::Zero());
  for (std::size_t i = 0; i < P.size(); ++i) P.viscosity[i] = 1e4;
  double start = 0.0;
  for (const auto& u : P.velocity) start = std::max(start, u.cwiseAbs().maxCoeff());
  ImplicitViscosity solver;
  std::vector<Vec<2>> a_visc;
  const auto report = solver.solve<2>(patch.domain, patch.list, patch.re, patch.c.n0, patch.c.lambda,
                                      ViscousWall{WallSlip::no_slip, 0.5 * patch.dp}, 0.1, patch.accel, a_visc);
  EXPECT_TRUE(report.converged);
  double end = 0.0, mean_x = 0.0;
  for (const auto& u : P.velocity) end = std::max(end, u.cwiseAbs().maxCoeff());
  for (std::size_t i = 0; i < P.size(); ++i) mean_x += P.velocity[i][0] / P.size();
  EXPECT_LE(end, start * (1.0 + 1e-9));
  // So viscous a material moves almost as one: every particle within 1 % of start of the (mass-weighted) mean.
  for (const auto& u : P.velocity) EXPECT_NEAR(u[0], mean_x, 0.01 * start);
}

// viscous_row's number against hand-computed sums: a fluid pair with two viscosities (harmonic mean) and a no-slip
// wall particle at depth d_j (mirror factor 1 + d_j / d_i); free slip drops the wall; beyond re nothing counts.
TEST(ImplicitViscosity, RowNumberIsTheRowsCouplingOverItsDensity) {
  const double re = 0.021, n0 = 3.0, lambda = 2e-4, dt = 1e-3;
  Particles<2> P;
  const std::size_t i = P.add(Vec<2>(0.0, 0.02), Kind::fluid, 0, 1000.0, 2e-3);
  P.add(Vec<2>(0.012, 0.02), Kind::fluid, 1, 1950.0, 6e-3);  // fluid at 0.012 m
  P.add(Vec<2>(0.0, 0.045), Kind::fluid, 0, 1000.0, 1.0);    // beyond re
  const std::size_t w = P.add(Vec<2>(0.005, 0.005), Kind::dummy, 0, 1000.0, 0.0);
  P.wall_normal[w] = Vec<2>(0.0, 1.0);
  P.wall_depth[w] = 0.005;  // face at y = 0.01; particle i at d_i = 0.01 from it
  NeighborGrid<2> grid(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), re);
  grid.bin(P.position);
  NeighborList list;
  build_neighbor_list(grid, P.position, re, list);
  const double c = 4.0 / (lambda * n0);
  const double mu_ij = 2.0 * 2e-3 * 6e-3 / (2e-3 + 6e-3);
  const double fluid = mu_ij * kernel_weight(0.012, re);
  const double wall = 2e-3 * (1.0 + 0.005 / 0.01) * kernel_weight(std::hypot(0.005, 0.015), re);
  EXPECT_NEAR(viscous_row<2>(i, P, list, re, n0, lambda, ViscousWall{WallSlip::no_slip, 0.005}, dt).number,
              dt * c * (fluid + wall) / 1000.0, 1e-14);
  EXPECT_NEAR(viscous_row<2>(i, P, list, re, n0, lambda, ViscousWall{WallSlip::free_slip, 0.005}, dt).number,
              dt * c * fluid / 1000.0, 1e-14);
}

// Only the stiff particles are unknowns (viscous row number above sqrt(tolerance)): in the patch at dt = 1e-4 the
// water's is ~1e-5, the sediment's ~0.1, so at tolerance 1e-8 the sediment alone is solved for. The step's result,
// u* = u + dt (a + a_visc(u~)) (coupling/simulation.cpp), then matches the fully implicit solution (every fluid
// particle an unknown, tolerance 1e-14) to O(tolerance), although u~ itself is off by O(s) on the explicit rows.
TEST(ImplicitViscosity, OnlyStiffParticlesAreUnknownsAndTheStepMatchesTheFullSolve) {
  const double dt = 1e-4;
  const ViscousWall wall{WallSlip::no_slip, 0.005};
  Patch full(true), split(true);
  const std::vector<Vec<2>> u0 = full.P.velocity;
  ImplicitViscosity exact;
  exact.tolerance = 1e-14;
  exact.max_iterations = 2000;
  std::vector<Vec<2>> a_full, a_split;
  ASSERT_TRUE(exact.solve<2>(full.domain, full.list, full.re, full.c.n0, full.c.lambda, wall, dt, full.accel, a_full).converged);
  std::size_t fluid = 0, sediment = 0;
  for (std::size_t i = 0; i < full.P.size(); ++i) {
    if (full.P.kind[i] != Kind::fluid) continue;
    ++fluid;
    sediment += full.P.phase[i] == 1;
    const double s = viscous_row<2>(i, split.P, split.list, split.re, split.c.n0, split.c.lambda, wall, dt).number;
    EXPECT_TRUE(full.P.phase[i] == 1 ? s > 1e-2 : s < 1e-4) << s;
  }
  EXPECT_EQ(exact.unknowns(), fluid);
  ImplicitViscosity solver;  // tolerance 1e-8: stiff above 1e-4
  ASSERT_TRUE(solver.solve<2>(split.domain, split.list, split.re, split.c.n0, split.c.lambda, wall, dt, split.accel, a_split).converged);
  EXPECT_EQ(solver.unknowns(), sediment);
  double worst_u = 0.0, worst_step = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < split.P.size(); ++i) {
    if (split.P.kind[i] != Kind::fluid) continue;
    const Vec<2> a = viscous_acceleration<2>(i, split.P, split.list, split.re, split.c.n0, split.c.lambda, wall);
    EXPECT_EQ(a_split[i], a);  // recomputed after the solve near the sediment, kept from the first walk elsewhere
    const Vec<2> step = u0[i] + dt * (split.accel[i] + a);
    worst_u = std::max(worst_u, (split.P.velocity[i] - full.P.velocity[i]).norm());
    worst_step = std::max(worst_step, (step - full.P.velocity[i]).norm());
    scale = std::max(scale, full.P.velocity[i].norm());
  }
  EXPECT_GT(worst_u / scale, 1e-6);     // u~ on the explicit rows: first order in s (5.6e-6 measured)
  EXPECT_LT(worst_step / scale, 1e-9);  // the step's result: within the tolerance (3.6e-11 measured)
}

}  // namespace
}  // namespace slide
