#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/export.h"
#include "framework/core/quantity.h"

namespace YAML {
class Node;
}  // namespace YAML

namespace fitfeel {
namespace scenario {
struct YamlAccess;  // the scene loader's, to put a CAD file's keys in a part (cad_parts.cc)
}  // namespace scenario

// A read-only view of one node of a scenario file that knows where it stands (file, line, column,
// key path) so that every check a framework or plugin makes on it fails with the same precise
// message: "file:line:column: key.path: expected ..., found ...". Plugins validate their own keys
// through it, so adding a surface type needs no change to the scenario parser.
//
// yaml-cpp stays behind this class (only the scenario loader and this file include it), so the
// model, plugin and installed headers that pass ConfigNode around do not depend on it.
class FITFEEL_API ConfigNode {
 public:
  ConfigNode(const YAML::Node& node, std::string file, std::string path);
  // Parses one YAML document from `text` (a scene, or a fragment in a test): the root node, its
  // positions reported in `file`. Syntax errors and a second document throw ScenarioError there.
  static ConfigNode Parse(std::string_view text, std::string file, std::string path = "");

  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  SourceLocation location() const;
  bool is_map() const;
  bool is_sequence() const;
  bool is_scalar() const;
  bool is_null() const;  // absent or written as null / nothing
  // Where `key` of this map is written (its key, not its value); this node's location if absent.
  SourceLocation KeyLocation(std::string_view key) const;

  // Keys of a map in file order; fails unless this is a map.
  std::vector<std::string> Keys() const;
  bool Has(std::string_view key) const;

  // Fails with "unknown key" (naming the allowed ones) if the map holds any other key.
  void ExpectOnlyKeys(const std::vector<std::string_view>& allowed) const;

  ConfigNode Child(std::string_view key) const;  // required
  std::optional<ConfigNode> Find(std::string_view key) const;
  std::vector<ConfigNode> Items() const;  // elements of a sequence

  // Scalar accessors on this node.
  std::string AsString() const;
  double AsQuantity(Dimension dimension) const;
  double AsQuantityIn(Dimension dimension, double min, double max, bool min_inclusive = true) const;
  long AsInteger(long min = std::numeric_limits<long>::min(),
                 long max = std::numeric_limits<long>::max()) const;
  std::uint64_t AsSeed() const;  // ParseSeed's (quantity.h)
  bool AsBool() const;
  std::string AsOneOf(const std::vector<std::string_view>& choices) const;

  // Shorthands for a required child.
  std::string String(std::string_view key) const { return Child(key).AsString(); }
  double Quantity(std::string_view key, Dimension dimension) const {
    return Child(key).AsQuantity(dimension);
  }
  double QuantityIn(std::string_view key, Dimension dimension, double min, double max) const {
    return Child(key).AsQuantityIn(dimension, min, max);
  }
  // Optional child with a default.
  double QuantityOr(std::string_view key, Dimension dimension, double fallback) const;
  std::string StringOr(std::string_view key, std::string fallback) const;

  // Throws ScenarioError at this node.
  [[noreturn]] void Fail(const std::string& expected, const std::string& found) const;
  // What this node holds, quoted for a message: "'20 mmm'", "a map", "nothing".
  std::string Describe() const;

 private:
  friend struct scenario::YamlAccess;
  const YAML::Node& node() const;

  std::shared_ptr<const YAML::Node> node_;
  std::string file_;
  std::string path_;
};

}  // namespace fitfeel
