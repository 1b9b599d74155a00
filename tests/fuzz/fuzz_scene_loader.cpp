// libFuzzer target for the scene reader and the --set parser (cases/load_scene.cpp): the input is a scene's YAML
// text, optionally followed by a line "%%" and then one --set assignment per line. Whatever the input, the loader must
// either return a resolved scene or throw SceneError (slide exits 2 with its message); any other exception, crash,
// leak or undefined behaviour is a finding. Built only with -DSLIDE_FUZZ=ON and clang (tests/fuzz/run_fuzz.sh).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cases/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find("\n%%\n");
  const std::string scene = input.substr(0, split);
  std::vector<std::string> overrides;
  if (split != std::string::npos) {
    std::istringstream lines(input.substr(split + 4));
    for (std::string line; std::getline(lines, line);) overrides.push_back(line);
  }
  try {
    const YAML::Node resolved = slide::cases::load_scene_text(scene, overrides);
    (void)resolved;
  } catch (const slide::cases::SceneError&) {
    // The expected refusal.
  }
  return 0;
}
