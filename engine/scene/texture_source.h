// Keeping Texture::sourceFromTexCoord in model files. Neither VRML97 nor glTF has a
// place for it, so writers add one WorldInfo info string (glTF: asset.extras.info)
// per texture cut from a photo, which other viewers ignore or show as text:
//   photowalk-texture-source H00 H10 H20 H01 H11 H21 H02 H12 H22 URL
// H column by column, mapping the scene's texture coordinates (s, t, 1), t = 0 at the
// bottom, to photo pixels; URL, the rest of the line, as the file names the texture
// (the VRML ImageTexture url, the glTF image name). Readers take these lines out of
// Scene::info again and put each on the textures with that url. A texture with a source
// and a detail layer (Texture::detail) also gets the line
//   photowalk-texture-detail URL
// right after its source line, and the writer puts the layer in the image
// detailUrl(URL) (texture_detail.h), which a reader loads. Writers and readers reach
// these through model_info.h, with photowalk's other lines.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/scene/scene.h"

namespace pw::engine {

inline constexpr const char* kTextureSourceTag = "photowalk-texture-source";

// scene.info plus one line per texture with a source that `urlOf` names (an empty
// name leaves the texture out); scene.info's own texture-source lines are replaced.
std::vector<std::string> infoWithTextureSources(const Scene& scene,
                                                const std::function<std::string(const Texture&)>& urlOf);

// A reader's image by the name the file gives it (the VRML url, the glTF image name);
// null when there is none or it cannot be read.
using ImageLoader = std::function<std::shared_ptr<const Image>(const std::string& url)>;

// Moves the texture-source and texture-detail lines out of scene.info onto the textures
// they name; each detail layer is loaded with `loadDetail` (none without one). Malformed
// lines (not nine finite numbers and a url) are dropped, and so is a detail layer that
// cannot be loaded or is not the texture's size.
void applyTextureSources(Scene& scene, const ImageLoader& loadDetail = {});

// The same homography for texture coordinates with t measured from the top (v = 1 - t:
// Vulkan's and glTF's convention); its own inverse.
glm::mat3 withFlippedT(const glm::mat3& sourceFromTexCoord);

}  // namespace pw::engine
