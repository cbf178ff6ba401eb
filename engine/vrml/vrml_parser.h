// VRML97 classic encoding to the generic node tree (ISO/IEC 14772-1, Annex A grammar).
//
// The parser is iterative (an explicit stack of frames, not recursion), so nesting
// depth is limited only by memory: 100000 nested Groups parse like any other file.
// PROTO and EXTERNPROTO declarations are recorded with their interfaces and bodies;
// instances keep their field values and are expanded later (vrml_proto.h). ROUTEs
// are checked and dropped with a note. Unknown node types and unknown fields are
// skipped with a warning. Everything else that breaks the grammar is an error with
// file:line:column and what was expected.
#pragma once

#include <memory>
#include <string_view>

#include "base/result.h"
#include "engine/vrml/diagnostics.h"
#include "engine/vrml/vrml_node.h"

namespace pw::engine::vrml {

// Checks the "#VRML V2.0 utf8" header (refusing VRML 1.0 and X3D with a clear
// message) and parses the rest. `text` is the decompressed file.
Result<Document> parseDocument(std::string_view text, std::shared_ptr<SourceFile> file, Diagnostics* diagnostics);

}  // namespace pw::engine::vrml
