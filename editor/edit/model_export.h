// The editor's Export: the model of the shot as it is now (saved or not), made by the
// build command's code (modeling::buildModel: textures cut from the photo, the
// viewpoints, the tour), written as VRML97 or glTF 2.0 by the file's name.
#pragma once

#include <filesystem>

#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/measure.h"
#include "metrology/shot.h"

namespace pw::edit {

// Writes the model of `shot` (its photo BGR, 8 bit; measured as `measurement`) to
// `out`: .wrl, .wrl.gz or .wrz (VRML97, the textures beside it as OUTSTEM_NAME.png)
// or .glb, .gltf (glTF 2.0, textures embedded), atomically, as `photowalk build` does.
// Errors: another name, the model cannot be built, the file cannot be written (then
// nothing is left behind).
Status exportModel(const metrology::Shot& shot, const cv::Mat& photo, const metrology::Measurement& measurement,
                   const std::filesystem::path& out);

}  // namespace pw::edit
