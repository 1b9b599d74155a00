// 3-D scenes (dimension: 3): what they build, counted by hand, and what they refuse, naming the key.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>
#include <tuple>

#include <string>

#include "cases/scene.hpp"
#include "coupling/rigid_bodies.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/mesh_files.hpp"

namespace slide::cases {
namespace {

std::string tank_scene(const std::string& lattice, const std::string& extra = "") {
  return "dimension: 3\n"
         "particle_spacing: 0.01\n"
         "lattice: " + lattice + "\n"
         "end_time: 0.01\n"
         "method: {initial_state: lattice}\n"
         "fluid:\n"
         "  phases: [{name: water, density: 1000}]\n"
         "  regions: [{type: below_level, level: 0.1}]\n"
         "walls: [{type: tank, min: [0, 0, 0], max: [0.1, 0.1, 0.2]}]\n"
         "gauges: [{name: centre, x: 0.05, y: 0.05}]\n" + extra;
}

std::string refusal_key(const std::string& text) {
  try {
    const YAML::Node r = load_scene_text(text, {});
    build_scene<3>(r, "s");
  } catch (const SceneError& e) {
    return e.key_path;
  }
  return "(accepted)";
}

// The cubic lattice: 10 x 10 cells across, 10 below the level; walls of 3 layers (re = 2.1 dp) around them.
TEST(Scene3D, CubicTankBuildsItsWaterAndWallsAsCountedByHand) {
  const auto scene = build_scene<3>(load_scene_text(tank_scene("square"), {}), "s");
  EXPECT_EQ(scene->fluid_count, 1000u);
  EXPECT_EQ(scene->wall_count + scene->dummy_count, std::size_t(16 * 16 * 3 + (16 * 16 - 10 * 10) * 20));
  ASSERT_EQ(scene->gauges.size(), 1u);
  EXPECT_EQ(scene->gauges[0].y, 0.05);
  EXPECT_EQ(scene->simulation->options.gravity, Vec<3>(0, 0, -9.81));  // the 3-D default: along -z
  EXPECT_EQ(scene->resolved["lattice"].as<std::string>(), "square");
}

// Two tanks one wall apart, [0, 0.1] and [0.13, 0.23] along x: the first's wall at x max and the second's at x min are
// one wall, x in [0.1, 0.13], 3 columns, where the second tank's points are the first's (cases/build_geometry_3d.cpp
// WallPlaces): 3 x 16 x (3 + 20), 1,104, made once. Each tank alone makes 3,888.
TEST(Scene3D, TanksThatMeetMakeEachWallPointOnce) {
  const std::string two_tanks = "walls: [{type: tank, min: [0, 0, 0], max: [0.1, 0.1, 0.2]},\n"
                                "        {type: tank, min: [0.13, 0, 0], max: [0.23, 0.1, 0.2]}]\n";
  std::string text = tank_scene("square");
  text.replace(text.find("walls:"), text.find("gauges:") - text.find("walls:"), two_tanks);
  const auto scene = build_scene<3>(load_scene_text(text, {}), "s");
  EXPECT_EQ(scene->wall_count + scene->dummy_count, std::size_t(2 * 3888 - 1104));
  EXPECT_EQ(scene->fluid_count, 2000u);
  const auto& P = scene->simulation->particles();
  std::set<std::tuple<long, long, long>> places;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    const Vec<3> q = P.position[i] / 0.01;
    EXPECT_TRUE(places.insert({std::lround(q[0] - 0.5), std::lround(q[1] - 0.5), std::lround(q[2] - 0.5)}).second)
        << "two particles at " << P.position[i].transpose();
  }
}

// The fcc lattice: the points s (i + 1/2, j + 1/2, k + 1/2), s = 0.7937 dp, i + j + k even, strictly inside the tank
// and below the level: i, j, k from 0 to 12 (12.5 s = 0.0992 m), half of the 13^3 (the even ones: (13^3 + 1) / 2).
TEST(Scene3D, FccTankHoldsTheLatticePointsInsideIt) {
  const auto scene = build_scene<3>(load_scene_text(tank_scene("fcc"), {}), "s");
  EXPECT_EQ(scene->fluid_count, std::size_t((13 * 13 * 13 + 1) / 2));
  // No water point within half a nearest spacing of a wall point: the lattice runs on through the walls.
  const auto& P = scene->simulation->particles();
  double closest = 1e9;
  for (std::size_t i = 0; i < P.size(); ++i)
    for (std::size_t j = 0; j < P.size(); ++j)
      if (P.kind[i] == Kind::fluid && P.kind[j] != Kind::fluid) closest = std::min(closest, (P.position[i] - P.position[j]).norm());
  EXPECT_NEAR(closest, nearest_spacing(LatticeKind::fcc, 0.01), 1e-12);
}

// Planes of symmetry on the fcc lattice pass through one of its planes (cases/build_geometry_3d.cpp): the lattice is
// moved by s/2 across x and y to put one on x = 0 and on y = 0 (the tank's corner at the origin lies midway between
// two), its points there are the water's and the walls' (their own images), and the particles with their mirror
// images are one fcc lattice, each site once: no stacking fault (images 0.794 dp across from their sources).
TEST(Scene3D, FccLatticeMeetsItsPlanesOfSymmetryThroughOneOfItsPlanes) {
  const std::string text = tank_scene("fcc");
  const std::string quarter = std::regex_replace(text, std::regex("max: \\[0.1, 0.1, 0.2\\]\\}"),
                                                 "max: [0.1, 0.1, 0.2], symmetry: [x_min, y_min]}");
  ASSERT_NE(quarter, text);
  const auto scene = build_scene<3>(load_scene_text(quarter, {}), "s");
  const double dp = 0.01, s = fcc_plane_spacing(dp);
  EXPECT_NEAR(scene->lattice_offset[0], 0.5 * s, 1e-15);
  EXPECT_NEAR(scene->lattice_offset[1], 0.5 * s, 1e-15);
  EXPECT_EQ(scene->lattice_offset[2], 0.0);
  // Water at x = m s and y = n s, m, n = 0..12 (13 s > 0.1 m), z = (k + 1/2) s, k = 0..12, m + n + k even.
  EXPECT_EQ(scene->fluid_count, std::size_t((13 * 13 * 13 + 1) / 2));
  const auto& P = scene->simulation->particles();
  std::vector<Vec<3>> sites;
  std::size_t water_on_a_plane = 0, walls_on_a_plane = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    const Vec<3>& x = P.position[i];
    ASSERT_GE(x[0], -1e-12);
    ASSERT_GE(x[1], -1e-12);
    const bool on = std::abs(x[0]) < 1e-12 || std::abs(x[1]) < 1e-12;
    (P.kind[i] == Kind::fluid ? water_on_a_plane : walls_on_a_plane) += on;
    for (int flip = 0; flip < 4; ++flip) {  // the particle and its images across x = 0, y = 0 and both
      const Vec<3> y((flip & 1) ? -x[0] : x[0], (flip & 2) ? -x[1] : x[1], x[2]);
      if (((flip & 1) && std::abs(x[0]) < 1e-12) || ((flip & 2) && std::abs(x[1]) < 1e-12)) continue;  // itself
      sites.push_back(y);
    }
  }
  // On x = 0: n + k even, 85 of 13 x 13; on y = 0 as many; on their line, k even: 7.
  EXPECT_EQ(water_on_a_plane, std::size_t(85 + 85 - 7));
  EXPECT_GT(walls_on_a_plane, 0u);
  // Every site on the lattice moved by (s/2, s/2, 0) (mirror images too), and none twice.
  std::set<std::tuple<long, long, long>> seen;
  for (const Vec<3>& y : sites) {
    const Vec<3> q = (y - scene->lattice_offset) / s - Vec<3>::Constant(0.5);
    const long i = std::lround(q[0]), j = std::lround(q[1]), k = std::lround(q[2]);
    ASSERT_NEAR((q - Vec<3>(i, j, k)).norm(), 0.0, 1e-9) << y.transpose();
    ASSERT_EQ(((i + j + k) % 2 + 2) % 2, 0) << "off the fcc lattice: " << y.transpose();
    EXPECT_TRUE(seen.insert({i, j, k}).second) << "a site twice: " << y.transpose();
  }
}

