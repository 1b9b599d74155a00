#pragma once
// `slide report DIR`: DIR/report.html, one self-contained page (images embedded as data: URLs, no scripts, nothing
// fetched) for a run folder (run.json: status, cost, time-step limits, the figures of tools/plot_run.py, the method
// and the resolved scene) or a sweep folder (plan.json: the recommendation, the accuracy-cost chart, the stability
// map, every run's row, the base scene and what was varied).
#include <filesystem>

namespace slide::tools {

// Exit codes: 0 written; 2 DIR is neither a run nor a sweep folder; 1 the page could not be written.
int report_command(const std::filesystem::path& dir);

}  // namespace slide::tools
