// The scene model: what the renderer draws and what VRML97 / glTF read and write.
//
// Independent of Vulkan. Units are metres, right-handed, Y up (VRML97 conventions).
// Everything is in world space except Shape::mesh, which is in the shape's local space
// and placed by Shape::transform, so that one mesh can be shared by several shapes.
// Shared pieces (meshes, appearances, textures) are held by shared_ptr: a VRML
// DEF/USE maps to the same pointer, and writers turn the same pointer back into USE.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/scene/image.h"

namespace pw::engine {

// VRML97 Material node (ISO/IEC 14772-1, 6.27), defaults as in the standard.
struct Material {
  glm::vec3 diffuseColor{0.8f, 0.8f, 0.8f};
  float ambientIntensity = 0.2f;
  glm::vec3 emissiveColor{0.0f};
  glm::vec3 specularColor{0.0f};
  float shininess = 0.2f;     // 0..1, exponent = shininess * 128
  float transparency = 0.0f;  // 0 opaque .. 1 invisible

  bool operator==(const Material&) const = default;
};

enum class TextureWrap : uint8_t { kRepeat, kClamp };

struct Texture {
  std::shared_ptr<const Image> image;  // RGBA8, never null for a usable texture
  std::string url;                     // as named in the source file ("" if made in code)
  TextureWrap wrapS = TextureWrap::kRepeat;
  TextureWrap wrapT = TextureWrap::kRepeat;
  // A texture cut from a photo (photowalk build): the plane homography from texture
  // coordinates (s, t, 1), t = 0 at the bottom, to the photo's pixels (u w, v w, w).
  // The texture holds no detail finer than one photo pixel, so the renderer filters it
  // for the part of a screen pixel's footprint beyond that pixel, not all of it, and a
  // view from the photo's camera gives the photo back unblurred. Files keep it as a
  // photowalk extension (texture_source.h).
  std::optional<glm::mat3> sourceFromTexCoord;
  // With a source: detail synthesized finer than the photo resolves, as a grey image of
  // the texture's size (texture_detail.h). `image` is then the composite; photowalk's
  // renderer divides the detail out where a view does not magnify the photo. Files keep
  // it as an image of its own and an info line (model_info.h).
  std::shared_ptr<const Image> detail;
};

// A shape with no material is drawn unlit (VRML97 6.5: full intensity texture or
// white/colour), with a material it follows the VRML97 lighting equations (4.14).
struct Appearance {
  std::optional<Material> material;
  std::shared_ptr<const Texture> texture;  // may be null
};

enum class Topology : uint8_t { kTriangles, kLines, kPoints };

// Indexed geometry in local space. Vertices are unique combinations of attributes
// (VRML index lists are resolved on load). normals/texCoords/colors are either empty
// or the same length as positions. Triangles are counter-clockwise when seen from
// the front.
struct Mesh {
  Topology topology = Topology::kTriangles;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> texCoords;  // (s, t), t = 0 at the bottom of the image (VRML)
  std::vector<glm::vec4> colors;     // per-vertex RGBA, replaces the diffuse colour
  std::vector<uint32_t> indices;
  bool solid = true;  // true: back faces are culled (VRML "solid TRUE")

  bool operator==(const Mesh&) const = default;
};

struct Shape {
  std::shared_ptr<const Mesh> mesh;
  std::shared_ptr<const Appearance> appearance;  // null: unlit white (VRML default)
  glm::mat4 transform{1.0f};                     // local to world
  std::string name;                              // DEF name or a descriptive label
};

enum class LightType : uint8_t { kDirectional, kPoint, kSpot };

// VRML97 DirectionalLight / PointLight / SpotLight, in world space.
struct Light {
  LightType type = LightType::kPoint;
  bool on = true;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float ambientIntensity = 0.0f;
  glm::vec3 position{0.0f};              // point, spot
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // directional, spot
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  // point, spot: 1 / (a0 + a1 d + a2 d^2)
  float radius = 100.0f;                 // point, spot: no light beyond this distance
  float beamWidth = 1.570796f;           // spot, radians
  float cutOffAngle = 0.785398f;         // spot, radians

