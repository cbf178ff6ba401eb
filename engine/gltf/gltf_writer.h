// glTF 2.0 export of the scene model (engine/scene/scene.h).
//
// What maps to what (the approximations are documented in gltf_mapping.h/.cpp):
//   Shape            -> node (translation/rotation/scale) + mesh. A transform with
//                       shear is not expressible as a glTF node, so such a shape's
//                       mesh is written already transformed (not shared). A mirroring
//                       transform becomes a positive one over a mirrored copy of the
//                       mesh (one per mesh), since viewers mishandle negative scales.
//   shared Mesh      -> one set of accessors; one glTF mesh per (Mesh, material).
//   Appearance       -> material, shared between shapes with equal content:
//                       no Material: KHR_materials_unlit (VRML97 4.14.3: unlit);
//                       Material: pbrMetallicRoughness (diffuse -> baseColor,
//                       1 - transparency -> alpha and alphaMode BLEND, shininess ->
//                       roughness, emissiveColor -> emissiveFactor, metallic 0);
//                       lines and points are unlit in their emissive colour (6.24).
//   Texture          -> texture + sampler (wrap modes, trilinear mipmapped
//                       filtering) + PNG image embedded in the binary buffer.
//   texCoords (s, t) -> TEXCOORD_0 (s, 1 - t): glTF's v runs down from the image top.
//   colors           -> COLOR_0 (VRML: they replace the diffuse colour; ignored,
//                       as in VRML, when an RGB texture is present).
//   Mesh::solid      -> material.doubleSided = !solid.
//   Viewpoint        -> perspective camera node named by its description.
//   Light            -> KHR_lights_punctual light node (lights that are off, have a
//                       zero radius or cut-off angle are left out).
//   title            -> scene name; info -> asset.extras.info.
// Background, NavigationInfo (except the camera's clip planes), light ambient
// intensity, specular colour and the headlight have no glTF counterpart and are
// not written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "base/result.h"
#include "engine/scene/scene.h"

namespace pw::engine {

enum class GltfContainer : uint8_t {
  kGlb,         // binary glTF: JSON chunk + BIN chunk (textures inside)
  kEmbeddedJson // .gltf JSON with the buffer as a base64 data: URI
};

// Writes `scene` to `out` atomically (a temporary file renamed into place, so a
// failure leaves no file and an existing `out` untouched). The extension picks the
// container: ".glb" binary, ".gltf" JSON with all data embedded (case-insensitive).
// Errors: an unknown extension, a missing folder, a scene the format cannot hold
// (non-finite numbers, indices out of range, a field of view outside (0, pi)), a
// file over 4 GiB, or an I/O failure; the message names the file or the shape.
Status writeGltf(const Scene& scene, const std::filesystem::path& out);

// The file's bytes, without writing it (for writers that stream elsewhere and for tests).
// jpegQuality 1..100: opaque textures as JPEG of that quality (a web page's size);
// 0: PNG, lossless.
Result<std::vector<uint8_t>> encodeGltf(const Scene& scene, GltfContainer container, int jpegQuality = 0);

}  // namespace pw::engine
