#include "tools/output_folder.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace slide::tools {

std::optional<std::string> output_folder_problem(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path wanted = fs::absolute(folder, ec);
  if (ec) return "cannot be resolved: " + ec.message();
  fs::path existing = wanted;
  while (!fs::exists(existing, ec) && existing.has_parent_path() && existing.parent_path() != existing)
    existing = existing.parent_path();
  const std::string which = existing == wanted ? "it" : existing.string();
  if (!fs::is_directory(existing, ec)) return which + " is a file, not a folder";
  std::string probe = (existing / ".slide-write-probe-XXXXXX").string();
  if (!mkdtemp(probe.data())) return "cannot create anything in " + which + ": " + std::strerror(errno);
  fs::remove(probe, ec);
  return std::nullopt;
}

}  // namespace slide::tools
