// The one CSV reader (cases/csv_table.hpp).
#include <gtest/gtest.h>

#include "cases/csv_table.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

TEST(CsvTable, SkipsCommentsKeepsEmptyCellsAndLineNumbers) {
  const auto dir = fresh_directory("csv_table");
  write_file(dir / "t.csv", "# units\ntime,x,note\n\n0,1.5,\n# more\n1,2.5,moved\n");
  const CsvTable t = read_csv(dir / "t.csv");
  EXPECT_EQ(t.header, (std::vector<std::string>{"time", "x", "note"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"0", "1.5", ""}));  // a last, empty cell is a cell
  EXPECT_EQ(t.line_numbers, (std::vector<long>{4, 6}));
  EXPECT_EQ(t.numbers("x"), (std::vector<double>{1.5, 2.5}));
  EXPECT_EQ(t.find_column("y"), -1);
  EXPECT_THROW(t.column("y"), std::out_of_range);
  EXPECT_THROW(t.numbers("note"), std::invalid_argument);
  EXPECT_THROW(read_csv(dir / "missing.csv"), std::runtime_error);
}

}  // namespace
}  // namespace slide::testing
