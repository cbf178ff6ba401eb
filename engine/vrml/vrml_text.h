// VRML97 Text and FontStyle (ISO/IEC 14772-1, 6.47, 6.20) as textured quads, one per
// line, in the z = 0 plane of the node's space, as texture-font viewers draw it. The
// glyphs come from the DejaVu fonts (Debian: fonts-dejavu-core) through stb_truetype;
// the texture is grey with the glyphs' coverage as alpha, so the shape's Material
// colours it (a grey texture modulates the diffuse colour, table 4.5).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "base/result.h"
#include "engine/scene/scene.h"
#include "engine/vrml/diagnostics.h"
#include "engine/vrml/vrml_geometry.h"

namespace pw::engine::vrml {

struct TextGeometry {
  Mesh mesh;                          // quads with texture coordinates, solid FALSE
  std::shared_ptr<const Image> glyphs;  // grey + alpha, one band per line
};

// nullopt (with a diagnostic) when there is nothing to draw: no strings, no font.
Result<std::optional<TextGeometry>> buildText(const Node& text, const NodeResolver& resolve, Diagnostics* diagnostics);

// Where the fonts are looked for (the first that exists): $PW_FONT_DIR, then the
// Debian and common system folders.
std::optional<std::filesystem::path> fontFile(const std::string& family, const std::string& style);

}  // namespace pw::engine::vrml
