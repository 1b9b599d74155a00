#include "cases/schema.hpp"

#include "cases/duplicate_keys.hpp"
#include "cases/yaml_text.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <regex>

#include <fmt/format.h>

namespace slide::cases {

// The immutable description behind a Schema handle. One struct for all kinds keeps the
// validation and documentation code as plain switches; unused members stay at their defaults.
struct Schema::Node {
  Kind kind;
  std::string doc;
  std::string unit;                        // Number, Vector
  std::optional<YAML::Node> default_value; // leaves only; always cloned before being handed out
  double min = -inf, max = inf;            // Number, Vector elements
  bool min_exclusive = false, max_exclusive = false;
  long imin = LONG_MIN, imax = LONG_MAX;   // Integer
  std::vector<std::string> choices;        // Choice
  int length = -1;                         // Vector (-1: any length)
  std::vector<std::pair<std::string, Schema>> fields;  // Map
  bool required = true;                    // Map
  std::optional<Schema> item;              // List
  std::size_t min_items = 0;               // List
  std::string tag;                         // Variant
  std::vector<std::pair<std::string, Schema>> variants;  // Variant, as given (for the document)
  std::vector<Schema> tagged;  // Variant: each variant's fields with the tag prepended (for resolve)
  std::optional<std::string> default_tag;  // Variant: the tag taken when it is left out
};

namespace {

using Node = Schema::Node;

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  throw SceneError(path, message);
}

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string at_index(const std::string& path, std::size_t i) { return fmt::format("{}[{}]", path, i); }

std::string quote(const std::string& s) { return "\"" + s + "\""; }

std::string comma_list(const std::vector<std::string>& items) { return fmt::format("{}", fmt::join(items, ", ")); }

// Shortest text that reads back to the same double ("2.1", "0", "-9.81", "1e-06").
std::string show(double x) { return fmt::format("{}", x); }
std::string show(long x) { return fmt::format("{}", x); }

std::string unit_suffix(const std::string& unit) { return unit.empty() ? "" : " (" + unit + ")"; }

// yaml-cpp keeps every scalar as text; a quoted scalar carries the non-specific tag "!" and is
// always a string, so `"12"` is not accepted where a number is expected.
bool is_plain_scalar(const YAML::Node& n) { return n.IsScalar() && n.Tag() != "!"; }

// Numbers as YAML 1.2 (core schema) writes them, plus inf/nan spelled without the dot, so that a
// user writing `nan` gets the "not finite" message rather than a confusing "got string".
std::optional<double> parse_number(const std::string& text) {
  static const std::regex decimal(R"([-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?)");
  if (std::regex_match(text, decimal)) return std::strtod(text.c_str(), nullptr);  // overflow gives inf
  std::string word = text;
  double sign = 1;
  if (!word.empty() && (word[0] == '+' || word[0] == '-')) {
    sign = word[0] == '-' ? -1 : 1;
    word.erase(0, 1);
  }
  if (!word.empty() && word[0] == '.') word.erase(0, 1);
  std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::tolower(c); });
  if (word == "inf" || word == "infinity") return sign * Schema::inf;
  if (word == "nan") return std::numeric_limits<double>::quiet_NaN();
  return std::nullopt;
}

std::optional<double> as_number(const YAML::Node& n) {
  return is_plain_scalar(n) ? parse_number(n.Scalar()) : std::nullopt;
}

// Only the YAML 1.2 spellings: yes/no/on/off/1/0 are too easy to write by accident.
std::optional<bool> as_bool(const YAML::Node& n) {
  if (!is_plain_scalar(n)) return std::nullopt;
  const std::string& s = n.Scalar();
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  return std::nullopt;
}

// What the user actually wrote, for "expected X, got Y" messages.
std::string describe(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Undefined: return "nothing";
    case YAML::NodeType::Null: return "null";
    case YAML::NodeType::Sequence: return fmt::format("a list of {} items", n.size());
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Scalar: break;
  }
  if (as_bool(n)) return "boolean " + n.Scalar();
  if (as_number(n)) return "number " + n.Scalar();
  return "string " + quote(n.Scalar());
}

