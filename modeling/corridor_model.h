// One measured corridor as a textured, true-scale model (issue: photo to walkable
// model). Textures are cut straight from the photo through the measured camera, so
// that rendering the model from that camera gives the photo back pixel for pixel.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "modeling/layout.h"
#include "modeling/side_room.h"
#include "modeling/stand_up.h"
#include "modeling/synthesis.h"
#include "engine/scene/camera.h"
#include "engine/scene/scene.h"
#include "metrology/measure.h"

namespace pw::modeling {

// Synthesized: the corridor runs on this far behind the photo's camera and is closed
// there by a wall (about where a person taking a photo down a corridor stands with
// their back to a wall or a door; the photo cannot say).
inline constexpr double kClosedBehindCameraM = 3.0;

struct ModelOptions {
  bool lit = false;          // false: photo-lit (no Material, headlight off); true: the seed paper's lighting
  double pxPerM = 0;         // texture resolution; 0: the photo's own best on each plane
  int maxTextureSide = 4096;
  // Texels per texture at most (the photo's best density on a big photo's walls would
  // give 4096 x 2000 and more, slow to cut and write for detail only the nearest metre
  // of a wall has); the density is scaled down evenly beyond it.
  double maxTexturePixels = 3.0e6;
  // true: only what the photo shows, as cut from it (`build --photo-only`); false: detail
  // synthesized where the photo saw a surface coarsely, and texture where it did not see
  // it, with the corridor closed behind the camera (modeling/synthesis.h).
  bool photoOnly = false;
  // With synthesis, also add detail where the photo saw a surface coarsely, as each
  // texture's detail layer (engine/scene/texture_detail.h: photowalk's renderer shows it
  // only where a view comes closer than the photo was taken); false: `build --no-detail`.
  bool detail = true;
  // Where the cut-outs of the shot's objects (GrabCut's masks, the fill behind them) are
  // kept between builds of the same photo's model (the editor's preview as a corner
  // moves); null: made each time.
  CutOutCache* cutOutCache = nullptr;
};

// The part of one surface that has a texture, and the texture.
struct SurfaceTexture {
  Rect rect;            // (s, t) range the texture covers (corridor_frame.h)
  engine::Image image;  // RGBA, sRGB; rows top to bottom = t from rect.t1 down to rect.t0
  double pxPerM = 0;
  double coveredFraction = 0;  // share of the texture the photo shows (the rest is filled)
  glm::mat3 sourceFromTexCoord{1.0f};  // engine::Texture::sourceFromTexCoord
  engine::Image detail;  // engine::Texture::detail (grey, the image's size); empty: none
};

struct CorridorModel {
  std::string name;
  metrology::Dimensions box;
  metrology::Measurement measurement;
  int photoWidth = 0;
  int photoHeight = 0;
  // How far towards the camera (z > 0) the photo shows the floor, walls and ceiling;
  // beyond that, up to behind the camera (untexturedNearM), surfaces continue: with
  // synthesis, textured (`extensions`) up to a wall closing the corridor there (the
  // near-end wall, in the far wall's look); photo-only, untextured and open.
  double photoNearM = 0;
  double untexturedNearM = 0;
  bool closed = false;  // the near-end wall at untexturedNearM
  std::array<std::optional<SurfaceTexture>, 5> textures;  // far wall, left, right, floor, ceiling
  // Synthesized (ModelOptions::photoOnly false): each surface's texture from photoNearM
  // to untexturedNearM (none for the far wall), what synthesis did to each texture, and
  // the near-end wall's colour (the far wall's median: its look without its door).
  std::array<std::optional<SurfaceTexture>, 5> extensions;
  std::array<SynthesisStats, 5> synthesis{};
  glm::vec3 nearEndColor{0.5f};
  // Objects stood up on the floor (stand_up.h); the textures above were cut from the
  // photo with them filled.
  std::vector<StandingObject> standing;
  // The cutouts that could not stand up, each the reason naming it (StoodUp::leftPainted):
  // painted on the surfaces as the photo shows them.
  std::vector<std::string> leftPainted;
  // Openings in the side walls with a room behind each (side_room.h).
  std::vector<SideRoom> rooms;
  // Per surface, for its untextured parts: the mean of the photo's pixels where it
  // shows the surface, averaged as stored (sRGB-encoded, not linear light), 0..1.
  std::array<glm::vec3, 5> meanColor{};
};

// An 8-bit BGR (OpenCV) image as an engine image: RGBA, opaque, rows top to bottom.
engine::Image imageFromBgr(const cv::Mat& bgr);

// A texture cut from the photo by rectify.h over a W x H metre rectangle whose metric
// (x, y) (from its top-left corner, y down) reaches the photo's pinhole pixels through
// `photoFromMetric`: its texture coordinates (s, t, 1), t = 0 at the bottom, to those
// pixels (engine::Texture::sourceFromTexCoord).
glm::mat3 sourceFromTexCoord(const cv::Matx33d& photoFromMetric, double widthM, double heightM);

// Cuts the textures out of the photo (BGR, 8 bit) for the measured corridor.
// `attached`: the corridor starts at another's wall, so nothing runs towards its camera.
Result<CorridorModel> makeCorridorModel(const std::string& name, const cv::Mat& photo,
                                        const metrology::Measurement& measurement, bool attached,
                                        const ModelOptions& options);

// The same with `cutouts` stood up on the floor (stand_up.h): the surfaces are cut from
// the photo with the objects filled, and the model holds them in `standing`; cutouts of
// shape kOpening open the side wall with a room behind (side_room.h), in `rooms`. An
// object that cannot stand up is left painted, its reason in `leftPainted`. Errors name
// the object (and the corridor).
Result<CorridorModel> makeCorridorModel(const std::string& name, const cv::Mat& photo,
                                        const metrology::Measurement& measurement,
                                        const std::vector<metrology::Cutout>& cutouts, bool attached,
                                        const ModelOptions& options);

// Why the scene's cutout `cutoutName` was left painted (its "left painted: cutout
// "NAME": ..." info line, which makeBuildingScene writes), or nothing: it stood up, or there
// is no such cutout.
std::optional<std::string> leftPaintedReason(const engine::Scene& scene, const std::string& cutoutName);

// A whole building (or one corridor): shapes, lights, viewpoints, navigation.
// `plan` places the corridors and holds the openings.
engine::Scene makeBuildingScene(const std::vector<CorridorModel>& corridors, const BuildingPlan& plan,
                                const ModelOptions& options);

// The camera that took a corridor's photo (imageWidth x imageHeight), placed in the
// building's world frame by `worldFromCorridor`, with the photo's exact intrinsics and
// the field of view they have: rendering from it at the photo's size lines up with the
// photo. The one place a measured camera becomes the engine's: the model's "Photo"
// viewpoint and render --camera-from both come from here.
engine::Camera photoCamera(const metrology::Measurement& measurement, int imageWidth, int imageHeight,
                           const glm::dmat4& worldFromCorridor);

}  // namespace pw::modeling
