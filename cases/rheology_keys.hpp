#pragma once
// The scene keys of a rheology (a phase's `rheology`, a deformable slide's), and reading them into fluid/'s types.
#include <string>

#include <yaml-cpp/yaml.h>

#include "cases/schema.hpp"
#include "fluid/name_table.hpp"
#include "fluid/rheology/rheology.hpp"

namespace slide::cases {

enum class RheologyModel { newtonian, herschel_bulkley, mohr_coulomb, granular };

inline constexpr auto rheology_model_names = make_name_table<RheologyModel>(
    std::pair{RheologyModel::newtonian, "newtonian"}, std::pair{RheologyModel::herschel_bulkley, "herschel_bulkley"},
    std::pair{RheologyModel::mohr_coulomb, "mohr_coulomb"}, std::pair{RheologyModel::granular, "granular"});

enum class RegularisationKind { papanastasiou, bi_viscosity };

inline constexpr auto regularisation_names = make_name_table<RegularisationKind>(
    std::pair{RegularisationKind::papanastasiou, "papanastasiou"},
    std::pair{RegularisationKind::bi_viscosity, "bi_viscosity"});

// The variant keyed by `model` (default newtonian), each model with its own keys (fluid/rheology/*.hpp).
Schema rheology_schema();

// A resolved `rheology` node (at key path `path`) as the model it names. Throws SceneError on parameters the law
// cannot take together (mu(I) needs mu_2 >= mu_s).
Rheology read_rheology(const YAML::Node& resolved, const std::string& path);

// Every model's keys in one map with defaults (a deformable slide's `rheology`: its model is named by the slide's
// own `model` key, so that switching the model is one key and the parameters stay in the scene).
Schema rheology_parameters_schema();
Rheology read_rheology(RheologyModel model, const YAML::Node& resolved_parameters, const std::string& path);

}  // namespace slide::cases
