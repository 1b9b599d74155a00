#include "cases/rheology_keys.hpp"

#include <fmt/format.h>

namespace slide::cases {
namespace {

using S = Schema;

// The yield term's regularisation and the power-law cap, shared by the models with a yield stress. Defaults: see
// the case files and tests/test_hb_poiseuille.cpp for the measured effect of the regularisation on the answer.
std::vector<std::pair<std::string, Schema>> yield_keys() {
  return {
      {"regularisation", S::choice("regularisation of the yield term: papanastasiou, tau_y (1 - exp(-m g)) / g; "
                                   "bi_viscosity, min(tau_y / g, max_viscosity) (fluid/rheology/regularisation.hpp)",
                                   regularisation_names.names(), "papanastasiou")},
      {"papanastasiou_exponent", S::number("Papanastasiou's m: the viscosity at rest is tau_y m", "s", 1000.0, 0.0,
                                           S::inf, true)},
      {"max_viscosity", S::number("cap of the yield term (bi_viscosity) or of eta (granular)", "Pa s", 1.0e4, 0.0, S::inf, true)},
      {"max_power_law_viscosity", S::number("cap of the power-law term K g^(n-1) for n < 1 (it diverges at rest)",
                                            "Pa s", 1.0e4, 0.0, S::inf, true)},
  };
}

std::vector<std::pair<std::string, Schema>> with(std::vector<std::pair<std::string, Schema>> a,
                                                 const std::vector<std::pair<std::string, Schema>>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

Regularisation read_regularisation(const YAML::Node& r) {
  if (regularisation_names.parse(r["regularisation"].as<std::string>()) == RegularisationKind::bi_viscosity)
    return BiViscosity{r["max_viscosity"].as<double>()};
  return Papanastasiou{r["papanastasiou_exponent"].as<double>()};
}

}  // namespace

Schema rheology_schema() {
  auto newtonian = S::map("viscosity independent of the shear rate",
                          {{"viscosity", S::number("dynamic viscosity", "Pa s", 1.0e-3, 0.0, S::inf)}});
  auto herschel_bulkley = S::map(
      "Herschel-Bulkley: eta = K g^(n-1) + tau_y / g, regularised (fluid/rheology/herschel_bulkley.hpp)",
      with({{"yield_stress", S::number("yield stress tau_y", "Pa", 0.0, 0.0, S::inf)},
            {"consistency", S::number("consistency K", "Pa s^n", std::nullopt, 0.0, S::inf)},
            {"flow_index", S::number("flow index n (1: Bingham)", "", 1.0, 0.0, S::inf, true)}},
           yield_keys()));
  auto mohr_coulomb = S::map(
      "Herschel-Bulkley with a pressure-dependent yield stress tau_y = c + p tan(phi) (fluid/rheology/mohr_coulomb.hpp)",
      with({{"cohesion", S::number("cohesion c", "Pa", 0.0, 0.0, S::inf)},
            {"friction_angle", S::number("internal friction angle phi", "deg", std::nullopt, 0.0, 90.0, false, true)},
            {"consistency", S::number("consistency K", "Pa s^n", 0.0, 0.0, S::inf)},
            {"flow_index", S::number("flow index n", "", 1.0, 0.0, S::inf, true)}},
           yield_keys()));
  // Defaults: Jop, Forterre & Pouliquen (2006)'s glass beads.
  auto granular = S::map(
      "dense granular flow, mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1), eta = mu(I) p / g (Jop, Forterre & Pouliquen "
      "2006; fluid/rheology/granular_mu_i.hpp); defaults are their glass beads",
      {{"mu_s", S::number("static friction coefficient", "", 0.38, 0.0, S::inf)},
       {"mu_2", S::number("limiting friction coefficient", "", 0.64, 0.0, S::inf)},
       {"i0", S::number("inertial number scale I0", "", 0.279, 0.0, S::inf, true)},
       {"grain_diameter", S::number("grain diameter d", "m", 0.53e-3, 0.0, S::inf, true)},
       {"grain_density", S::number("grain density rho_s", "kg/m^3", 2450.0, 0.0, S::inf, true)},
       {"max_viscosity", S::number("cap of eta (regularisation at rest)", "Pa s", 1.0e4, 0.0, S::inf, true)},
       {"min_viscosity", S::number("floor of eta where the pressure vanishes", "Pa s", 0.0, 0.0, S::inf)}});
  return S::variant("rheology of the phase", "model",
                    {{"newtonian", newtonian},
                     {"herschel_bulkley", herschel_bulkley},
                     {"mohr_coulomb", mohr_coulomb},
                     {"granular", granular}},
                    "newtonian");
}

Rheology read_rheology(RheologyModel model, const YAML::Node& r, const std::string& path) {
  switch (model) {
    case RheologyModel::newtonian: return Newtonian{r["viscosity"].as<double>()};
    case RheologyModel::herschel_bulkley:
      return HerschelBulkley{r["yield_stress"].as<double>(), r["consistency"].as<double>(), r["flow_index"].as<double>(),
                             read_regularisation(r), r["max_power_law_viscosity"].as<double>()};
    case RheologyModel::mohr_coulomb:
      return MohrCoulomb{r["cohesion"].as<double>(),      r["friction_angle"].as<double>(),
                         r["consistency"].as<double>(),   r["flow_index"].as<double>(),
                         read_regularisation(r),          r["max_power_law_viscosity"].as<double>()};
    case RheologyModel::granular:
      // mu(I) rises from mu_s at rest to mu_2 as I grows; mu_2 < mu_s would make faster flow weaker.
      if (r["mu_2"].as<double>() < r["mu_s"].as<double>())
        throw SceneError(path + ".mu_2", fmt::format("is {:g}, below mu_s ({:g}): mu(I) rises from mu_s at rest to "
                                                     "mu_2, so mu_2 >= mu_s",
                                                     r["mu_2"].as<double>(), r["mu_s"].as<double>()));
      return GranularMuI{r["mu_s"].as<double>(),           r["mu_2"].as<double>(),
                         r["i0"].as<double>(),             r["grain_diameter"].as<double>(),
                         r["grain_density"].as<double>(),  r["max_viscosity"].as<double>(),
                         r["min_viscosity"].as<double>()};
  }
  throw std::logic_error("unknown rheology model");
}

Rheology read_rheology(const YAML::Node& r, const std::string& path) {
  return read_rheology(rheology_model_names.parse(r["model"].as<std::string>()), r, path);
}

Schema rheology_parameters_schema() {
  // The union of the variants' keys, each with the variant's default; required keys get a default here (their
  // model's key is then simply read): consistency 0 (a plastic without viscosity beyond its regularisation),
  // friction_angle 30 degrees.
  std::vector<std::pair<std::string, Schema>> fields;
  auto add = [&](const std::string& name, Schema s) {
    for (const auto& f : fields)
      if (f.first == name) return;
    fields.emplace_back(name, std::move(s));
  };
  add("viscosity", S::number("newtonian: dynamic viscosity", "Pa s", 1.0e-3, 0.0, S::inf));
  add("yield_stress", S::number("herschel_bulkley: yield stress tau_y", "Pa", 0.0, 0.0, S::inf));
  add("consistency", S::number("herschel_bulkley, mohr_coulomb: consistency K", "Pa s^n", 0.0, 0.0, S::inf));
  add("flow_index", S::number("herschel_bulkley, mohr_coulomb: flow index n", "", 1.0, 0.0, S::inf, true));
  add("cohesion", S::number("mohr_coulomb: cohesion c", "Pa", 0.0, 0.0, S::inf));
  add("friction_angle", S::number("mohr_coulomb: internal friction angle phi", "deg", 30.0, 0.0, 90.0, false, true));
  for (auto& f : yield_keys()) add(f.first, f.second);
  add("mu_s", S::number("granular: static friction coefficient", "", 0.38, 0.0, S::inf));
  add("mu_2", S::number("granular: limiting friction coefficient", "", 0.64, 0.0, S::inf));
  add("i0", S::number("granular: inertial number scale I0", "", 0.279, 0.0, S::inf, true));
  add("grain_diameter", S::number("granular: grain diameter d", "m", 0.53e-3, 0.0, S::inf, true));
  add("grain_density", S::number("granular: grain density rho_s", "kg/m^3", 2450.0, 0.0, S::inf, true));
  add("min_viscosity", S::number("granular: floor of eta where the pressure vanishes", "Pa s", 0.0, 0.0, S::inf));
  return S::map("rheology parameters of a deformable slide, for the model its `model` key names (the keys of the "
                "others are ignored); fluid/rheology/*.hpp",
                std::move(fields), false);
}

}  // namespace slide::cases
