#include "engine/vrml/vrml_node.h"

#include <array>

namespace pw::engine::vrml {

namespace {
constexpr std::array<const char*, 20> kFieldTypeNames = {
    "SFBool", "SFColor", "SFFloat", "SFImage", "SFInt32", "SFNode", "SFRotation", "SFString", "SFTime", "SFVec2f",
    "SFVec3f", "MFColor", "MFFloat", "MFInt32", "MFNode", "MFRotation", "MFString", "MFTime", "MFVec2f", "MFVec3f",
};
}  // namespace

const char* fieldTypeName(FieldType type) { return kFieldTypeNames[static_cast<size_t>(type)]; }

std::optional<FieldType> fieldTypeFromName(std::string_view name) {
  for (size_t i = 0; i < kFieldTypeNames.size(); ++i) {
    if (name == kFieldTypeNames[i]) return static_cast<FieldType>(i);
  }
  return std::nullopt;
}

bool isMultiple(FieldType type) { return type >= FieldType::kMFColor; }

bool isNodeType(FieldType type) { return type == FieldType::kSFNode || type == FieldType::kMFNode; }

int componentCount(FieldType type) {
  switch (type) {
    case FieldType::kSFVec2f: case FieldType::kMFVec2f: return 2;
    case FieldType::kSFVec3f: case FieldType::kMFVec3f: case FieldType::kSFColor: case FieldType::kMFColor: return 3;
    case FieldType::kSFRotation: case FieldType::kMFRotation: return 4;
    default: return 1;
  }
}

const char* fieldAccessName(FieldAccess access) {
  switch (access) {
    case FieldAccess::kField: return "field";
    case FieldAccess::kExposedField: return "exposedField";
    case FieldAccess::kEventIn: return "eventIn";
    case FieldAccess::kEventOut: return "eventOut";
  }
  return "?";
}

int NodeType::findField(std::string_view name) const {
  for (size_t i = 0; i < fields.size(); ++i) {
    const FieldDecl& f = fields[i];
    if ((f.access == FieldAccess::kField || f.access == FieldAccess::kExposedField) && f.name == name) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

int NodeType::findMember(std::string_view name) const {
  for (size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].name == name) return static_cast<int>(i);
  }
  // 4.10.2: an exposedField X also has the eventIn set_X and the eventOut X_changed.
  constexpr std::string_view kSet = "set_", kChanged = "_changed";
  std::string_view base;
  if (name.substr(0, kSet.size()) == kSet) {
    base = name.substr(kSet.size());
  } else if (name.size() > kChanged.size() && name.substr(name.size() - kChanged.size()) == kChanged) {
    base = name.substr(0, name.size() - kChanged.size());
  } else {
    return -1;
  }
  for (size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].access == FieldAccess::kExposedField && fields[i].name == base) return static_cast<int>(i);
  }
  return -1;
}

const FieldValue* Node::given(int index) const {
  for (const auto& [i, value] : values) {
    if (i == index) return &value;
  }
  return nullptr;
}

const FieldValue& Node::field(int index) const {
  const FieldValue* v = given(index);
  return v ? *v : type->fields[static_cast<size_t>(index)].defaultValue;
}

FieldValue& Node::set(int index) {
  for (auto& [i, value] : values) {
    if (i == index) {
      value = FieldValue{};
      return value;
    }
  }
  values.emplace_back(static_cast<uint16_t>(index), FieldValue{});
  return values.back().second;
}

std::string Node::where() const {
  return (file ? file->displayName : std::string("<input>")) + ":" + std::to_string(pos.line) + ":" +
         std::to_string(pos.column);
}

void Node::takeChildren(std::vector<NodePtr>& out) {
  for (auto& [index, value] : values) {
    for (NodePtr& child : value.nodes) {
      if (child) out.push_back(std::move(child));
    }
    value.nodes.clear();
  }
  if (expansion) out.push_back(std::move(expansion));
}

Node::~Node() {
  std::vector<NodePtr> pending;
  takeChildren(pending);
  while (!pending.empty()) {
    NodePtr node = std::move(pending.back());
    pending.pop_back();
    // Only the last owner empties the node, so that its destructor (run right here,
    // when `node` goes out of scope) has nothing left to recurse into.
    if (node.use_count() == 1) node->takeChildren(pending);
  }
}

Document::~Document() {
  // Nodes first: they point at protos and node types owned here.
  roots.clear();
  for (auto& proto : protos) proto->body.clear();
}

}  // namespace pw::engine::vrml
