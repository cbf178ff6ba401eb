// Parsing one field value of a non-node type (ISO/IEC 14772-1, section 5: field types).
#pragma once

#include <string_view>

#include "base/result.h"
#include "engine/vrml/vrml_node.h"
#include "engine/vrml/vrml_tokenizer.h"

namespace pw::engine::vrml {

// "file.wrl:12:5: MESSAGE"
Error errorAt(std::string_view fileName, SourcePos pos, std::string_view message);

// Reads one value of `type` (not SFNode/MFNode) into `out`: a single value, or for
// MF types a bracketed list or a single value. `fieldName` names the field in errors.
// Numbers for single-precision fields must fit in a float.
Status parseFieldValue(Tokenizer& tokens, FieldType type, FieldValue& out, std::string_view fileName,
                       std::string_view fieldName);

}  // namespace pw::engine::vrml