// Two planes of symmetry across one axis on the fcc lattice must both pass through its planes: 0.1 m apart is 12.6
// plane spacings, refused naming the second, as is 12 spacings missed by 7e-7 dp (a point within 1e-9 dp of a plane
// is on it); 12 spacings apart is taken.
TEST(Scene3D, RefusesFccPlanesOfSymmetryNotWholePlaneSpacingsApart) {
  const auto with = [](const std::string& max_x) {
    return std::regex_replace(tank_scene("fcc"), std::regex("max: \\[0.1, 0.1, 0.2\\]\\}"),
                              "max: [" + max_x + ", 0.1, 0.2], symmetry: [x_min, x_max]}");
  };
  EXPECT_EQ(refusal_key(with("0.1")), "walls[0].symmetry[1]");
  EXPECT_EQ(refusal_key(with("0.09524407")), "walls[0].symmetry[1]");  // 12 s = 0.0952440631 m: 7e-7 dp off
  EXPECT_EQ(refusal_key(with(fmt::format("{:.17g}", 12 * fcc_plane_spacing(0.01)))), "(accepted)");
}

// Two planes of symmetry across one axis closer than two neighbour-search radii (the images of one side's particles
// would reach the other's) are refused before anything is made, naming the second plane and the spacing that fits
// (before, the solver refused it after the particles were made, naming domain.periodic_x).
TEST(Scene3D, RefusesPlanesOfSymmetryCloserThanTwoSearchRadii) {
  const auto with = [](const std::string& max_y) {
    return std::regex_replace(tank_scene("square"), std::regex("max: \\[0.1, 0.1, 0.2\\]\\}"),
                              "max: [0.1, " + max_y + ", 0.2], symmetry: [y_min, y_max]}");
  };
  try {
    build_scene<3>(load_scene_text(with("0.03"), {}), "s");
    ADD_FAILURE() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key_path, "walls[0].symmetry[1]");
    EXPECT_NE(std::string(e.what()).find("particle_spacing"), std::string::npos) << e.what();
  }
  EXPECT_EQ(refusal_key(with("0.1")), "(accepted)");
}

