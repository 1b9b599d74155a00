#include "cases/yaml_text.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace slide::cases {
namespace {

// Thrown from inside the event handler to stop the parse at the first problem.
struct Stop {
  std::string why;
};

// Counts the nodes of every document as a recursive walk would visit them: an alias counts the nodes of its anchor.
class ExpandedSize : public YAML::EventHandler {
 public:
  explicit ExpandedSize(const YamlLimits& limits) : limits_(limits) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string&) override {
    leaf(mark, anchor);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    for (const Open& o : open_)
      if (o.anchor == anchor)
        throw Stop{at(mark) + "an alias refers to the anchor that contains it: the node would contain itself"};
    const auto size = sizes_.find(anchor);
    add(mark, size == sizes_.end() ? 1 : size->second);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    start(mark, anchor);
  }
  void OnSequenceEnd() override { end(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    start(mark, anchor);
  }
  void OnMapEnd() override { end(); }

 private:
  struct Open {
    YAML::anchor_t anchor;
    std::size_t nodes;  // this collection and everything in it so far, aliases expanded
  };

  static std::string at(const YAML::Mark& mark) { return "line " + std::to_string(mark.line + 1) + ": "; }

  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor) {
    if (anchor != YAML::NullAnchor) sizes_[anchor] = 1;
    add(mark, 1);
  }
  void start(const YAML::Mark& mark, YAML::anchor_t anchor) {
    if (static_cast<int>(open_.size()) >= limits_.max_depth)
      throw Stop{at(mark) + "nested deeper than " + std::to_string(limits_.max_depth) + " levels"};
    open_.push_back({anchor, 0});
    add(mark, 1);
  }
  void end() {
    const Open closed = open_.back();
    open_.pop_back();
    if (closed.anchor != YAML::NullAnchor) sizes_[closed.anchor] = closed.nodes;
    if (!open_.empty()) open_.back().nodes += closed.nodes;
  }
  // `count` nodes join the innermost open collection (and the document's total).
  void add(const YAML::Mark& mark, std::size_t count) {
    if (count > limits_.max_nodes - std::min(total_, limits_.max_nodes))
      throw Stop{at(mark) + "the document stands for more than " + std::to_string(limits_.max_nodes) +
                 " nodes once its aliases are expanded"};
    total_ += count;
    if (!open_.empty()) open_.back().nodes += count;
  }

  const YamlLimits& limits_;
  std::vector<Open> open_;
  std::unordered_map<YAML::anchor_t, std::size_t> sizes_;
  std::size_t total_ = 0;
};

// Stops at the start of a document: used after the first one, which is all YAML::Load reads. A second document
// would be ignored without a word, and yaml-cpp 0.7 can return empty documents without end after some malformed text
// (the fuzzer found one), so the parse never goes past it.
class AnotherDocument : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override {
    throw Stop{"line " + std::to_string(mark.line + 1) +
               ": a second YAML document begins here: a file of slide holds one (no --- between documents)"};
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

}  // namespace

std::optional<std::string> yaml_text_problem(const std::string& text, const YamlLimits& limits) {
  if (text.size() > limits.max_bytes)
    return "the text is " + std::to_string(text.size()) + " bytes, more than the " + std::to_string(limits.max_bytes) +
           " a YAML file of slide may have";
  std::istringstream in(text);
  try {
    YAML::Parser parser(in);
    ExpandedSize size(limits);
    if (!parser.HandleNextDocument(size)) return std::nullopt;  // no document: an empty text
    AnotherDocument another;
    parser.HandleNextDocument(another);
  } catch (const Stop& s) {
    return s.why;
  } catch (const YAML::Exception& e) {
    return "not valid YAML: " + std::string(e.what());
  }
  return std::nullopt;
}

YAML::Node load_yaml_text(const std::string& text, const YamlLimits& limits) {
  if (const auto problem = yaml_text_problem(text, limits)) throw YamlTextRefused(*problem);
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw YamlTextRefused("not valid YAML: " + std::string(e.what()));
  }
}

}  // namespace slide::cases
