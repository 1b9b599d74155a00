// Rheology models against their exact formulas and limits, and the MPS shear rate against exact velocity fields on
// regular lattices and next to a no-slip floor.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <set>
#include <string_view>
#include <vector>

#include "fluid/lattice.hpp"
#include "fluid/phase.hpp"
#include "fluid/strain_rate.hpp"
#include "fluid/walls.hpp"
#include "tests/lattice_block.hpp"

namespace slide {
namespace {

// ---------------------------------------------------------------------------------------------------------------
// Rheology

TEST(Rheology, HerschelBulkleyWithoutYieldStressIsNewtonianExactly) {
  const double K = 0.37;
  const Newtonian newtonian{K};
  for (const Regularisation reg : {Regularisation{Papanastasiou{100.0}}, Regularisation{BiViscosity{1e4}}}) {
    const HerschelBulkley hb{0.0, K, 1.0, reg, 1e3};
    for (double g : {0.0, 1e-9, 1e-3, 0.7, 1.0, 42.0, 1e6}) {
      EXPECT_EQ(hb.effective_viscosity(g, 123.0), K) << g;
      EXPECT_EQ(hb.effective_viscosity(g, 123.0), newtonian.effective_viscosity(g, 123.0));
      EXPECT_EQ(effective_viscosity(Rheology{hb}, g, -5.0), K);
    }
  }
}

TEST(Rheology, PapanastasiouTendsToExactHerschelBulkley) {
  const double tau_y = 50.0, K = 2.0, n = 0.8, g = 0.5;
  const double exact = tau_y / g + K * std::pow(g, n - 1.0);
  double previous = INFINITY;
  for (double m = 1.0; m <= 64.0; m *= 2.0) {
    const HerschelBulkley hb{tau_y, K, n, Papanastasiou{m}, 1e9};
    const double error = std::abs(hb.effective_viscosity(g, 0.0) - exact);
    // The regularisation's own error is tau_y exp(-m g) / g.
    EXPECT_NEAR(error, tau_y * std::exp(-m * g) / g, 1e-12 * exact) << m;
    EXPECT_LT(error, previous) << m;
    previous = error;
    if (m >= 32.0) {
      EXPECT_LT(error / exact, 1e-6) << m;
    }
  }
}

TEST(Rheology, PapanastasiouLimitAtRestIsYieldStressTimesExponent) {
  const double tau_y = 50.0, m = 300.0;
  EXPECT_EQ(yield_viscosity(Papanastasiou{m}, tau_y, 0.0), tau_y * m);
  // Continuous there: tau_y (1 - exp(-m g)) / g = tau_y m (1 - m g / 2 + ...), which expm1 resolves at tiny m g.
  const double g = 1e-12;
  EXPECT_NEAR(yield_viscosity(Papanastasiou{m}, tau_y, g), tau_y * m * (1.0 - 0.5 * m * g), 1e-15 * tau_y * m);
}

TEST(Rheology, BiViscosityIsExactAboveCrossoverAndCappedBelow) {
  const double tau_y = 50.0, mu_max = 1000.0;  // crossover shear rate tau_y / mu_max = 0.05 1/s
  const BiViscosity bi{mu_max};
  for (double g : {0.051, 0.1, 1.0, 10.0, 1e4}) EXPECT_EQ(yield_viscosity(bi, tau_y, g), tau_y / g) << g;
  for (double g : {0.0, 1e-12, 1e-3, 0.049}) EXPECT_EQ(yield_viscosity(bi, tau_y, g), mu_max) << g;
  EXPECT_EQ(yield_viscosity(bi, 0.0, 0.0), 0.0);  // no yield stress, no yield viscosity
  // Inside a Herschel-Bulkley fluid: the power-law part is added unchanged.
  const HerschelBulkley hb{tau_y, 2.0, 1.0, bi, 1e9};
  EXPECT_EQ(hb.effective_viscosity(1.0, 0.0), 2.0 + tau_y);
  EXPECT_EQ(hb.effective_viscosity(0.0, 0.0), 2.0 + mu_max);
  // Tends to tau_y / g at fixed g as mu_max grows, and is exact once mu_max exceeds it.
  const double g = 1e-3, exact = tau_y / g;  // 5e4 Pa s
  double previous = INFINITY;
  for (double cap = 1e2; cap <= 1e6; cap *= 10.0) {
    const double error = exact - yield_viscosity(BiViscosity{cap}, tau_y, g);
    EXPECT_LE(error, previous) << cap;
    if (cap < exact) {
      EXPECT_EQ(error, exact - cap);
    } else {
      EXPECT_EQ(error, 0.0);
    }
    previous = error;
  }
}

TEST(Rheology, ShearThinningPowerLawHasItsOwnCap) {
  const double K = 10.0, n = 0.5, cap = 1000.0;  // K g^-1/2 = cap at g = 1e-4 1/s
  const HerschelBulkley hb{0.0, K, n, Papanastasiou{100.0}, cap};
  for (double g : {0.0, 1e-12, 1e-8, 0.99e-4}) EXPECT_EQ(hb.effective_viscosity(g, 0.0), cap) << g;
  for (double g : {1.01e-4, 1e-2, 1.0, 400.0}) EXPECT_EQ(hb.effective_viscosity(g, 0.0), K * std::pow(g, n - 1.0)) << g;
  EXPECT_DOUBLE_EQ(hb.effective_viscosity(1e-2, 0.0), 100.0);
  // The cap is the power law's alone: a yield stress adds its regularised term on top.
  const HerschelBulkley with_yield{5.0, K, n, BiViscosity{1e5}, cap};
  EXPECT_EQ(with_yield.effective_viscosity(1e-8, 0.0), cap + 1e5);
  // Shear-thickening: no cap, 0 at rest.
  const HerschelBulkley thick{0.0, K, 1.5, Papanastasiou{100.0}, cap};
  EXPECT_EQ(thick.effective_viscosity(0.0, 0.0), 0.0);
  EXPECT_EQ(thick.effective_viscosity(1e8, 0.0), K * std::pow(1e8, 0.5));
}

TEST(Rheology, MohrCoulombWithoutFrictionIsHerschelBulkley) {
  const double c = 80.0;
  for (const Regularisation reg : {Regularisation{Papanastasiou{50.0}}, Regularisation{BiViscosity{1e4}}}) {
    const MohrCoulomb mc{c, 0.0, 3.0, 0.6, reg, 5e3};
    const HerschelBulkley hb{c, 3.0, 0.6, reg, 5e3};
    for (double p : {-1e3, 0.0, 10.0, 1e5})
      for (double g : {0.0, 1e-6, 0.01, 1.0, 100.0}) {
        EXPECT_EQ(mc.yield_stress(p), c);
        EXPECT_EQ(mc.effective_viscosity(g, p), hb.effective_viscosity(g, p)) << p << " " << g;
      }
  }
}

TEST(Rheology, MohrCoulombYieldStressIsPressureTimesTanPhi) {
  const double phi = 30.0, p = 2000.0, tan_phi = std::tan(M_PI / 6.0);
  const MohrCoulomb frictional{0.0, phi, 0.0, 1.0, Papanastasiou{1.0}, 1e9};
  EXPECT_DOUBLE_EQ(frictional.yield_stress(p), p * tan_phi);
  EXPECT_EQ(frictional.yield_stress(-p), 0.0);  // tension adds no strength
  EXPECT_EQ(MohrCoulomb({7.0, phi, 0.0, 1.0, Papanastasiou{1.0}, 1e9}).yield_stress(-p), 7.0);
  // Shear stress at a small shear rate: eta g = tau_y (1 - exp(-m g)) exactly, which tends to p tan(phi) as the
  // regularisation sharpens (m grows).
  const double g = 1e-3, tau = p * tan_phi;
  double previous = INFINITY;
  for (double m = 1e3; m <= 6.4e4; m *= 2.0) {
    const MohrCoulomb mc{0.0, phi, 0.0, 1.0, Papanastasiou{m}, 1e9};
    const double stress = mc.effective_viscosity(g, p) * g;
    EXPECT_NEAR(stress, tau * -std::expm1(-m * g), 1e-12 * tau) << m;
    EXPECT_LT(std::abs(stress - tau), previous) << m;
    previous = std::abs(stress - tau);
  }
  EXPECT_LT(previous / tau, 1e-12);
  // Bi-viscosity: exactly p tan(phi) above the crossover.
  const MohrCoulomb bi{0.0, phi, 0.0, 1.0, BiViscosity{1e9}, 1e9};
  EXPECT_NEAR(bi.effective_viscosity(g, p) * g, tau, 1e-14 * tau);
}

GranularMuI sand() {
  // Glass beads of Jop, Forterre & Pouliquen 2006: mu_s = tan 20.9 deg, mu_2 = tan 32.76 deg, I0 = 0.279.
  return GranularMuI{0.38, 0.64, 0.279, 0.53e-3, 2450.0, 1e12};
}

TEST(Rheology, MuIAtSmallInertialNumberGivesStaticFrictionTimesPressure) {
  const GranularMuI m = sand();
  const double p = 1000.0;
  double previous = INFINITY;
  for (double g = 1.0; g >= 1e-8; g /= 10.0) {
    const double I = m.inertial_number(g, p);
    EXPECT_DOUBLE_EQ(I, g * 0.53e-3 / std::sqrt(p / 2450.0));
    const double stress = m.effective_viscosity(g, p) * g;
    EXPECT_NEAR(stress, m.friction(I) * p, 1e-13 * p);
    const double error = std::abs(stress - m.mu_s * p);
    EXPECT_LT(error, previous) << g;
    previous = error;
  }
  EXPECT_LT(previous / (m.mu_s * p), 1e-6);
  EXPECT_EQ(m.friction(0.0), m.mu_s);
}

TEST(Rheology, MuIAtLargeInertialNumberTendsToMu2) {
  const GranularMuI m = sand();
  double previous = INFINITY;
  for (double I = 1.0; I <= 1e12; I *= 100.0) {
    const double error = m.mu_2 - m.friction(I);
    EXPECT_GT(error, 0.0);
    EXPECT_LT(error, previous) << I;
    EXPECT_NEAR(error, (m.mu_2 - m.mu_s) * m.i0 / (I + m.i0), 1e-15) << I;
    previous = error;
  }
  EXPECT_LT(previous, 1e-12);
  EXPECT_EQ(m.friction(INFINITY), m.mu_2);
}

TEST(Rheology, MuIAtI0IsTheMeanOfBothFrictions) {
  const GranularMuI m = sand();
  // mu_s + (mu_2 - mu_s) / 2: mu_2 - mu_s is exact (Sterbenz, mu_2 / 2 <= mu_s <= 2 mu_2) and halving is exact, so
  // both sides are the rounding of the same real number.
  EXPECT_EQ(m.friction(m.i0), (m.mu_s + m.mu_2) / 2.0);
}

TEST(Rheology, MuICapAndPressureFloor) {
  GranularMuI m = sand();
  m.max_viscosity_pa_s = 500.0;
  EXPECT_EQ(m.effective_viscosity(0.0, 1000.0), 500.0);   // at rest under pressure: the cap
  EXPECT_EQ(m.effective_viscosity(1e-6, 1000.0), 500.0);
  EXPECT_EQ(m.effective_viscosity(1.0, 0.0), 0.0);        // no pressure, no strength
  EXPECT_EQ(m.effective_viscosity(0.0, -10.0), 0.0);
  m.min_viscosity_pa_s = 1e-3;
  EXPECT_EQ(m.effective_viscosity(1.0, -10.0), 1e-3);
  EXPECT_EQ(m.effective_viscosity(1e9, 1e-6), 1e-3);      // mu(I) p / g below the floor
  const double g = 100.0, p = 1000.0;
  EXPECT_EQ(m.effective_viscosity(g, p), m.friction(m.inertial_number(g, p)) * p / g);
}

TEST(Rheology, VariantDispatchNamesAndYieldStress) {
  const std::vector<Phase> phases{
      {"water", 1000.0, Newtonian{1e-3}},
      {"mud", 1800.0, HerschelBulkley{0.0, 0.5, 0.7, Papanastasiou{100.0}, 1e3}},
      {"clay", 1800.0, HerschelBulkley{40.0, 0.5, 0.7, BiViscosity{1e4}, 1e3}},
      {"soil", 1900.0, MohrCoulomb{0.0, 30.0, 0.5, 1.0, Papanastasiou{100.0}, 1e3}},
      {"sand", 2000.0, sand()},
  };
  const std::vector<std::string_view> names{"newtonian", "herschel_bulkley", "herschel_bulkley", "mohr_coulomb",
                                            "granular"};
  const std::vector<bool> yield{false, false, true, true, true};
  for (std::size_t k = 0; k < phases.size(); ++k) {
    EXPECT_EQ(model_name(phases[k].rheology), names[k]) << phases[k].name;
    EXPECT_EQ(has_yield_stress(phases[k].rheology), yield[k]) << phases[k].name;
  }
  EXPECT_EQ(effective_viscosity(phases[0].rheology, 5.0, 1e4), 1e-3);
  EXPECT_EQ(effective_viscosity(phases[2].rheology, 2.0, 0.0),
            std::get<HerschelBulkley>(phases[2].rheology).effective_viscosity(2.0, 0.0));
  EXPECT_EQ(effective_viscosity(phases[3].rheology, 2.0, 500.0),
            std::get<MohrCoulomb>(phases[3].rheology).effective_viscosity(2.0, 500.0));
  EXPECT_EQ(effective_viscosity(phases[4].rheology, 2.0, 500.0), sand().effective_viscosity(2.0, 500.0));
  const std::vector<bool> pressure{false, false, false, true, true};
  for (std::size_t k = 0; k < phases.size(); ++k) EXPECT_EQ(depends_on_pressure(phases[k].rheology), pressure[k]);
}

// Before t = 0 a phase settles as a fluid: Newtonian mu, Herschel-Bulkley's and Mohr-Coulomb's K (the model without
// its yield term at 1/s), mu(I)'s floor.
TEST(Rheology, SettlingViscosityIsTheModelWithoutItsYieldTerm) {
  EXPECT_EQ(settling_viscosity(Newtonian{1e-3}), 1e-3);
  const HerschelBulkley hb{40.0, 0.5, 0.7, Papanastasiou{100.0}, 1e3};
  EXPECT_EQ(settling_viscosity(hb), 0.5);
  EXPECT_EQ(settling_viscosity(hb), HerschelBulkley({0.0, 0.5, 0.7, Papanastasiou{100.0}, 1e3}).effective_viscosity(1.0, 0.0));
  EXPECT_EQ(settling_viscosity(MohrCoulomb{5.0, 30.0, 2.0, 1.0, Papanastasiou{100.0}, 1e3}), 2.0);
  GranularMuI g = sand();
  g.min_viscosity_pa_s = 0.25;
  EXPECT_EQ(settling_viscosity(g), 0.25);
}

// What slide check holds a slide with at rest (strength_at_rest) is the limit of eta(g, p) g as g -> 0 of each model,
// on the effective pressure: exact values, and the models' own stress at a small shear rate.
TEST(Rheology, StrengthAtRestIsTheStressOfTheModelAtVanishingShear) {
  const double p = 800.0;
  EXPECT_EQ(strength_at_rest(Newtonian{1e-3}, p), 0.0);
  EXPECT_EQ(strength_at_rest(HerschelBulkley{40.0, 0.5, 1.0, BiViscosity{1e12}, 1e3}, p), 40.0);
  const MohrCoulomb mc{5.0, 30.0, 0.5, 1.0, BiViscosity{1e12}, 1e3};
  EXPECT_NEAR(strength_at_rest(mc, p), 5.0 + p * std::tan(M_PI / 6.0), 1e-12);
  EXPECT_EQ(strength_at_rest(mc, -100.0), 5.0);  // tension: cohesion only
  const GranularMuI m = sand();
  EXPECT_DOUBLE_EQ(strength_at_rest(m, p), 0.38 * p);
  EXPECT_EQ(strength_at_rest(m, -100.0), 0.0);
  const double g = 1e-9;
  for (const Rheology& r : {Rheology(mc), Rheology(m)})
    EXPECT_NEAR(effective_viscosity(r, g, p) * g, strength_at_rest(r, p), 1e-5 * strength_at_rest(r, p));
}

// ---------------------------------------------------------------------------------------------------------------
// Strain rate

template <int D>
void build_list(const Particles<D>& P, double re, NeighborList& list) {
  Vec<D> lo = P.position[0], hi = P.position[0];
  for (const auto& x : P.position) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  NeighborGrid<D> grid(lo - Vec<D>::Constant(re), hi + Vec<D>::Constant(re), re);
  grid.bin(P.position);
  build_neighbor_list(grid, P.position, re, list);
}

// The operator tests' block of fluid (tests/lattice_block.hpp), with velocities and a shear-rate check.
template <int D>
struct Block : testing::Lattice<D> {
  using testing::Lattice<D>::Lattice;
  using testing::Lattice<D>::particles;
  using testing::Lattice<D>::list;
  using testing::Lattice<D>::constants;
  using testing::Lattice<D>::dp;
  using testing::Lattice<D>::re;
  using testing::Lattice<D>::interior;
  template <class F>
  void set_velocity(F&& u) {
    for (std::size_t i = 0; i < particles.size(); ++i) particles.velocity[i] = u(particles.position[i]);
  }
  // Checks every interior particle's shear rate against `exact`; returns how many were checked.
  int expect_shear_rate(double exact, double scale) const {
    int checked = 0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
      if (!interior(i)) continue;
      ++checked;
      EXPECT_NEAR(shear_rate<D>(i, particles, list, re, constants.n0, ViscousWall{WallSlip::no_slip, 0.5 * dp}), exact, 1e-9 * scale) << i;
    }
    return checked;
  }
};

template <int D>
void expect_exact_shear_rates(LatticeKind kind) {
  Block<D> B(kind);
  const double gamma = 3.7, a = 1.3, omega = 2.1;
  // Simple shear u = (gamma y, 0): L = [[0, gamma], [0, 0]], D:D = gamma^2 / 2, shear rate gamma.
  B.set_velocity([&](const Vec<D>& x) { Vec<D> u = Vec<D>::Zero(); u[0] = gamma * x[1]; return u; });
  EXPECT_GT(B.expect_shear_rate(gamma, gamma), 0);
  for (std::size_t i = 0; i < B.particles.size(); ++i)
    if (B.interior(i)) {
      Mat<D> exact = Mat<D>::Zero();
      exact(0, 1) = gamma;
      const Mat<D> L = velocity_gradient<D>(i, B.particles, B.list, B.re, B.constants.n0, ViscousWall{WallSlip::no_slip, 0.5 * B.dp});
      EXPECT_NEAR((L - exact).norm(), 0.0, 1e-9 * gamma) << i;
    }
  // Pure extension u = (a x, -a y): D = diag(a, -a), sqrt(2 D:D) = 2a.
  B.set_velocity([&](const Vec<D>& x) { Vec<D> u = Vec<D>::Zero(); u[0] = a * x[0]; u[1] = -a * x[1]; return u; });
  B.expect_shear_rate(2.0 * a, a);
  // Solid-body rotation u = omega (-y, x): D = 0.
  B.set_velocity([&](const Vec<D>& x) { Vec<D> u = Vec<D>::Zero(); u[0] = -omega * x[1]; u[1] = omega * x[0]; return u; });
  B.expect_shear_rate(0.0, omega);
}

TEST(StrainRate, ExactForLinearFieldsOnSquareLattice) { expect_exact_shear_rates<2>(LatticeKind::square); }
TEST(StrainRate, ExactForLinearFieldsOnHexagonalLattice) { expect_exact_shear_rates<2>(LatticeKind::hexagonal); }
TEST(StrainRate, ExactForLinearFieldsOnCubicLattice) { expect_exact_shear_rates<3>(LatticeKind::square); }

// A channel floor: the face y = 0 from x = -3.5 dp to (columns + 3.5) dp, fixed wall particles (velocity 0) from
// polyline_boundary below it (walking +x, the fluid lies on the left, above), and square-lattice fluid above in simple
// shear u = (gamma y, 0), which vanishes on the face.
struct ShearedChannel {
  static constexpr int columns = 14, rows = 12;
  double dp = 0.1, re;
  double gamma = 3.7;
  int layers;
  Particles<2> P;
  NeighborList list;
  LatticeConstants constants;

