// The VRML97 parser's internals, shared by vrml_parser.cpp (statements, nodes and
// fields) and vrml_parser_declarations.cpp (PROTO, EXTERNPROTO, ROUTE, Script
// interfaces). Not part of the library's interface: use vrml_parser.h.
#pragma once

#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "base/result.h"
#include "engine/vrml/diagnostics.h"
#include "engine/vrml/vrml_node.h"
#include "engine/vrml/vrml_tokenizer.h"

namespace pw::engine::vrml::detail {

// Frames deeper than this are refused: at about 400 bytes per nested node this is
// already hundreds of megabytes of nodes.
inline constexpr size_t kMaxDepth = 1000000;

class Parser {
 public:
  Parser(std::string_view text, Document& document, Diagnostics* diagnostics)
      : tokens_(text, SourcePos{}), doc_(document), file_(document.file.get()), diag_(diagnostics) {}

  Status run();

 private:
  enum class FrameKind { kScene, kProtoBody, kNodeList, kNode, kInterface };

  struct Frame {
    FrameKind kind = FrameKind::kScene;
    SourcePos open;
    std::vector<NodePtr> nodes;    // statement lists: what was parsed so far
    NodePtr node;                  // kNode
    NodeType* ownType = nullptr;   // kNode of a Script: its own interface, extended as declared
    std::string defName;           // kNode
    int pendingField = -1;         // kNode: the field a child frame or USE fills
    std::unique_ptr<Proto> proto;  // kInterface, kProtoBody
    bool pendingDefault = false;   // kInterface: the last declaration awaits a node value
  };

  struct Scope {
    std::unordered_map<std::string, NodePtr> defs;
    std::unordered_set<std::string> skippedDefs;  // DEFs of nodes that were skipped
    std::vector<std::string> protoNames;  // PROTOs declared here, to hide again on leaving
    const Proto* defining = nullptr;  // the PROTO whose body this scope is
  };

  Status stepStatements();
  Status stepNode();
  Status stepInterface();
  Status startNodeStatement(const char* context);
  // A node-valued field's value: an MFNode's '[' opens a node list, anything else is
  // one node statement (`context` says what was expected).
  Status beginNodeValue(FieldType type, const char* context);
  Status finishNode();
  Status beginProto();
  Status parseExternProto();
  Status parseRoute();
  Status parseScriptDeclaration();
  Status parseIs(Frame& frame, int member);
  Status parseInterfaceDeclaration(NodeType& type, std::string_view owner);
  Status skipBalanced(SourcePos open, std::string_view what);
  Status skipUnknownValue();
  Status push(Frame frame);

  void deliver(NodePtr node);
  void deliverList(std::vector<NodePtr> nodes);
  const Proto* findProto(std::string_view name) const;
  // Makes a PROTO visible in the current scope (replacing one of the same name there).
  void declareProto(const std::string& name, const Proto* proto);
  void leaveScope();
  Scope& scope() { return scopes_.back(); }

  Result<Token> expect(TokenKind kind, const char* what);
  Result<std::string> expectIdentifier(const char* what);
  Error errorHere(const Token& found, const std::string& expected) const;
  std::string at(SourcePos pos) const {
    return file_->displayName + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column);
  }

  Tokenizer tokens_;
  Document& doc_;
  const SourceFile* file_;
  Diagnostics* diag_;
  std::vector<Frame> stack_;
  std::vector<Scope> scopes_;
  // PROTO name -> the declarations visible now, innermost last, with the scope depth
  // each was declared at: a lookup is one hash probe however deep the nesting.
  std::unordered_map<std::string, std::vector<std::pair<size_t, const Proto*>>> visibleProtos_;
  bool routeNoted_ = false;
};

}  // namespace pw::engine::vrml::detail
