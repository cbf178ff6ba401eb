#include "engine/vrml/vrml_text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb_truetype.h>

#include "base/atomic_file.h"
#include "base/input_file.h"
#include "engine/vrml/vrml_fields.h"

namespace pw::engine::vrml {
namespace {

namespace fs = std::filesystem;

constexpr float kPixelsPerEm = 64.0f;  // glyph raster: sharp at a text's usual on-screen size
constexpr int kMaxTextureSide = 4096;
constexpr size_t kMaxLines = 256;
constexpr size_t kMaxLineLength = 4096;  // code points

// Font files by content, read once per process (Text nodes share a handful of fonts).
std::shared_ptr<const std::string> fontBytes(const fs::path& path) {
  static std::mutex mutex;
  static std::map<fs::path, std::shared_ptr<const std::string>> cache;
  std::lock_guard lock(mutex);
  if (auto found = cache.find(path); found != cache.end()) return found->second;
  auto bytes = readInputFile(path, kFontInput);
  std::shared_ptr<const std::string> result = bytes ? std::make_shared<const std::string>(std::move(*bytes)) : nullptr;
  cache.emplace(path, result);
  return result;
}

// UTF-8 to code points; a malformed byte stands for itself (Latin-1), never an error.
std::vector<int> codePoints(const std::string& text) {
  std::vector<int> out;
  for (size_t i = 0; i < text.size();) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char c = byte(i);
    int length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    bool valid = length > 0 && i + length <= text.size();
    for (int k = 1; valid && k < length; ++k) valid = (byte(i + k) & 0xc0) == 0x80;
    if (!valid) {
      out.push_back(c);
      ++i;
      continue;
    }
    int cp = length == 1 ? c : c & (0x7f >> length);
    for (int k = 1; k < length; ++k) cp = (cp << 6) | (byte(i + k) & 0x3f);
    out.push_back(cp);
    i += static_cast<size_t>(length);
  }
  return out;
}

struct LineRaster {
  std::vector<int> codes;
  float widthPx = 0;
};

float lineWidth(const stbtt_fontinfo& font, const std::vector<int>& codes, float scale) {
  float x = 0;
  for (size_t i = 0; i < codes.size(); ++i) {
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font, codes[i], &advance, &bearing);
    x += advance * scale;
    if (i + 1 < codes.size()) x += scale * stbtt_GetCodepointKernAdvance(&font, codes[i], codes[i + 1]);
  }
  return x;
}

// Draws one line into `image` (grey, alpha = coverage) with its baseline at row `baseline`.
void drawLine(const stbtt_fontinfo& font, const std::vector<int>& codes, float scale, int baseline, Image& image) {
  float x = 1.0f;
  std::vector<unsigned char> glyph;
  for (size_t i = 0; i < codes.size(); ++i) {
    const int pen = static_cast<int>(std::floor(x));
    const float shift = x - pen;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointBitmapBoxSubpixel(&font, codes[i], scale, scale, shift, 0.0f, &x0, &y0, &x1, &y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      glyph.assign(static_cast<size_t>(w) * h, 0);
      stbtt_MakeCodepointBitmapSubpixel(&font, glyph.data(), w, h, w, scale, scale, shift, 0.0f, codes[i]);
      for (int gy = 0; gy < h; ++gy) {
        const int y = baseline + y0 + gy;
        if (y < 0 || y >= image.height) continue;
        for (int gx = 0; gx < w; ++gx) {
          const int px = pen + x0 + gx;
          if (px < 0 || px >= image.width) continue;
          uint8_t* p = image.pixel(px, y);
          p[3] = std::max(p[3], glyph[static_cast<size_t>(gy) * w + gx]);  // overlapping glyphs: the stronger
        }
      }
    }
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font, codes[i], &advance, &bearing);
    x += advance * scale;
    if (i + 1 < codes.size()) x += scale * stbtt_GetCodepointKernAdvance(&font, codes[i], codes[i + 1]);
  }
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

}  // namespace

