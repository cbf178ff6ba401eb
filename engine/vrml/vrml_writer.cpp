#include "engine/vrml/vrml_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <unordered_set>

#include "base/atomic_file.h"
#include "base/input_file.h"
#include "base/staging.h"
#include "engine/scene/model_info.h"
#include "engine/scene/texture_detail.h"
#include "engine/vrml/gzip.h"
#include "engine/vrml/vrml_tokenizer.h"
#include "engine/vrml/vrml_transform.h"

namespace pw::engine {

namespace fs = std::filesystem;

namespace {

// Shortest decimal that reads back to exactly this float (std::to_chars guarantees it).
void appendNumber(std::string& out, float v) {
  char buffer[32];
  out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
}

// Doubles that are floats print as floats (short); others need up to 17 digits.
void appendNumber(std::string& out, double v) {
  if (static_cast<double>(static_cast<float>(v)) == v) return appendNumber(out, static_cast<float>(v));
  char buffer[40];
  out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
}

template <class Vec>
void appendVector(std::string& out, const Vec& v) {
  for (int i = 0; i < Vec::length(); ++i) {
    if (i) out += ' ';
    appendNumber(out, v[i]);
  }
}

void appendString(std::string& out, const std::string& s) {
  out += '"';
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  out += '"';
}

bool isKeyword(const std::string& s) {
  static const char* const kKeywords[] = {"DEF", "EXTERNPROTO", "FALSE", "IS", "NULL", "PROTO", "ROUTE", "TO",
                                          "TRUE", "USE", "eventIn", "eventOut", "exposedField", "field"};
  return std::any_of(std::begin(kKeywords), std::end(kKeywords), [&](const char* k) { return s == k; });
}

// A valid VRML identifier made from `name` (Annex A.2), or "" for an empty name.
std::string identifierFrom(const std::string& name) {
  if (name.empty()) return {};
  std::string id;
  for (unsigned char c : name) id += vrml::isIdRestChar(c) ? static_cast<char>(c) : '_';
  if (!vrml::isIdFirstChar(static_cast<unsigned char>(id[0])) || isKeyword(id)) id = "_" + id;
  return id;
}

double roundToDigits(double v, int digits) {
  if (v == 0.0) return 0.0;
  char buffer[40];
  auto r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, digits);
  double out = v;
  std::from_chars(buffer, r.ptr, out);
  return out;
}

// Transform fields for a shape's matrix that read back to exactly that matrix, with as
// few digits as possible: the decomposition rounded to 6, 7, ... significant digits,
// the first that composes to the same float matrix (17 digits always do).
vrml::TransformFields shortestFields(const glm::mat4& matrix) {
  const vrml::TransformFields exact = vrml::decomposeTransform(glm::dmat4(matrix));
  for (int digits : {6, 7, 8, 9, 11, 13, 15}) {
    vrml::TransformFields f = exact;
    for (int i = 0; i < 4; ++i) {
      f.rotation[i] = roundToDigits(f.rotation[i], digits);
      f.scaleOrientation[i] = roundToDigits(f.scaleOrientation[i], digits);
    }
    for (int i = 0; i < 3; ++i) f.scale[i] = roundToDigits(f.scale[i], digits);
    if (f.scale == glm::dvec3(1.0)) f.scaleOrientation = {0.0, 0.0, 1.0, 0.0};
    if (vrml::toFloatMatrix(vrml::composeTransform(f)) == matrix) return f;
  }
  return exact;
}

bool finite(const glm::vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::vec4& v) { return finite(glm::vec3(v)) && std::isfinite(v.w); }

Status checkMesh(const Mesh& m, size_t shapeIndex) {
  const std::string where = "shape " + std::to_string(shapeIndex) + ": ";
  const size_t n = m.positions.size();
  if ((!m.normals.empty() && m.normals.size() != n) || (!m.texCoords.empty() && m.texCoords.size() != n) ||
      (!m.colors.empty() && m.colors.size() != n)) {
    return makeError(where + "mesh attribute arrays differ in length from its positions");
  }
  const size_t per = m.topology == Topology::kTriangles ? 3 : m.topology == Topology::kLines ? 2 : 1;
  if (m.indices.size() % per != 0) return makeError(where + "mesh index count is not a multiple of " + std::to_string(per));
  for (uint32_t i : m.indices) {
    if (i >= n) return makeError(where + "mesh index " + std::to_string(i) + " is out of range");
  }
  for (const auto& p : m.positions) {
    if (!finite(p)) return makeError(where + "mesh has a non-finite position");
  }
  for (const auto& v : m.normals) {
    if (!finite(v)) return makeError(where + "mesh has a non-finite normal");
  }
  for (const auto& v : m.texCoords) {
    if (!finite(v)) return makeError(where + "mesh has a non-finite texture coordinate");
  }
  for (const auto& v : m.colors) {
    if (!finite(v)) return makeError(where + "mesh has a non-finite colour");
  }
  return {};
}

class Writer {
 public:
  Writer(const Scene& scene, const VrmlWriteOptions& options, const std::unordered_map<const Image*, std::string>& urls)
      : scene_(scene), options_(options), urls_(urls) {}