// "in [0, 10]", " >= 0", "": the accepted interval as it reads after "expected a number".
std::string interval(double lo, double hi, bool lo_ex, bool hi_ex) {
  const bool has_lo = lo > -Schema::inf, has_hi = hi < Schema::inf;
  if (has_lo && has_hi)
    return fmt::format(" in {}{}, {}{}", lo_ex ? "(" : "[", show(lo), show(hi), hi_ex ? ")" : "]");
  if (has_lo) return fmt::format(" {} {}", lo_ex ? ">" : ">=", show(lo));
  if (has_hi) return fmt::format(" {} {}", hi_ex ? "<" : "<=", show(hi));
  return "";
}

// "0 < value <= 10", "value >= 0" (or ">= 0" when var is empty), "any" when unbounded.
template <class T>
std::string bounds(T lo, T hi, bool has_lo, bool has_hi, bool lo_ex, bool hi_ex, const std::string& var) {
  if (has_lo && has_hi)
    return fmt::format("{} {} {} {} {}", show(lo), lo_ex ? "<" : "<=", var.empty() ? "x" : var,
                       hi_ex ? "<" : "<=", show(hi));
  const std::string prefix = var.empty() ? "" : var + " ";
  if (has_lo) return fmt::format("{}{} {}", prefix, lo_ex ? ">" : ">=", show(lo));
  if (has_hi) return fmt::format("{}{} {}", prefix, hi_ex ? "<" : "<=", show(hi));
  return "any";
}

std::string number_bounds(const Node& s, const std::string& var) {
  return bounds(s.min, s.max, s.min > -Schema::inf, s.max < Schema::inf, s.min_exclusive, s.max_exclusive, var);
}

std::string integer_bounds(const Node& s, const std::string& var) {
  return bounds(s.imin, s.imax, s.imin != LONG_MIN, s.imax != LONG_MAX, false, false, var);
}

std::string integer_interval(const Node& s) {
  const double lo = s.imin == LONG_MIN ? -Schema::inf : double(s.imin);
  const double hi = s.imax == LONG_MAX ? Schema::inf : double(s.imax);
  return interval(lo, hi, false, false);
}

std::string without_period(std::string s) {
  while (!s.empty() && (s.back() == '.' || s.back() == ' ')) s.pop_back();
  return s;
}

// Shared by number() and the elements of vector(): type, finiteness, then range.
double check_number(const Node& s, const YAML::Node& in, const std::string& path) {
  const std::string expected =
      "a number" + interval(s.min, s.max, s.min_exclusive, s.max_exclusive) + unit_suffix(s.unit);
  const std::optional<double> v = as_number(in);
  if (!v) fail(path, "expected " + expected + ", got " + describe(in));
  if (!std::isfinite(*v)) fail(path, fmt::format("value {} is not a finite number; expected {}", in.Scalar(), expected));
  const bool below = s.min_exclusive ? *v <= s.min : *v < s.min;
  const bool above = s.max_exclusive ? *v >= s.max : *v > s.max;
  if (below || above)
    fail(path, fmt::format("value {} is out of range: expected {}{}", show(*v), number_bounds(s, "value"),
                           unit_suffix(s.unit)));
  return *v;
}

