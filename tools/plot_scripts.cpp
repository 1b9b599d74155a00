#include "tools/plot_scripts.hpp"

#include <cstdlib>
#include <iostream>

#include "tools/shell_quote.hpp"

namespace slide::tools {

bool run_plot_script(const std::string& script, const std::filesystem::path& dir) {
  const std::filesystem::path path = std::filesystem::path(SLIDE_TOOLS_DIR) / script;
  if (!std::filesystem::exists("/usr/bin/python3") || !std::filesystem::exists(path)) {
    std::cerr << "slide: charts skipped (they need /usr/bin/python3 and " << path.string() << ")\n";
    return false;
  }
  const std::string command = "/usr/bin/python3 " + shell_quoted(path.string()) + " " + shell_quoted(dir.string()) + " 1>&2";
  if (std::system(command.c_str()) != 0) {
    std::cerr << "slide: charts failed (" << command << ")\n";
    return false;
  }
  return true;
}

}  // namespace slide::tools
