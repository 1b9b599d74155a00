// A gate (walls[].gate): a wall that holds the water while it settles and is taken away at t = 0, as a dam break's
// gate is lifted. The column settles at rest behind it, starts the run with no gate particle left and ids that are
// still creation ranks, and then collapses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "coupling/advance.hpp"
#include "coupling/relaxation.hpp"
#include "fluid/state_stream.hpp"
#include "fluid/lattice.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

// A 0.1 m x 0.2 m column in a 0.5 m tank, held by a gate at x = 0.1 while it settles; hexagonal lattice.
// The gate is listed first, and reaches into the floor: the floor must keep every particle it would have without it.
std::string gated_column(const std::string& initial_state, bool with_gate = true) {
  return R"(particle_spacing: 0.01
end_time: 0.1
lattice: hexagonal
fluid:
  phases: [{name: water}]
  regions: [{type: rectangle, min: [0, 0], max: [0.1, 0.2]}]
walls:
)" + std::string(with_gate ? "  - {name: gate, points: [[0.1, -0.047], [0.1, 0.3]], gate: true}\n" : "") + R"(  - name: tank
    points: [[0, 0.3], [0, 0], [0.5, 0], [0.5, 0.3]]
method:
  gradient: variational
  wall_pressure: extrapolated
  initial_state: )" + initial_state + R"(
  settling_time: 0.5
)";
}

TEST(Gate, HoldsTheWaterWhileItSettlesAndIsGoneAtTheStart) {
  const auto dir = fresh_directory("gate");
  write_file(dir / "s.yaml", gated_column("settled"));
  auto scene = cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "gate");
  auto& sim = *scene->simulation;
  const auto& P = sim.particles();
  // The same scene without the gate: the tank's boundary particles are the ones left.
  write_file(dir / "no_gate.yaml", gated_column("lattice", false));  // not settled: nothing would hold it
  const auto ungated = cases::build_scene<2>(cases::load_scene(dir / "no_gate.yaml", {}), "no_gate");
  EXPECT_EQ(scene->wall_count + scene->dummy_count, ungated->wall_count + ungated->dummy_count);
  EXPECT_GT(scene->gate_particles, 0u);
  EXPECT_EQ(scene->fluid_count + scene->wall_count + scene->dummy_count, P.size());
  // No boundary particle is left on the gate's line above the floor, and the ids are 0 .. n - 1.
  std::vector<std::uint32_t> ids(P.id.begin(), P.id.end());
  std::sort(ids.begin(), ids.end());
  for (std::size_t k = 0; k < ids.size(); ++k) ASSERT_EQ(ids[k], k);
  double right_edge = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] == Kind::fluid) right_edge = std::max(right_edge, P.position[i][0]);
    else EXPECT_FALSE(P.position[i][1] > 0.0 && std::abs(P.position[i][0] - 0.1) < 0.03) << P.position[i].transpose();
  }
  // The gate held the column: its water is still behind the gate's line at t = 0 and at rest.
  EXPECT_LT(right_edge, 0.1);
  EXPECT_LT(sim.max_fluid_speed(), 0.01);
  // Released, the column collapses: its front passes x = 0.15 m within 0.1 s (the shallow-water front, 2 sqrt(g h) t,
  // would be 0.28 m beyond the gate by then; the real front starts slower).
  ASSERT_TRUE(run_scene(*scene, [](const Simulation<2>&) {}));
  double front = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::fluid) front = std::max(front, P.position[i][0]);
  EXPECT_GT(front, 0.15);
}

TEST(Gate, NeedsTheSettledStartAndNoPeriodicDomain) {
  const auto dir = fresh_directory("gate_start");
  write_file(dir / "s.yaml", gated_column("lattice"));
  CommandResult r = run_command(slide_binary() + " check " + (dir / "s.yaml").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("walls[0].gate"), std::string::npos) << r.output;
  // A period of 65 columns of the hexagonal lattice (0.698 m): a period the lattice fits (cases/build_options.cpp).
  const double period_end = -0.1 + 65.0 * nearest_spacing(LatticeKind::hexagonal, 0.01);
  write_file(dir / "p.yaml", gated_column("settled") +
                                 fmt::format("domain: {{min: [-0.1, -0.1], max: [{:.17g}, 0.5], periodic_x: true}}\n",
                                             period_end));
  r = run_command(slide_binary() + " check " + (dir / "p.yaml").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("walls[0].gate"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("periodic"), std::string::npos) << r.output;
}

// Without its gate the column flows while it settles (the default start): refused with exit 2, naming the key and
// how far the water moved, before anything is written (cases/build_initial_state.cpp: water at rest moves a few dp;
// this column about 15).
TEST(Gate, AColumnThatNothingHoldsIsNotSettled) {
  const auto dir = fresh_directory("no_gate_settled");
  write_file(dir / "s.yaml", gated_column("settled", false));
  const CommandResult r = run_command(slide_binary() + " run " + (dir / "s.yaml").string() + " --out " +
                                      (dir / "out").string() + " --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("method.initial_state"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("not at rest"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(particle "), std::string::npos) << r.output;  // which one moved the most, from where
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << r.output;  // nothing written, not even the folder
  // Refused when a check finds it (every twentieth of the 0.5 s: coupling/relaxation.hpp), not at the end: the
  // column has moved 5.2 dp, its bound, well before (at 0.15 s, measured at stop 65).
  const auto by = r.output.find("by t = ");
  ASSERT_NE(by, std::string::npos) << r.output;
  const double at = std::stod(r.output.substr(by + 7));
  EXPECT_LT(at, 0.5) << r.output;
  EXPECT_NEAR(at / 0.025, std::round(at / 0.025), 0.05) << r.output;  // at a check (printed to 3 digits)
  EXPECT_NE(r.output.find("s of its 0.5 s of settling"), std::string::npos) << r.output;
}

// Settling stops at the second check running that finds its water not at rest; a checkpoint taken between the two
// keeps the first's finding (coupling/relaxation.cpp, Settling::save_state), so that a resumed run refuses where the
// straight one does. The ungated column (checks every 0.025 s of its 0.5 s) is first found at 0.15 s (test above).
TEST(Gate, TheFirstFindingOfWaterNotAtRestIsKeptInTheSettlingsState) {
  const auto dir = fresh_directory("settling_finding");
  write_file(dir / "s.yaml", gated_column("settled", false));
  struct StopAt : StepObserver<2> {
    double time;
    explicit StopAt(double t) : time(t) {}
    bool before_step(const Simulation<2>& sim) override { return sim.time() < time; }
  };
  const auto finding_at = [&](double stop) {
    auto scene = cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "column", dir,
                                       cases::StartOfRun::left_to_caller);
    Settling<2> settling(*scene->simulation, *scene->pending_settling);
    StopAt at(stop);
    EXPECT_EQ(settling.advance({&at}).outcome, AdvanceResult::Outcome::stopped);
    StateWriter out;
    settling.save_state(out);
    // Read back into another settling, written again: the same bytes.
    Settling<2> other(*scene->simulation, *scene->pending_settling);
    StateReader in(out.bytes());
    other.restore_state(in);
    StateWriter again;
    other.save_state(again);
    EXPECT_EQ(again.bytes(), out.bytes());
    return out.bytes().back();
  };
  EXPECT_EQ(finding_at(0.14), 0);  // checked at 0.025 ... 0.125 s: at rest so far
  EXPECT_EQ(finding_at(0.16), 1);  // found at 0.15 s, refused at 0.175 s
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace slide::testing
