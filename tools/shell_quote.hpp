#pragma once
// One argument quoted for a POSIX shell: inside single quotes, each ' written as '\''.
#include <string>

namespace slide::tools {

inline std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace slide::tools
