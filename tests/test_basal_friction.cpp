// Coulomb basal friction of a sediment against walls (fluid/basal_friction.hpp; scene key basal_friction_angle):
// the wall-viscosity function against its exact value, and a sediment block stiff enough not to deform, sliding on
// a wall, against the closed form of a rigid block with that friction.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "fluid/basal_friction.hpp"
#include "fluid/lattice.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/viscosity.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"
#include "tests/sediment_block.hpp"

namespace slide::testing {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

TEST(BasalFriction, CoefficientOfTheAngle) {
  EXPECT_DOUBLE_EQ(basal_friction_coefficient(0.0), 0.0);
  EXPECT_NEAR(basal_friction_coefficient(45.0), 1.0, 1e-15);
  EXPECT_NEAR(basal_friction_coefficient(20.0), 0.36397023426620234, 1e-15);
  EXPECT_EQ(basal_friction_coefficient(90.0), inf);
}

// s = min(1, mu_b sigma / (mu g_w)): exact values on either side of the bound, and the cases where it stays 1.
TEST(BasalFriction, WallFractionIsTheCoulombBoundOverTheNoSlipStress) {
  // mu 100 Pa s, g_w 2 /s: the no-slip wall stress 200 Pa; mu_b 0.5, sigma 300 Pa: the bound 150 Pa.
  EXPECT_DOUBLE_EQ(coulomb_wall_fraction(100.0, 0.5, 300.0, 2.0), 0.75);
  EXPECT_DOUBLE_EQ(100.0 * coulomb_wall_fraction(100.0, 0.5, 300.0, 2.0) * 2.0, 0.5 * 300.0);  // mu_w g_w = mu_b sigma
  EXPECT_EQ(coulomb_wall_fraction(100.0, 0.5, 500.0, 2.0), 1.0);  // bound 250 Pa above 200 Pa: no-slip
  EXPECT_EQ(coulomb_wall_fraction(100.0, inf, 300.0, 2.0), 1.0);  // no bound
  EXPECT_EQ(coulomb_wall_fraction(100.0, 0.5, 300.0, 0.0), 1.0);  // nothing slides
  EXPECT_EQ(coulomb_wall_fraction(0.0, 0.5, 300.0, 2.0), 1.0);    // inviscid
  EXPECT_EQ(coulomb_wall_fraction(100.0, 0.5, -50.0, 2.0), 0.0);  // tension: no friction
  EXPECT_EQ(coulomb_wall_fraction(100.0, 0.0, 300.0, 2.0), 0.0);  // frictionless
}

// The key: `basal_friction_angle` on a phase and on a deformable slide, 90 (no-slip) by default; slide check prints it;
// a value outside [0, 90] exits 2 naming the key.
const char* kScene = R"(particle_spacing: 0.02
end_time: 0.01
fluid:
  phases: [{name: water}, {name: mud, density: 1800, rheology: {model: herschel_bulkley, yield_stress: 10, consistency: 1}}]
  regions: [{type: rectangle, min: [0, 0], max: [0.2, 0.2]}, {type: rectangle, phase: mud, min: [0.3, 0], max: [0.4, 0.1]}]
walls:
  - points: [[0, 0.4], [0, 0], [0.6, 0], [0.6, 0.4]]
bodies:
  - {name: slab, model: herschel_bulkley, density: 1950, shape: {type: box, center: [0.5, 0.05], size: [0.1, 0.1]},
     rheology: {yield_stress: 100, consistency: 1}}
method: {initial_state: lattice}
)";

CommandResult check(const std::string& extra) {
  const auto dir = fresh_directory("basal_check");
  write_file(dir / "scene.yaml", kScene);
  return run_command(slide_binary() + " check " + (dir / "scene.yaml").string() + " " + extra);
}

