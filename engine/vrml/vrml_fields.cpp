#include "engine/vrml/vrml_fields.h"

#include <cassert>

namespace pw::engine::vrml {

namespace {
const FieldValue kEmpty;
const NodePtr kNullNode;
const std::string kEmptyString;

double component(const FieldValue& v, size_t i) { return i < v.doubles.size() ? v.doubles[i] : 0.0; }
}  // namespace

const FieldValue& fieldOf(const Node& node, std::string_view name) {
  const int index = node.type->findField(name);
  assert(index >= 0 && "field not in the node type");
  return index >= 0 ? node.field(index) : kEmpty;
}

bool getBool(const Node& node, std::string_view name) {
  const FieldValue& v = fieldOf(node, name);
  return !v.ints.empty() && v.ints[0] != 0;
}

int32_t getInt(const Node& node, std::string_view name) {
  const FieldValue& v = fieldOf(node, name);
  return v.ints.empty() ? 0 : v.ints[0];
}

double getDouble(const Node& node, std::string_view name) { return component(fieldOf(node, name), 0); }

glm::dvec2 getVec2(const Node& node, std::string_view name) {
  const FieldValue& v = fieldOf(node, name);
  return {component(v, 0), component(v, 1)};
}

glm::dvec3 getVec3(const Node& node, std::string_view name) {
  const FieldValue& v = fieldOf(node, name);
  return {component(v, 0), component(v, 1), component(v, 2)};
}

glm::dvec4 getVec4(const Node& node, std::string_view name) {
  const FieldValue& v = fieldOf(node, name);
  return {component(v, 0), component(v, 1), component(v, 2), component(v, 3)};
}

const std::string& getString(const Node& node, std::string_view name) {
  const FieldValue& v = fieldOf(node, name);
  return v.strings.empty() ? kEmptyString : v.strings[0];
}

const std::vector<std::string>& getStrings(const Node& node, std::string_view name) {
  return fieldOf(node, name).strings;
}

const std::vector<float>& getFloats(const Node& node, std::string_view name) { return fieldOf(node, name).floats; }

const std::vector<int32_t>& getInts(const Node& node, std::string_view name) { return fieldOf(node, name).ints; }

const NodePtr& getNode(const Node& node, std::string_view name) {
  const FieldValue& v = fieldOf(node, name);
  return v.nodes.empty() ? kNullNode : v.nodes[0];
}

const std::vector<NodePtr>& getNodes(const Node& node, std::string_view name) { return fieldOf(node, name).nodes; }

}  // namespace pw::engine::vrml
