// fluid/cell_partition.hpp: recursive coordinate bisection of the neighbour grid's cells by their particles, against
// partitions worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "fluid/cell_partition.hpp"
#include "tests/scene_runner.hpp"

namespace slide {
namespace {

TEST(CellPartition, OneProcessOwnsEveryCell) {
  const CellPartition<2> p({3, 2}, std::vector<std::int64_t>(6, 5), 1);
  EXPECT_EQ(p.owners(), std::vector<int>(6, 0));
}

// A row of 8 cells (x fastest), all the particles in the first four: two processes cut it after cell 2, where the
// weight before the cut (2 of 4 loaded cells) is half the total; empty cells weigh 1/1024 of a particle each.
TEST(CellPartition, TwoProcessesCutWhereHalfTheParticlesLie) {
  const std::vector<std::int64_t> w{10, 10, 10, 10, 0, 0, 0, 0};
  const CellPartition<2> p({8, 1}, w, 2);
  EXPECT_EQ(p.owners(), (std::vector<int>{0, 0, 1, 1, 1, 1, 1, 1}));
}

// A 4 x 2 grid, uniform: the longest axis (x, 4 cells) is cut first, then each 2 x 2 half across x again (the first of
// two equal extents), so four processes get one column each of the 2-cell-high grid.
TEST(CellPartition, FourProcessesOnAUniformGridGetEqualBlocks) {
  const CellPartition<2> p({4, 2}, std::vector<std::int64_t>(8, 3), 4);
  EXPECT_EQ(p.owners(), (std::vector<int>{0, 1, 2, 3, 0, 1, 2, 3}));
}

// Three processes: the first gets a third of the weight, the other two share the rest.
TEST(CellPartition, ThreeProcessesShareByWeightIn3D) {
  std::vector<std::int64_t> w(6 * 1 * 1, 7);  // a row of 6 along x
  const CellPartition<3> p({6, 1, 1}, w, 3);
  EXPECT_EQ(p.owners(), (std::vector<int>{0, 0, 1, 1, 2, 2}));
}

// 3 x 3 cells on 9 processes: no cut across x or y leaves 4 and 5 processes a cell each (columns of 3 cells); split
// 3 and 6 instead, every process still gets one cell.
TEST(CellPartition, AsManyProcessesAsCellsGetOneCellEach) {
  const CellPartition<2> p({3, 3}, std::vector<std::int64_t>(9, 1), 9);
  std::vector<int> owners = p.owners();
  std::sort(owners.begin(), owners.end());
  EXPECT_EQ(owners, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
}

// A 4 x 2 grid whose particles lie in its first column, 30 in the lower cell and 10 in the upper: no cut between
// columns comes near half (the first column holds all 40), so the cut falls inside it, along y: the first process
// takes the lower cell (30), the second the rest (10). Cutting between columns only, the first took all 40.
TEST(CellPartition, ACutFallsInsideASlabWhereNoneBetweenSlabsIsNearTheShare) {
  const CellPartition<2> p({4, 2}, {30, 0, 0, 0, 10, 0, 0, 0}, 2);
  EXPECT_EQ(p.owners(), (std::vector<int>{0, 1, 1, 1, 1, 1, 1, 1}));
}

// 16 and 64 processes on a loaded block of 60 x 70 cells (9-11 particles each) in a 200 x 100 grid: each of the
// log2(P) cuts on the way to a process is within 0.5 % of the weight it cuts (1 % of an even half) or within a cell
// of its share, so no share exceeds the
// mean by more than those errors compounded. Cut between slabs only (stop 56), the largest share was 6.9 % (16) and
// 13.4 % (64) above the mean on such a block.
TEST(CellPartition, ManyProcessesShareWithinEachCutsTolerance) {
  const std::array<int, 2> cells{200, 100};
  std::vector<std::int64_t> w(200 * 100, 0);
  std::uint32_t state = 1;
  for (int y = 0; y < 70; ++y)
    for (int x = 0; x < 60; ++x) {
      state = state * 1664525u + 1013904223u;  // a fixed sequence (numerical recipes' generator)
      w[static_cast<std::size_t>(y * 200 + x)] = 9 + (state >> 16) % 3;
    }
  for (const int parts : {16, 64}) {
    const std::vector<int> owner = CellPartition<2>(cells, w, parts).owners();
    std::vector<double> load(static_cast<std::size_t>(parts), 0.0);
    double total = 0.0, heaviest_cell = 0.0;
    for (std::size_t c = 0; c < owner.size(); ++c) {
      load[static_cast<std::size_t>(owner[c])] += double(w[c]);
      total += double(w[c]);
      heaviest_cell = std::max(heaviest_cell, double(w[c]));
    }
    const double levels = std::log2(double(parts)), mean = total / parts;
    EXPECT_LE(*std::max_element(load.begin(), load.end()), mean * std::pow(1.01, levels) + levels * heaviest_cell)
        << parts << " processes";
  }
}

TEST(CellPartition, MoreProcessesThanCellsAreRefused) {
  EXPECT_THROW(CellPartition<2>({2, 1}, std::vector<std::int64_t>(2, 1), 3), std::invalid_argument);
}

}  // namespace
}  // namespace slide

namespace slide {
namespace {

// A run on more processes than its neighbour grid has cells is refused before it starts (slide run exits 2 with
// this message; Simulation::check_processes).
TEST(CellPartition, ARunOnMoreProcessesThanCellsIsRefusedByName) {
  const auto scene = testing::load_shipped_scene<2>("dam_break_2d.yaml", {"end_time=0.01"});
  const Simulation<2>& sim = *scene->simulation;
  const auto cells = static_cast<int>(sim.grid().total_cells());
  EXPECT_NO_THROW(sim.check_processes(cells));
  try {
    sim.check_processes(cells + 1);
    ADD_FAILURE() << "not refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(cells + 1) + " processes for a neighbour grid of " +
                                         std::to_string(cells) + " cells"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace slide