  Result<std::string> run();

 private:
  void line(const std::string& text) {
    out_.append(static_cast<size_t>(indent_) * 2, ' ');
    out_ += text;
    out_ += '\n';
  }
  void open(const std::string& text) {
    line(text + " {");
    ++indent_;
  }
  void close(const std::string& suffix = "") {
    --indent_;
    line("}" + suffix);
  }
  template <class Vec>
  void field(const char* name, const Vec& v) {
    std::string s = name;
    s += ' ';
    appendVector(s, v);
    line(s);
  }
  void field(const char* name, float v) {
    std::string s = std::string(name) + " ";
    appendNumber(s, v);
    line(s);
  }
  void field(const char* name, bool v) { line(std::string(name) + (v ? " TRUE" : " FALSE")); }
  template <class Vec>
  void array(const char* head, const std::vector<Vec>& values, const char* tail = "}") {
    line(std::string(head) + " [");
    ++indent_;
    std::string s;
    for (const Vec& v : values) {
      s.clear();
      appendVector(s, v);
      s += ',';
      line(s);
    }
    --indent_;
    line(std::string("] ") + tail);
  }
  std::string uniqueName(const std::string& prefix) {
    while (true) {
      std::string name = prefix + "_" + std::to_string(++counter_);
      if (!reserved_.count(name)) return name;
    }
  }

  void writeHeader();
  void writeLight(const Light& light);
  void writeViewpoint(const Viewpoint& v);
  void writeShape(const Shape& shape);
  void writeAppearance(const Appearance& appearance);
  void writeMesh(const Mesh& mesh, const std::string& head);

