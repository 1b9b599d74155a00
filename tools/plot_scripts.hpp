#pragma once
// The plotting scripts in this source tree's tools/ (tools/plot_run.py, tools/plot_sweep.py), run with Debian's
// /usr/bin/python3 (which sees python3-matplotlib).
#include <filesystem>
#include <string>

namespace slide::tools {

// Runs `/usr/bin/python3 tools/<script> <dir>`, its output to our stderr. False, with a line on stderr saying why, when
// python or the script is missing or the script fails: a missing chart is reported, never fatal.
bool run_plot_script(const std::string& script, const std::filesystem::path& dir);

}  // namespace slide::tools