TEST(BasalFriction, SlideCheckPrintsTheWallCondition) {
  const CommandResult r = check("--set fluid.phases[1].basal_friction_angle=25 --set bodies[0].basal_friction_angle=20");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("water     1000 kg/m^3, newtonian"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no-slip at walls"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("basal friction 25 deg (mu_b 0.4663) at walls"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("basal friction 20 deg (mu_b 0.364) at walls"), std::string::npos) << r.output;
}

TEST(BasalFriction, KeysSetThePhasesCoefficients) {
  const auto dir = fresh_directory("basal_keys");
  write_file(dir / "s.yaml", kScene);
  const auto plain = cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
  ASSERT_EQ(plain->simulation->phases.size(), 3u);  // water, mud, the slab's
  for (const auto& p : plain->simulation->phases) EXPECT_EQ(p.basal_friction, inf) << p.name << ": default no-slip";
  const auto set = cases::build_scene<2>(
      cases::load_scene(dir / "s.yaml", {"fluid.phases[1].basal_friction_angle=25", "bodies[0].basal_friction_angle=20"}),
      "s");
  const auto& ph = set->simulation->phases;
  EXPECT_EQ(ph[0].basal_friction, inf);
  EXPECT_NEAR(ph[1].basal_friction, std::tan(25.0 * M_PI / 180.0), 1e-15);
  EXPECT_NEAR(ph[2].basal_friction, std::tan(20.0 * M_PI / 180.0), 1e-15);
}

TEST(BasalFriction, OutOfRangeAngleNamesTheKey) {
  for (const std::string key : {"fluid.phases[1].basal_friction_angle", "bodies[0].basal_friction_angle"})
    for (const std::string value : {"95", "-1"}) {
      const CommandResult r = check("--set " + key + "=" + value);
      EXPECT_EQ(r.exit_code, 2) << r.output;
      EXPECT_NE(r.output.find(key), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("out of range"), std::string::npos) << r.output;
    }
}

// Every particle's neighbours within re (the blocks below lie inside x in [-1, 4], y in [-1, 1]).
NeighborList neighbour_list_of(const Particles<2>& P, double re) {
  NeighborGrid<2> grid(Vec<2>(-1.0, -1.0), Vec<2>(4.0, 1.0), re);
  grid.bin(P.position);
  NeighborList nl;
  build_neighbor_list(grid, P.position, re, nl, P.size());
  return nl;
}

// The x force on fluid particle i (mass rho dp^2 per unit width) from its wall pairs of the viscous term.
double wall_pairs_force_x(std::size_t i, const Particles<2>& P, const NeighborList& nl, double re,
                          const ViscousWall& wall, const LatticeConstants& lc, double dp) {
  Vec<2> sum = Vec<2>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q)
    if (P.kind[*q] != Kind::fluid && distance_squared<2>(P.position[*q], P.position[i]) < re * re)
      sum += viscous_pair_term<2>(i, *q, distance_squared<2>(P.position[*q], P.position[i]), P, re, wall);
  return P.density[i] * dp * dp * viscous_scale<2>(i, P, lc.n0, lc.lambda) * sum[0];
}

// A block of fluid particles on the square lattice (dp = 0.1) sliding at U = (0.3, -0.05) (a normal part too) over
// a flat wall of three layers moving at u_b = (-0.1, 0): every particle's wall shear rate is the tangential slip
// 0.4 m/s over its distance from the face (clipped at dp / 2), and its normal stress its pressure carried down to the
// face with rho g d_i. Then the wall pairs of the viscous term, summed over the rows in front of one wall particle's
// width, give the Coulomb stress mu_b sigma per unit area (fluid/basal_friction.hpp: the lattice's second moment).
TEST(BasalFriction, WallShearRateAndTheDiscreteWallStressAreExact) {
  const double dp = 0.1, re = 2.1 * dp, rho = 2000.0, p = 1500.0, mu = 500.0, mu_b = 0.4;
  const Vec<2> gravity(0.0, -9.81), U(0.3, -0.05), ub(-0.1, 0.0);
  Particles<2> P;
  const int nx = 30;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < nx; ++i) {
      const std::size_t j = P.add(Vec<2>((i + 0.5) * dp, -(k + 0.5) * dp), k == 0 ? Kind::wall : Kind::dummy, 0, rho, 0.0);
      P.wall_normal[j] = Vec<2>(0.0, 1.0);
      P.wall_depth[j] = (k + 0.5) * dp;
      P.velocity[j] = ub;
    }
  const std::size_t first_fluid = P.size();
  for (int r = 0; r < 4; ++r)
    for (int i = 0; i < nx; ++i) {
      const std::size_t j = P.add(Vec<2>((i + 0.5) * dp, (r + 0.5) * dp), Kind::fluid, 0, rho, mu);
      P.velocity[j] = U;
      P.pressure[j] = p;
    }
  const NeighborList nl = neighbour_list_of(P, re);
  const LatticeConstants lc = lattice_constants<2>(dp, re);
  const ViscousWall wall{WallSlip::no_slip, 0.5 * dp};
  // The column above the middle wall particle: rows r = 0..3 at x = 15.5 dp.
  double force_x = 0.0;  // per unit width, on the column's fluid particles from their wall pairs
  for (int r = 0; r < 4; ++r) {
    const std::size_t i = first_fluid + r * nx + 15;
    const double d_i = (r + 0.5) * dp;
    const WallShear s = wall_shear<2>(i, P, nl, re, wall.min_distance, gravity);
    if (r <= 1) {  // rows within re of the wall
      EXPECT_NEAR(s.rate, 0.4 / d_i, 1e-12) << "row " << r;
      EXPECT_NEAR(s.normal_stress, p + rho * 9.81 * d_i, 1e-9) << "row " << r;
    } else {
      EXPECT_EQ(s.rate, 0.0) << "row " << r;
    }
    // The same normal stress on both rows (sigma = p), so that their sum is exactly the Coulomb stress mu_b p.
    P.wall_fraction[i] = coulomb_wall_fraction(mu, mu_b, p, s.rate);
    if (r <= 1) {
      EXPECT_LT(P.wall_fraction[i], 1.0) << "row " << r << ": the bound must act";
    }
    force_x += wall_pairs_force_x(i, P, nl, re, wall, lc, dp);
  }
  // Per unit area of the face (the column is dp wide): -mu_b p against the slip (+x).
  std::printf("wall stress of the column %.6g Pa, Coulomb mu_b p = %.6g Pa\n", force_x / dp, mu_b * p);
  EXPECT_NEAR(force_x / dp, -mu_b * p, 1e-9 * mu_b * p);
}

