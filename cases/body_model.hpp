#pragma once
// What a slide or floating body is made of (scene key `bodies[].model`). build_slides_and_bodies
// (cases/build_bodies.cpp) switches on it: rigid makes a Bullet rigid body with boundary particles; a slide of
// sediment particles filling the same outline will be another model here.
#include "fluid/name_table.hpp"

namespace slide::cases {

enum class BodyModel {
  rigid,  // a Bullet rigid body whose boundary particles exchange forces with the fluid
};

inline constexpr auto body_model_names = make_name_table<BodyModel>(std::pair{BodyModel::rigid, "rigid"});

inline std::string_view to_string(BodyModel m) { return body_model_names.name(m); }

}  // namespace slide::cases
