// Statements, nodes and field values (ISO/IEC 14772-1, Annex A); the declarations
// (PROTO, EXTERNPROTO, ROUTE, Script interfaces) are in vrml_parser_declarations.cpp.
#include "engine/vrml/vrml_parser.h"

#include "engine/vrml/vrml_field_parser.h"
#include "engine/vrml/vrml_parser_internal.h"

namespace pw::engine::vrml {

namespace detail {

Error Parser::errorHere(const Token& found, const std::string& expected) const {
  if (found.kind == TokenKind::kInvalid) return errorAt(file_->displayName, found.pos, describe(found));
  return errorAt(file_->displayName, found.pos, "expected " + expected + ", found " + describe(found));
}

Result<Token> Parser::expect(TokenKind kind, const char* what) {
  const Token& t = tokens_.peek();
  if (t.kind != kind) return errorHere(t, what);
  return tokens_.next();
}

Result<std::string> Parser::expectIdentifier(const char* what) {
  const Token& t = tokens_.peek();
  if (t.kind != TokenKind::kIdentifier) return errorHere(t, what);
  return std::string(tokens_.next().text);
}

Status Parser::push(Frame frame) {
  if (stack_.size() >= kMaxDepth) {
    return errorAt(file_->displayName, frame.open,
                   "nodes are nested more than " + std::to_string(kMaxDepth) + " deep; photowalk refuses such files");
  }
  stack_.push_back(std::move(frame));
  return {};
}

const Proto* Parser::findProto(std::string_view name) const {
  auto found = visibleProtos_.find(std::string(name));
  return found == visibleProtos_.end() || found->second.empty() ? nullptr : found->second.back().second;
}

void Parser::declareProto(const std::string& name, const Proto* proto) {
  auto& declarations = visibleProtos_[name];
  if (!declarations.empty() && declarations.back().first == scopes_.size()) {
    declarations.back().second = proto;  // a later PROTO of the same name in the same scope wins
    return;
  }
  declarations.emplace_back(scopes_.size(), proto);
  scope().protoNames.push_back(name);
}

void Parser::leaveScope() {
  for (const std::string& name : scope().protoNames) {
    auto found = visibleProtos_.find(name);
    found->second.pop_back();
    if (found->second.empty()) visibleProtos_.erase(found);
  }
  scopes_.pop_back();
}

Status Parser::run() {
  scopes_.emplace_back();
  Frame scene;
  scene.kind = FrameKind::kScene;
  stack_.push_back(std::move(scene));
  while (!stack_.empty()) {
    Status step;
    switch (stack_.back().kind) {
      case FrameKind::kScene:
      case FrameKind::kProtoBody:
      case FrameKind::kNodeList: step = stepStatements(); break;
      case FrameKind::kNode: step = stepNode(); break;
      case FrameKind::kInterface: step = stepInterface(); break;
    }
    if (!step) return step;
  }
  return {};
}

void Parser::deliver(NodePtr node) {
  Frame& f = stack_.back();
  switch (f.kind) {
    case FrameKind::kScene:
    case FrameKind::kNodeList:
      if (node) f.nodes.push_back(std::move(node));
      break;
    case FrameKind::kProtoBody:
      // Keep skipped nodes as null: the first body node decides what an instance is.
      f.nodes.push_back(std::move(node));
      break;
    case FrameKind::kNode: {
      FieldValue& value = f.node->set(f.pendingField);
      if (node) value.nodes.push_back(std::move(node));
      f.pendingField = -1;
      break;
    }
    case FrameKind::kInterface: {
      FieldValue& value = f.proto->interface.fields.back().defaultValue;
      value.nodes.clear();
      if (node) value.nodes.push_back(std::move(node));
      f.pendingDefault = false;
      break;
    }
  }
}

void Parser::deliverList(std::vector<NodePtr> nodes) {
  Frame& f = stack_.back();
  if (f.kind == FrameKind::kNode) {
    f.node->set(f.pendingField).nodes = std::move(nodes);
    f.pendingField = -1;
  } else if (f.kind == FrameKind::kInterface) {
    f.proto->interface.fields.back().defaultValue.nodes = std::move(nodes);
    f.pendingDefault = false;
  }
}

Status Parser::stepStatements() {
  Frame& f = stack_.back();
  const Token& t = tokens_.peek();
  if (t.kind == TokenKind::kEnd && f.kind == FrameKind::kScene) {
    doc_.roots = std::move(f.nodes);
    stack_.pop_back();
    return {};
  }
  if (t.kind == TokenKind::kCloseBrace && f.kind == FrameKind::kProtoBody) {
    tokens_.next();
    std::unique_ptr<Proto> proto = std::move(f.proto);
    proto->body = std::move(f.nodes);
    if (proto->body.empty()) {
      return errorAt(file_->displayName, t.pos, "the body of PROTO " + proto->interface.name + " (opened at " +
                                                    at(f.open) + ") has no node; it needs at least one");
    }
    stack_.pop_back();
    leaveScope();
    const Proto* registered = proto.get();
    declareProto(proto->interface.name, registered);
    if (scopes_.size() == 1) doc_.topLevelProtos[proto->interface.name] = registered;
    doc_.protos.push_back(std::move(proto));
    return {};
  }
  if (t.kind == TokenKind::kCloseBracket && f.kind == FrameKind::kNodeList) {
    tokens_.next();
    std::vector<NodePtr> nodes = std::move(f.nodes);
    stack_.pop_back();
    deliverList(std::move(nodes));
    return {};
  }
  if (t.kind == TokenKind::kEnd || t.kind == TokenKind::kInvalid) {
    if (f.kind == FrameKind::kProtoBody) {
      return errorHere(t, "'}' to close the body of PROTO " + f.proto->interface.name + " opened at " + at(f.open));
    }
    return errorHere(t, "']' to close the list opened at " + at(f.open));
  }
  if (f.kind != FrameKind::kNodeList && t.kind == TokenKind::kIdentifier) {
    if (t.text == "PROTO") return beginProto();
    if (t.text == "EXTERNPROTO") return parseExternProto();
    if (t.text == "ROUTE") return parseRoute();
  }
  return startNodeStatement(f.kind == FrameKind::kNodeList ? "a node, USE or ']'" : "a node, PROTO or ROUTE");
}

Status Parser::skipBalanced(SourcePos open, std::string_view what) {
  int depth = 1;
  while (depth > 0) {
    const Token t = tokens_.next();
    switch (t.kind) {
      case TokenKind::kOpenBrace:
      case TokenKind::kOpenBracket: ++depth; break;
      case TokenKind::kCloseBrace:
      case TokenKind::kCloseBracket: --depth; break;
      case TokenKind::kIdentifier:
        // A later USE of a name defined in skipped text refers to nothing, quietly.
        if (t.text == "DEF" && tokens_.peek().kind == TokenKind::kIdentifier) {
          scope().skippedDefs.insert(std::string(tokens_.next().text));
        }
        break;
      case TokenKind::kEnd:
        return errorHere(t, "'}' to close " + std::string(what) + " opened at " + at(open));
      case TokenKind::kInvalid:
        return errorHere(t, "");
      default: break;
    }
  }
  return {};
}

Status Parser::beginNodeValue(FieldType type, const char* context) {
  if (type == FieldType::kMFNode && tokens_.peek().kind == TokenKind::kOpenBracket) {
    Frame list;
    list.kind = FrameKind::kNodeList;
    list.open = tokens_.next().pos;
    return push(std::move(list));
  }
  return startNodeStatement(context);
}

Status Parser::startNodeStatement(const char* context) {
  const Token first = tokens_.peek();
  if (first.kind != TokenKind::kIdentifier) return errorHere(first, context);
  tokens_.next();
  std::string defName;
  if (first.text == "USE") {
    auto name = expectIdentifier("a node name after USE");
    if (!name) return name.error();
    auto found = scope().defs.find(*name);
    if (found != scope().defs.end()) {
      deliver(found->second);
      return {};
    }
    if (scope().skippedDefs.count(*name)) {
      deliver(nullptr);
      return {};
    }
    return errorAt(file_->displayName, first.pos, "USE " + *name + " refers to no node: no DEF " + *name +
                                                      " precedes it" + (scopes_.size() > 1 ? " in this PROTO body" : ""));
  }
  if (first.text == "NULL") {
    const Frame& f = stack_.back();
    const bool sfNode = f.kind == FrameKind::kNode && f.pendingField >= 0 &&
                        f.node->type->fields[static_cast<size_t>(f.pendingField)].type == FieldType::kSFNode;
    if (!sfNode && f.kind != FrameKind::kInterface) return errorHere(first, context);
    deliver(nullptr);
    return {};
  }
  Token typeToken = first;
  if (first.text == "DEF") {
    auto name = expectIdentifier("a node name after DEF");
    if (!name) return name.error();
    defName = std::move(*name);
    if (tokens_.peek().kind != TokenKind::kIdentifier) return errorHere(tokens_.peek(), "a node type after DEF " + defName);
    typeToken = tokens_.next();
  }
  const std::string typeName(typeToken.text);
  if (tokens_.peek().kind != TokenKind::kOpenBrace) {
    if (!defName.empty() || builtinNodeType(typeName) || findProto(typeName)) {
      return errorHere(tokens_.peek(), "'{' after the node type " + typeName);
    }
    return errorHere(typeToken, context);
  }
  const Token open = tokens_.next();

  const Proto* proto = findProto(typeName);
  const NodeType* type = proto ? &proto->interface : builtinNodeType(typeName);
  if (!type) {
    if (diag_) diag_->warn(at(typeToken.pos) + ": unknown node type " + typeName + "; skipped");
    PW_TRY(skipBalanced(open.pos, "the unknown node " + typeName));
    if (!defName.empty()) {
      scope().defs.erase(defName);
      scope().skippedDefs.insert(defName);
    }
    deliver(nullptr);
    return {};
  }
  Frame frame;
  frame.kind = FrameKind::kNode;
  frame.open = typeToken.pos;
  frame.node = std::make_shared<Node>();
  frame.node->proto = proto;
  frame.node->file = file_;
  frame.node->pos = typeToken.pos;
  frame.node->defName = defName;
  if (!proto && typeName == "Script") {
    // A Script declares its own fields and events (6.40); give it a type of its own.
    doc_.nodeTypes.push_back(std::make_unique<NodeType>(*type));
    frame.ownType = doc_.nodeTypes.back().get();
    type = frame.ownType;
  }
  frame.node->type = type;
  frame.defName = std::move(defName);
  return push(std::move(frame));
}

Status Parser::finishNode() {
  Frame& f = stack_.back();
  NodePtr node = std::move(f.node);
  const std::string defName = std::move(f.defName);
  stack_.pop_back();
  if (!defName.empty()) {
    // Registered only now, so that a node cannot USE itself (no cycles).
    scope().defs[defName] = node;
    scope().skippedDefs.erase(defName);
  }
  deliver(std::move(node));
  return {};
}

Status Parser::skipUnknownValue() {
  const Token& t = tokens_.peek();
  switch (t.kind) {
    case TokenKind::kOpenBracket:
    case TokenKind::kOpenBrace: {
      const Token open = tokens_.next();
      return skipBalanced(open.pos, "a value");
    }
    case TokenKind::kInteger:
    case TokenKind::kFloat:
      while (tokens_.peek().kind == TokenKind::kInteger || tokens_.peek().kind == TokenKind::kFloat) tokens_.next();
      return {};
    case TokenKind::kString:
      tokens_.next();
      return {};
    case TokenKind::kIdentifier:
      break;
    default:
      return {};
  }
  if (t.text == "TRUE" || t.text == "FALSE" || t.text == "NULL") {
    tokens_.next();
    return {};
  }
  if (t.text == "USE" || t.text == "IS") {
    tokens_.next();
    tokens_.next();
    return {};
  }
  if (t.text == "DEF") {
    tokens_.next();
    if (tokens_.peek().kind == TokenKind::kIdentifier) scope().skippedDefs.insert(std::string(tokens_.next().text));
    if (tokens_.peek().kind == TokenKind::kIdentifier) tokens_.next();
  } else if (tokens_.peekSecond().kind == TokenKind::kOpenBrace) {
    tokens_.next();
  } else {
    return {};  // the next field name: the unknown field had no recognisable value
  }
  auto open = expect(TokenKind::kOpenBrace, "'{'");
  if (!open) return open.error();
  return skipBalanced(open->pos, "a node");
}

Status Parser::stepNode() {
  Frame& f = stack_.back();
  const Token& t = tokens_.peek();
  if (t.kind == TokenKind::kCloseBrace) {
    tokens_.next();
    return finishNode();
  }
  if (t.kind != TokenKind::kIdentifier) {
    if (t.kind == TokenKind::kEnd) {
      return errorHere(t, "'}' to close the " + f.node->typeName() + " opened at " + at(f.open));
    }
    return errorHere(t, "a field name or '}' in " + f.node->typeName());
  }
  if (t.text == "PROTO") return beginProto();
  if (t.text == "EXTERNPROTO") return parseExternProto();
  if (t.text == "ROUTE") return parseRoute();
  if (f.ownType && (t.text == "field" || t.text == "eventIn" || t.text == "eventOut" || t.text == "exposedField")) {
    return parseScriptDeclaration();
  }
  const Token nameToken = tokens_.next();
  const std::string name(nameToken.text);
  const int member = f.node->type->findMember(name);
  if (member < 0) {
    if (diag_) {
      diag_->warn(at(nameToken.pos) + ": " + f.node->typeName() + " has no field " + name + "; its value is skipped");
    }
    return skipUnknownValue();
  }
  if (tokens_.peek().kind == TokenKind::kIdentifier && tokens_.peek().text == "IS") return parseIs(f, member);
  const FieldDecl& decl = f.node->type->fields[static_cast<size_t>(member)];
  if (decl.access == FieldAccess::kEventIn || decl.access == FieldAccess::kEventOut || decl.name != name) {
    // decl.name differs for set_X / X_changed: the events of an exposedField X.
    const bool in = decl.access == FieldAccess::kEventIn || name.rfind("set_", 0) == 0;
    return errorAt(file_->displayName, nameToken.pos,
                   name + " is an " + (in ? "eventIn" : "eventOut") + " of " + f.node->typeName() +
                       " and cannot be given a value (only 'IS' inside a PROTO)");
  }
  if (!isNodeType(decl.type)) {
    return parseFieldValue(tokens_, decl.type, f.node->set(member), file_->displayName, name);
  }
  f.pendingField = member;
  const std::string context = "a node, USE" + std::string(decl.type == FieldType::kSFNode ? ", NULL" : ", '['") +
                              " for field '" + name + "' (" + fieldTypeName(decl.type) + ")";
  return beginNodeValue(decl.type, context.c_str());
}

}  // namespace detail

namespace {

Status checkHeader(std::string_view text, const std::string& name) {
  if (text.empty()) return makeError(name + ": the file is empty; a VRML97 file starts with '#VRML V2.0 utf8'");
  const size_t lineEnd = text.find_first_of("\r\n");
  const std::string_view first = text.substr(0, lineEnd);
  constexpr std::string_view kHeader = "#VRML V2.0 utf8";
  if (first.substr(0, kHeader.size()) == kHeader) return {};
  if (first.substr(0, 10) == "#VRML V1.0") {
    return makeError(name + ": VRML 1.0 is not supported; photowalk reads VRML97 files (#VRML V2.0 utf8)");
  }
  if (first.substr(0, 4) == "#X3D" || first.substr(0, 5) == "<?xml") {
    return makeError(name + ": X3D files are not supported; photowalk reads VRML97 (#VRML V2.0 utf8)");
  }
  // None of the file's content is quoted: an Inline may name any file, and a message
  // must not carry a line of someone's /etc/shadow.
  return makeError(name + ":1:1: not a VRML97 file: its first line does not start with '#VRML V2.0 utf8'");
}

}  // namespace

Result<Document> parseDocument(std::string_view text, std::shared_ptr<SourceFile> file, Diagnostics* diagnostics) {
  PW_TRY(checkHeader(text, file->displayName));
  Document document;
  document.file = std::move(file);
  detail::Parser parser(text, document, diagnostics);
  PW_TRY(parser.run());
  return document;
}

}  // namespace pw::engine::vrml
