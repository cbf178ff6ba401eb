#include "engine/vrml/vrml_parser.h"

#include <unordered_map>
#include <unordered_set>

#include "engine/vrml/vrml_field_parser.h"

namespace pw::engine::vrml {

namespace {

// Frames deeper than this are refused: at about 400 bytes per nested node this is
// already hundreds of megabytes of nodes.
constexpr size_t kMaxDepth = 1000000;

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
    std::unordered_map<std::string, const Proto*> protos;
    const Proto* defining = nullptr;  // the PROTO whose body this scope is
  };

  Status stepStatements();
  Status stepNode();
  Status stepInterface();
  Status startNodeStatement(const char* context);
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
  bool routeNoted_ = false;
};

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
  const std::string key(name);
  for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s) {
    auto found = s->protos.find(key);
    if (found != s->protos.end()) return found->second;
  }
  return nullptr;
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
    scopes_.pop_back();
    const Proto* registered = proto.get();
    scope().protos[proto->interface.name] = registered;
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

Status Parser::parseIs(Frame& frame, int member) {
  const Token isToken = tokens_.next();
  auto target = expectIdentifier("an interface name after IS");
  if (!target) return target.error();
  const Proto* defining = scope().defining;
  if (!defining) {
    return errorAt(file_->displayName, isToken.pos, "IS is only allowed inside a PROTO body");
  }
  const int protoIndex = defining->interface.findMember(*target);
  if (protoIndex < 0) {
    return errorAt(file_->displayName, isToken.pos,
                   "PROTO " + defining->interface.name + " has no field or event named " + *target);
  }
  const FieldDecl& mine = frame.node->type->fields[static_cast<size_t>(member)];
  const FieldDecl& theirs = defining->interface.fields[static_cast<size_t>(protoIndex)];
  if (mine.type != theirs.type) {
    return errorAt(file_->displayName, isToken.pos,
                   mine.name + " is " + fieldTypeName(mine.type) + " but " + defining->interface.name + "." +
                       theirs.name + " is " + fieldTypeName(theirs.type) + "; IS needs the same type");
  }
  frame.node->isMappings.push_back({static_cast<uint16_t>(member), *target});
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
  if (decl.type == FieldType::kMFNode && tokens_.peek().kind == TokenKind::kOpenBracket) {
    Frame list;
    list.kind = FrameKind::kNodeList;
    list.open = tokens_.next().pos;
    return push(std::move(list));
  }
  const std::string context = "a node, USE" + std::string(decl.type == FieldType::kSFNode ? ", NULL" : ", '['") +
                              " for field '" + name + "' (" + fieldTypeName(decl.type) + ")";
  return startNodeStatement(context.c_str());
}

// "field TYPE name [value]" / "eventIn TYPE name" ... into `type`.
Status Parser::parseInterfaceDeclaration(NodeType& type, std::string_view owner) {
  const Token accessToken = tokens_.next();
  FieldDecl decl;
  if (accessToken.text == "field") decl.access = FieldAccess::kField;
  else if (accessToken.text == "exposedField") decl.access = FieldAccess::kExposedField;
  else if (accessToken.text == "eventIn") decl.access = FieldAccess::kEventIn;
  else decl.access = FieldAccess::kEventOut;
  const Token typeToken = tokens_.peek();
  auto typeName = expectIdentifier("a field type (SFBool, MFNode, ...)");
  if (!typeName) return typeName.error();
  const auto fieldType = fieldTypeFromName(*typeName);
  if (!fieldType) return errorHere(typeToken, "a field type such as SFFloat or MFNode");
  decl.type = *fieldType;
  const Token nameToken = tokens_.peek();
  auto name = expectIdentifier("a field name");
  if (!name) return name.error();
  decl.name = std::move(*name);
  for (const FieldDecl& existing : type.fields) {
    if (existing.name == decl.name) {
      return errorAt(file_->displayName, nameToken.pos, std::string(owner) + " declares " + decl.name + " twice");
    }
  }
  type.fields.push_back(std::move(decl));
  return {};
}