TEST(Scene3D, RefusesWhatIsNot3DNamingTheKey) {
  EXPECT_EQ(refusal_key(tank_scene("square", "gravity: [0, -9.81]\n")), "gravity");
  EXPECT_EQ(refusal_key(tank_scene("hexagonal")), "lattice");
  std::string mirror = tank_scene("square");
  mirror.replace(mirror.find("method: {initial_state: lattice}"), 32, "method: {initial_state: lattice, wall_pressure: mirror}");
  EXPECT_EQ(refusal_key(mirror), "method.wall_pressure");
  EXPECT_EQ(refusal_key(tank_scene("square") + "profiles: {times: [0.1], x_min: 0, x_max: 0.1}\n"), "profiles.x_min");
  std::string four = tank_scene("square");
  four.replace(four.find("dimension: 3"), 12, "dimension: 4");
  EXPECT_EQ(refusal_key(four), "dimension");
  // A 2-D scene given to the 3-D builder.
  try {
    build_scene<2>(load_scene_text(tank_scene("square"), {}), "s");
    ADD_FAILURE() << "a 3-D scene built as 2-D";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key_path, "dimension");
  }
}

// A box body: its boundary particles are its surface layers on a grid of the spacing (4 x 4 x 2 cells of dp, all
// within the 3 layers: 32), and the water keeps clear of it (none inside it or within dp/2 of its surface).
TEST(Scene3D, BoxBodyHasItsLayersAndTheWaterKeepsClearOfIt) {
  const std::string body = "bodies: [{name: box, shape: {type: box, center: [0.05, 0.05, 0.05], size: [0.04, 0.04, "
                           "0.02]}, density: 600}]\n";
  const auto scene = build_scene<3>(load_scene_text(tank_scene("square", body), {}), "s");
  ASSERT_EQ(scene->bodies.size(), 1u);
  const auto& rep = scene->bodies[0];
  EXPECT_EQ(rep.particles, 32u);
  EXPECT_NEAR(rep.mass, 600.0 * 0.04 * 0.04 * 0.02, 1e-15);
  EXPECT_NEAR(rep.area, 0.04 * 0.04 * 0.02, 1e-18);
  EXPECT_NEAR(rep.buoyancy_ratio, 1000.0 / 600.0, 1e-9);  // wholly below the level
  const auto& P = scene->simulation->particles();
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    const Vec<3> d = (P.position[i] - Vec<3>(0.05, 0.05, 0.05)).cwiseAbs() - Vec<3>(0.02, 0.02, 0.01);
    EXPECT_GE(d.maxCoeff(), 0.5 * 0.01 - 1e-12) << "water at " << P.position[i].transpose();
  }
  ASSERT_TRUE(scene->simulation->bodies());
  EXPECT_EQ(scene->simulation->bodies()->size(), 1u);
}

// A deformable slide (the same body, model herschel_bulkley): its particles are the lattice points inside the box
// (4 x 4 x 2 cell centres on the cubic lattice), of its own phase named after it; the water fills the rest of the
// tank on the same lattice, with no gap and none inside it; the report has the volume and mass in 3-D units. One key
// switches it back to a rigid body. A box region that reaches into it is refused naming the region.
TEST(Scene3D, DeformableSlideFillsItsShapeAndOneKeyMakesItRigid) {
  const std::string body = "bodies: [{name: sand, model: herschel_bulkley, shape: {type: box, center: [0.05, 0.05, "
                           "0.02], size: [0.04, 0.04, 0.02]}, density: 1800, rheology: {yield_stress: 50}}]\n";
  const auto scene = build_scene<3>(load_scene_text(tank_scene("square", body), {}), "s");
  ASSERT_EQ(scene->slides.size(), 1u);
  const auto& rep = scene->slides[0];
  EXPECT_EQ(rep.particles, 32u);
  EXPECT_NEAR(rep.volume, 0.04 * 0.04 * 0.02, 1e-18);
  EXPECT_NEAR(rep.mass_particles, 32 * 1800.0 * 1e-6, 1e-12);
  EXPECT_TRUE(scene->bodies.empty());
  EXPECT_FALSE(scene->simulation->bodies());
  const auto& P = scene->simulation->particles();
  std::size_t sand = 0, water = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    const Vec<3> d = (P.position[i] - Vec<3>(0.05, 0.05, 0.02)).cwiseAbs() - Vec<3>(0.02, 0.02, 0.01);
    if (P.phase[i] == rep.phase) {
      ++sand;
      EXPECT_LT(d.maxCoeff(), 0.0);
    } else {
      ++water;
      EXPECT_GT(d.maxCoeff(), 0.0) << "water at " << P.position[i].transpose();
    }
  }
  EXPECT_EQ(sand, 32u);
  EXPECT_EQ(water, 1000u - 32u);  // 10 x 10 x 10 cells below the level, less the slide's
  const auto rigid = build_scene<3>(load_scene_text(tank_scene("square", body), {"bodies[0].model=rigid"}), "r");
  EXPECT_TRUE(rigid->slides.empty());
  EXPECT_EQ(rigid->bodies.size(), 1u);
  std::string overlap = tank_scene("square", body);
  overlap.replace(overlap.find("regions: [{type: below_level, level: 0.1}]"), 42,
                  "regions: [{type: box, min: [0, 0, 0], max: [0.1, 0.1, 0.03]}]");
  EXPECT_EQ(refusal_key(overlap), "fluid.regions[0]");
}

