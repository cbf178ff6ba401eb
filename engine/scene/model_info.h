// What photowalk keeps in a model file beyond VRML97 and glTF: typed in the Scene in
// memory, encoded as WorldInfo info strings (glTF: asset.extras.info) only when a file
// is written, and decoded when one is read. Other viewers ignore these lines or show
// them as text. README, "What a model file carries beyond VRML97", documents them:
//   photowalk-tour X Y Z X Y Z ...                 Scene::tour (at least two points)
//   photowalk-camera FX FY CU CV W H DESCRIPTION   Viewpoint::intrinsics of the
//       viewpoint with that description (the rest of the line; the k-th such line of a
//       description goes to the k-th viewpoint of that description)
//   photowalk-texture-source ...                   Texture::sourceFromTexCoord
//       (texture_source.h)
//   photowalk-texture-detail URL                   Texture::detail (texture_detail.h)
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/scene/scene.h"
#include "engine/scene/texture_source.h"

namespace pw::engine {

inline constexpr const char* kTourTag = "photowalk-tour";
inline constexpr const char* kCameraTag = "photowalk-camera";

// The info strings a writer puts in the file: scene.info (less any photowalk lines it
// holds), then the tour, the viewpoints' intrinsics and the texture sources, whose
// texture `urlOf` names as the file does (texture_source.h).
std::vector<std::string> infoForFile(const Scene& scene, const std::function<std::string(const Texture&)>& urlOf);

// What a reader does with the info strings it read into scene.info: takes the photowalk
// lines out and puts what they say where it belongs (Scene::tour, Viewpoint::intrinsics,
// Texture::sourceFromTexCoord). Malformed lines are dropped.
// Detail layers are loaded with `loadDetail` (texture_source.h).
void takeModelInfo(Scene& scene, const ImageLoader& loadDetail = {});

// One line each way, for tests and tools. decode* return nothing for a line that is not
// theirs or is malformed (a tour of fewer than two points, numbers that are not
// finite, a focal length or image size that is not positive).
std::string encodeTourLine(const std::vector<glm::vec3>& waypoints);
std::optional<std::vector<glm::vec3>> decodeTourLine(const std::string& line);
std::string encodeCameraLine(const Intrinsics& intrinsics, const std::string& description);
std::optional<std::pair<std::string, Intrinsics>> decodeCameraLine(const std::string& line);

}  // namespace pw::engine
