#pragma once
// Text made safe inside HTML or XML content and attribute values (report.html, particles.xdmf).
#include <string>
#include <string_view>

namespace slide::tools {

inline std::string markup_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace slide::tools