std::optional<fs::path> fontFile(const std::string& family, const std::string& style) {
  const std::string f = upper(family), s = upper(style);
  const bool bold = s == "BOLD" || s == "BOLDITALIC";
  const bool italic = s == "ITALIC" || s == "BOLDITALIC";
  std::string base = "DejaVuSerif", slant = "Italic";
  if (f == "SANS") base = "DejaVuSans", slant = "Oblique";
  if (f == "TYPEWRITER") base = "DejaVuSansMono", slant = "Oblique";
  std::string suffix = bold && italic ? "-Bold" + slant : bold ? "-Bold" : italic ? "-" + slant : "";
  std::vector<fs::path> dirs;
  if (const char* dir = std::getenv("PW_FONT_DIR"); dir && *dir) dirs.emplace_back(dir);
  dirs.insert(dirs.end(), {"/usr/share/fonts/truetype/dejavu", "/usr/share/fonts/dejavu", "/usr/share/fonts/TTF",
                           "/usr/local/share/fonts"});
  for (const std::string& name : {base + suffix, base, std::string("DejaVuSans")}) {
    for (const fs::path& dir : dirs) {
      std::error_code error;
      if (fs::is_regular_file(dir / (name + ".ttf"), error)) return dir / (name + ".ttf");
    }
  }
  return std::nullopt;
}