// A prism: a right-angled triangle (legs 0.04 m, given clockwise) in its frame's x-y plane, swept 0.04 m along the
// frame's z, turned by roll 90 degrees so that the triangle lies in the scene's x-z plane and the prism runs across y
// (a 2-D wedge extruded): in the world, x - cx >= -0.02, z - cz >= -0.02, (x - cx) + (z - cz) <= 0, |y - cy| <= 0.02.
// Its volume is half the cube's; every boundary particle lies in it; no water does.
TEST(Scene3D, PrismBodyIsItsOutlineSweptAndTurned) {
  const std::string body = "bodies: [{name: wedge, shape: {type: prism, center: [0.05, 0.05, 0.05], outline: [[-0.02, "
                           "-0.02], [-0.02, 0.02], [0.02, -0.02]], length: 0.04, angles: [90, 0, 0]}, density: 600}]\n";
  const auto scene = build_scene<3>(load_scene_text(tank_scene("square", body), {}), "s");
  ASSERT_EQ(scene->bodies.size(), 1u);
  EXPECT_NEAR(scene->bodies[0].area, 0.5 * 0.04 * 0.04 * 0.04, 1e-15);
  EXPECT_NEAR(scene->bodies[0].mass, 600.0 * 0.5 * 0.04 * 0.04 * 0.04, 1e-12);
  EXPECT_GT(scene->bodies[0].particles, 0u);
  const auto inside = [](const Vec<3>& p, double tolerance) {
    const Vec<3> q = p - Vec<3>(0.05, 0.05, 0.05);
    return q[0] >= -0.02 - tolerance && q[2] >= -0.02 - tolerance && q[0] + q[2] <= tolerance &&
           std::abs(q[1]) <= 0.02 + tolerance;
  };
  const auto& P = scene->simulation->particles();
  std::size_t body_particles = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] == Kind::fluid) {
      EXPECT_FALSE(inside(P.position[i], 0.0)) << "water at " << P.position[i].transpose();
    } else if ((P.position[i] - Vec<3>(0.05, 0.05, 0.05)).cwiseAbs().maxCoeff() < 0.03) {
      ++body_particles;
      EXPECT_TRUE(inside(P.position[i], 1e-12)) << "boundary particle at " << P.position[i].transpose();
    }
  }
  EXPECT_EQ(body_particles, scene->bodies[0].particles);
}

TEST(Scene3D, RefusesAConcavePrismNamingItsOutline) {
  const std::string body = "bodies: [{name: notch, shape: {type: prism, center: [0.05, 0.05, 0.05], outline: [[-0.02, "
                           "-0.02], [0.02, -0.02], [0.0, 0.0], [0.02, 0.02], [-0.02, 0.02]], length: 0.04}, "
                           "density: 600}]\n";
  EXPECT_EQ(refusal_key(tank_scene("square", body)), "bodies[0].shape.outline");
}

TEST(Scene3D, RefusesBadBodiesNamingTheKey) {
  const auto with = [](const std::string& fields) {
    return tank_scene("square", "bodies: [{name: box, shape: {type: box, center: [0.05, 0.05, 0.05], size: [0.04, "
                                "0.04, 0.02]}" + fields + "}]\n");
  };
  EXPECT_EQ(refusal_key(with(", density: 600, mass: 1")), "bodies[0].density");
  EXPECT_EQ(refusal_key(with("")), "bodies[0].density");
  EXPECT_EQ(refusal_key(with(", density: 600, locked: [w]")), "bodies[0].locked[0]");
  EXPECT_EQ(refusal_key(with(", density: 600, locked: [ry]")), "bodies[0].locked");
  EXPECT_EQ(refusal_key(with(", density: 600, motion: prescribed")), "bodies[0].prescribed");  // without its law
  EXPECT_EQ(refusal_key(with(", density: 600, model: deformable")), "bodies[0].model");  // not in 3-D yet
  EXPECT_EQ(refusal_key(with(", density: 600, during_settling: free")), "bodies[0].during_settling");  // no settling
  std::string outside = with(", density: 600");
  outside.replace(outside.find("center: [0.05, 0.05, 0.05]"), 26, "center: [0.09, 0.05, 0.05]");
  EXPECT_EQ(refusal_key(outside), "bodies[0].shape");
  std::string flat = with(", density: 600");
  flat.replace(flat.find("size: [0.04, 0.04, 0.02]"), 24, "size: [0.04, 0.04, 0.0]");
  EXPECT_EQ(refusal_key(flat), "bodies[0].shape.size");
}

