#pragma once
// One table per option: the enum values and the names a scene uses for them. The schema lists its choices from the
// table, the scene parser reads a name through it and to_string writes one, so adding a model is one edit here.
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace slide {

template <class E, std::size_t N>
struct NameTable {
  std::array<std::pair<E, std::string_view>, N> entries;

  constexpr std::string_view name(E value) const {
    for (const auto& [v, n] : entries)
      if (v == value) return n;
    return "?";
  }
  constexpr std::optional<E> find(std::string_view text) const {
    for (const auto& [v, n] : entries)
      if (n == text) return v;
    return std::nullopt;
  }
  // For text the schema has already checked against names(): an unknown name here is a programming error.
  E parse(std::string_view text) const {
    if (auto v = find(text)) return *v;
    throw std::logic_error("unknown option name \"" + std::string(text) + "\"");
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : entries) out.emplace_back(e.second);
    return out;
  }
};

template <class E, class... Pairs>
constexpr auto make_name_table(Pairs... pairs) {
  return NameTable<E, sizeof...(Pairs)>{{std::pair<E, std::string_view>(pairs)...}};
}

}  // namespace slide