  bool operator==(const Light&) const = default;
};

// VRML97's default Viewpoint fieldOfView (ISO/IEC 14772-1, 6.53): pi/4.
inline constexpr float kDefaultFieldOfViewRad = 0.785398f;

// A photo's pinhole camera, in pixels of an imageWidth x imageHeight image with pixel
// centres at integer coordinates (u right, v down; OpenCV's convention): the lens that
// took it, principal point included, which a field of view alone cannot say.
// camera.h's intrinsicsFor fits it to frames of other sizes. metrology::Intrinsics is
// the camera a measurement solves for; the engine may not see metrology (nor metrology
// the engine), so modeling::photoCamera converts one into the other.
struct Intrinsics {
  double focalXPx = 0;
  double focalYPx = 0;
  double principalU = 0;
  double principalV = 0;
  // The image the figures are in pixels of; 0 x 0: whatever frame is drawn, taken as
  // they are.
  int imageWidth = 0;
  int imageHeight = 0;

  bool operator==(const Intrinsics&) const = default;
};

// VRML97 Viewpoint: the camera looks along its local -Z with +Y up, rotated by
// `orientation` (axis x, y, z and angle w in radians) and placed at `position`.
struct Viewpoint {
  std::string description;
  glm::vec3 position{0.0f, 0.0f, 10.0f};
  glm::vec4 orientation{0.0f, 0.0f, 1.0f, 0.0f};
  float fieldOfViewRad = kDefaultFieldOfViewRad;  // the smaller of the horizontal and vertical angles
  // The exact lens of a photo's camera (photowalk build's "Photo" viewpoint): when set,
  // it is what photowalk draws with; fieldOfViewRad keeps the nearest VRML field of
  // view for other viewers. Files keep it as a photowalk extension (model_info.h).
  std::optional<Intrinsics> intrinsics;

  bool operator==(const Viewpoint&) const = default;
};

struct NavigationInfo {
  bool headlight = true;
  // VRML avatarSize: collision radius, eye height above the ground, highest step.
  float avatarRadiusM = 0.25f;
  float avatarHeightM = 1.6f;
  float stepHeightM = 0.75f;
  float speedMps = 1.0f;
  std::vector<std::string> type{"WALK", "ANY"};
  float visibilityLimitM = 0.0f;  // 0: infinite

  bool operator==(const NavigationInfo&) const = default;
};

struct Scene {
  std::vector<Shape> shapes;
  std::vector<Light> lights;
  std::vector<Viewpoint> viewpoints;  // the first one is the initial camera
  NavigationInfo navigation;
  glm::vec3 backgroundColor{0.0f};    // VRML Background skyColor[0]
  std::string title;                  // WorldInfo title
  std::vector<std::string> info;      // WorldInfo info, the user's own lines
  // The walk through the model that `photowalk tour` takes (photowalk build writes it),
  // as waypoints in world space, metres; empty: none. Files keep it as a photowalk
  // extension (model_info.h).
  std::vector<glm::vec3> tour;
};

// Axis-aligned bounds of a point set; empty() when it holds nothing.
struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};
  bool empty() const { return min.x > max.x; }
  void add(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
  void add(const Bounds& b) { if (!b.empty()) { add(b.min); add(b.max); } }
  glm::vec3 center() const { return (min + max) * 0.5f; }
  glm::vec3 size() const { return max - min; }
};

Bounds localBounds(const Mesh& mesh);
Bounds worldBounds(const Shape& shape);
Bounds sceneBounds(const Scene& scene);

// Fills mesh.normals with area-weighted vertex normals of its triangles (for meshes
// whose vertices are already split where creases should be).
void computeSmoothNormals(Mesh& mesh);

// Each triangle cut into k x k smaller ones (k >= 1; points, lines and k = 1 come back
// unchanged), every attribute interpolated. Points on a shared edge come out bit for
// bit the same from both triangles, so the surface stays closed. For renderers that
// light per vertex (large faces would otherwise lose a lamp's pool of light).
Mesh subdivideTriangles(const Mesh& mesh, int k);

// A viewpoint that shows the whole scene from +Z when a file has none.
Viewpoint defaultViewpoint(const Scene& scene);

}  // namespace pw::engine