// A sphere on the tank's corner x = y = 0, whose two sides there are planes of symmetry: the model holds a quarter of
// it (a quarter of the stated mass, a quarter of its volume), its boundary particles all on the tank's side, and the
// water keeps dp/2 clear of its surface.
std::string quarter_sphere_scene(const std::string& body_fields, const std::string& method = "wall_slip: free_slip") {
  return "dimension: 3\n"
         "particle_spacing: 0.01\n"
         "end_time: 0.01\n"
         "method: {initial_state: lattice, " + method + "}\n"
         "fluid:\n"
         "  phases: [{name: water, density: 1000}]\n"
         "  regions: [{type: below_level, level: 0.1}]\n"
         "walls: [{type: tank, min: [0, 0, 0], max: [0.15, 0.15, 0.2], symmetry: [x_min, y_min]}]\n"
         "bodies: [{name: ball, shape: {type: sphere, center: [0, 0, 0.08], radius: 0.05}" + body_fields + "}]\n";
}

TEST(Scene3D, SphereCutBySymmetryPlanesIsItsQuarter) {
  const auto scene = build_scene<3>(load_scene_text(quarter_sphere_scene(", mass: 0.2, locked: [x, y, rx, ry, rz]"), {}), "s");
  ASSERT_EQ(scene->bodies.size(), 1u);
  const auto& rep = scene->bodies[0];
  const double V = 4.0 / 3.0 * M_PI * 0.05 * 0.05 * 0.05;
  EXPECT_NEAR(rep.mass, 0.05, 1e-12);
  EXPECT_NEAR(rep.area, V / 4.0, 1e-12 * V);
  // The quarter's centre of mass: 3R/8 from each plane, at the sphere's height.
  EXPECT_NEAR(rep.placed[0], 3.0 * 0.05 / 8.0, 1e-3 * 0.05);
  EXPECT_NEAR(rep.placed[2], 0.08, 1e-12);
  EXPECT_GT(rep.particles, 100u);
  const auto& P = scene->simulation->particles();
  std::size_t body_particles = 0, on_a_plane = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    const double r = (P.position[i] - Vec<3>(0.0, 0.0, 0.08)).norm();
    if (P.kind[i] == Kind::fluid) {
      EXPECT_GE(r, 0.05 + 0.5 * 0.01 - 1e-12) << "water at " << P.position[i].transpose();
      continue;
    }
    // None beyond a symmetry side (mirror images stand there); a point on it is its own image, put exactly on it.
    EXPECT_GE(P.position[i][0], 0.0);
    EXPECT_GE(P.position[i][1], 0.0);
    if (r > 0.05) continue;  // the tank's own particles
    ++body_particles;
    on_a_plane += P.position[i][0] == 0.0 || P.position[i][1] == 0.0;
  }
  EXPECT_GE(on_a_plane, 1u);  // the Fibonacci rings' first points, at y = 0
  EXPECT_GE(body_particles, rep.particles);
}