  explicit ShearedChannel(double re_over_dp) : re(re_over_dp * dp), layers(boundary_layers(re_over_dp)) {
    for (const auto& b : polyline_boundary({Vec<2>(-3.5 * dp, 0.0), Vec<2>((columns + 3.5) * dp, 0.0)}, true, dp,
                                           layers)) {
      const std::size_t i = P.add(b.position, b.layer == 0 ? Kind::wall : Kind::dummy, 0, 1000.0, 1e-3);
      P.wall_normal[i] = b.normal;
      P.wall_depth[i] = b.depth;
    }
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < columns; ++i) {
        const std::size_t n = P.add(lattice_point(LatticeKind::square, dp, i, j), Kind::fluid, 0, 1000.0, 1e-3);
        P.velocity[n] = Vec<2>(gamma * P.position[n][1], 0.0);
      }
    build_list<2>(P, re, list);
    constants = lattice_constants<2>(dp, re);
  }
  int row(std::size_t i) const { return static_cast<int>(std::floor(P.position[i][1] / dp)); }
  // Fluid particles whose kernel support holds a full lattice: away from the sides and the top.
  bool tested(std::size_t i) const {
    const auto& x = P.position[i];
    return P.kind[i] == Kind::fluid && x[0] > re && x[0] < columns * dp - re && x[1] < rows * dp - re;
  }
};

