// fluid/cell_partition.hpp: recursive coordinate bisection of the neighbour grid's cells by their particles, against
// partitions worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
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
