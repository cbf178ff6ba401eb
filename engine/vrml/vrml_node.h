// The generic VRML97 node tree: what the parser produces before any conversion.
//
// Every node is typed by a NodeType (the built-in tables of ISO/IEC 14772-1 section 6,
// a PROTO's interface, or a Script's own declarations); field values are stored only
// where the file gives them, the rest come from the type's defaults. DEF/USE make the
// tree a DAG: one NodePtr referenced from several places. The parser registers a DEF
// name only once its node is complete, so a node can never contain itself and the
// graph has no cycles.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "engine/vrml/vrml_tokenizer.h"

namespace pw::engine::vrml {

enum class FieldType : uint8_t {
  kSFBool, kSFColor, kSFFloat, kSFImage, kSFInt32, kSFNode, kSFRotation, kSFString, kSFTime, kSFVec2f, kSFVec3f,
  kMFColor, kMFFloat, kMFInt32, kMFNode, kMFRotation, kMFString, kMFTime, kMFVec2f, kMFVec3f,
};

const char* fieldTypeName(FieldType type);
std::optional<FieldType> fieldTypeFromName(std::string_view name);
bool isMultiple(FieldType type);
bool isNodeType(FieldType type);  // SFNode, MFNode
// Numbers per value: 3 for SFColor/MFColor/SFVec3f, 4 for rotations, 1 for floats...
int componentCount(FieldType type);

enum class FieldAccess : uint8_t { kField, kExposedField, kEventIn, kEventOut };
const char* fieldAccessName(FieldAccess access);

struct Node;
using NodePtr = std::shared_ptr<Node>;

// One field's value. Which vector is used depends on the type:
//   ints:    SFBool (0/1), SFInt32, MFInt32, SFImage (width height components pixels...)
//   doubles: single-valued float types (SFFloat SFVec2f SFVec3f SFColor SFRotation) and
//            SFTime/MFTime; kept in double so that transforms compose without loss
//   floats:  multiple-valued float types (MFFloat MFVec2f MFVec3f MFColor MFRotation),
//            single precision as the standard defines them, for big arrays
//   strings: SFString, MFString
//   nodes:   SFNode (empty = NULL), MFNode; null entries are nodes that were skipped
struct FieldValue {
  std::vector<int32_t> ints;
  std::vector<double> doubles;
  std::vector<float> floats;
  std::vector<std::string> strings;
  std::vector<NodePtr> nodes;
};

struct FieldDecl {
  FieldAccess access = FieldAccess::kField;
  FieldType type = FieldType::kSFBool;
  std::string name;
  FieldValue defaultValue;  // empty for eventIn/eventOut
};

struct NodeType {
  std::string name;
  std::vector<FieldDecl> fields;

  // Index of a field or exposedField called `name`, or -1.
  int findField(std::string_view name) const;
  // Index of any interface member called `name`, accepting set_X / X_changed for an
  // exposedField X, or -1.
  int findMember(std::string_view name) const;
};

// Where a file came from; urls inside it resolve against `dir`.
struct SourceFile {
  std::filesystem::path path;  // as given, for messages
  std::filesystem::path dir;   // folder for relative urls
  std::string displayName;     // path.string(), cached
  // Where its urls may lead (README: What photowalk reads): the folder of the model
  // that was opened (an Inline's file keeps it) and any a person named. Empty: `dir`.
  std::vector<std::filesystem::path> folders;
};

struct Proto;

// "field IS protoField" inside a PROTO body (4.8.3): the field takes the value of the
// instance's (or the PROTO's default) interface field of that name.
struct IsMapping {
  uint16_t field = 0;
  std::string protoField;
};

struct Node {
  const NodeType* type = nullptr;  // never null
  const Proto* proto = nullptr;    // non-null for an instance of a PROTO/EXTERNPROTO
  std::vector<std::pair<uint16_t, FieldValue>> values;  // fields given in the file
  std::vector<IsMapping> isMappings;
  std::string defName;
  const SourceFile* file = nullptr;
  SourcePos pos;
  NodePtr expansion;  // proto instance: the expanded body, made on first use

  Node() = default;
  Node(const Node&) = default;
  Node& operator=(const Node&) = delete;
  // Releases children iteratively: a chain of 100000 nested Groups must not recurse.
  ~Node();

  const std::string& typeName() const { return type->name; }
  // The value given in the file, or the type's default.
  const FieldValue& field(int index) const;
  const FieldValue* given(int index) const;
  FieldValue& set(int index);
  // "file.wrl:12:3" for messages.
  std::string where() const;

  // Moves every child NodePtr (field values and expansion) into `out`.
  void takeChildren(std::vector<NodePtr>& out);
};

// A PROTO or EXTERNPROTO declaration. The interface is the node type of its instances.
struct Proto {
  NodeType interface;
  std::vector<NodePtr> body;  // PROTO: body[0] is what an instance becomes
  bool external = false;
  std::vector<std::string> urls;  // EXTERNPROTO
  const SourceFile* file = nullptr;
  SourcePos pos;
  // EXTERNPROTO, once resolved (lazily, by the scene conversion) to a PROTO in another
  // file; a cache, hence mutable.
  mutable const Proto* resolved = nullptr;
  mutable bool resolveFailed = false;
};

// Everything parsed from one file. Owns the nodes, protos and dynamic node types.
struct Document {
  std::shared_ptr<SourceFile> file;
  std::vector<NodePtr> roots;  // top-level node statements in order (null: skipped)
  std::vector<std::unique_ptr<Proto>> protos;       // all of them, nested ones included
  std::vector<std::unique_ptr<NodeType>> nodeTypes;  // Script nodes' own interfaces
  std::unordered_map<std::string, const Proto*> topLevelProtos;  // for EXTERNPROTO "file#Name"
  std::vector<std::shared_ptr<Document>> externals;  // documents EXTERNPROTOs resolved into

  Document() = default;
  Document(Document&&) = default;
  Document& operator=(Document&&) = default;
  ~Document();
};

// The VRML97 built-in node types (all 54 of section 6), or null for an unknown name.
const NodeType* builtinNodeType(std::string_view name);

}  // namespace pw::engine::vrml
