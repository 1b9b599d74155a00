// The option name tables: every value has one name, every name reads back as its value, and the scene schema offers
// exactly the table's names (one table per option serves the schema, the parser and to_string).
#include <gtest/gtest.h>

#include <set>

#include "cases/body_choices.hpp"
#include "cases/body_model.hpp"
#include "cases/initial_state.hpp"
#include "cases/rheology_keys.hpp"
#include "cases/scene.hpp"
#include "cases/wall_side.hpp"
#include "coupling/rigid_bodies.hpp"
#include "fluid/fluid_options.hpp"

namespace slide {
namespace {

template <class Table>
void expect_round_trip(const Table& table) {
  std::set<std::string> seen;
  for (const auto& [value, name] : table.entries) {
    EXPECT_TRUE(seen.insert(std::string(name)).second) << "duplicate name " << name;
    ASSERT_TRUE(table.find(name).has_value()) << name;
    EXPECT_TRUE(*table.find(name) == value) << name;
    EXPECT_EQ(table.name(value), name);
  }
  EXPECT_FALSE(table.find("no_such_option").has_value());
  EXPECT_THROW(table.parse("no_such_option"), std::logic_error);
}

TEST(NameTable, EveryOptionReadsBackAsItself) {
  expect_round_trip(gradient_model_names);
  expect_round_trip(lattice_kind_names);
  expect_round_trip(wall_slip_names);
  expect_round_trip(wall_pressure_names);
  expect_round_trip(time_step_limit_names);
  expect_round_trip(cases::initial_state_names);
  expect_round_trip(BodyMotion::mode_names);
  expect_round_trip(viscous_scheme_names);
  expect_round_trip(cases::rheology_model_names);
  expect_round_trip(cases::regularisation_names);
  expect_round_trip(cases::body_model_names);
  expect_round_trip(cases::during_settling_names);
  expect_round_trip(cases::prescribed_law_names);
  expect_round_trip(cases::locked_component_names);
  expect_round_trip(cases::fluid_side_names);
}

// The reference document lists a choice's names as "one of: a, b, ...": each table's names appear there, in order.
TEST(NameTable, SchemaOffersTheTablesNames) {
  const std::string doc = cases::scene_reference();  // the 2-D and the 3-D scenes' tables
  auto listed = [&](const std::vector<std::string>& names) {
    std::string joined = "one of: ";
    for (std::size_t k = 0; k < names.size(); ++k) joined += (k ? ", " : "") + names[k];
    return doc.find(joined + " |") != std::string::npos;
  };
  EXPECT_TRUE(listed(gradient_model_names.names()));
  // Each dimension offers its own lattices: square and its close packing (hexagonal in 2-D, fcc in 3-D).
  const auto lattice = [](LatticeKind k) { return std::string(to_string(k)); };
  EXPECT_TRUE(listed({lattice(LatticeKind::square), lattice(LatticeKind::hexagonal)}));
  EXPECT_TRUE(listed({lattice(LatticeKind::square), lattice(LatticeKind::fcc)}));
  EXPECT_EQ(lattice_kind_names.names().size(), 3u);
  EXPECT_TRUE(listed(wall_slip_names.names()));
  EXPECT_TRUE(listed(wall_pressure_names.names()));
  EXPECT_TRUE(listed(cases::initial_state_names.names()));
  EXPECT_TRUE(listed(BodyMotion::mode_names.names()));
  EXPECT_TRUE(listed(cases::body_model_names.names()));
  EXPECT_TRUE(listed(cases::during_settling_names.names()));
  EXPECT_TRUE(listed(cases::prescribed_law_names.names()));
  EXPECT_TRUE(listed(cases::locked_component_names.names()));
  EXPECT_TRUE(listed(cases::fluid_side_names.names()));
}

}  // namespace
}  // namespace slide
