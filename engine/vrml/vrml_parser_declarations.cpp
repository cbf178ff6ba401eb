// PROTO and EXTERNPROTO declarations (ISO/IEC 14772-1, 4.8 and 4.9), IS mappings,
// ROUTE statements and Script interface declarations (6.40).
#include "engine/vrml/vrml_field_parser.h"
#include "engine/vrml/vrml_parser_internal.h"

namespace pw::engine::vrml::detail {

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
  return beginNodeValue(decl.type, "a node, USE or NULL as the default value");
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
  declareProto(*name, registered);
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
  return beginNodeValue(decl.type, "a node, USE or NULL");
}

}  // namespace pw::engine::vrml::detail
