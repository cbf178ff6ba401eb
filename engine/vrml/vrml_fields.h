// Typed reads of a built-in node's fields by name, falling back to the standard's
// default when the file does not give one. Used by the scene conversion, which only
// reads nodes whose types come from the built-in table (PROTO instances are expanded
// first), so a name missing from the type is a programming error caught in tests.
#pragma once

#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "engine/vrml/vrml_node.h"

namespace pw::engine::vrml {

const FieldValue& fieldOf(const Node& node, std::string_view name);

bool getBool(const Node& node, std::string_view name);
int32_t getInt(const Node& node, std::string_view name);
double getDouble(const Node& node, std::string_view name);    // SFFloat, SFTime
glm::dvec2 getVec2(const Node& node, std::string_view name);  // SFVec2f
glm::dvec3 getVec3(const Node& node, std::string_view name);  // SFVec3f, SFColor
glm::dvec4 getVec4(const Node& node, std::string_view name);  // SFRotation
const std::string& getString(const Node& node, std::string_view name);  // "" when absent
const std::vector<std::string>& getStrings(const Node& node, std::string_view name);
const std::vector<float>& getFloats(const Node& node, std::string_view name);  // MF float types
const std::vector<int32_t>& getInts(const Node& node, std::string_view name);   // MFInt32, SFImage
const NodePtr& getNode(const Node& node, std::string_view name);                // SFNode (may be null)
const std::vector<NodePtr>& getNodes(const Node& node, std::string_view name);  // MFNode

}  // namespace pw::engine::vrml