TEST(StrainRate, PolylineFloorIsBelowTheFluid) {
  const ShearedChannel C(2.1);
  int walls = 0;
  for (std::size_t i = 0; i < C.P.size(); ++i)
    if (C.P.kind[i] != Kind::fluid) {
      ++walls;
      EXPECT_LT(C.P.position[i][1], 0.0);
      EXPECT_EQ(C.P.wall_normal[i], Vec<2>(0.0, 1.0));
      EXPECT_NEAR(C.P.wall_depth[i], -C.P.position[i][1], 1e-15);
    }
  EXPECT_EQ(walls, 3 * (ShearedChannel::columns + 8));
}

// The mirror factor is the one the viscous force uses: viscous_pair_term with mu = 1 is factor * W * (u_j - u_i).
TEST(StrainRate, WallMirrorAgreesWithViscousPairTerm) {
  ShearedChannel C(3.1);
  int pairs = 0;
  for (std::size_t i = 0; i < C.P.size(); ++i) {
    if (C.P.kind[i] != Kind::fluid) continue;
    for (const std::uint32_t* q = C.list.begin(i); q != C.list.end(i); ++q) {
      const std::uint32_t j = *q;
      const double r2 = distance_squared<2>(C.P.position[i], C.P.position[j]);
      if (C.P.kind[j] == Kind::fluid || r2 >= C.re * C.re) continue;
      C.P.viscosity[i] = 1.0;
      const Vec<2> force = viscous_pair_term<2>(i, j, r2, C.P, C.re, ViscousWall{WallSlip::no_slip, 0.5 * C.dp});
      const Vec<2> mirrored = kernel_weight(std::sqrt(r2), C.re) * velocity_difference<2>(i, j, C.P, 0.5 * C.dp);
      EXPECT_NEAR((force - mirrored).norm(), 0.0, 1e-15 * (1.0 + force.norm()));
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 0);
}

// No-slip floor: the mirrored wall velocity -(d_j / d_i) u_i = -gamma d_j is exactly the linear field continued below
// the face (gamma y_j), so the shear rate is exact in every row, the first (d_i = dp/2, at the clip) included, for
// the default kernel and a wider one. (With Morris et al.'s cap of the factor at 1.5, the first row read
// 0.8748867 gamma at re = 2.1 dp, and rows 0 and 1 0.848222 and 0.9999925 gamma at re = 3.1 dp.)
void expect_floor_shear_rates_exact(double re_over_dp) {
  const ShearedChannel C(re_over_dp);
  std::set<int> rows;
  for (std::size_t i = 0; i < C.P.size(); ++i) {
    if (!C.tested(i)) continue;
    const double g = shear_rate<2>(i, C.P, C.list, C.re, C.constants.n0, ViscousWall{WallSlip::no_slip, 0.5 * C.dp});
    EXPECT_NEAR(g, C.gamma, 1e-9 * C.gamma) << "row " << C.row(i);
    rows.insert(C.row(i));
  }
  EXPECT_TRUE(rows.count(0) && rows.count(1));
}

TEST(StrainRate, NoSlipFloorExactInEveryRowDefaultKernel) { expect_floor_shear_rates_exact(2.1); }
TEST(StrainRate, NoSlipFloorExactInEveryRowWiderKernel) { expect_floor_shear_rates_exact(3.1); }

// A particle nearer the face than the clip (dp/4) takes the factor of one at dp/2: 1 + d_j / (dp/2), not 1 + d_j / d_i.
// On a sheared lattice (each row slid along x by its own offset, as a shear flow leaves them) seed eq. 3's d / n0
// normalisation is wrong and the corrected gradient is not: a linear shear reads exactly.
TEST(StrainRate, ExactOnAShearedLattice) {
  Block<2> B;
  auto& P = B.particles;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double row = std::round(P.position[i][1] / B.dp);
    P.position[i][0] += std::fmod(0.37 * row * row, 1.0) * B.dp;
  }
  build_list<2>(P, B.re, B.list);
  const double gamma = 3.7;
  B.set_velocity([&](const Vec<2>& x) { return Vec<2>(gamma * x[1], 0.0); });
  EXPECT_GT(B.expect_shear_rate(gamma, gamma), 0);
  // Seed eq. 3 alone (the normalisation d / n0) reads it off by up to several per cent here.
  double worst = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!B.interior(i)) continue;
    Mat<2> A = Mat<2>::Zero();
    for (const std::uint32_t* q = B.list.begin(i); q != B.list.end(i); ++q) {
      const Vec<2> r = P.position[*q] - P.position[i];
      if (r.squaredNorm() < B.re * B.re)
        A += kernel_weight(r.norm(), B.re) / r.squaredNorm() * (P.velocity[*q] - P.velocity[i]) * r.transpose();
    }
    worst = std::max(worst, std::abs(shear_rate_of<2>((2.0 / B.constants.n0) * A) - gamma) / gamma);
  }
  EXPECT_GT(worst, 0.01);
}