// The same on the hexagonal lattice laid along a face (fluid/walls.hpp): rows of nearest spacing a, h = a sqrt(3) / 2
// apart, the first at h / 2 = 0.465 dp in front of the face, under the pairs' clip at dp / 2 (fluid/viscosity.hpp).
// The rows' wall pairs over one period a of the face still give the Coulomb stress mu_b p exactly: each particle
// carries its share sum (d_i + d_j) W_ij of the crossing pairs' sum (fluid/basal_friction.hpp). With the clipped rate
// alone the column carried about 3 % more, and a Coulomb block slid 17.5 % slower than the closed form at 20 degrees.
TEST(BasalFriction, DiscreteWallStressIsExactOnTheHexagonalRowsAlongAFace) {
  const double dp = 0.1, re = 2.1 * dp, rho = 2000.0, p = 1500.0, mu = 500.0, mu_b = 0.4;
  const double a = nearest_spacing(LatticeKind::hexagonal, dp), h = row_spacing(LatticeKind::hexagonal, dp);
  const Vec<2> gravity(0.0, -9.81), U(0.3, 0.0);
  Particles<2> P;
  const int nx = 30;
  for (int k = 0; k < 3; ++k)  // lattice rows j = -1, -2, -3 continue the fluid's rows j = 0, 1, ... behind the face
    for (int i = 0; i < nx; ++i) {
      const double x = (i + 0.5 * ((k + 1) % 2)) * a;
      const std::size_t j = P.add(Vec<2>(x, -(k + 0.5) * h), k == 0 ? Kind::wall : Kind::dummy, 0, rho, 0.0);
      P.wall_normal[j] = Vec<2>(0.0, 1.0);
      P.wall_depth[j] = (k + 0.5) * h;
    }
  const std::size_t first_fluid = P.size();
  for (int r = 0; r < 4; ++r)
    for (int i = 0; i < nx; ++i) {
      const std::size_t j = P.add(Vec<2>((i + 0.5 * (r % 2)) * a, (r + 0.5) * h), Kind::fluid, 0, rho, mu);
      P.velocity[j] = U;
      P.pressure[j] = p;
    }
  const NeighborList nl = neighbour_list_of(P, re);
  const LatticeConstants lc = lattice_constants<2>(dp, re, LatticeKind::hexagonal);
  const ViscousWall wall{WallSlip::no_slip, 0.5 * dp};
  ASSERT_LT(0.5 * h, wall.min_distance);  // the first row is clipped
  double force_x = 0.0;  // per unit width, on one particle of each row (one per period a) from its wall pairs
  for (int r = 0; r < 4; ++r) {
    const std::size_t i = first_fluid + r * nx + 15;
    const WallShear s = wall_shear<2>(i, P, nl, re, wall.min_distance, gravity);
    P.wall_fraction[i] = coulomb_wall_fraction(mu, mu_b, p, s.rate);
    force_x += wall_pairs_force_x(i, P, nl, re, wall, lc, dp);
  }
  std::printf("hexagonal rows: wall stress of a period %.6g Pa, Coulomb mu_b p = %.6g Pa\n", force_x / a, mu_b * p);
  EXPECT_NEAR(force_x / a, -mu_b * p, 1e-9 * mu_b * p);
}

