#pragma once
// The channel's error measure (issue 13): the last velocity profile of a run (velocity_profile.csv) against plane
// Poiseuille flow's closed form (coupling/hb_poiseuille.hpp). `slide sweep` (error.measure: poiseuille_profile) calls
// it on each run's folder; tests/test_error_measures.cpp checks it on exact tables.
#include <filesystem>

#include "cases/csv_table.hpp"
#include "coupling/hb_poiseuille.hpp"

namespace slide::tools {

struct PoiseuilleProfileError {
  double rms = 0.0;         // over the last profile's rows weighted by their particles: (u - u_exact) / u_max
  double centreline = 0.0;  // (mean u of the rows nearest the centre - u_max) / u_max
  double time = 0.0;        // s, the profile's time
  long particles = 0;
};

// The rows of the last time in `profile` (columns time, y, u, particles) against exact.velocity(y - centre). Each
// row stands for its particles at the row's mean velocity, so this is channel_profile_error's l2 with every particle
// given its row's mean. std::runtime_error when the table has no rows.
PoiseuilleProfileError poiseuille_profile_error(const CsvTable& profile, const HbPoiseuille& exact, double centre);

// The same for a run folder, the closed form from the scene in its run.json: fluid.phases[0]'s rheology (newtonian:
// K = viscosity, n = 1, tau0 = 0; herschel_bulkley: its three), G = density x gravity.x, and the channel between the
// lowest and the highest wall vertex (walls[].points). std::runtime_error for another rheology, or where the fluid
// would not flow (G H <= tau0).
PoiseuilleProfileError poiseuille_profile_error(const std::filesystem::path& run_folder);

}  // namespace slide::tools