long check_integer(const Node& s, const YAML::Node& in, const std::string& path) {
  const std::string expected = "an integer" + integer_interval(s);
  const std::optional<double> v = as_number(in);
  if (!v) fail(path, "expected " + expected + ", got " + describe(in));
  // Plain digit strings are parsed exactly (doubles lose precision beyond 2^53); "3.0" and "1e3"
  // are accepted because they are integral.
  static const std::regex digits(R"([-+]?[0-9]+)");
  long value;
  if (std::regex_match(in.Scalar(), digits)) {
    errno = 0;
    value = std::strtol(in.Scalar().c_str(), nullptr, 10);
    if (errno == ERANGE) fail(path, fmt::format("value {} is out of range: expected {}", in.Scalar(), expected));
  } else {
    if (!std::isfinite(*v) || *v != std::floor(*v) || std::fabs(*v) >= 9.2e18)
      fail(path, "expected " + expected + ", got " + describe(in));
    value = static_cast<long>(*v);
  }
  if (value < s.imin || value > s.imax)
    fail(path, fmt::format("value {} is out of range: expected {}", value, integer_bounds(s, "value")));
  return value;
}

std::vector<std::string> names_of(const std::vector<std::pair<std::string, Schema>>& items) {
  std::vector<std::string> names;
  for (const auto& item : items) names.push_back(item.first);
  return names;
}

