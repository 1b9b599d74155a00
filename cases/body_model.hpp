#pragma once
// What a slide or floating body is made of (scene key `bodies[].model`). build_slides_and_bodies
// (cases/build_bodies.cpp) switches on it: rigid makes a Bullet rigid body with boundary particles; every other model
// fills the same outline with sediment particles of that rheology (cases/rheology_keys.hpp), a deformable slide.
#include <optional>

#include "cases/rheology_keys.hpp"
#include "fluid/name_table.hpp"

namespace slide::cases {

enum class BodyModel {
  rigid,             // a Bullet rigid body whose boundary particles exchange forces with the fluid
  newtonian,         // sediment particles: a heavy Newtonian fluid
  herschel_bulkley,  // sediment particles: Herschel-Bulkley (the seed paper's model)
  mohr_coulomb,      // sediment particles: pressure-dependent yield stress
  granular,          // sediment particles: mu(I)
};

inline constexpr auto body_model_names = make_name_table<BodyModel>(
    std::pair{BodyModel::rigid, "rigid"}, std::pair{BodyModel::newtonian, "newtonian"},
    std::pair{BodyModel::herschel_bulkley, "herschel_bulkley"}, std::pair{BodyModel::mohr_coulomb, "mohr_coulomb"},
    std::pair{BodyModel::granular, "granular"});

inline std::string_view to_string(BodyModel m) { return body_model_names.name(m); }

// The rheology model of a deformable slide; none for a rigid body.
inline std::optional<RheologyModel> sediment_rheology(BodyModel m) {
  if (m == BodyModel::rigid) return std::nullopt;
  return rheology_model_names.parse(to_string(m));
}

}  // namespace slide::cases