// The sliding block. Tilted gravity, g (sin a, -cos a), on a flat floor: a slope of angle a without a rotated box on
// an unrotated lattice (whose steps would make the particles' distances from the face uneven). A 0.4 m x 0.1 m
// Bingham block (yield stress 5000 Pa, over twice its weight per area rho g h = 1913 Pa, so it does not deform) of
// 1950 kg/m^3 on a 1.5 m floor, in air: a scene needs a fluid region, so a few particles of water sit in a cup of
// their own 0.5 m beyond the floor's end. c0 = 20 m/s, more than ten times the block's speed. The run starts from the
// lattice: the block settles onto the floor in its first hundredths of a second.
struct BlockRun {
  std::vector<double> t, along;  // centre of mass down the slope (+x) from where it was at t = 0
  double largest_particle = 0.0;
  double largest_shape_change = 0.0;  // m, largest change of a particle's offset from the centre of mass
  long steps = 0;
  std::string check;
  double slope_angle_deg = 0.0;  // slide check's yield criterion at rest: the face's angle to gravity's normal plane
  std::string criterion;
};

BlockRun block_on_tilted_floor(double slope_deg, const std::string& basal, double dp, double end_time) {
  const double a = slope_deg * M_PI / 180.0;
  const std::string yaml = fmt::format(R"(particle_spacing: {dp}
end_time: {end}
gravity: [{gx}, {gy}]
fluid:
  phases: [{{name: water, density: 1000, rheology: {{model: newtonian, viscosity: 1.0e-3}}}}]
  regions: [{{type: rectangle, min: [2.0, 0], max: [2.06, 0.04]}}]
walls:
  - {{name: floor, points: [[0, 0.3], [0, 0], [1.5, 0], [1.5, 0.3]]}}
  - {{name: cup, points: [[2.0, 0.1], [2.0, 0], [2.06, 0], [2.06, 0.1]]}}
bodies:
  - name: block
    model: herschel_bulkley
    shape: {{type: box, center: [0.3, 0.05], size: [0.4, 0.1]}}
    density: 1950
    rheology: {{yield_stress: 5000, consistency: 1, flow_index: 1}}
{basal}
# Measured on the square lattice with the mirror wall (-2.8 %). On the default hexagonal lattice with extrapolated
# walls it slides 6.6 % slower than the closed form (measured, cause not yet found: issue 12's closing note).
method: {{gradient: variational, sound_speed: 20, initial_state: lattice, wall_pressure: mirror}}
lattice: square
output: {{snapshots: false}}
)",
                                       fmt::arg("dp", dp), fmt::arg("end", end_time), fmt::arg("gx", g * std::sin(a)),
                                       fmt::arg("gy", -g * std::cos(a)), fmt::arg("basal", basal));
  auto scene = build_scene_text(fmt::format("basal_{:.0f}_{}", slope_deg, basal.size()), yaml);
  const std::uint8_t phase = scene->slides[0].phase;
  auto& sim = *scene->simulation;
  BlockRun r;
  r.slope_angle_deg = scene->slides[0].slope_angle_deg;
  r.criterion = scene->slides[0].criterion;
  const Vec<2> c0 = centre_of_mass(sim.particles(), phase);
  const auto start = slide_positions(sim.particles(), phase);
  EXPECT_TRUE(run_scene(*scene, [&](const Simulation<2>& s) {
    const Vec<2> c = centre_of_mass(s.particles(), phase);
    r.t.push_back(s.time());
    r.along.push_back(c[0] - c0[0]);
    for (std::size_t i = 0; i < s.particles().size(); ++i) {
      if (s.particles().kind[i] != Kind::fluid || s.particles().phase[i] != phase) continue;
      const Vec<2>& x0 = start.at(s.particles().id[i]);
      r.largest_particle = std::max(r.largest_particle, (s.particles().position[i] - x0).norm());
      r.largest_shape_change =
          std::max(r.largest_shape_change, ((s.particles().position[i] - c) - (x0 - c0)).norm());
    }
  }));
  r.steps = sim.step_count();
  return r;
}

// Least-squares x = c0 + c1 t + c2 t^2 over t >= t0: the acceleration 2 c2 (the start-up before t0 left out).
double fitted_acceleration(const BlockRun& r, double t0) {
  std::vector<int> rows;
  for (std::size_t k = 0; k < r.t.size(); ++k)
    if (r.t[k] >= t0) rows.push_back(static_cast<int>(k));
  Eigen::MatrixXd A(rows.size(), 3);
  Eigen::VectorXd b(rows.size());
  for (std::size_t m = 0; m < rows.size(); ++m) {
    const double t = r.t[rows[m]];
    A(m, 0) = 1.0, A(m, 1) = t, A(m, 2) = t * t;
    b(m) = r.along[rows[m]];
  }
  const Eigen::Vector3d c = A.colPivHouseholderQr().solve(b);
  return 2.0 * c(2);
}

