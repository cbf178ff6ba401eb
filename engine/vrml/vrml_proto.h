// PROTO instancing (ISO/IEC 14772-1, 4.8): an instance becomes a copy of the first
// node of its PROTO's body, with every "field IS protoField" taking the instance's
// value for that field (or the PROTO's default). DEF/USE inside the body stay shared
// inside each copy. Copies are made iteratively and counted, so that nested PROTOs
// that multiply (a "billion laughs" file) end in an error, not in exhausted memory.
#pragma once

#include <functional>

#include "base/result.h"
#include "engine/vrml/vrml_node.h"

namespace pw::engine::vrml {

class ProtoExpander {
 public:
  // Finds the PROTO an EXTERNPROTO stands for (loading its file), or null when it
  // cannot be found (the resolver reports why).
  using Resolver = std::function<const Proto*(const Proto& externProto)>;

  explicit ProtoExpander(Resolver resolver, size_t maxCopiedNodes = 1000000)
      : resolver_(std::move(resolver)), maxCopiedNodes_(maxCopiedNodes) {}

  // For a proto instance, the built-in node it expands to (following instances of
  // instances); null when the PROTO's first body node was skipped or an EXTERNPROTO
  // could not be resolved. Any other node is returned as is. The expansion is cached
  // in the instance, so a USEd instance expands once.
  Result<NodePtr> expand(const NodePtr& node);

 private:
  Result<NodePtr> copyBody(const Node& instance, const Proto& proto);

  Resolver resolver_;
  size_t maxCopiedNodes_;
  size_t copiedNodes_ = 0;
};

}  // namespace pw::engine::vrml
