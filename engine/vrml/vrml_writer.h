// Writing the scene model as VRML97 (ISO/IEC 14772-1, classic UTF-8 encoding).
//
// The output is indented, one Shape per scene shape (inside a Transform when its
// matrix is not the identity), with DEF/USE for meshes, appearances and textures that
// several shapes share, Viewpoints with descriptions, NavigationInfo, lights,
// Background and WorldInfo. Numbers are the shortest decimal text that reads back to
// the same float, so that readVrml(writeVrml(scene)) gives the same scene.
#pragma once

#include <filesystem>
#include <string>
#include <unordered_map>

#include "base/result.h"
#include "engine/scene/scene.h"

namespace pw::engine {

struct VrmlWriteOptions {
  bool jpegTextures = false;  // write textures as JPEG (quality 92) instead of PNG
  std::string title;          // WorldInfo title; empty: the scene's own title
  // A texture's file name taken by a file that neither the model now at `out` nor one
  // of its other VRML names (OUTSTEM.wrl, .wrz, .wrl.gz) names (a person's own
  // m_s_floor.png) is not written over: the texture gets a free name
  // (m_s_floor_2.png). True (build --force): such files are replaced.
  bool overwriteForeignFiles = false;
};

// Writes `out` (.wrl, or gzip-compressed when it ends in .gz or .wrz) atomically, and
// each distinct texture image beside it as OUTSTEM_NAME.png (or .jpg), referenced by a
// relative url. Fails, writing nothing, on a scene that is not well formed (an index
// out of range, attribute arrays of the wrong length, a non-finite number). All files
// are written into a hidden folder beside `out` first and moved into place once whole
// (base/staging.h): when one cannot be written, none of them appears and the previous
// model stays as it was. A texture whose bytes differ from the file of its name that
// the previous model names takes a name of its own (OUTSTEM_NAME_2.png), so that a
// kill among the renames leaves one model whole; the previous model's textures that
// no model at `out`'s names uses any more are removed once the new model is in place.
Status writeVrml(const Scene& scene, const std::filesystem::path& out, const VrmlWriteOptions& options = {});

// The VRML97 text of a scene. `imageUrls` gives the url written for each texture image
// (a texture whose image has no entry is left out).
Result<std::string> vrmlText(const Scene& scene, const VrmlWriteOptions& options,
                             const std::unordered_map<const Image*, std::string>& imageUrls);

}  // namespace pw::engine