Status Parser::stepInterface() {
  Frame& f = stack_.back();
  const Token& t = tokens_.peek();
  if (t.kind == TokenKind::kCloseBracket) {
    tokens_.next();
    auto open = expect(TokenKind::kOpenBrace, ("'{' to start the body of PROTO " + f.proto->interface.name).c_str());
    if (!open) return open.error();
    f.kind = FrameKind::kProtoBody;
    f.open = open->pos;
    Scope body;
    body.defining = f.proto.get();
    scopes_.push_back(std::move(body));
    return {};
  }
  if (t.kind != TokenKind::kIdentifier ||
      (t.text != "field" && t.text != "exposedField" && t.text != "eventIn" && t.text != "eventOut")) {
    return errorHere(t, "field, exposedField, eventIn, eventOut or ']' in the interface of PROTO " +
                            f.proto->interface.name);
  }
  NodeType& type = f.proto->interface;
  PW_TRY(parseInterfaceDeclaration(type, "PROTO " + type.name));
  FieldDecl& decl = type.fields.back();
  if (decl.access == FieldAccess::kEventIn || decl.access == FieldAccess::kEventOut) return {};
  if (!isNodeType(decl.type)) {
    return parseFieldValue(tokens_, decl.type, decl.defaultValue, file_->displayName, decl.name);
  }
  f.pendingDefault = true;
  if (decl.type == FieldType::kMFNode && tokens_.peek().kind == TokenKind::kOpenBracket) {
    Frame list;
    list.kind = FrameKind::kNodeList;
    list.open = tokens_.next().pos;
    return push(std::move(list));
  }
  return startNodeStatement("a node, USE or NULL as the default value");
}

Status Parser::beginProto() {
  const Token protoToken = tokens_.next();
  auto name = expectIdentifier("a name after PROTO");
  if (!name) return name.error();
  auto open = expect(TokenKind::kOpenBracket, ("'[' to start the interface of PROTO " + *name).c_str());
  if (!open) return open.error();
  Frame frame;
  frame.kind = FrameKind::kInterface;
  frame.open = protoToken.pos;
  frame.proto = std::make_unique<Proto>();
  frame.proto->interface.name = std::move(*name);
  frame.proto->file = file_;
  frame.proto->pos = protoToken.pos;
  return push(std::move(frame));
}

Status Parser::parseExternProto() {
  const Token externToken = tokens_.next();
  auto name = expectIdentifier("a name after EXTERNPROTO");
  if (!name) return name.error();
  auto open = expect(TokenKind::kOpenBracket, ("'[' to start the interface of EXTERNPROTO " + *name).c_str());
  if (!open) return open.error();
  auto proto = std::make_unique<Proto>();
  proto->interface.name = *name;
  proto->external = true;
  proto->file = file_;
  proto->pos = externToken.pos;
  while (tokens_.peek().kind != TokenKind::kCloseBracket) {
    const Token& t = tokens_.peek();
    if (t.kind != TokenKind::kIdentifier ||
        (t.text != "field" && t.text != "exposedField" && t.text != "eventIn" && t.text != "eventOut")) {
      return errorHere(t, "field, exposedField, eventIn, eventOut or ']' in the interface of EXTERNPROTO " + *name);
    }
    PW_TRY(parseInterfaceDeclaration(proto->interface, "EXTERNPROTO " + *name));
  }
  tokens_.next();
  FieldValue urls;
  PW_TRY(parseFieldValue(tokens_, FieldType::kMFString, urls, file_->displayName, "EXTERNPROTO url"));
  proto->urls = std::move(urls.strings);
  const Proto* registered = proto.get();
  scope().protos[*name] = registered;
  if (scopes_.size() == 1) doc_.topLevelProtos[*name] = registered;
  doc_.protos.push_back(std::move(proto));
  return {};
}

