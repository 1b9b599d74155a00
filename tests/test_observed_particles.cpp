// Which particles the observers' copy of a run on several processes takes in (cases/observed_particles.hpp): those a
// gauge or profile reaches, directly or through a periodic or mirror image; the fluid of a slide's phase; all the fluid
// for the 2-D flume's diagnostics; a rigid body's wall particles for 3-D outlines. Exact answers on placed particles.
#include <gtest/gtest.h>

#include "cases/observed_particles.hpp"

namespace slide {
namespace {

template <int D>
std::size_t add(Particles<D>& P, const Vec<D>& x, Kind kind = Kind::fluid, std::uint8_t phase = 0) {
  return P.add(x, kind, phase, 1000.0, 1e-3);
}

TEST(ObservedParticles, AGaugeReadsTheFluidWithinReachAndAcrossThePeriod) {
  cases::Scene<2> scene;
  scene.gauges.push_back({"g", 0.02, 0.0});
  GhostLayout images;
  images.period = PeriodicX{0.0, 1.0};
  const cases::ObservedParticles<2> observed(scene, images, 0.1);
  Particles<2> P;
  add(P, Vec<2>(0.11, 0.5));               // 0 : 0.09 from the gauge
  add(P, Vec<2>(0.13, 0.5));               // 1 : 0.11
  add(P, Vec<2>(0.95, 0.5));               // 2 : its image at -0.05 lies 0.07 from it
  add(P, Vec<2>(0.85, 0.5));               // 3 : its image 0.17
  add(P, Vec<2>(0.02, 0.3), Kind::wall);   // 4 : a wall particle under the gauge
  add(P, Vec<2>(0.02, 0.3), Kind::dummy);  // 5
  EXPECT_TRUE(observed(P, 0));
  EXPECT_FALSE(observed(P, 1));
  EXPECT_TRUE(observed(P, 2));
  EXPECT_FALSE(observed(P, 3));
  EXPECT_FALSE(observed(P, 4));
  EXPECT_FALSE(observed(P, 5));
  // Without the period, the far end's particle is not read.
  const cases::ObservedParticles<2> closed(scene, GhostLayout{}, 0.1);
  EXPECT_FALSE(closed(P, 2));
  EXPECT_TRUE(closed(P, 0));
}

TEST(ObservedParticles, A3dGaugeReadsAcrossAPlaneOfSymmetryAndAProfileAlongItsSegment) {
  cases::Scene<3> scene;
  scene.gauges.push_back({"g", 0.5, -0.06});
  GhostLayout images;
  images.mirrors.push_back(MirrorPlane{1, 0.0, true});
  const cases::ObservedParticles<3> observed(scene, images, 0.1);
  Particles<3> P;
  add(P, Vec<3>(0.5, 0.05, 0.2));   // 0 : 0.11 from the gauge; its mirror image (y = -0.05) 0.01
  add(P, Vec<3>(0.5, 0.2, 0.2));    // 1 : image 0.14 away
  add(P, Vec<3>(0.56, 0.025, 0.9));  // 2 : 0.104 away; its image 0.070
  EXPECT_TRUE(observed(P, 0));
  EXPECT_FALSE(observed(P, 1));
  EXPECT_TRUE(observed(P, 2));
  EXPECT_FALSE(cases::ObservedParticles<3>(scene, GhostLayout{}, 0.1)(P, 0));

  cases::Scene<3> profiled;
  profiled.profiles.times = {1.0};
  profiled.profiles.from = {0.0, 0.0};
  profiled.profiles.to = {1.0, 0.0};
  const cases::ObservedParticles<3> along(profiled, GhostLayout{}, 0.1);
  Particles<3> Q;
  add(Q, Vec<3>(0.5, 0.09, 0.0));   // 0 : beside the segment
  add(Q, Vec<3>(0.5, 0.11, 0.0));   // 1
  add(Q, Vec<3>(1.05, 0.05, 0.0));  // 2 : beyond its end, 0.071 from it
  add(Q, Vec<3>(1.08, 0.07, 0.0));  // 3 : 0.106 from its end
  EXPECT_TRUE(along(Q, 0));
  EXPECT_FALSE(along(Q, 1));
  EXPECT_TRUE(along(Q, 2));
  EXPECT_FALSE(along(Q, 3));
}

TEST(ObservedParticles, SlidesTheirPhaseAndTheFlumesDiagnosticsAllTheFluid) {
  Particles<2> P;
  add(P, Vec<2>(5.0, 0.0), Kind::fluid, 0);  // 0 : water far from everything
  add(P, Vec<2>(5.0, 0.0), Kind::fluid, 1);  // 1 : sediment
  add(P, Vec<2>(5.0, 0.0), Kind::wall, 1);   // 2 : a wall particle of phase 1 (walls are not the slide)
  cases::Scene<2> slide;
  slide.slides.push_back({});
  slide.slides.back().phase = 1;
  const cases::ObservedParticles<2> of_slide(slide, GhostLayout{}, 0.1);
  EXPECT_FALSE(of_slide(P, 0));
  EXPECT_TRUE(of_slide(P, 1));
  EXPECT_FALSE(of_slide(P, 2));
  cases::Scene<2> flume;
  flume.surge_front.enabled = true;
  const cases::ObservedParticles<2> of_flume(flume, GhostLayout{}, 0.1);
  EXPECT_TRUE(of_flume(P, 0));
  EXPECT_TRUE(of_flume(P, 1));
  EXPECT_FALSE(of_flume(P, 2));
  EXPECT_FALSE(cases::ObservedParticles<2>(cases::Scene<2>{}, GhostLayout{}, 0.1)(P, 1));
}

TEST(ObservedParticles, ThreeDOutlinesReadTheRigidBodiesWallParticles) {
  Particles<3> P;
  add(P, Vec<3>(0.0, 0.0, 0.0), Kind::wall);  // 0 : a tank's
  const std::size_t b = add(P, Vec<3>(0.0, 0.0, 0.0), Kind::wall);
  P.attach_to_body(b, 0, Vec<3>::Zero(), Vec<3>::UnitZ());
  cases::Scene<3> scene;
  scene.slide_outline_times = {0.5};
  const cases::ObservedParticles<3> observed(scene, GhostLayout{}, 0.1);
  EXPECT_FALSE(observed(P, 0));
  EXPECT_TRUE(observed(P, 1));
  scene.slide_outline_times.clear();
  EXPECT_FALSE(cases::ObservedParticles<3>(scene, GhostLayout{}, 0.1)(P, 1));
}

}  // namespace
}  // namespace slide
