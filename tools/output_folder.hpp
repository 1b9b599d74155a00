#pragma once
// Whether a run can write its output folder, found before anything is built or written (exit 2, naming --out).
#include <filesystem>
#include <optional>
#include <string>

namespace slide::tools {

// Why `folder` cannot hold a run's output (it or a folder above it is a file, or nothing can be created there), or
// nothing. The nearest folder that exists is probed by making and removing a temporary folder in it: permission
// bits alone do not tell (a read-only file system, /proc, or running as root).
std::optional<std::string> output_folder_problem(const std::filesystem::path& folder);

}  // namespace slide::tools
