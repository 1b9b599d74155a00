// Planes of symmetry by mirror ghosts (fluid/ghosts.hpp, fluid/mirror_plane.hpp, walls[].symmetry), against exact
// answers: the images of a point, a vector and a corrective matrix; the images a particle gets near one and two
// planes and on one; and a quarter of a symmetric tank, with a floating box on its corner, that evolves as the whole
// tank does (the square lattice and the box's particles are mirror-symmetric about the planes, so the quarter's
// particles are the whole's at the same places).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "cases/scene.hpp"
#include "coupling/rigid_bodies.hpp"
#include "fluid/domain.hpp"
#include "fluid/ghosts.hpp"

namespace slide {
namespace {

TEST(MirrorGhosts, ImagesOfPointsVectorsAndMatrices) {
  const std::uint8_t flip_x = 1;
  const Vec<3> x(0.3, -0.2, 0.5), offset(2.0 * 0.1, 0.0, 0.0);  // across x = 0.1
  EXPECT_EQ(image_point<3>(x, flip_x, offset), Vec<3>(-0.3 + 0.2, -0.2, 0.5));
  EXPECT_EQ(image_vector<3>(Vec<3>(1.0, 2.0, 3.0), 5), Vec<3>(-1.0, 2.0, -3.0));  // across x and z
  Mat<3> m;
  m << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  Mat<3> expected;  // L(a, b) s_a s_b, s = (-1, 1, 1): the first row and column negated, their corner kept
  expected << 1, -2, -3, -4, 5, 6, -7, 8, 9;
  EXPECT_EQ(image_matrix<3>(m, flip_x), expected);
  // A reflection's image of a matrix is R L R: the same.
  const Mat<3> R = Vec<3>(-1.0, 1.0, 1.0).asDiagonal();
  EXPECT_EQ(Mat<3>(R * m * R), expected);
}

TEST(MirrorGhosts, AParticleGetsAnImageAcrossEachNearPlaneAndBoth) {
  GhostLayout layout;
  layout.mirrors = {{0, 0.0, true}, {1, 1.0, false}};  // x >= 0 and y <= 1
  const double margin = 0.1;
  Particles<3> P;
  P.add(Vec<3>(0.5, 0.5, 0.2), Kind::fluid, 0, 1000.0, 1e-3);    // far from both: none
  P.add(Vec<3>(0.05, 0.5, 0.2), Kind::fluid, 0, 1000.0, 1e-3);   // near x = 0: one
  P.add(Vec<3>(0.02, 0.97, 0.2), Kind::wall, 0, 1000.0, 1e-3);   // near both: three
  P.add(Vec<3>(0.0, 0.5, 0.2), Kind::fluid, 0, 1000.0, 1e-3);    // on x = 0: its own image, none
  P.velocity[2] = Vec<3>(1.0, 2.0, 3.0);
  P.wall_normal[2] = Vec<3>(0.6, -0.8, 0.0);
  P.pressure[2] = 7.0;
  add_ghosts(P, layout, margin);
  ASSERT_EQ(P.real_count(), 4u);
  ASSERT_EQ(P.ghost_count(), 4u);
  EXPECT_EQ(P.ghost_source, (std::vector<std::uint32_t>{1, 2, 2, 2}));
  EXPECT_EQ(P.position[4], Vec<3>(-0.05, 0.5, 0.2));
  const Vec<3> across_x(-0.02, 0.97, 0.2), across_y(0.02, -0.97 + 2.0, 0.2), across_both(-0.02, -0.97 + 2.0, 0.2);
  EXPECT_EQ(P.position[5], across_x);
  EXPECT_EQ(P.position[6], across_y);
  EXPECT_EQ(P.position[7], across_both);
  EXPECT_EQ(P.velocity[5], Vec<3>(-1.0, 2.0, 3.0));
  EXPECT_EQ(P.velocity[6], Vec<3>(1.0, -2.0, 3.0));
  EXPECT_EQ(P.velocity[7], Vec<3>(-1.0, -2.0, 3.0));
  EXPECT_EQ(P.wall_normal[7], Vec<3>(-0.6, 0.8, 0.0));
  EXPECT_EQ(P.pressure[7], 7.0);
  EXPECT_EQ(P.kind[7], Kind::wall);
  // Moving the source moves its images (the motion halo).
  P.position[2][0] = 0.03;
  P.velocity[2][1] = 5.0;
  sync_ghost_motion(P);
  EXPECT_EQ(P.position[5][0], -0.03);
  EXPECT_EQ(P.velocity[6][1], -5.0);
  // A real fluid particle beyond a plane comes back as its image; boundary particles are left where they are.
  remove_ghosts(P);
  P.position[1] = Vec<3>(-0.01, 0.5, 0.2);
  P.velocity[1] = Vec<3>(-2.0, 1.0, 0.0);
  reflect_into_mirrors(P, layout.mirrors);
  EXPECT_EQ(P.position[1], Vec<3>(0.01, 0.5, 0.2));
  EXPECT_EQ(P.velocity[1], Vec<3>(2.0, 1.0, 0.0));
}

// A particle on a plane stays on it (fluid/ghosts.hpp, hold_on_planes, through the motion halo): one a rounding off
// the second plane of an axis is put back on it with no velocity or acceleration across it, and gets no image there at
// the next rebuild; one a millionth of a spacing off is left alone and gets its image; boundary particles are left.
TEST(MirrorGhosts, AParticleOnAPlaneIsHeldOnIt) {
  Domain<3> domain;
  auto& P = domain.particles;
  const double at = 0.0555590368188870, margin = 0.024;  // x <= 7 fcc plane spacings at dp 0.01
  GhostLayout layout;
  layout.mirrors = {{0, 0.0, true}, {0, at, false}};
  domain.set_ghost_layout(layout);
  P.add(Vec<3>(at - 1e-13, 0.02, 0.1), Kind::fluid, 0, 1000.0, 1e-3);  // on it to rounding
  P.add(Vec<3>(at - 1e-8, 0.03, 0.1), Kind::fluid, 0, 1000.0, 1e-3);   // a millionth of dp off: near it
  P.add(Vec<3>(at + 1e-13, 0.04, 0.1), Kind::wall, 0, 1000.0, 0.0);    // a boundary particle: left where it is
  P.add(Vec<3>(0.03, 0.05, 0.1), Kind::fluid, 0, 1000.0, 1e-3);        // far from both: none
  for (std::size_t i = 0; i < 4; ++i) {
    P.velocity[i] = Vec<3>(1e-9, 0.1, 0.2);
    P.acceleration[i] = Vec<3>(2e-9, 0.3, 0.4);
  }
  ASSERT_TRUE(domain.make_ghosts(margin));
  EXPECT_EQ(P.ghost_source, (std::vector<std::uint32_t>{1}));  // the first gets none: it is its own image
  domain.refresh({HaloField::motion});
  EXPECT_EQ(P.position[0], Vec<3>(at, 0.02, 0.1));
  EXPECT_EQ(P.velocity[0], Vec<3>(0.0, 0.1, 0.2));
  EXPECT_EQ(P.acceleration[0], Vec<3>(0.0, 0.3, 0.4));
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(P.velocity[i], Vec<3>(1e-9, 0.1, 0.2)) << i;
    EXPECT_EQ(P.acceleration[i], Vec<3>(2e-9, 0.3, 0.4)) << i;
  }
  EXPECT_EQ(P.position[1][0], at - 1e-8);
  EXPECT_EQ(P.position[2][0], at + 1e-13);
  EXPECT_EQ(P.position[4], Vec<3>(-(at - 1e-8) + 2.0 * at, 0.03, 0.1));  // the ghost follows its source
  // Without the hold, a rounding drift of 7e-11 m (measured over 6 s of settling) took such a particle past the
  // on-plane tolerance (2.4e-11 m here) and gave it an image 1.4e-10 m away: held, it gets none.
  P.position[0][0] = at - 7e-12;
  domain.refresh({HaloField::motion});
  domain.drop_ghosts();
  ASSERT_TRUE(domain.make_ghosts(margin));
  EXPECT_EQ(P.ghost_source, (std::vector<std::uint32_t>{1}));
}

// A tank [-W, W]^2 x H whole, and its quarter [0, W]^2 with the sides x = 0 and y = 0 as planes of symmetry; water on
// the square lattice to 0.05 m and, when asked, a floating box on the axis (density 500, free to heave only).
// On the fcc lattice both are moved by c = s/2 across x and y (s its plane spacing), where the unmoved lattice has a
// plane: the whole tank's lattice is then mirror-symmetric about x = c and y = c, and the quarter's meets its planes
// of symmetry there without a move (cases/build_geometry_3d.cpp), so that the two hold the same particles again.
std::string tank(bool quarter, bool with_box, const std::string& lattice = "square",
                 const std::string& phase = "{name: water, density: 1000}") {
  const double c = lattice == "fcc" ? 0.5 * fcc_plane_spacing(0.01) : 0.0;
  const double lo = quarter ? c : c - 0.06, hi = c + 0.06;
  const auto v = [](double a, double b, double z) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", a, b, z); };
  std::string s = "dimension: 3\n"
                  "particle_spacing: 0.01\n"
                  "lattice: " + lattice + "\n"
                  "end_time: 0.01\n"
                  "method: {initial_state: lattice}\n"
                  "fluid:\n"
                  "  phases: [" + phase + "]\n"
                  "  regions: [{type: below_level, level: 0.05}]\n"
                  "walls: [{type: tank, min: " + v(lo, lo, 0) + ", max: " + v(hi, hi, 0.2) +
                  (quarter ? ", symmetry: [x_min, y_min]" : "") + "}]\n";
  if (with_box)
    s += "bodies: [{name: box, shape: {type: box, center: [0, 0, 0.05], size: [0.04, 0.04, 0.04]}, density: 500, "
         "locked: [x, y, rx, ry, rz]}]\n"
         "rigid: {wall_contact: false}\n";
  return s;
}

using Place = std::tuple<long, long, long>;
Place place_of(const Vec<3>& x) {
  return {std::lround(x[0] / 1e-4), std::lround(x[1] / 1e-4), std::lround(x[2] / 1e-4)};
}

// Every particle of the quarter is the whole tank's particle at its place: same kind, number density and pressure
// (to rounding: the sums run in another order), and after 300 steps of 1e-4 s (with the neighbour lists and ghosts rebuilt on the way) the same
// position and velocity.
void expect_quarter_is_the_whole(bool with_box, const std::string& lattice = "square",
                                 const std::string& phase = "{name: water, density: 1000}",
                                 const std::vector<std::string>& overrides = {}) {
  const auto whole =
      cases::build_scene<3>(cases::load_scene_text(tank(false, with_box, lattice, phase), overrides), "w");
  const auto quarter =
      cases::build_scene<3>(cases::load_scene_text(tank(true, with_box, lattice, phase), overrides), "q");
  auto& W = *whole->simulation;
  auto& Q = *quarter->simulation;
  const auto match = [&](const char* when) {
    std::map<Place, std::size_t> at;
    const auto& PW = W.particles();
    const auto& PQ = Q.particles();
    for (std::size_t i = 0; i < PW.real_count(); ++i) at[place_of(PW.position[i])] = i;
    std::size_t matched = 0;
    for (std::size_t i = 0; i < PQ.real_count(); ++i) {
      const auto it = at.find(place_of(PQ.position[i]));
      ASSERT_NE(it, at.end()) << when << ": the whole tank has no particle at " << PQ.position[i].transpose();
      const std::size_t j = it->second;
      EXPECT_EQ(PQ.kind[i], PW.kind[j]);
      EXPECT_LT((PQ.position[i] - PW.position[j]).norm(), 1e-12) << when;
      EXPECT_LT((PQ.velocity[i] - PW.velocity[j]).norm(), 1e-10) << when;
      EXPECT_NEAR(PQ.number_density[i], PW.number_density[j], 1e-10 * PW.number_density[j]) << when;
      EXPECT_NEAR(PQ.pressure[i], PW.pressure[j], 1e-6) << when;  // Pa, of about 500 Pa on the floor
      ++matched;
    }
    // The quarter holds a quarter of the whole's fluid and its share of the walls (no wall on its symmetry sides).
    EXPECT_GT(matched, PW.real_count() / 5) << when;
  };
  match("at the start");
  // The whole holds each of the quarter's fluid particles and its images: four, two on a plane (fcc), one on both.
  const double c = lattice == "fcc" ? 0.5 * fcc_plane_spacing(0.01) : 0.0;
  std::size_t quarter_fluid = 0, whole_fluid = 0;
  for (std::size_t i = 0; i < Q.particles().real_count(); ++i) {
    const Vec<3>& x = Q.particles().position[i];
    if (Q.particles().kind[i] == Kind::fluid)
      quarter_fluid += (std::abs(x[0] - c) < 1e-12 ? 1 : 2) * (std::abs(x[1] - c) < 1e-12 ? 1 : 2);
  }
  for (std::size_t i = 0; i < W.particles().real_count(); ++i) whole_fluid += W.particles().kind[i] == Kind::fluid;
  EXPECT_EQ(quarter_fluid, whole_fluid);
  // A flow towards the axis, mirror-symmetric, that moves the water across the planes' neighbourhoods (and rebuilds
  // the lists): v = -u (x, y, 0) / W.
  for (Simulation<3>* sim : {&W, &Q}) {
    auto& P = sim->particles();
    for (std::size_t i = 0; i < P.real_count(); ++i)
      if (P.kind[i] == Kind::fluid)
        P.velocity[i] = -0.3 / 0.06 * Vec<3>(P.position[i][0] - c, P.position[i][1] - c, 0.0);
    copy_to_ghosts(P, P.velocity);
  }
  const long rebuilds_before = Q.neighbor_rebuilds();
  for (int s = 0; s < 300; ++s) {
    const auto w = W.step(1e-4, TimeStepLimit::dt_max), q = Q.step(1e-4, TimeStepLimit::dt_max);
    ASSERT_FALSE(w.has_value()) << "whole, step " << s << ": " << w->reason;
    ASSERT_FALSE(q.has_value()) << "quarter, step " << s << ": " << q->reason;
  }
  EXPECT_GE(Q.neighbor_rebuilds(), rebuilds_before + 2);  // the ghosts were made afresh on the way
  match("after 300 steps");
  if (!with_box) return;
  // The quarter box has a quarter of the mass and takes a quarter of the force: it heaves as the whole one does.
  const auto qs = Q.bodies()->state(0), ws = W.bodies()->state(0);
  EXPECT_NEAR(qs.position[2], ws.position[2], 1e-12);
  EXPECT_GT(std::abs(ws.velocity[2]), 1e-4);  // it does move
  EXPECT_NEAR(4.0 * Q.bodies()->force[0].total()[2], W.bodies()->force[0].total()[2],
              1e-9 * std::abs(W.bodies()->force[0].total()[2]));
}

TEST(MirrorGhosts, AQuarterTankEvolvesAsTheWholeOne) { expect_quarter_is_the_whole(false); }
TEST(MirrorGhosts, AQuarterBoxOnTheAxisHeavesAsTheWholeOne) { expect_quarter_is_the_whole(true); }
TEST(MirrorGhosts, AQuarterTankOnTheFccLatticeEvolvesAsTheWholeOne) { expect_quarter_is_the_whole(false, "fcc"); }

// The semi-implicit viscous solve (fluid/implicit_viscosity.hpp) with mirror images: a Bingham fluid (yield stress
// 1 Pa, 10 Pa s; its regularised viscosity makes every particle an unknown of the solve), which the scene's automatic
// scheme solves implicitly, in the quarter tank evolves as in the whole one. The two solves are each its own system,
// solved here to a relative residual of 1e-13 (the default 1e-8 leaves differences of that order). With the images'
// velocities taken as their sources' (no sign) it fails. Before the images
// entered the matrix with their sign (stop 50), planes of symmetry and the implicit viscosity were refused together.
TEST(MirrorGhosts, AQuarterTankOfViscousFluidUnderTheImplicitSolveEvolvesAsTheWholeOne) {
  expect_quarter_is_the_whole(false, "fcc",
                              "{name: mud, density: 1000, rheology: {model: herschel_bulkley, yield_stress: 1, "
                              "consistency: 10, flow_index: 1}}",
                              {"method.implicit_tolerance=1e-13"});
}

}  // namespace
}  // namespace slide
