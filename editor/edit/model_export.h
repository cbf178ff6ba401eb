// The editor's Export: the model of the shot as it is now (saved or not), made by the
// build command's code (modeling::buildModel: textures cut from the photo, the
// viewpoints, the tour), written as VRML97, glTF 2.0 or a web page by the file's name.
#pragma once

#include <filesystem>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/measure.h"
#include "metrology/shot.h"
#include "engine/web/web_page.h"
#include "modeling/pipeline.h"

namespace pw::edit {

// Writes the model of `shot` (its photo BGR, 8 bit; measured as `measurement`) to
// `out`: .wrl, .wrl.gz or .wrz (VRML97, the textures beside it as OUTSTEM_NAME.png),
// .glb, .gltf (glTF 2.0, textures embedded), atomically, as `photowalk build` does, or
// .html (one web page, as `photowalk share` writes it).
// Errors: another name, the model cannot be built, the file cannot be written (then
// nothing is left behind).
Status exportModel(const metrology::Shot& shot, const cv::Mat& photo, const metrology::Measurement& measurement,
                   const std::filesystem::path& out);

// What a web page of `scene` shows beyond the glTF (`photowalk share`, Export): each
// corridor's dimensions (none for a model read from a file) and the tour `photowalk
// tour` walks, sampled every 0.05 s.
engine::WebPageOptions webPageOptionsFor(const engine::Scene& scene, const std::vector<modeling::CorridorModel>& corridors);

}  // namespace pw::edit