void print_run(const char* what, const BlockRun& r, double dp) {
  std::printf("%s: moved %.4g m in %.2f s (%.3f dp), largest particle displacement %.4g m, largest change of shape "
              "%.3g m = %.3f dp, %ld steps\n",
              what, r.along.back(), r.t.back(), r.along.back() / dp, r.largest_particle, r.largest_shape_change,
              r.largest_shape_change / dp, r.steps);
}

// mu_b = tan 15 deg < tan 30 deg: the block slides as a rigid block, s = 1/2 g (sin a - mu_b cos a) t^2.
// Tolerance 5 %: the friction is the Coulomb stress exactly on a lattice at uniform pressure (the unit test above);
// what is left is the pressure: the EOS pressure of the bottom rows of a block 5 dp thick, noisy after the start from
// the lattice, and its free ends, where the pressure falls to zero over a spacing. Here an error in the friction
// comes out 0.87 times as large in the acceleration (mu_b cos a / (sin a - mu_b cos a)). Measured (the printout):
// -2.78 % at dp = 0.02, -2.23 % at dp = 0.01 (the long test), with the semi-implicit stage's incremental predictor
// (coupling/simulation.cpp; before it, -3.34 % and -3.59 %); frictionless (basal_friction_angle 0, not a test) the
// front particle's fitted acceleration was 0.67 % below g sin a at dp = 0.02 (before the predictor), so most of the
// deficit is a friction a few per cent above mu_b times the weight.
void expect_rigid_block_acceleration(double dp) {
  const double slope = 30.0, phi_b = 15.0, t0 = 0.1;
  const BlockRun r = block_on_tilted_floor(slope, fmt::format("    basal_friction_angle: {}", phi_b), dp, 0.5);
  const double a = slope * M_PI / 180.0, mu_b = std::tan(phi_b * M_PI / 180.0);
  const double closed = g * (std::sin(a) - mu_b * std::cos(a));
  const double fitted = fitted_acceleration(r, t0);
  std::printf("dp = %g m\n", dp);
  print_run("slope 30 deg, basal friction 15 deg", r, dp);
  std::printf("acceleration fitted over t >= %.2f s: %.4f m/s^2, rigid block g (sin a - mu_b cos a) = %.4f m/s^2, "
              "%+.2f %%; frictionless g sin a = %.4f\n",
              t0, fitted, closed, 100.0 * (fitted / closed - 1.0), g * std::sin(a));
  EXPECT_NEAR(fitted, closed, 0.05 * closed);
  EXPECT_LT(r.largest_shape_change, 0.5 * dp);
  // slide check's criterion at rest reads the slope from gravity: a flat floor under gravity tilted by 30 degrees is a
  // 30 degree slope, whose basal shear rho g h sin a = 957 Pa the yield stress holds and the friction does not.
  std::printf("slide check: %s\n", r.criterion.c_str());
  EXPECT_NEAR(r.slope_angle_deg, slope, 1e-9);
  EXPECT_NE(r.criterion.find("stands at rest"), std::string::npos);
  EXPECT_NE(r.criterion.find("slides"), std::string::npos);
}

TEST(BasalFriction, BlockSlidesAsARigidBlockWithItsFriction) { expect_rigid_block_acceleration(0.02); }

// The same at half the spacing (10 rows): the ctest label `long`.
TEST(LongBasalFriction, BlockSlidesAsARigidBlockWithItsFrictionAtHalfTheSpacing) { expect_rigid_block_acceleration(0.01); }

// mu_b = tan 40 deg > tan 30 deg: the block stays.
TEST(BasalFriction, BlockStaysWhereFrictionHoldsIt) {
  const double dp = 0.02;
  const BlockRun r = block_on_tilted_floor(30.0, "    basal_friction_angle: 40", dp, 0.5);
  print_run("slope 30 deg, basal friction 40 deg", r, dp);
  EXPECT_LT(r.largest_particle, 0.5 * dp);
  EXPECT_NE(r.criterion.find("holds"), std::string::npos) << r.criterion;
}

// Without the key the wall is no-slip: the block stays.
TEST(BasalFriction, BlockStaysOnANoSlipWall) {
  const double dp = 0.02;
  const BlockRun r = block_on_tilted_floor(30.0, "", dp, 0.5);
  print_run("slope 30 deg, no-slip", r, dp);
  EXPECT_LT(r.largest_particle, 0.5 * dp);
}

}  // namespace
}  // namespace slide::testing
