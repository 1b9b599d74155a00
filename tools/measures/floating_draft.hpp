#pragma once
// The floating body's error measure (issue 13): its draft against Archimedes. `slide sweep` (error.measure:
// floating_draft) calls it on each run's folder; tests/test_error_measures.cpp checks it on exact tables.
#include <filesystem>

#include "cases/csv_table.hpp"

namespace slide::tools {

struct FloatingDraft {
  double draft_m = 0.0;  // time mean of (mean water level at the gauges - the body's bottom)
  double exact_m = 0.0;  // Archimedes: the box's height x its density / the water's
  double relative_error = 0.0;  // |draft / exact - 1|
};

// An upright box of height `height_m` floating in still water: its draft at each row of gauges.csv (time, then one
// free-surface elevation per gauge, in m) is the gauges' mean level less the box's bottom, y - height / 2, with y the
// first body's centre in bodies.csv (columns time, body, y; linearly interpolated in time). The draft is the
// trapezoidal time mean over from_time <= t; the exact draft is rho_body / rho_water x height.
// std::runtime_error when fewer than two gauge rows from from_time on have a level at every gauge, or when a gauge
// row from from_time on falls outside the times of bodies.csv.
FloatingDraft floating_draft(const CsvTable& gauges, const CsvTable& bodies, double height_m, double body_density,
                             double water_density, double from_time);

// The same for a run folder: the box and the densities from the scene in its run.json (bodies[0]: shape box with
// angle 0, density or mass; fluid.phases[0].density). std::runtime_error when bodies[0] is not an upright box.
FloatingDraft floating_draft(const std::filesystem::path& run_folder, double from_time);

}  // namespace slide::tools