  const Scene& scene_;
  const VrmlWriteOptions& options_;
  const std::unordered_map<const Image*, std::string>& urls_;
  std::string out_;
  int indent_ = 0;
  int counter_ = 0;
  std::unordered_set<std::string> reserved_;  // shape DEF names, not to be reused
  std::unordered_map<const void*, int> uses_;
  std::unordered_map<const void*, std::string> defined_;
};

void Writer::writeHeader() {
  line("#VRML V2.0 utf8");
  line("# Written by photowalk");
  line("");
  const std::string& title = options_.title.empty() ? scene_.title : options_.title;
  const std::vector<std::string> info = infoForFile(scene_, [&](const Texture& texture) {
    auto url = urls_.find(texture.image.get());
    return url == urls_.end() ? std::string() : url->second;
  });
  if (!title.empty() || !info.empty()) {
    open("WorldInfo");
    if (!title.empty()) {
      std::string s = "title ";
      appendString(s, title);
      line(s);
    }
    if (!info.empty()) {
      line("info [");
      ++indent_;
      for (const std::string& i : info) {
        std::string s;
        appendString(s, i);
        line(s + ",");
      }
      --indent_;
      line("]");
    }
    close();
  }
  const NavigationInfo& nav = scene_.navigation;
  open("NavigationInfo");
  field("headlight", nav.headlight);
  {
    std::string s = "avatarSize [ ";
    appendVector(s, glm::vec3(nav.avatarRadiusM, nav.avatarHeightM, nav.stepHeightM));
    line(s + " ]");
  }
  field("speed", nav.speedMps);
  {
    std::string s = "type [";
    for (size_t i = 0; i < nav.type.size(); ++i) {
      s += i ? ", " : " ";
      appendString(s, nav.type[i]);
    }
    line(s + " ]");
  }
  if (nav.visibilityLimitM != 0.0f) field("visibilityLimit", nav.visibilityLimitM);
  close();
  if (scene_.backgroundColor != glm::vec3(0.0f)) {
    std::string s = "Background { skyColor [ ";
    appendVector(s, scene_.backgroundColor);
    line(s + " ] }");
  }
}

void Writer::writeViewpoint(const Viewpoint& v) {
  open("Viewpoint");
  field("position", v.position);
  field("orientation", v.orientation);
  field("fieldOfView", v.fieldOfViewRad);
  if (!v.description.empty()) {
    std::string s = "description ";
    appendString(s, v.description);
    line(s);
  }
  close();
}

void Writer::writeLight(const Light& l) {
  open(l.type == LightType::kDirectional ? "DirectionalLight" : l.type == LightType::kPoint ? "PointLight" : "SpotLight");
  if (!l.on) field("on", false);
  field("color", l.color);
  field("intensity", l.intensity);
  field("ambientIntensity", l.ambientIntensity);
  if (l.type != LightType::kPoint) field("direction", l.direction);
  if (l.type != LightType::kDirectional) {
    field("location", l.position);
    field("attenuation", l.attenuation);
    field("radius", l.radius);
  }
  if (l.type == LightType::kSpot) {
    field("beamWidth", l.beamWidth);
    field("cutOffAngle", l.cutOffAngle);
  }
  close();
}

void Writer::writeAppearance(const Appearance& a) {
  if (a.material) {
    const Material& m = *a.material;
    const Material d;
    if (m == d) {
      line("material Material { }");
    } else {
      open("material Material");
      if (m.ambientIntensity != d.ambientIntensity) field("ambientIntensity", m.ambientIntensity);
      if (m.diffuseColor != d.diffuseColor) field("diffuseColor", m.diffuseColor);
      if (m.emissiveColor != d.emissiveColor) field("emissiveColor", m.emissiveColor);
      if (m.specularColor != d.specularColor) field("specularColor", m.specularColor);
      if (m.shininess != d.shininess) field("shininess", m.shininess);
      if (m.transparency != d.transparency) field("transparency", m.transparency);
      close();
    }
  }
  const Texture* t = a.texture.get();
  if (!t || !t->image) return;
  auto url = urls_.find(t->image.get());
  if (url == urls_.end()) return;
  auto done = defined_.find(t);
  if (done != defined_.end()) {
    line("texture USE " + done->second);
    return;
  }
  std::string head = "texture ";
  if (uses_[t] > 1) {
    const std::string name = uniqueName("Texture");
    defined_[t] = name;
    head += "DEF " + name + " ";
  }
  open(head + "ImageTexture");
  std::string s = "url ";
  appendString(s, url->second);
  line(s);
  if (t->wrapS == TextureWrap::kClamp) field("repeatS", false);
  if (t->wrapT == TextureWrap::kClamp) field("repeatT", false);
  close();
}

// `head` precedes the node type: "geometry " or "geometry DEF Mesh_3 ".
void Writer::writeMesh(const Mesh& m, const std::string& head) {
  if (m.topology == Topology::kPoints) {
    open(head + "PointSet");
    bool identity = m.indices.size() == m.positions.size();
    for (size_t i = 0; identity && i < m.indices.size(); ++i) identity = m.indices[i] == i;
    std::vector<glm::vec3> points;
    std::vector<glm::vec3> colors;
    for (size_t i = 0; i < m.indices.size(); ++i) {
      const uint32_t k = identity ? static_cast<uint32_t>(i) : m.indices[i];
      points.push_back(m.positions[k]);
      if (!m.colors.empty()) colors.emplace_back(m.colors[k]);
    }
    array("coord Coordinate { point", points);
    if (!colors.empty()) array("color Color { color", colors);
    close();
    return;
  }
  const bool lines = m.topology == Topology::kLines;
  open(head + (lines ? "IndexedLineSet" : "IndexedFaceSet"));
  if (!lines && !m.solid) field("solid", false);
  array("coord Coordinate { point", m.positions);
  if (!lines && !m.normals.empty()) array("normal Normal { vector", m.normals);
  if (!lines && !m.texCoords.empty()) array("texCoord TextureCoordinate { point", m.texCoords);
  if (!m.colors.empty()) {
    std::vector<glm::vec3> rgb(m.colors.begin(), m.colors.end());
    array("color Color { color", rgb);
  }
  line("coordIndex [");
  ++indent_;
  const size_t per = lines ? 2 : 3;
  std::string s;
  for (size_t i = 0; i + per <= m.indices.size(); i += per) {
    s.clear();
    for (size_t k = 0; k < per; ++k) s += std::to_string(m.indices[i + k]) + ' ';
    s += "-1,";
    line(s);
  }
  --indent_;
  line("]");
  close();
}

void Writer::writeShape(const Shape& shape) {
  const bool transformed = shape.transform != glm::mat4(1.0f);
  if (transformed) {
    const vrml::TransformFields f = shortestFields(shape.transform);
    open("Transform");
    // The translation is the matrix's own float column: write it as floats (exact and
    // short); the rest in double, so that composing it again rounds to the same floats.
    field("translation", glm::vec3(shape.transform[3]));
    if (f.rotation.w != 0.0) field("rotation", f.rotation);
    if (f.scale != glm::dvec3(1.0)) field("scale", f.scale);
    if (f.scaleOrientation.w != 0.0) field("scaleOrientation", f.scaleOrientation);
  }
  const std::string id = identifierFrom(shape.name);
  open(std::string(transformed ? "children " : "") + (id.empty() ? "" : "DEF " + id + " ") + "Shape");
  if (shape.appearance) {
    const Appearance* a = shape.appearance.get();
    auto done = defined_.find(a);
    if (done != defined_.end()) {
      line("appearance USE " + done->second);
    } else {
      std::string head = "appearance ";
      if (uses_[a] > 1) {
        const std::string name = uniqueName("Appearance");
        defined_[a] = name;
        head += "DEF " + name + " ";
      }
      open(head + "Appearance");
      writeAppearance(*a);
      close();
    }
  }
  const Mesh* mesh = shape.mesh.get();
  auto done = defined_.find(mesh);
  if (done != defined_.end()) {
    line("geometry USE " + done->second);
  } else {
    std::string head = "geometry ";
    if (uses_[mesh] > 1) {
      const std::string name = uniqueName("Mesh");
      defined_[mesh] = name;
      head += "DEF " + name + " ";
    }
    writeMesh(*mesh, head);
  }
  close();
  if (transformed) close();
}

Result<std::string> Writer::run() {
  for (size_t i = 0; i < scene_.shapes.size(); ++i) {
    const Shape& s = scene_.shapes[i];
    if (!s.mesh) continue;
    PW_TRY(checkMesh(*s.mesh, i));
    for (int c = 0; c < 4; ++c) {
      if (!finite(s.transform[c])) return makeError("shape " + std::to_string(i) + ": non-finite transform");
    }
    ++uses_[s.mesh.get()];
    if (s.appearance) {
      ++uses_[s.appearance.get()];
      // Count texture uses once per appearance: a shared appearance carries it.
      if (uses_[s.appearance.get()] == 1 && s.appearance->texture) ++uses_[s.appearance->texture.get()];
    }
    const std::string id = identifierFrom(s.name);
    if (!id.empty()) reserved_.insert(id);
  }
  for (const Viewpoint& v : scene_.viewpoints) {
    if (!finite(v.position) || !finite(v.orientation) || !std::isfinite(v.fieldOfViewRad)) {
      return makeError("viewpoint '" + v.description + "' has a non-finite value");
    }
  }
  for (const Light& l : scene_.lights) {
    if (!finite(l.position) || !finite(l.direction) || !finite(l.color) || !finite(l.attenuation) ||
        !std::isfinite(l.radius)) {
      return makeError("a light has a non-finite value");
    }
  }
  writeHeader();
  for (const Viewpoint& v : scene_.viewpoints) writeViewpoint(v);
  for (const Light& l : scene_.lights) writeLight(l);
  if (!scene_.viewpoints.empty() || !scene_.lights.empty()) line("");
  for (const Shape& s : scene_.shapes) {
    if (!s.mesh || s.mesh->indices.empty()) continue;
    writeShape(s);
  }
  return std::move(out_);
}

// File-name part from a texture url: its stem, reduced to safe characters.
std::string textureStem(const std::string& url) {
  std::string stem = fs::path(url).stem().string();
  std::string out;
  for (char c : stem) {
    const bool safe = std::isalnum(static_cast<unsigned char>(c)) || c == '-';
    if (safe) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
    if (out.size() >= 40) break;
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out.empty() ? "texture" : out;
}

bool endsWith(std::string s, const std::string& suffix) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The strings the model now at `out` quotes (its urls among them), and the detail
// layers named after them: the files this writer wrote beside it before, which a new
// model of that name may replace. Nothing when there is no model there (or it cannot
// be read).
std::unordered_set<std::string> quotedInPreviousModel(const fs::path& out, bool gz) {
  std::unordered_set<std::string> quoted;
  auto bytes = readInputFile(out, kModelInput);
  if (!bytes) return quoted;
  std::string text = std::move(*bytes);
  if (gz || isGzip(text)) {
    auto plain = gunzip(text, out.string(), kModelInput.maxBytes);
    if (!plain) return quoted;
    text = std::move(*plain);
  }
  for (size_t open = text.find('"'); open != std::string::npos;) {
    const size_t close = text.find('"', open + 1);
    if (close == std::string::npos) break;
    if (close - open - 1 <= 4096) {
      const std::string url = text.substr(open + 1, close - open - 1);
      quoted.insert(url);
      quoted.insert(detailUrl(url));  // a texture's detail layer is named after it, not quoted
    }
    open = text.find('"', close + 1);
  }
  return quoted;
}

}  // namespace

Result<std::string> vrmlText(const Scene& scene, const VrmlWriteOptions& options,
                             const std::unordered_map<const Image*, std::string>& imageUrls) {
  return Writer(scene, options, imageUrls).run();
}

Status writeVrml(const Scene& scene, const fs::path& out, const VrmlWriteOptions& options) {
  const std::string name = out.filename().string();
  const bool gz = endsWith(name, ".gz") || endsWith(name, ".wrz");
  std::string outStem = name.substr(0, name.find('.'));
  if (outStem.empty()) outStem = "scene";
  // Which files beside `out` are photowalk's: those the model now at `out` names, and
  // those its other VRML names (OUTSTEM.wrl, .wrz, .wrl.gz: they share the textures'
  // names) name. Any other file there is a person's, never written over.
  std::unordered_set<std::string> previous, siblings;
  for (const std::string& sibling : {name, outStem + ".wrl", outStem + ".wrz", outStem + ".wrl.gz"}) {
    std::error_code existsEc;
    const fs::path model = out.parent_path() / sibling;
    if (!fs::is_regular_file(model, existsEc)) continue;
    const auto quoted = quotedInPreviousModel(model, sibling != outStem + ".wrl");
    (sibling == name ? previous : siblings).insert(quoted.begin(), quoted.end());
  }
  // One file per distinct image, named after the output and the texture's own url,
  // encoded before it is named: a name is usable when nothing is there, or when the
  // file there is photowalk's and holds these very bytes. A texture that changed gets
  // a name of its own (m_s_floor_2.png), so that the previous model keeps its textures
  // until the new one replaces it in one rename (base/staging.h).
  std::unordered_map<const Image*, std::string> urls;
  std::map<std::string, std::vector<uint8_t>> files;  // by name
  const auto usable = [&](const std::string& file, const std::vector<uint8_t>& bytes) {
    if (files.count(file)) return false;
    std::error_code ec;
    const fs::path there = out.parent_path() / file;
    if (!fs::exists(fs::symlink_status(there, ec))) return true;
    if (!previous.count(file) && !siblings.count(file)) return options.overwriteForeignFiles;
    if (!fs::is_regular_file(fs::symlink_status(there, ec)) || fs::file_size(there, ec) != bytes.size()) return false;
    auto held = readInputFile(there, kTextureInput);
    return held && held->size() == bytes.size() && std::equal(bytes.begin(), bytes.end(), held->begin(), [](uint8_t a, char b) {
             return a == static_cast<uint8_t>(b);
           });
  };
  const char* extension = options.jpegTextures ? ".jpg" : ".png";
  for (const Shape& s : scene.shapes) {
    if (!s.appearance || !s.appearance->texture || !s.appearance->texture->image) continue;
    const Texture& t = *s.appearance->texture;
    if (urls.count(t.image.get()) || t.image->empty()) continue;
    // A texture this writer named for the same output stem keeps its name, so that
    // rewriting a file does not stack prefixes (hall_hall_floor.png).
    std::string stem = textureStem(t.url);
    if (stem.rfind(outStem + "_", 0) == 0 && stem.size() > outStem.size() + 1) stem = stem.substr(outStem.size() + 1);
    const std::string base = outStem + "_" + stem;
    // Grey (intensity) textures stay PNG: a JPEG would come back in colour, replacing
    // the material's colour instead of modulating it.
    const char* ext = t.image->grey ? ".png" : extension;
    auto bytes = encodeImage(*t.image, ext);
    if (!bytes) return makeError((out.parent_path() / (base + ext)).string() + ": " + bytes.message());
    // Its detail layer (texture_detail.h) beside it, named after it, as the info lines say.
    const Image* detail = t.sourceFromTexCoord && hasDetail(t) && !urls.count(t.detail.get()) ? t.detail.get() : nullptr;
    std::vector<uint8_t> detailBytes;
    if (detail) {
      auto encoded = encodeImage(*detail, fs::path(detailUrl(base + ext)).extension().string());
      if (!encoded) return makeError((out.parent_path() / detailUrl(base + ext)).string() + ": " + encoded.message());
      detailBytes = std::move(*encoded);
    }
    std::string file = base + ext;
    for (int k = 2; !usable(file, *bytes) || (detail && !usable(detailUrl(file), detailBytes)); ++k) {
      file = base + "_" + std::to_string(k) + ext;
    }
    urls.emplace(t.image.get(), file);
    files.emplace(file, std::move(*bytes));
    if (detail) {
      urls.emplace(detail, detailUrl(file));
      files.emplace(detailUrl(file), std::move(detailBytes));
    }
  }
  auto text = vrmlText(scene, options, urls);
  if (!text) return makeError(out.string() + ": " + text.message());
  if (gz) {
    auto compressed = gzipCompress(*text);
    if (!compressed) return makeError(out.string() + ": " + compressed.message());
    text = std::move(*compressed);
  }
  // The model and its textures are written into a hidden folder beside `out` and moved
  // into place only when all are whole, the textures first, the model that names them
  // last; then the previous model's textures that no model here names any more go. A
  // failed (or killed) write leaves the previous model as it was, and the next write
  // removes what a killed one left (base/staging.h).
  auto staged = StagedFiles::create(out.parent_path(), name);
  if (!staged) return makeError(out.string() + ": " + staged.message());
  std::vector<std::string> order;
  for (const auto& [file, bytes] : files) {
    const std::span<const char> span(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (Status saved = writeFileAtomic(staged->pathFor(file), span); !saved) {
      return makeError((out.parent_path() / file).string() + ": " + saved.message());
    }
    order.push_back(file);
  }
  if (Status written = writeFileAtomic(staged->pathFor(name), *text); !written) {
    return makeError(out.string() + ": " + written.message());
  }
  order.push_back(name);
  // What the model at `out` names when this one replaces it (read under the commit's
  // lock: another build may have replaced it since), less what this one or a sibling
  // names. Only image files named after this output: the model's other strings are
  // descriptions, or urls of files that are not photowalk's to remove.
  const auto replaced = [&] {
    std::vector<std::string> gone;
    for (const std::string& file : quotedInPreviousModel(out, gz)) {
      const std::string ext = fs::path(file).extension().string();
      if (file.rfind(outStem + "_", 0) != 0 || (ext != ".png" && ext != ".jpg") || file.find('/') != std::string::npos) continue;
      if (!files.count(file) && !siblings.count(file)) gone.push_back(file);
    }
    return gone;
  };
  return staged->commit(order, replaced);
}

}  // namespace pw::engine