TEST(StrainRate, MirrorClipsTheDistanceFromTheFace) {
  EXPECT_EQ(no_slip_mirror_factor(0.025, 0.05, 0.05), 2.0);
  EXPECT_DOUBLE_EQ(no_slip_mirror_factor(0.05, 0.15, 0.05), 4.0);
  EXPECT_DOUBLE_EQ(no_slip_mirror_factor(0.2, 0.15, 0.05), 1.75);
  EXPECT_EQ(no_slip_mirror_factor(-0.01, 0.05, 0.05), 2.0);  // past the face
}

// Free slip: boundary particles are left out, so the channel gives what the fluid alone gives, whatever the walls'
// velocity. Every row is exact, those within re of the wall too: their neighbours lie on one side only, but the
// corrected gradient (M^-1 in place of d / n0) is exact for a linear field on any neighbourhood that spans the plane.
TEST(StrainRate, FreeSlipLeavesWallsOut) {
  ShearedChannel C(2.1);
  Particles<2> fluid;
  std::vector<std::size_t> in_fluid(C.P.size(), 0);
  for (std::size_t i = 0; i < C.P.size(); ++i) {
    if (C.P.kind[i] != Kind::fluid) {
      C.P.velocity[i] = Vec<2>(5.0, -7.0);  // ignored
      continue;
    }
    in_fluid[i] = fluid.add(C.P.position[i], Kind::fluid, 0, 1000.0, 1e-3);
    fluid.velocity[in_fluid[i]] = C.P.velocity[i];
  }
  NeighborList fluid_list;
  build_list<2>(fluid, C.re, fluid_list);
  int near_wall = 0;
  for (std::size_t i = 0; i < C.P.size(); ++i) {
    if (!C.tested(i)) continue;
    const double g = shear_rate<2>(i, C.P, C.list, C.re, C.constants.n0, ViscousWall{WallSlip::free_slip, 0.5 * C.dp});
    EXPECT_NEAR(g, shear_rate<2>(in_fluid[i], fluid, fluid_list, C.re, C.constants.n0, ViscousWall{WallSlip::free_slip, 0.5 * C.dp}),
                1e-12 * C.gamma);
    EXPECT_NEAR(g, C.gamma, 1e-9 * C.gamma) << "y = " << C.P.position[i][1];
    if (C.P.position[i][1] < C.re) ++near_wall;
  }
  EXPECT_GT(near_wall, 0);
}

}  // namespace
}  // namespace slide
