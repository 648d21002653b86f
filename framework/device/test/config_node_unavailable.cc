// Built into tests only while the framework has no ConfigNode implementation (it lands with the
// scenario module; see framework/device/CMakeLists.txt). Plugin sources compiled into tests
// reference ConfigNode from their DoConfigure; these definitions satisfy the link and refuse to
// run. No test built in that configuration parses YAML.
#include <stdexcept>

#include "framework/core/config_node.h"

namespace fitfeel {
namespace {

[[noreturn]] void Unavailable() {
  throw std::logic_error("ConfigNode is not implemented in this build (scenario module missing)");
}

}  // namespace

ConfigNode::ConfigNode(YAML::Node, std::string, std::string) { Unavailable(); }
SourceLocation ConfigNode::location() const { Unavailable(); }
bool ConfigNode::is_map() const { Unavailable(); }
bool ConfigNode::is_sequence() const { Unavailable(); }
bool ConfigNode::is_scalar() const { Unavailable(); }
std::vector<std::string> ConfigNode::Keys() const { Unavailable(); }
bool ConfigNode::Has(std::string_view) const { Unavailable(); }
void ConfigNode::ExpectOnlyKeys(const std::vector<std::string_view>&) const { Unavailable(); }
ConfigNode ConfigNode::Child(std::string_view) const { Unavailable(); }
std::optional<ConfigNode> ConfigNode::Find(std::string_view) const { Unavailable(); }
std::vector<ConfigNode> ConfigNode::Items() const { Unavailable(); }
std::string ConfigNode::AsString() const { Unavailable(); }
double ConfigNode::AsQuantity(Dimension) const { Unavailable(); }
double ConfigNode::AsQuantityIn(Dimension, double, double, bool) const { Unavailable(); }
long ConfigNode::AsInteger(long, long) const { Unavailable(); }
bool ConfigNode::AsBool() const { Unavailable(); }
std::string ConfigNode::AsOneOf(const std::vector<std::string_view>&) const { Unavailable(); }
double ConfigNode::QuantityOr(std::string_view, Dimension, double) const { Unavailable(); }
std::string ConfigNode::StringOr(std::string_view, std::string) const { Unavailable(); }
void ConfigNode::Fail(const std::string&, const std::string&) const { Unavailable(); }
std::string ConfigNode::Describe() const { Unavailable(); }
std::string FormatQuantity(double, Dimension) { Unavailable(); }

}  // namespace fitfeel