// A cylinder body: its mass from its density and exact volume; its boundary particles inside it, the wall layer
// half a spacing in from its side, caps and rims, one a dp^2 of that layer's surface (within 5 %).
TEST(Scene3D, CylinderBodyHasItsVolumeAndItsSurfaceParticles) {
  const std::string scene_text = tank_scene("square", "bodies: [{name: drum, shape: {type: cylinder, center: [0.05, "
                                                      "0.05, 0.1], radius: 0.03, height: 0.04, angles: [90, 0, 0]}, "
                                                      "density: 600}]\n");
  const auto scene = build_scene<3>(load_scene_text(scene_text, {}), "s");
  ASSERT_EQ(scene->bodies.size(), 1u);
  const double R = 0.03, H = 0.04;
  EXPECT_NEAR(scene->bodies[0].mass, 600.0 * M_PI * R * R * H, 1e-12);
  const auto& P = scene->simulation->particles();
  std::size_t wall_layer = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    if (P.body_of(i) != 0) continue;
    const Vec<3> q = P.position[i] - Vec<3>(0.05, 0.05, 0.1);  // its axis along y (turned 90 degrees about x)
    const double d_r = std::hypot(q[0], q[2]) - R, d_y = std::abs(q[1]) - 0.5 * H;
    EXPECT_LT(std::max(d_r, d_y), 0.0);
    if (P.kind[i] != Kind::wall) continue;
    ++wall_layer;
    // Half a grid step (R / 3 or H / 4 here) in from what it faces.
    EXPECT_NEAR(std::min(std::abs(d_r), std::abs(d_y)), 0.005, 1e-12);
    // Its depth: to the side or a cap, or to the rim where it is behind both.
    const bool rim = std::abs(d_r + 0.005) < 1e-12 && std::abs(d_y + 0.005) < 1e-12;
    EXPECT_NEAR(P.wall_depth[i], rim ? 0.005 * std::sqrt(2.0) : 0.005, 1e-12);
  }
  // The wall layer's own surface: the side at R - dp / 2 over H, and the caps inside the side's ring.
  const double area = 2.0 * M_PI * (R - 0.005) * H + 2.0 * M_PI * (R - 0.01) * (R - 0.01);
  EXPECT_NEAR(double(wall_layer), area / (0.01 * 0.01), 0.05 * area / (0.01 * 0.01));
}

// A side of symmetry is free-slip by its mirror images whatever the other walls are; a body it cuts must move along it.
TEST(Scene3D, RefusesABodyThatMayLeaveItsSymmetryPlanes) {
  EXPECT_EQ(refusal_key(quarter_sphere_scene(", mass: 0.2, locked: [x, y, rx, ry, rz]", "wall_slip: no_slip")),
            "(accepted)");
  EXPECT_EQ(refusal_key(quarter_sphere_scene(", mass: 0.2, locked: [y, rx, ry, rz]")), "bodies[0].locked");
  EXPECT_EQ(refusal_key(quarter_sphere_scene(", mass: 0.2, locked: [x, y]")), "bodies[0].locked");
  // A prescribed body moves along the planes that cut it, and its keys come together.
  const std::string law = ", mass: 0.2, motion: prescribed, prescribed: {s0: 1, t0: 1, direction: ";
  EXPECT_EQ(refusal_key(quarter_sphere_scene(law + "[0, 0, -1]}")), "(accepted)");
  EXPECT_EQ(refusal_key(quarter_sphere_scene(law + "[1, 0, -1]}")), "bodies[0].prescribed.direction");
  EXPECT_EQ(refusal_key(quarter_sphere_scene(law + "[0, 0, 0]}")), "bodies[0].prescribed.direction");
  EXPECT_EQ(refusal_key(quarter_sphere_scene(law + "[0, 0, -1]}, locked: [x]")), "bodies[0].locked");
  EXPECT_EQ(refusal_key(quarter_sphere_scene(", mass: 0.2, motion: prescribed")), "bodies[0].prescribed");
  EXPECT_EQ(refusal_key(quarter_sphere_scene(", mass: 0.2, locked: [x, y, rx, ry, rz], prescribed: {s0: 1, t0: 1, "
                                             "direction: [0, 0, 1]}")),
            "bodies[0].prescribed");
  EXPECT_EQ(refusal_key(quarter_sphere_scene(", mass: 0.2, locked: [x, y, rx, ry, rz]").replace(
                quarter_sphere_scene("").find("radius: 0.05"), 12, "radius: 0.0")),
            "bodies[0].shape.radius");
}


