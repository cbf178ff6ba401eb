// How VRML97 quantities in the scene model become glTF 2.0 quantities.
//
// Small pure functions, kept apart from the writer so that each approximation is
// stated once, next to its reason, and can be tested on its own. VRML97 references
// are to ISO/IEC 14772-1:1997; glTF references to the glTF 2.0 specification and the
// KHR_lights_punctual / KHR_materials_unlit extension texts.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/scene/scene.h"

namespace pw::engine::gltf {

// glTF sampler wrap codes (glTF 2.0, 5.26: sampler.wrapS/wrapT).
inline constexpr int kWrapRepeat = 10497;
inline constexpr int kWrapClampToEdge = 33071;
inline constexpr int kFilterLinear = 9729;
inline constexpr int kFilterLinearMipmapLinear = 9987;

int wrapCode(TextureWrap wrap);

// glTF's perceptual roughness for a VRML shininess in [0, 1]. VRML97 4.14.4 uses the
// Blinn-Phong exponent n = 128 * shininess; the Beckmann distribution with the same
// highlight has alpha^2 = 2 / (n + 2) (Walter et al., "Microfacet Models for
// Refraction", EGSR 2007, eq. 30), and glTF's roughness is sqrt(alpha) (glTF 2.0,
// Appendix B: alpha = roughness^2). shininess 0 -> 1, 0.2 -> 0.52, 1 -> 0.35.
float roughnessFromShininess(float shininess);

// A node transform split into translation, rotation and scale (glTF 2.0, 5.25:
// node.matrix must be decomposable to TRS, which rules out shear and projection).
struct Trs {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // unit length
  glm::vec3 scale{1.0f};
};

// The TRS form of `m`, or nothing when `m` has shear, a projective last row, a zero
// scale or non-finite entries (such a shape's mesh is written already transformed).
// Recomposing the result reproduces `m` to within 1e-5 of its largest scale.
std::optional<Trs> decomposeTrs(const glm::mat4& m);

// Whether `transform` squashes space flat (|det| ~ 0 relative to its scale): faces
// under it have no area and are not drawn; the writer and the reader both leave such
// shapes out.
bool flattens(const glm::mat4& transform);

// glTF perspective camera from a VRML Viewpoint (VRML97 6.53) and the NavigationInfo
// bound with it (6.29).
struct PerspectiveCamera {
  float yfovRad = 0;
  float znearM = 0;
  float zfarM = 0;  // visibilityLimit, or the renderer's far plane when that is infinite
};
PerspectiveCamera perspectiveFromViewpoint(const Viewpoint& viewpoint, const NavigationInfo& navigation);

// KHR_lights_punctual intensity for a VRML light (see the .cpp for the derivation).
// Point and spot lights: candela; directional lights: lux.
inline constexpr float kLightMatchDistanceM = 2.0f;
float punctualIntensity(const Light& light);

// The reverse, for reading glTF lights: sets intensity and attenuation of `light`
// (whose type is set) so that punctualIntensity gives `gltfIntensity` back. Point
// and spot lights become inverse-square VRML lights, intensity 1 and attenuation
// (0, 0, pi / I): exact wherever VRML's attenuation is not clamped at 1, that is
// beyond sqrt(I / pi) metres (1.8 m for 10 cd). Directional: I / pi, at most 1.
void setIntensityFromPunctual(Light& light, float gltfIntensity);

// The reverse of roughnessFromShininess (clamped to VRML's [0, 1]).
float shininessFromRoughness(float roughness);

// Spot cone angles for KHR_lights_punctual: 0 <= inner < outer <= pi/2.
struct SpotCone {
  float innerRad = 0;
  float outerRad = 0;
};
SpotCone spotCone(const Light& light);


// VRML97 colours are display values (browsers wrote them to the screen without any
// transfer function); glTF colour factors and COLOR_0 are linear (glTF 2.0, 3.9.2),
// and viewers encode to sRGB on output. Decoding with the sRGB curve (IEC 61966-2-1)
// keeps the colour a VRML browser showed. Clamps to [0, 1]; NaN becomes 0.
float linearFromSrgb(float encoded);
glm::vec3 linearFromSrgb(const glm::vec3& encoded);
// The reverse, for reading glTF colours into the scene model.
float srgbFromLinear(float linear);
glm::vec3 srgbFromLinear(const glm::vec3& linear);

// The double whose shortest decimal form is the float's shortest decimal form
// (0.8f -> 0.8 rather than 0.800000011920929): readable JSON that reads back as the
// same float. Not for accessor min/max, which must equal the stored floats exactly.
double shortestDouble(float value);

// VRML97 6.23 default texture mapping for geometry with a texture and no texture
// coordinates: s runs 0..1 along the longest side of the bounding box, t along the
// second longest, 0..(second / longest) (ties prefer X, then Y, then Z).
std::vector<glm::vec2> defaultTexCoords(const std::vector<glm::vec3>& positions);

}  // namespace pw::engine::gltf