Status Parser::parseRoute() {
  const Token routeToken = tokens_.next();
  std::string parts[4];
  for (int i = 0; i < 4; ++i) {
    auto id = expectIdentifier(i % 2 == 0 ? "a node name in ROUTE" : "an event name in ROUTE");
    if (!id) return id.error();
    parts[i] = std::move(*id);
    if (i % 2 == 0) {
      auto period = expect(TokenKind::kPeriod, "'.' between node and event in ROUTE");
      if (!period) return period.error();
    } else if (i == 1) {
      const Token& to = tokens_.peek();
      if (to.kind != TokenKind::kIdentifier || to.text != "TO") return errorHere(to, "TO in ROUTE");
      tokens_.next();
    }
  }
  if (diag_) {
    for (int i : {0, 2}) {
      if (!scope().defs.count(parts[i]) && !scope().skippedDefs.count(parts[i])) {
        diag_->warn(at(routeToken.pos) + ": ROUTE names " + parts[i] + ", which no DEF defines");
      }
    }
    if (!routeNoted_) {
      diag_->note(at(routeToken.pos) + ": ROUTEs are ignored (photowalk shows static scenes)");
      routeNoted_ = true;
    }
  }
  return {};
}

Status Parser::parseScriptDeclaration() {
  Frame& f = stack_.back();
  PW_TRY(parseInterfaceDeclaration(*f.ownType, "Script"));
  const int member = static_cast<int>(f.ownType->fields.size() - 1);
  FieldDecl& decl = f.ownType->fields.back();
  if (tokens_.peek().kind == TokenKind::kIdentifier && tokens_.peek().text == "IS") return parseIs(f, member);
  if (decl.access == FieldAccess::kEventIn || decl.access == FieldAccess::kEventOut) return {};
  if (!isNodeType(decl.type)) {
    return parseFieldValue(tokens_, decl.type, f.node->set(member), file_->displayName, decl.name);
  }
  f.pendingField = member;
  if (decl.type == FieldType::kMFNode && tokens_.peek().kind == TokenKind::kOpenBracket) {
    Frame list;
    list.kind = FrameKind::kNodeList;
    list.open = tokens_.next().pos;
    return push(std::move(list));
  }
  return startNodeStatement("a node, USE or NULL");
}

Status checkHeader(std::string_view text, const std::string& name) {
  if (text.empty()) return makeError(name + ": the file is empty; a VRML97 file starts with '#VRML V2.0 utf8'");
  const size_t lineEnd = text.find_first_of("\r\n");
  const std::string_view first = text.substr(0, lineEnd);
  constexpr std::string_view kHeader = "#VRML V2.0 utf8";
  if (first.substr(0, kHeader.size()) == kHeader) return {};
  if (first.substr(0, 10) == "#VRML V1.0") {
    return makeError(name + ": VRML 1.0 is not supported; convert the file to VRML97 (#VRML V2.0 utf8) first, "
                            "e.g. with view3dscene --write");
  }
  if (first.substr(0, 4) == "#X3D" || first.substr(0, 5) == "<?xml") {
    return makeError(name + ": X3D files are not supported; photowalk reads VRML97 (#VRML V2.0 utf8)");
  }
  std::string shown(first.substr(0, 40));
  for (char& c : shown) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  }
  return makeError(name + ":1:1: not a VRML97 file: the first line must start with '#VRML V2.0 utf8', not '" + shown +
                   "'");
}

}  // namespace

Result<Document> parseDocument(std::string_view text, std::shared_ptr<SourceFile> file, Diagnostics* diagnostics) {
  PW_TRY(checkHeader(text, file->displayName));
  Document document;
  document.file = std::move(file);
  Parser parser(text, document, diagnostics);
  PW_TRY(parser.run());
  return document;
}

}  // namespace pw::engine::vrml
