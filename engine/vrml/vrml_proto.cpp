#include "engine/vrml/vrml_proto.h"

#include <unordered_map>

namespace pw::engine::vrml {

namespace {
// Instances whose PROTO body starts with another instance, and so on. Real files
// nest a few levels; a file that EXTERNPROTOs itself would go on forever.
constexpr int kMaxInstanceChain = 64;
}  // namespace

Result<NodePtr> ProtoExpander::expand(const NodePtr& node) {
  NodePtr current = node;
  int chain = 0;
  while (current && current->proto) {
    if (current->expansion) {
      current = current->expansion;
      continue;
    }
    if (++chain > kMaxInstanceChain) {
      return makeError(current->where() + ": PROTO instances nest more than " + std::to_string(kMaxInstanceChain) +
                       " deep (a PROTO that instantiates itself through EXTERNPROTO?)");
    }
    const Proto* proto = current->proto;
    if (proto->external) {
      proto = resolver_ ? resolver_(*proto) : nullptr;
      if (!proto) return NodePtr{};
    }
    if (proto->body.empty() || !proto->body[0]) return NodePtr{};
    auto copy = copyBody(*current, *proto);
    if (!copy) return copy.error();
    current->expansion = *copy;
    current = std::move(*copy);
  }
  return current;
}

Result<NodePtr> ProtoExpander::copyBody(const Node& instance, const Proto& proto) {
  // 1. The body's nodes reachable from its first node, each once (DEF/USE keeps sharing).
  std::unordered_map<const Node*, NodePtr> copies;
  std::vector<const Node*> pending{proto.body[0].get()};
  std::vector<const Node*> order;
  while (!pending.empty()) {
    const Node* n = pending.back();
    pending.pop_back();
    if (copies.count(n)) continue;
    if (++copiedNodes_ > maxCopiedNodes_) {
      return makeError(instance.where() + ": expanding PROTO " + proto.interface.name + " needs more than " +
                       std::to_string(maxCopiedNodes_) + " node copies; photowalk refuses it");
    }
    auto copy = std::make_shared<Node>(*n);
    copy->expansion.reset();
    copies.emplace(n, std::move(copy));
    order.push_back(n);
    for (const auto& [index, value] : n->values) {
      for (const NodePtr& child : value.nodes) {
        if (child && !copies.count(child.get())) pending.push_back(child.get());
      }
    }
  }
  // 2. Point the copies at each other, then fill the IS fields from the instance.
  for (const Node* original : order) {
    Node& copy = *copies.at(original);
    for (auto& [index, value] : copy.values) {
      for (NodePtr& child : value.nodes) {
        if (child) child = copies.at(child.get());
      }
    }
    for (const IsMapping& mapping : copy.isMappings) {
      const FieldDecl& decl = copy.type->fields[mapping.field];
      if (decl.access == FieldAccess::kEventIn || decl.access == FieldAccess::kEventOut) continue;
      const FieldValue* value = nullptr;
      const int given = instance.type->findMember(mapping.protoField);
      if (given >= 0) value = instance.given(given);
      if (!value) {
        const int declared = proto.interface.findMember(mapping.protoField);
        if (declared < 0) continue;  // checked when the PROTO was parsed or resolved
        value = &proto.interface.fields[static_cast<size_t>(declared)].defaultValue;
      }
      copy.set(mapping.field) = *value;
    }
    copy.isMappings.clear();
  }
  return copies.at(proto.body[0].get());
}

}  // namespace pw::engine::vrml