// A box given as a mesh file (in millimetres, turned 30 degrees about z) is the same body as the box shape: the same
// mass, centre and inertia; its boundary particles lie inside it, the wall layer about half a spacing in.
TEST(Scene3D, MeshBodyIsTheBodyItsFileDescribes) {
  const auto dir = testing::fresh_directory("mesh_body");
  testing::write_stl_binary(dir / "box_mm.stl", rigid::box_surface(rigid::Vec3::Zero(), rigid::Vec3(60.0, 60.0, 40.0)));
  const std::string mesh = "bodies: [{name: b, shape: {type: mesh, file: box_mm.stl, scale: 0.001, position: [0.05, "
                           "0.05, 0.06], angles: [0, 0, 30]}, density: 600}]\n";
  const std::string box = "bodies: [{name: b, shape: {type: box, center: [0.05, 0.05, 0.06], size: [0.06, 0.06, 0.04], "
                          "angles: [0, 0, 30]}, density: 600}]\n";
  const auto from_mesh = build_scene<3>(load_scene_text(tank_scene("square", mesh), {}), "s", dir);
  const auto from_box = build_scene<3>(load_scene_text(tank_scene("square", box), {}), "s", dir);
  ASSERT_EQ(from_mesh->bodies.size(), 1u);
  EXPECT_NEAR(from_mesh->bodies[0].mass, 600.0 * 0.06 * 0.06 * 0.04, 1e-9);  // float coordinates in the file
  EXPECT_NEAR(from_mesh->bodies[0].mass, from_box->bodies[0].mass, 1e-9);
  EXPECT_NEAR(from_mesh->bodies[0].inertia, from_box->bodies[0].inertia, 1e-12);
  EXPECT_NEAR((from_mesh->bodies[0].placed - from_box->bodies[0].placed).norm(), 0.0, 1e-9);
  const auto& P = from_mesh->simulation->particles();
  const rigid::Mat3 turn(Eigen::AngleAxisd(M_PI / 6.0, Eigen::Vector3d::UnitZ()));
  std::size_t wall_layer = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    const Vec<3> q = (turn.transpose() * (P.position[i] - Vec<3>(0.05, 0.05, 0.06))).cwiseAbs() - Vec<3>(0.03, 0.03, 0.02);
    if (P.kind[i] == Kind::fluid) {
      EXPECT_GE(q.maxCoeff(), 0.5 * 0.01 - 1e-9) << "water at " << P.position[i].transpose();
      continue;
    }
    if (P.body_of(i) != 0) continue;
    EXPECT_LT(q.maxCoeff(), 0.0);
    EXPECT_NEAR(P.wall_depth[i], -q.maxCoeff(), 1e-9);  // its depth is its distance to the nearest face
    EXPECT_NEAR(P.wall_normal[i].norm(), 1.0, 1e-12);
    if (P.kind[i] != Kind::wall) continue;
    ++wall_layer;
    EXPECT_NEAR(P.wall_depth[i], 0.005, 0.0025 + 1e-9);
  }
  // Between the wall layer's own surface (the box inset by dp / 2) and the box's surface, one point per dp^2.
  const double inset = 2.0 * (0.05 * 0.05 + 2.0 * 0.05 * 0.03), outer = 2.0 * (0.06 * 0.06 + 2.0 * 0.06 * 0.04);
  EXPECT_GT(double(wall_layer), inset / 1e-4);
  EXPECT_LT(double(wall_layer), outer / 1e-4);
}

// An L-shaped prism, closed and outward but not convex: the square [0.03, 0.07]^2 less its quarter x, y > 0.05, over
// z in [0.04, 0.06].
rigid::TriangleSurface ell_prism() {
  rigid::TriangleSurface ell = rigid::prism_surface({{0, 0}, {0.04, 0}, {0.04, 0.02}, {0.02, 0.02}, {0.02, 0.04}, {0, 0.04}},
                                                    0.02, rigid::Vec3(0.03, 0.03, 0.05));
  // prism_surface fans its caps from the first corner, which is wrong for a concave outline: the L's caps by hand.
  ell.triangles.resize(0);
  const int n = 6;
  const std::array<std::array<int, 3>, 4> cap{{{0, 2, 1}, {0, 3, 2}, {0, 5, 3}, {3, 5, 4}}};
  for (const auto& t : cap) {
    ell.triangles.push_back({t[0], t[1], t[2]});
    ell.triangles.push_back({n + t[0], n + t[2], n + t[1]});
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    ell.triangles.push_back({i, j, n + j});
    ell.triangles.push_back({i, n + j, n + i});
  }
  return ell;
}

