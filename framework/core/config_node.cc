#include "framework/core/config_node.h"

#include <charconv>
#include <cmath>
#include <set>
#include <sstream>
#include <system_error>
#include <utility>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include "framework/core/quantity_parse.h"

namespace fitfeel {
namespace {

std::string JoinPath(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

std::string Join(const std::vector<std::string_view>& items) {
  std::string out;
  for (std::string_view item : items) out += (out.empty() ? "" : ", ") + std::string(item);
  return out;
}

// yaml-cpp marks are 0-based; editors and compilers count from 1.
SourceLocation LocationOf(const YAML::Mark& mark, const std::string& file) {
  if (mark.is_null() || mark.line < 0) return SourceLocation{file, 0, 0};
  return SourceLocation{file, mark.line + 1, mark.column + 1};
}

// Where the root node of each YAML document of `text` is, up to the third (a caller refuses a
// second document; the third tells a second document from a token the parser cannot get past).
// A document whose root is where the one before it was is such a token: refused as the syntax
// error it is, where it is.
std::vector<YAML::Mark> DocumentRoots(const std::string& text) {
  class Roots final : public YAML::EventHandler {
   public:
    std::vector<YAML::Mark> marks;
    void OnDocumentStart(const YAML::Mark&) override { root_ = true; }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { Node(mark); }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { Node(mark); }
    void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  const std::string&) override {
      Node(mark);
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {
      Node(mark);
    }
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                    YAML::EmitterStyle::value) override {
      Node(mark);
    }
    void OnMapEnd() override {}

   private:
    void Node(const YAML::Mark& mark) {
      if (root_) marks.push_back(mark);
      root_ = false;
    }
    bool root_ = false;
  };
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  Roots roots;
  while (roots.marks.size() < 3 && parser.HandleNextDocument(roots)) {
    const std::size_t n = roots.marks.size();
    if (n >= 2 && roots.marks[n - 1].pos == roots.marks[n - 2].pos) {
      throw YAML::ParserException(roots.marks[n - 1], "a token that starts no YAML node");
    }
  }
  return roots.marks;
}

std::string RangeText(Dimension dimension, double min, double max, bool min_inclusive) {
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  const std::string lo = FormatQuantity(min, dimension);
  const std::string hi = FormatQuantity(max, dimension);
  if (has_min && has_max) return (min_inclusive ? "in [" : "in (") + lo + ", " + hi + "]";
  if (has_min) return (min_inclusive ? ">= " : "> ") + lo;
  if (has_max) return "<= " + hi;
  return "";
}

// " (too large)" where `text` is digits past what a T holds, for a refusal's "found" (the
// integer and seed accessors share it).
template <typename T>
std::string TooLargeNote(const std::string& text) {
  T ignored = 0;
  const bool too_large =
      !text.empty() && std::from_chars(text.data() + (text[0] == '+'), text.data() + text.size(),
                                       ignored)
                               .ec == std::errc::result_out_of_range;
  return too_large ? " (too large)" : "";
}

}  // namespace

ConfigNode::ConfigNode(const YAML::Node& node, std::string file, std::string path)
    : node_(std::make_shared<const YAML::Node>(node)),
      file_(std::move(file)),
      path_(std::move(path)) {}

ConfigNode ConfigNode::Parse(std::string_view text, std::string file, std::string path) {
  YAML::Node root;
  try {
    // The documents are counted by their roots first, then the first is built (YAML::Load reads
    // one document). Not LoadAll: yaml-cpp 0.7 (Debian 12's) never ends it on a document that
    // starts with a token no node can start with (",", "!,", "&a ,"): each document comes back
    // empty at that token without consuming it, and LoadAll keeps them until memory runs out
    // (fixed upstream after 0.8, yaml-cpp pull request 1319; found here by the scenario fuzzer).
    const std::string owned(text);
    const std::vector<YAML::Mark> roots = DocumentRoots(owned);
    if (roots.size() > 1) {
      throw ScenarioError(LocationOf(roots[1], file), path,
                          "one scene per file (a single YAML document)", "a second document");
    }
    root = YAML::Load(owned);
  } catch (const YAML::Exception& e) {
    // yaml-cpp's own wording of the syntax error (e.g. "end of map not found") is what was found.
    throw ScenarioError(LocationOf(e.mark, file), path, "valid YAML", e.msg);
  }
  return ConfigNode(root, std::move(file), std::move(path));
}

const YAML::Node& ConfigNode::node() const { return *node_; }

bool ConfigNode::is_null() const { return !node().IsDefined() || node().IsNull(); }

SourceLocation ConfigNode::KeyLocation(std::string_view key) const {
  if (is_map()) {
    for (const auto& item : node()) {
      if (item.first.IsScalar() && item.first.Scalar() == key) {
        return LocationOf(item.first.Mark(), file_);
      }
    }
  }
  return location();
}

SourceLocation ConfigNode::location() const { return LocationOf(node().Mark(), file_); }

bool ConfigNode::is_map() const { return node().IsDefined() && node().IsMap(); }
bool ConfigNode::is_sequence() const { return node().IsDefined() && node().IsSequence(); }
bool ConfigNode::is_scalar() const { return node().IsDefined() && node().IsScalar(); }

std::string ConfigNode::Describe() const {
  if (!node().IsDefined() || node().IsNull()) return "nothing";
  if (node().IsMap()) return "a map";
  if (node().IsSequence()) return "a list";
  return "'" + node().Scalar() + "'";
}

void ConfigNode::Fail(const std::string& expected, const std::string& found) const {
  throw ScenarioError(location(), path_, expected, found);
}

std::vector<std::string> ConfigNode::Keys() const {
  if (!is_map()) Fail("a map", Describe());
  std::vector<std::string> keys;
  std::set<std::string> seen;
  for (const auto& item : node()) {
    const YAML::Node& key = item.first;
    if (!key.IsScalar()) {
      throw ScenarioError(LocationOf(key.Mark(), file_), path_, "a plain key (a name)",
                          key.IsMap() ? "a map as a key" : "a list as a key");
    }
    // yaml-cpp 0.7 keeps both entries of a repeated key and lookups see only the first, so a
    // repeated key would silently drop a value the user wrote.
    if (!seen.insert(key.Scalar()).second) {
      throw ScenarioError(LocationOf(key.Mark(), file_), JoinPath(path_, key.Scalar()),
                          "each key once", "'" + key.Scalar() + "' a second time");
    }
    keys.push_back(key.Scalar());
  }
  return keys;
}

bool ConfigNode::Has(std::string_view key) const {
  if (!is_map()) return false;
  for (const auto& item : node()) {
    if (item.first.IsScalar() && item.first.Scalar() == key) return true;
  }
  return false;
}

void ConfigNode::ExpectOnlyKeys(const std::vector<std::string_view>& allowed) const {
  Keys();  // map, plain keys, no repeats
  for (const auto& item : node()) {
    const std::string& key = item.first.Scalar();
    bool known = false;
    for (std::string_view a : allowed) known = known || a == key;
    if (!known) {
      throw ScenarioError(LocationOf(item.first.Mark(), file_), JoinPath(path_, key),
                          allowed.empty() ? "no keys here" : "one of the keys " + Join(allowed),
                          "unknown key '" + key + "'");
    }
  }
}

std::optional<ConfigNode> ConfigNode::Find(std::string_view key) const {
  if (!is_map()) Fail("a map", Describe());
  for (const auto& item : node()) {
    if (item.first.IsScalar() && item.first.Scalar() == key) {
      return ConfigNode(item.second, file_, JoinPath(path_, key));
    }
  }
  return std::nullopt;
}

ConfigNode ConfigNode::Child(std::string_view key) const {
  std::optional<ConfigNode> child = Find(key);
  if (!child) {
    // Reported where the enclosing map starts: that is where the key has to be added.
    std::string present;
    for (const auto& item : node()) {
      if (item.first.IsScalar()) present += (present.empty() ? "" : ", ") + item.first.Scalar();
    }
    throw ScenarioError(location(), JoinPath(path_, key),
                        "key '" + std::string(key) + "' (required)",
                        present.empty() ? "an empty map" : "only the keys " + present);
  }
  return *child;
}

std::vector<ConfigNode> ConfigNode::Items() const {
  if (!is_sequence()) Fail("a list", Describe());
  std::vector<ConfigNode> items;
  for (std::size_t i = 0; i < node().size(); ++i) {
    items.emplace_back(node()[i], file_, path_ + "[" + std::to_string(i) + "]");
  }
  return items;
}

std::string ConfigNode::AsString() const {
  if (!is_scalar()) Fail("a text value", Describe());
  return node().Scalar();
}

double ConfigNode::AsQuantity(Dimension dimension) const {
  if (!is_scalar()) Fail(DescribeDimension(dimension), Describe());
  internal::QuantityParse parsed = internal::TryParseQuantity(node().Scalar(), dimension);
  if (!parsed.problem.empty()) Fail(DescribeDimension(dimension), parsed.problem);
  return parsed.value;
}

double ConfigNode::AsQuantityIn(Dimension dimension, double min, double max,
                                bool min_inclusive) const {
  const double value = AsQuantity(dimension);
  const bool above = min_inclusive ? value >= min : value > min;
  if (!above || value > max) {
    Fail(internal::DimensionName(dimension) + " " + RangeText(dimension, min, max, min_inclusive),
         Describe());
  }
  return value;
}

long ConfigNode::AsInteger(long min, long max) const {
  const std::string expected = DescribeIntegerRange(min, max);
  if (!is_scalar()) Fail(expected, Describe());
  const std::string& text = node().Scalar();
  const std::optional<long> value = ParseInteger(text, min, max);
  if (!value) {
    Fail(expected, Describe() + TooLargeNote<long>(text));
  }
  return *value;
}

std::uint64_t ConfigNode::AsSeed() const {
  if (!is_scalar()) Fail(kSeedRange, Describe());
  const std::string& text = node().Scalar();
  const std::optional<std::uint64_t> value = ParseSeed(text);
  if (!value) {
    Fail(kSeedRange, Describe() + TooLargeNote<std::uint64_t>(text));
  }
  return *value;
}

bool ConfigNode::AsBool() const {
  if (!is_scalar()) Fail("true or false", Describe());
  bool value = false;
  if (!YAML::convert<bool>::decode(node(), value)) Fail("true or false", Describe());
  return value;
}

std::string ConfigNode::AsOneOf(const std::vector<std::string_view>& choices) const {
  const std::string expected = "one of " + Join(choices);
  if (!is_scalar()) Fail(expected, Describe());
  const std::string& text = node().Scalar();
  for (std::string_view choice : choices) {
    if (choice == text) return text;
  }
  Fail(expected, Describe());
}

double ConfigNode::QuantityOr(std::string_view key, Dimension dimension, double fallback) const {
  std::optional<ConfigNode> child = Find(key);
  return child ? child->AsQuantity(dimension) : fallback;
}

std::string ConfigNode::StringOr(std::string_view key, std::string fallback) const {
  std::optional<ConfigNode> child = Find(key);
  return child ? child->AsString() : std::move(fallback);
}

}  // namespace fitfeel