// The value an absent key takes, or nullopt when it has none. An optional map is built from its
// fields' defaults; if one of its required fields has no default, the map stays absent.
std::optional<YAML::Node> absent_value(const Node& s) {
  switch (s.kind) {
    case Schema::Kind::List:
      if (s.min_items == 0) return YAML::Node(YAML::NodeType::Sequence);
      return std::nullopt;
    case Schema::Kind::Map: {
      if (s.required) return std::nullopt;
      YAML::Node out(YAML::NodeType::Map);
      for (const auto& [name, field] : s.fields) {
        // resolve() of an absent value is exactly "fill from defaults"; a field that cannot be
        // filled (required, no default) makes the whole map absent rather than an error.
        try {
          YAML::Node filled = field.resolve(YAML::Node(YAML::NodeType::Undefined), name);
          if (filled.IsDefined()) out[name] = filled;
        } catch (const SceneError&) {
          return std::nullopt;
        }
      }
      return out;
    }
    case Schema::Kind::Variant: {
      if (!s.default_tag) return std::nullopt;
      YAML::Node tagged(YAML::NodeType::Map);
      tagged[s.tag] = *s.default_tag;
      try {
        const auto names = names_of(s.variants);
        const auto k = std::size_t(std::find(names.begin(), names.end(), *s.default_tag) - names.begin());
        return s.tagged[k].resolve(tagged, "");
      } catch (const SceneError&) {
        return std::nullopt;  // the default variant has required fields
      }
    }
    default:
      if (s.default_value) return YAML::Clone(*s.default_value);
      return std::nullopt;
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Errors

SceneError::SceneError(std::string key_path_, std::string message_)
    : std::runtime_error((key_path_.empty() ? std::string("<root>") : key_path_) + ": " + message_),
      key_path(std::move(key_path_)),
      message(std::move(message_)) {}

// ---------------------------------------------------------------------------------------------
// Construction. Each factory checks its own default against itself, so a typo in the scene
// description (e.g. a default outside the range) fails at start-up rather than in a user's run.

Schema::Schema(std::shared_ptr<const Node> node) : node_(std::move(node)) {}

namespace {
Schema checked(Schema s, const std::optional<YAML::Node>& default_value) {
  if (default_value) {
    try {
      s.resolve(*default_value, "<default>");
    } catch (const SceneError& e) {
      throw std::invalid_argument(fmt::format("schema \"{}\": bad default: {}", s.doc(), e.what()));
    }
  }
  return s;
}
}  // namespace

Schema Schema::number(std::string doc, std::string unit, std::optional<double> default_value, double min,
                      double max, bool min_exclusive, bool max_exclusive) {
  if (!(min <= max)) throw std::invalid_argument("schema \"" + doc + "\": min > max");
  auto n = std::make_shared<Node>();
  n->kind = Kind::Number;
  n->doc = std::move(doc);
  n->unit = std::move(unit);
  n->min = min, n->max = max, n->min_exclusive = min_exclusive, n->max_exclusive = max_exclusive;
  if (default_value) n->default_value = YAML::Node(*default_value);
  return checked(Schema(n), n->default_value);
}

Schema Schema::integer(std::string doc, std::optional<long> default_value, long min, long max) {
  if (min > max) throw std::invalid_argument("schema \"" + doc + "\": min > max");
  auto n = std::make_shared<Node>();
  n->kind = Kind::Integer;
  n->doc = std::move(doc);
  n->imin = min, n->imax = max;
  if (default_value) n->default_value = YAML::Node(*default_value);
  return checked(Schema(n), n->default_value);
}

Schema Schema::boolean(std::string doc, std::optional<bool> default_value) {
  auto n = std::make_shared<Node>();
  n->kind = Kind::Boolean;
  n->doc = std::move(doc);
  if (default_value) n->default_value = YAML::Node(*default_value);
  return Schema(n);
}

Schema Schema::choice(std::string doc, std::vector<std::string> choices, std::optional<std::string> default_value) {
  if (choices.empty()) throw std::invalid_argument("schema \"" + doc + "\": no choices");
  auto n = std::make_shared<Node>();
  n->kind = Kind::Choice;
  n->doc = std::move(doc);
  n->choices = std::move(choices);
  if (default_value) n->default_value = YAML::Node(*default_value);
  return checked(Schema(n), n->default_value);
}

Schema Schema::text(std::string doc, std::optional<std::string> default_value) {
  auto n = std::make_shared<Node>();
  n->kind = Kind::Text;
  n->doc = std::move(doc);
  if (default_value) n->default_value = YAML::Node(*default_value);
  return Schema(n);
}

Schema Schema::vector(std::string doc, std::string unit, int length, std::optional<std::vector<double>> default_value,
                      double min, double max) {
  if (length == 0 || length < -1) throw std::invalid_argument("schema \"" + doc + "\": bad vector length");
  if (!(min <= max)) throw std::invalid_argument("schema \"" + doc + "\": min > max");
  auto n = std::make_shared<Node>();
  n->kind = Kind::Vector;
  n->doc = std::move(doc);
  n->unit = std::move(unit);
  n->length = length;
  n->min = min, n->max = max;
  if (default_value) {
    YAML::Node seq(YAML::NodeType::Sequence);
    for (double x : *default_value) seq.push_back(x);
    seq.SetStyle(YAML::EmitterStyle::Flow);
    n->default_value = seq;
  }
  return checked(Schema(n), n->default_value);
}

Schema Schema::map(std::string doc, std::vector<std::pair<std::string, Schema>> fields, bool required) {
  auto n = std::make_shared<Node>();
  n->kind = Kind::Map;
  n->doc = std::move(doc);
  n->fields = std::move(fields);
  n->required = required;
  return Schema(n);
}

Schema Schema::list(std::string doc, Schema item, std::size_t min_items) {
  auto n = std::make_shared<Node>();
  n->kind = Kind::List;
  n->doc = std::move(doc);
  n->item = std::move(item);
  n->min_items = min_items;
  return Schema(n);
}

Schema Schema::variant(std::string doc, std::string tag, std::vector<std::pair<std::string, Schema>> variants,
                       std::optional<std::string> default_tag) {
  if (variants.empty()) throw std::invalid_argument("schema \"" + doc + "\": no variants");
  if (default_tag && std::none_of(variants.begin(), variants.end(), [&](const auto& v) { return v.first == *default_tag; }))
    throw std::invalid_argument("schema \"" + doc + "\": the default tag names no variant");
  auto n = std::make_shared<Node>();
  n->kind = Kind::Variant;
  n->default_tag = std::move(default_tag);
  n->doc = std::move(doc);
  n->tag = std::move(tag);
  n->variants = std::move(variants);
  // Resolving a variant = resolving its map with the tag as one more (first) field, so unknown-key
  // messages list the tag too and the output keeps the tag first.
  for (const auto& [name, vmap] : n->variants) {
    if (vmap.kind() != Kind::Map) throw std::invalid_argument("schema \"" + n->doc + "\": variant is not a map");
    std::vector<std::pair<std::string, Schema>> fields{{n->tag, choice("Variant tag.", {name}, std::nullopt)}};
    for (const auto& field : vmap.node_->fields) {
      if (field.first == n->tag) throw std::invalid_argument("schema \"" + n->doc + "\": field named like the tag");
      fields.push_back(field);
    }
    n->tagged.push_back(map(vmap.doc(), std::move(fields), true));
  }
  return Schema(n);
}

Schema::Kind Schema::kind() const { return node_->kind; }
const std::string& Schema::doc() const { return node_->doc; }

bool Schema::is_optional() const {
  switch (node_->kind) {
    case Kind::Map: return !node_->required;
    case Kind::List: return node_->min_items == 0;
    case Kind::Variant: return node_->default_tag.has_value();
    default: return node_->default_value.has_value();
  }
}

// ---------------------------------------------------------------------------------------------
// Validation

YAML::Node Schema::resolve(const YAML::Node& input, const std::string& path) const {
  const Node& s = *node_;
  // An absent value (undefined node) only reaches here from absent_value() for optional maps.
  if (!input.IsDefined()) {
    if (auto d = absent_value(s)) return *d;
    if (is_optional()) return YAML::Node(YAML::NodeType::Undefined);
    fail(path, "missing required key (" + without_period(s.doc) + ")");
  }

  switch (s.kind) {
    case Kind::Number: return YAML::Node(check_number(s, input, path));

    case Kind::Integer: return YAML::Node(check_integer(s, input, path));

    case Kind::Boolean: {
      const std::optional<bool> b = as_bool(input);
      if (!b) fail(path, "expected true or false, got " + describe(input));
      return YAML::Node(*b);
    }

    case Kind::Choice: {
      const bool ok = input.IsScalar() &&
                      std::find(s.choices.begin(), s.choices.end(), input.Scalar()) != s.choices.end();
      if (!ok) fail(path, "expected one of: " + comma_list(s.choices) + ", got " + describe(input));
      return YAML::Node(input.Scalar());
    }

    case Kind::Text:
      if (!input.IsScalar()) fail(path, "expected a string, got " + describe(input));
      return YAML::Node(input.Scalar());

    case Kind::Vector: {
      const std::string expected =
          (s.length > 0 ? fmt::format("a list of {} numbers", s.length) : std::string("a list of numbers")) +
          unit_suffix(s.unit);
      if (!input.IsSequence()) fail(path, "expected " + expected + ", got " + describe(input));
      if (s.length > 0 && input.size() != std::size_t(s.length))
        fail(path, "expected " + expected + ", got " + describe(input));
      YAML::Node out(YAML::NodeType::Sequence);
      for (std::size_t i = 0; i < input.size(); ++i) out.push_back(check_number(s, input[i], at_index(path, i)));
      out.SetStyle(YAML::EmitterStyle::Flow);
      return out;
    }

    case Kind::List: {
      // `regions:` with nothing after it reads as null: take it as an empty list.
      if (!input.IsSequence() && !input.IsNull()) fail(path, "expected a list, got " + describe(input));
      const std::size_t n = input.IsSequence() ? input.size() : 0;
      if (n < s.min_items)
        fail(path, fmt::format("expected at least {} item{}, got {}", s.min_items, s.min_items == 1 ? "" : "s", n));
      YAML::Node out(YAML::NodeType::Sequence);
      for (std::size_t i = 0; i < n; ++i) out.push_back(s.item->resolve(input[i], at_index(path, i)));
      return out;
    }

    case Kind::Map: {
      const std::vector<std::string> names = names_of(s.fields);
      // A section written with nothing under it (`fluid:`) reads as null: take it as empty.
      if (!input.IsMap() && !input.IsNull())
        fail(path, "expected a map with keys " + comma_list(names) + ", got " + describe(input));
      // Unknown keys first: a misspelt key is the likely cause of any "missing" error that follows.
      std::vector<std::pair<std::string, YAML::Node>> given;
      if (input.IsMap()) {
        for (const auto& kv : input) {
          if (!kv.first.IsScalar()) fail(path, "keys must be names, got " + describe(kv.first));
          const std::string key = kv.first.Scalar();
          if (std::find(names.begin(), names.end(), key) == names.end())
            fail(join(path, key), "unknown key; accepted keys: " + comma_list(names));
          given.emplace_back(key, kv.second);
        }
      }
      YAML::Node out(YAML::NodeType::Map);
      for (const auto& [name, field] : s.fields) {
        const auto it = std::find_if(given.begin(), given.end(), [&name = name](const auto& g) { return g.first == name; });
        YAML::Node value = field.resolve(it == given.end() ? YAML::Node(YAML::NodeType::Undefined) : it->second,
                                         join(path, name));
        if (value.IsDefined()) out[name] = value;  // undefined: an optional map left absent
      }
      return out;
    }

    case Kind::Variant: {
      const std::vector<std::string> names = names_of(s.variants);
      const std::string tag_path = join(path, s.tag);
      if (!input.IsMap())
        fail(path, fmt::format("expected a map with key '{}' (one of: {}), got {}", s.tag, comma_list(names),
                               describe(input)));
      YAML::Node tag = input[s.tag];  // const lookup: does not insert
      if (!tag.IsDefined() && s.default_tag) {
        YAML::Node with_tag(YAML::NodeType::Map);
        with_tag[s.tag] = *s.default_tag;
        for (const auto& kv : input) with_tag[kv.first] = kv.second;
        return resolve(with_tag, path);
      }
      if (!tag.IsDefined())
        fail(tag_path, "missing required key (selects the kind of " + without_period(s.doc) +
                           "; one of: " + comma_list(names) + ")");
      const auto it = tag.IsScalar() ? std::find(names.begin(), names.end(), tag.Scalar()) : names.end();
      if (it == names.end()) fail(tag_path, "expected one of: " + comma_list(names) + ", got " + describe(tag));
      return s.tagged[std::size_t(it - names.begin())].resolve(input, path);
    }
  }
  fail(path, "internal error: unknown schema kind");
}

// ---------------------------------------------------------------------------------------------
// Documentation

namespace {

struct Row {
  std::string key, type, unit, default_value, range, doc;
};

std::string default_text(const Node& s) {
  if (!s.default_value) return "required";
  const YAML::Node& d = *s.default_value;
  switch (s.kind) {
    case Schema::Kind::Number: return show(d.as<double>());
    case Schema::Kind::Choice:
    case Schema::Kind::Text: return quote(d.Scalar());
    case Schema::Kind::Vector: {
      std::vector<std::string> parts;
      for (const auto& x : d) parts.push_back(show(x.as<double>()));
      return "[" + comma_list(parts) + "]";
    }
    default: return d.Scalar();  // integer, boolean
  }
}

std::string leaf_type(const Node& s) {
  switch (s.kind) {
    case Schema::Kind::Number: return "number";
    case Schema::Kind::Integer: return "integer";
    case Schema::Kind::Boolean: return "boolean";
    case Schema::Kind::Choice: return "choice";
    case Schema::Kind::Text: return "string";
    case Schema::Kind::Vector: return s.length > 0 ? fmt::format("vector[{}]", s.length) : "vector";
    case Schema::Kind::Map: return "map";
    case Schema::Kind::List: return "list";
    case Schema::Kind::Variant: return "variant";
  }
  return "?";
}

std::string leaf_range(const Node& s) {
  switch (s.kind) {
    case Schema::Kind::Number: return number_bounds(s, "");
    case Schema::Kind::Integer: return integer_bounds(s, "");
    case Schema::Kind::Boolean: return "true, false";
    case Schema::Kind::Choice: return "one of: " + comma_list(s.choices);
    case Schema::Kind::Text: return "any";
    case Schema::Kind::Vector: {
      const std::string each = number_bounds(s, "");
      const std::string length = s.length > 0 ? fmt::format("length {}", s.length) : "any length";
      return each == "any" ? length : length + "; each " + each;
    }
    default: return "";
  }
}

}  // namespace

// Gives the documentation walk read access to the description behind a Schema handle.
struct SchemaAccess {
  static const Node& node(const Schema& s) { return *s.node_; }
};

namespace {

// Appends the rows for `s` at `path`. `self_row` is false for list items and variant bodies,
// whose own row (the list's, the variant's) was already written.
void walk(const Node& s, const std::string& path, bool self_row, std::vector<Row>& rows) {
  switch (s.kind) {
    case Schema::Kind::Map:
      if (self_row && !path.empty())
        rows.push_back({path, "map", "", s.required ? "required" : "optional", "", s.doc});
      for (const auto& [name, field] : s.fields) walk(SchemaAccess::node(field), join(path, name), true, rows);
      break;
    case Schema::Kind::List: {
      const Node& item = SchemaAccess::node(*s.item);
      const bool leaf_item = item.kind != Schema::Kind::Map && item.kind != Schema::Kind::List &&
                             item.kind != Schema::Kind::Variant;
      std::string range = s.min_items > 0 ? fmt::format("at least {} item{}", s.min_items, s.min_items == 1 ? "" : "s")
                                           : std::string("any length");
      if (leaf_item && !leaf_range(item).empty() && leaf_range(item) != "any") range += "; each " + leaf_range(item);
      rows.push_back({path, "list of " + leaf_type(item), leaf_item ? item.unit : "",
                      s.min_items == 0 ? "[]" : "required", range, s.doc});
      if (!leaf_item) walk(item, path + "[]", false, rows);
      break;
    }
    case Schema::Kind::Variant: {
      const std::vector<std::string> names = names_of(s.variants);
      if (self_row) rows.push_back({path, "variant", "", s.default_tag ? "optional" : "required", "", s.doc});
      rows.push_back({join(path, s.tag), "choice", "", s.default_tag ? "\"" + *s.default_tag + "\"" : "required",
                      "one of: " + comma_list(names),
                      "Selects the kind of " + without_period(s.doc) + "; the fields of each kind follow."});
      for (const auto& [name, vmap] : s.variants) {
        const std::string vpath = fmt::format("{} ({}: {})", path, s.tag, name);
        rows.push_back({vpath, "map", "", "", "", vmap.doc()});
        walk(SchemaAccess::node(vmap), vpath, false, rows);
      }
      break;
    }
    default:
      if (self_row)
        rows.push_back({path, leaf_type(s), s.unit, default_text(s), leaf_range(s), s.doc});
      break;
  }
}

}  // namespace

std::string Schema::document(const std::string& title, int level) const {
  std::vector<Row> rows;
  walk(*node_, "", true, rows);
  // Markdown table cells cannot hold '|' or line breaks.
  const auto cell = [](std::string text) {
    std::string out;
    for (char c : text) {
      if (c == '|') out += "\\|";
      else if (c == '\n') out += ' ';
      else out += c;
    }
    return out;
  };
  std::string md = std::string(std::size_t(std::max(1, level)), '#') + " " + title + "\n\n";
  if (!node_->doc.empty()) md += node_->doc + "\n\n";
  md += "Keys marked `required` must be given; every other key may be left out and takes its default.\n\n";
  md += "| key | type | unit | default | accepted | description |\n";
  md += "|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
    md += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", cell(r.key), cell(r.type), cell(r.unit),
                      cell(r.default_value), cell(r.range), cell(r.doc));
  return md;
}

// ---------------------------------------------------------------------------------------------
// Command-line overrides

namespace {

// One step of an override path: a map key, an explicit list index ("[2]"), or a bare number
// ("2"), which indexes a list or names a map key depending on what is found there.
struct Step {
  enum Kind { Key, Index, Number } kind;
  std::string key;
  std::size_t index = 0;
};

[[noreturn]] void bad_override(const std::string& assignment, const std::string& why) {
  throw SceneError("--set", fmt::format("invalid override \"{}\": {}", assignment, why));
}

std::vector<Step> parse_steps(const std::string& assignment, const std::string& path) {
  static const std::regex segment(R"(([^\[\]]*)((\[[0-9]+\])*))");
  static const std::regex digits(R"([0-9]+)");
  std::vector<Step> steps;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    const std::string seg = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    std::smatch m;
    if (!std::regex_match(seg, m, segment) || (m[1].length() == 0 && (steps.empty() || m[2].length() == 0)))
      bad_override(assignment, "malformed key path; expected e.g. fluid.regions[1].level=0.5");
    const std::string name = m[1];
    if (!name.empty()) {
      if (std::regex_match(name, digits)) steps.push_back({Step::Number, name, std::stoul(name)});
      else steps.push_back({Step::Key, name, 0});
    }
    // Each "[n]" suffix is an explicit list index.
    const std::string indices = m[2];
    for (std::size_t p = 0; p < indices.size();) {
      const std::size_t close = indices.find(']', p);
      steps.push_back({Step::Index, "", std::stoul(indices.substr(p + 1, close - p - 1))});
      p = close + 1;
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return steps;
}

}  // namespace

void apply_override(YAML::Node& root, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos) bad_override(assignment, "expected key.path=value");
  const std::string path = assignment.substr(0, eq);
  if (path.empty()) bad_override(assignment, "empty key path");
  const std::vector<Step> steps = parse_steps(assignment, path);

  YAML::Node value;
  try {
    value = load_yaml_text(assignment.substr(eq + 1));
  } catch (const YamlTextRefused& e) {
    bad_override(assignment, std::string("cannot parse the value: ") + e.what());
  }
  if (const auto d = find_duplicate_key(value)) bad_override(assignment, "key " + d->path + " " + duplicate_key_message(*d));

  // An empty scene is a null node without storage; give it a map to hang keys on.
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);

  // Walk with reset(), never operator=: assigning one yaml-cpp node to another overwrites the
  // target's content, which would corrupt the scene while descending.
  YAML::Node cur;
  cur.reset(root);
  std::string where;  // the path walked so far, for messages
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const Step& step = steps[i];
    const bool last = i + 1 == steps.size();
    const bool as_index = step.kind == Step::Index || (step.kind == Step::Number && cur.IsSequence());
    if (as_index) {
      const std::string here = fmt::format("{}[{}]", where, step.index);
      if (!cur.IsSequence())
        bad_override(assignment, fmt::format("cannot index {} with [{}]: it is not a list",
                                             where.empty() ? "the scene" : quote(where), step.index));
      if (step.index >= cur.size())
        bad_override(assignment, fmt::format("list index {} is out of range: {} has {} items", step.index,
                                             quote(where), cur.size()));
      if (last) {
        cur[step.index] = value;
      } else {
        YAML::Node next = cur[step.index];
        cur.reset(next);
      }
      where = here;
    } else {
      const std::string here = join(where, step.key);
      // Null sections (`fluid:` with nothing under it) become maps; lists and scalars are refused
      // because yaml-cpp would silently turn them into maps.
      if (!cur.IsMap() && !cur.IsNull())
        bad_override(assignment, fmt::format("cannot set key {} inside {}: it is not a map", quote(step.key),
                                             where.empty() ? "the scene" : quote(where)));
      if (last) {
        cur[step.key] = value;
      } else {
        if (!cur[step.key].IsDefined()) cur[step.key] = YAML::Node(YAML::NodeType::Map);
        YAML::Node next = cur[step.key];
        cur.reset(next);
      }
      where = here;
    }
  }
}

}  // namespace slide::cases