// Water inside a shape (fluid.regions[] type shape): a concave mesh holds the cell centres strictly inside it, counted
// by hand (the L's 12 cells of dp across, 2 deep: 24), none in its notch; a box given as a mesh holds the same points as
// the box region; water outside the tank or inside a slide is refused naming the region.
TEST(Scene3D, WaterRegionFillsTheInsideOfAShapeEvenAConcaveMesh) {
  const auto dir = testing::fresh_directory("water_shapes");
  testing::write_obj(dir / "ell.obj", ell_prism());
  testing::write_stl_binary(dir / "box.stl", rigid::box_surface(rigid::Vec3(0.05, 0.04, 0.033),
                                                                rigid::Vec3(0.061, 0.05, 0.043)));
  const std::string below = "regions: [{type: below_level, level: 0.1}]";
  const auto with_region = [&](const std::string& region, const std::string& extra = "") {
    std::string text = tank_scene("fcc", extra);
    return text.replace(text.find(below), below.size(), "regions: [" + region + "]");
  };
  const auto water = [&](const std::string& text) {
    const auto scene = build_scene<3>(load_scene_text(text, {}), "s", dir);
    std::vector<Vec<3>> points;
    const auto& P = scene->simulation->particles();
    for (std::size_t i = 0; i < P.real_count(); ++i)  // not the mirror images beyond a plane of symmetry
      if (P.kind[i] == Kind::fluid) points.push_back(P.position[i]);
    return points;
  };
  std::string ell_scene = tank_scene("square");
  ell_scene.replace(ell_scene.find(below), below.size(), "regions: [{type: shape, shape: {type: mesh, file: ell.obj}}]");
  const auto ell = water(ell_scene);
  EXPECT_EQ(ell.size(), 24u);
  for (const auto& p : ell) EXPECT_FALSE(p[0] > 0.05 && p[1] > 0.05) << "water in the notch at " << p.transpose();
  const auto as_mesh = water(with_region("{type: shape, shape: {type: mesh, file: box.stl}}"));
  const auto as_box = water(with_region("{type: box, min: [0.0195, 0.015, 0.0115], max: [0.0805, 0.065, 0.0545]}"));
  ASSERT_GT(as_box.size(), 100u);
  EXPECT_EQ(as_mesh, as_box);
  EXPECT_EQ(refusal_key(with_region("{type: shape, shape: {type: sphere, center: [0.09, 0.05, 0.05], radius: 0.03}}")),
            "fluid.regions[0].shape");
  // A box region is held to the tanks as a shape is (before, its water outside them was taken).
  EXPECT_EQ(refusal_key(with_region("{type: box, min: [0.02, 0.02, 0.02], max: [0.15, 0.05, 0.05]}")),
            "fluid.regions[0].max");
  // A shape a plane of symmetry cuts: its part on the scene's side, the plane's own points included (the lattice has a
  // plane there): about half the sphere's 4/3 pi r^3 / dp^3 = 113.1 points.
  std::string halved = with_region("{type: shape, shape: {type: sphere, center: [0, 0.05, 0.05], radius: 0.03}}");
  halved.replace(halved.find("max: [0.1, 0.1, 0.2]}"), 21, "max: [0.1, 0.1, 0.2], symmetry: [x_min]}");
  const auto half = water(halved);
  std::size_t on_plane = 0;
  for (const auto& p : half) {
    EXPECT_GE(p[0], -1e-12);
    on_plane += std::abs(p[0]) < 1e-12;
  }
  EXPECT_GT(on_plane, 0u);
  EXPECT_NEAR(double(half.size()) - 0.5 * double(on_plane), 0.5 * 4.0 / 3.0 * M_PI * 27.0, 6.0) << half.size();
  const std::string sand = "bodies: [{name: sand, model: herschel_bulkley, shape: {type: box, center: [0.05, 0.05, "
                           "0.02], size: [0.04, 0.04, 0.02]}, density: 1800, rheology: {yield_stress: 50}}]\n";
  EXPECT_EQ(refusal_key(with_region("{type: shape, shape: {type: sphere, center: [0.05, 0.05, 0.04], radius: 0.02}}",
                                    sand)),
            "fluid.regions[0]");
}

TEST(Scene3D, RefusesABadMeshNamingTheKeyAndTheFile) {
  const auto dir = testing::fresh_directory("mesh_refusals");
  testing::write_obj(dir / "ell.obj", ell_prism());
  rigid::TriangleSurface open_box = rigid::box_surface(rigid::Vec3(0.05, 0.05, 0.05), rigid::Vec3::Constant(0.02));
  open_box.triangles.pop_back();
  testing::write_obj(dir / "open.obj", open_box);
  const auto message = [&](const std::string& file) {
    try {
      build_scene<3>(load_scene_text(tank_scene("square", "bodies: [{name: b, shape: {type: mesh, file: " + file +
                                                                "}, density: 600}]\n"), {}), "s", dir);
    } catch (const SceneError& e) {
      return e.key_path + ": " + e.what();
    }
    return std::string("(accepted)");
  };
  // A concave body is taken as its convex pieces (SolidBody.ConcaveBodyCollidesAsItsConvexPieces)...
  EXPECT_EQ(message("ell.obj"), "(accepted)");
  const auto ell = build_scene<3>(load_scene_text(tank_scene("square", "bodies: [{name: b, shape: {type: mesh, file: "
                                                                       "ell.obj}, density: 600}]\n"), {}), "s", dir);
  EXPECT_NEAR(ell->bodies[0].mass, 600.0 * (0.04 * 0.04 - 0.02 * 0.02) * 0.02, 1e-12);
  // ... but not yet one that a plane of symmetry cuts.
  std::string cut = tank_scene("square", "bodies: [{name: b, shape: {type: mesh, file: ell.obj}, density: 600}]\n");
  cut.replace(cut.find("min: [0, 0, 0]"), 14, "min: [0.05, 0, 0], symmetry: [x_min]");
  cut.replace(cut.find("regions: [{type: below_level, level: 0.1}]"), 42,
              "regions: [{type: box, min: [0.05, 0, 0], max: [0.1, 0.1, 0.02]}]");
  try {
    build_scene<3>(load_scene_text(cut, {}), "s", dir);
    ADD_FAILURE() << "a concave body cut by a plane of symmetry was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key_path, "bodies[0].shape");
    EXPECT_NE(std::string(e.what()).find("concave"), std::string::npos) << e.what();
  }
  EXPECT_NE(message("open.obj").find("open.obj: it is not closed"), std::string::npos) << message("open.obj");
  EXPECT_NE(message("none.stl").find("none.stl: no such file"), std::string::npos) << message("none.stl");
}

}  // namespace
}  // namespace slide::cases