Result<std::optional<TextGeometry>> buildText(const Node& text, const NodeResolver& resolve, Diagnostics* diagnostics) {
  const auto warn = [&](const std::string& message) {
    if (diagnostics) diagnostics->warn(text.where() + ": " + message);
  };
  std::vector<std::string> strings = getStrings(text, "string");
  if (strings.size() > kMaxLines) {
    warn("Text has " + std::to_string(strings.size()) + " lines; the first " + std::to_string(kMaxLines) + " are drawn");
    strings.resize(kMaxLines);
  }
  if (strings.empty()) return std::optional<TextGeometry>{};

  // FontStyle (6.20); its defaults when there is none.
  std::string family = "SERIF", style = "PLAIN", majorJustify = "BEGIN", minorJustify = "FIRST";
  double size = 1.0, spacing = 1.0;
  bool leftToRight = true, topToBottom = true;
  auto styleNode = resolve(getNode(text, "fontStyle"));
  if (!styleNode) return styleNode.error();
  if (*styleNode && (*styleNode)->typeName() == "FontStyle") {
    const Node& fontStyle = **styleNode;
    for (const std::string& name : getStrings(fontStyle, "family")) {
      const std::string u = upper(name);
      if (u == "SERIF" || u == "SANS" || u == "TYPEWRITER") {
        family = u;
        break;
      }
    }
    style = getString(fontStyle, "style");
    const std::vector<std::string>& justify = getStrings(fontStyle, "justify");
    if (!justify.empty()) majorJustify = upper(justify[0]);
    if (justify.size() > 1) minorJustify = upper(justify[1]);
    size = getDouble(fontStyle, "size");
    spacing = getDouble(fontStyle, "spacing");
    leftToRight = getBool(fontStyle, "leftToRight");
    topToBottom = getBool(fontStyle, "topToBottom");
    if (!getBool(fontStyle, "horizontal")) warn("vertical Text (horizontal FALSE) is drawn horizontally");
  } else if (*styleNode) {
    warn("Text.fontStyle wants a FontStyle, not a " + (*styleNode)->typeName() + "; ignored");
  }
  if (!(std::isfinite(size) && size > 0)) {
    warn("FontStyle size must be positive; the text is skipped");
    return std::optional<TextGeometry>{};
  }
  if (!std::isfinite(spacing)) spacing = 1.0;

  const auto path = fontFile(family, style);
  const std::shared_ptr<const std::string> bytes = path ? fontBytes(*path) : nullptr;
  stbtt_fontinfo font;
  const auto* data = bytes ? reinterpret_cast<const unsigned char*>(bytes->data()) : nullptr;
  if (!data || stbtt_GetFontOffsetForIndex(data, 0) < 0 || !stbtt_InitFont(&font, data, stbtt_GetFontOffsetForIndex(data, 0))) {
    warn("Text needs the DejaVu fonts (Debian package fonts-dejavu-core, or PW_FONT_DIR); the text is skipped");
    return std::optional<TextGeometry>{};
  }

  std::vector<LineRaster> lines(strings.size());
  float pixelsPerEm = kPixelsPerEm;
  float scale = stbtt_ScaleForMappingEmToPixels(&font, pixelsPerEm);
  float widest = 0;
  for (size_t i = 0; i < strings.size(); ++i) {
    lines[i].codes = codePoints(strings[i]);
    if (lines[i].codes.size() > kMaxLineLength) {
      warn("a Text line of " + std::to_string(lines[i].codes.size()) + " characters is cut to " +
           std::to_string(kMaxLineLength));
      lines[i].codes.resize(kMaxLineLength);
    }
    if (!leftToRight) std::reverse(lines[i].codes.begin(), lines[i].codes.end());
    widest = std::max(widest, lineWidth(font, lines[i].codes, scale));
  }
  if (widest + 2 > kMaxTextureSide) {  // a long line: fewer pixels per em
    pixelsPerEm *= (kMaxTextureSide - 2) / (widest + 2);
    scale = stbtt_ScaleForMappingEmToPixels(&font, pixelsPerEm);
  }
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&font, &ascent, &descent, &gap);
  const int above = static_cast<int>(std::ceil(ascent * scale)) + 1;
  const int below = static_cast<int>(std::ceil(-descent * scale)) + 1;
  const int band = above + below;
  int width = 2;
  for (LineRaster& line : lines) {
    line.widthPx = lineWidth(font, line.codes, scale);
    width = std::max(width, static_cast<int>(std::ceil(line.widthPx)) + 2);
  }
  width = std::min(width, kMaxTextureSide);
  const int height = band * static_cast<int>(lines.size());
  if (height > kMaxTextureSide * 4) {
    warn("Text is too tall to draw; skipped");
    return std::optional<TextGeometry>{};
  }
  auto glyphs = std::make_shared<Image>(makeImage(width, height, 0xffffff00));
  glyphs->grey = true;
  for (size_t i = 0; i < lines.size(); ++i) drawLine(font, lines[i].codes, scale, static_cast<int>(i) * band + above, *glyphs);

  // Layout (6.47): the first baseline at y = 0, lines size * spacing apart, downwards
  // (topToBottom) or upwards; the major justification places each line along x, the
  // minor one the block along y; `length` and `maxExtent` compress lines along x.
  if (leftToRight == false) {
    if (majorJustify == "BEGIN" || majorJustify == "FIRST") majorJustify = "END";
    else if (majorJustify == "END") majorJustify = "BEGIN";
  }
  const double metresPerPixel = size / pixelsPerEm;
  const std::vector<float>& lengths = getFloats(text, "length");
  const double maxExtent = getDouble(text, "maxExtent");
  const double step = size * spacing * (topToBottom ? -1.0 : 1.0);
  const double top = above * metresPerPixel, bottom = -below * metresPerPixel;
  double shiftY = 0;
  if (minorJustify == "BEGIN") shiftY = topToBottom ? -top : -bottom;
  if (minorJustify == "END") shiftY = topToBottom ? -(step * (lines.size() - 1) + bottom) : -(step * (lines.size() - 1) + top);
  if (minorJustify == "MIDDLE") shiftY = -0.5 * (step * (lines.size() - 1) + (topToBottom ? top + bottom : bottom + top));

  TextGeometry out;
  out.glyphs = glyphs;
  Mesh& mesh = out.mesh;
  mesh.solid = false;
  for (size_t i = 0; i < lines.size(); ++i) {
    const double naturalWidth = (lines[i].widthPx + 2) * metresPerPixel;
    double lineWidthM = naturalWidth;
    if (i < lengths.size() && std::isfinite(lengths[i]) && lengths[i] > 0) lineWidthM = lengths[i];
    if (std::isfinite(maxExtent) && maxExtent > 0 && lineWidthM > maxExtent) lineWidthM = maxExtent;
    double x0 = 0;
    if (majorJustify == "MIDDLE") x0 = -0.5 * lineWidthM;
    if (majorJustify == "END") x0 = -lineWidthM;
    const double baseline = step * static_cast<double>(i) + shiftY;
    const float u1 = static_cast<float>((lines[i].widthPx + 2) / width);
    const float tTop = 1.0f - static_cast<float>(i) * band / height, tBottom = 1.0f - static_cast<float>(i + 1) * band / height;
    const uint32_t first = static_cast<uint32_t>(mesh.positions.size());
    const float yb = static_cast<float>(baseline + bottom), yt = static_cast<float>(baseline + top);
    const float xa = static_cast<float>(x0), xb = static_cast<float>(x0 + lineWidthM);
    mesh.positions.insert(mesh.positions.end(), {{xa, yb, 0}, {xb, yb, 0}, {xb, yt, 0}, {xa, yt, 0}});
    mesh.normals.insert(mesh.normals.end(), 4, glm::vec3(0, 0, 1));
    mesh.texCoords.insert(mesh.texCoords.end(), {{0, tBottom}, {u1, tBottom}, {u1, tTop}, {0, tTop}});
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  }
  return std::optional<TextGeometry>(std::move(out));
}

}  // namespace pw::engine::vrml
