// The rheology scene keys: each model's keys read into its fluid/ type, defaults filled, wrong keys refused.
#include <gtest/gtest.h>

#include "cases/rheology_keys.hpp"

namespace slide::cases {
namespace {

Rheology read(const std::string& yaml) { return read_rheology(rheology_schema().resolve(YAML::Load(yaml)), "rheology"); }

TEST(RheologyKeys, EachModelReadsIntoItsType) {
  EXPECT_EQ(std::get<Newtonian>(read("{}")).viscosity_pa_s, 1e-3);
  EXPECT_EQ(std::get<Newtonian>(read("{viscosity: 0.5}")).viscosity_pa_s, 0.5);

  const auto hb = std::get<HerschelBulkley>(
      read("{model: herschel_bulkley, yield_stress: 10, consistency: 5, flow_index: 0.5, papanastasiou_exponent: 200}"));
  EXPECT_EQ(hb.yield_stress_pa, 10.0);
  EXPECT_EQ(hb.consistency_pa_s_n, 5.0);
  EXPECT_EQ(hb.flow_index, 0.5);
  EXPECT_EQ(std::get<Papanastasiou>(hb.regularisation).exponent_s, 200.0);
  EXPECT_EQ(hb.max_power_law_viscosity_pa_s, 1e4);

  const auto bi = std::get<HerschelBulkley>(
      read("{model: herschel_bulkley, consistency: 1, regularisation: bi_viscosity, max_viscosity: 300}"));
  EXPECT_EQ(std::get<BiViscosity>(bi.regularisation).max_viscosity_pa_s, 300.0);
  EXPECT_EQ(bi.yield_stress_pa, 0.0);
  EXPECT_EQ(bi.flow_index, 1.0);

  const auto mc = std::get<MohrCoulomb>(read("{model: mohr_coulomb, friction_angle: 30, cohesion: 5}"));
  EXPECT_EQ(mc.friction_angle_deg, 30.0);
  EXPECT_EQ(mc.cohesion_pa, 5.0);
  EXPECT_EQ(mc.consistency_pa_s_n, 0.0);

  const auto g = std::get<GranularMuI>(read("{model: granular, grain_diameter: 0.001}"));
  EXPECT_EQ(g.mu_s, 0.38);
  EXPECT_EQ(g.mu_2, 0.64);
  EXPECT_EQ(g.i0, 0.279);
  EXPECT_EQ(g.grain_diameter_m, 0.001);
  EXPECT_EQ(g.grain_density_kg_m3, 2450.0);
}

TEST(RheologyKeys, WrongKeysAreRefusedWithTheirPath) {
  auto error_path = [](const std::string& yaml) {
    try {
      rheology_schema().resolve(YAML::Load(yaml), "rheology");
    } catch (const SceneError& e) {
      return e.key_path;
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_path("{model: herschel_bulkley}"), "rheology.consistency");  // required
  EXPECT_EQ(error_path("{model: herschel_bulkley, consistency: 1, friction_angle: 3}"), "rheology.friction_angle");
  EXPECT_EQ(error_path("{model: mohr_coulomb, friction_angle: 90}"), "rheology.friction_angle");  // below 90
  EXPECT_EQ(error_path("{model: plastic}"), "rheology.model");
  EXPECT_EQ(error_path("{yield_stress: 3}"), "rheology.yield_stress");  // newtonian has no yield stress
}

TEST(RheologyKeys, ModelNamesMatchTheRheologyTypes) {
  for (const auto& [model, name] : rheology_model_names.entries) {
    std::string yaml = "{model: " + std::string(name);
    if (model == RheologyModel::herschel_bulkley) yaml += ", consistency: 1";
    if (model == RheologyModel::mohr_coulomb) yaml += ", friction_angle: 30";
    EXPECT_EQ(model_name(read(yaml + "}")), name);
  }
}

// A slide's flat parameter map: the model is named elsewhere; each model reads its keys from the same map.
TEST(RheologyKeys, FlatParametersServeEveryModel) {
  const YAML::Node p = rheology_parameters_schema().resolve(
      YAML::Load("{yield_stress: 200, consistency: 3, friction_angle: 35, mu_s: 0.5}"));
  const auto hb = std::get<HerschelBulkley>(read_rheology(RheologyModel::herschel_bulkley, p, "rheology"));
  EXPECT_EQ(hb.yield_stress_pa, 200.0);
  EXPECT_EQ(hb.consistency_pa_s_n, 3.0);
  const auto mc = std::get<MohrCoulomb>(read_rheology(RheologyModel::mohr_coulomb, p, "rheology"));
  EXPECT_EQ(mc.friction_angle_deg, 35.0);
  EXPECT_EQ(std::get<GranularMuI>(read_rheology(RheologyModel::granular, p, "rheology")).mu_s, 0.5);
  EXPECT_EQ(std::get<Newtonian>(read_rheology(RheologyModel::newtonian, p, "rheology")).viscosity_pa_s, 1e-3);
  EXPECT_THROW(rheology_parameters_schema().resolve(YAML::Load("{yeld_stress: 1}")), SceneError);
}


// mu(I) rises from mu_s to mu_2: mu_2 below mu_s is refused naming the key (issue 30); equal is a constant mu.
TEST(RheologyKeys, GranularMuTwoBelowMuSIsRefusedNamingIt) {
  EXPECT_EQ(std::get<GranularMuI>(read("{model: granular, mu_s: 0.4, mu_2: 0.4}")).mu_2, 0.4);
  try {
    read_rheology(rheology_schema().resolve(YAML::Load("{model: granular, mu_s: 0.5, mu_2: 0.3}")),
                  "bodies[0].rheology");
    FAIL() << "mu_2 < mu_s accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("bodies[0].rheology.mu_2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is 0.3, below mu_s (0.5)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slide::cases
