// Objects stood up (issue 25, part 3): what stands in front of the walls (a person, a
// cabinet, a pillar) becomes a cut-out standing on the floor instead of a smear painted
// across the floor and the wall behind it, as Tour Into the Picture (Horry et al., 1997)
// stood up its foreground objects.
//
// A person outlines the object in the photo (the shot's `cutouts`); OpenCV's GrabCut
// finds the object inside the outline; the object's lowest pixel is where it meets the
// floor. The cut-out is a vertical rectangle through that floor point, facing the photo's
// camera, as wide and as high as the object's pixels reach on it, textured with the photo
// and with the object's mask as alpha. A box-like object (a cabinet, a bench) is a box
// instead: its footprint from where the mask's lowest pixels meet the floor, then the box
// whose outline in the photo best covers the mask; the faces the photo sees are textured
// as the cut-out is, the others take the object's colour. From the photo's camera it covers exactly the
// object's pixels, so the model still gives the photo back; from elsewhere the object
// stands in the corridor. The floor and walls behind it are filled from their
// surroundings (inpainting), so that they no longer carry it.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core.hpp>

#include "base/result.h"
#include "engine/scene/image.h"
#include "metrology/measure.h"
#include "metrology/shot.h"

namespace pw::modeling {

// One face of an object stood up: a rectangle in the corridor's model frame, its corners
// bottom-left, bottom-right, top-right, top-left as seen from outside.
struct StandingFace {
  std::array<glm::dvec3, 4> cornersM{};
  glm::dvec3 normal{0.0};  // outwards
  // RGBA: the photo on the face, alpha the object's mask as the photo's camera sees it
  // through the face; where that camera does not see the face (a box's back and far
  // side: `photo` false), `colour` with the same alpha.
  engine::Image image;
  bool photo = true;
  // Its texture coordinates (s, t, 1), t = 0 at the bottom, to the photo's pinhole pixels
  // (engine::Texture::sourceFromTexCoord): the renderer reads it as the photo was seen.
  glm::mat3 sourceFromTexCoord{1.0f};
  glm::vec3 colour{0.5f};  // RGB 0-1: the object's mean colour in the photo
};

struct StandingObject {
  std::string name;
  metrology::CutoutShape shape = metrology::CutoutShape::kFlat;
  // Flat: one face, an upright rectangle facing the photo's camera, its bottom edge on the
  // floor. A box: its five faces above the floor, sides along the corridor's axes.
  std::vector<StandingFace> faces;
  glm::dvec3 footM{0.0};    // flat: where the object's lowest pixel meets the floor; a box: its footprint's middle
  double widthM = 0;        // flat: as the object's pixels reach on its plane; a box: across the corridor (x)
  double heightM = 0;
  double depthM = 0;        // a box: along the corridor (z); flat: 0
  // A box: its depth's ± (2 px of its outline along the side the photo shows), and
  // whether the photo shows it at all (false: its side is seen so nearly edge on that the
  // ± is over half of it, and the depth is a cabinet's, 0.5 m).
  double depthSigmaM = 0;
  bool depthSeen = true;
  double distanceM = 0;     // from the photo's camera to the foot, along the floor
  int maskPixels = 0;       // photo pixels GrabCut gave the object
};

struct StoodUp {
  std::vector<StandingObject> objects;
  cv::Mat behind;  // the photo (BGR) with the stood objects' pixels filled from their surroundings
  // The cutouts that could not stand up, each the reason naming it ("cutout "lamp": its
  // top meets the ceiling beyond the corridor's ..."): they stay painted on the surfaces
  // behind them (their pixels are not filled), as they were before they were outlined.
  std::vector<std::string> leftPainted;
};

// What GrabCut and the fill make of a photo's outlines: each object's mask (CV_8U, the
// photo's size) and the photo with them filled from their surroundings. They depend on
// the photo and the outlines only, not on the corners.
struct CutOuts {
  std::vector<cv::Mat> masks;
  cv::Mat behind;
};

// The cut-outs of the last few (photo, outlines) seen, so that a model rebuilt as a
// corner moves (the editor's preview) does not run GrabCut and the fill again: about
// 0.7 s for a person at the full preview of a 9-megapixel photo (preview_bench). A photo is known by its
// pixels' address, size and channel sums. Not thread-safe: one builder thread uses it.
class CutOutCache {
 public:
  // The cut-outs of `outlines` (each already checked and in pixels) in `photo`, made
  // with `make` unless kept from an earlier call.
  const CutOuts& get(const cv::Mat& photo, const std::vector<std::vector<cv::Point>>& outlines,
                     const std::function<CutOuts()>& make);
  // The photo filled about only the objects `stood` marks (the others are left painted:
  // their pixels stay), for the cut-outs the last get() returned, made with `fill` unless
  // kept: which objects stand seldom changes as a corner moves, and the fill costs about
  // a quarter of a second at the full preview of a 9-megapixel photo.
  const cv::Mat& behindStood(const std::vector<bool>& stood, const std::function<cv::Mat()>& fill);
  int made() const { return made_; }  // how many times `make` or `fill` ran (tests)

 private:
  struct Entry {
    const void* data = nullptr;
    cv::Size size;
    cv::Scalar sums;
    std::vector<std::vector<cv::Point>> outlines;
    CutOuts cut;
    std::vector<std::pair<std::vector<bool>, cv::Mat>> stoodFills;  // behindStood's, most recent last
  };
  static constexpr size_t kStoodFills = 2;
  static constexpr size_t kEntries = 4;  // the reduced and full previews, before and after an edit
  std::vector<Entry> entries_;          // most recent last
  int made_ = 0;
};

// What standUpObjects makes: the objects and the photo filled behind them, or the
// objects alone (a check of the outlines, as the editor's at an outline's close: the
// fill costs about a quarter of a second for a person on a 9-megapixel photo).
enum class StandUpParts { kObjectsAndFill, kObjectsOnly };

// The model-frame point where the photo pixel's ray (through the lens's distortion) meets
// the plane through `origin` with normal `normal`; nullopt behind the camera or along the
// plane.
std::optional<glm::dvec3> onPlane(const metrology::Measurement& m, glm::dvec2 photoPx, glm::dvec3 origin,
                                  glm::dvec3 normal);

// Stands up each of `cutouts` in the measured corridor seen in `photo` (BGR, 8 bit).
// A cutout that cannot stand up in this corridor is left painted, with the reason in
// StoodUp::leftPainted: an object GrabCut and the outline leave empty, a lowest pixel
// above the horizon (it does not stand on the floor the photo shows) or beyond the
// corridor's floor, a hanging object whose top is not on the ceiling. (The corners
// moved, a cutout that stood up may no longer: the model still builds.) Errors are the
// outlines themselves: a point not a number, an outline outside the photo. `cache`:
// where the masks and the fill are kept between calls (null: made each time;
// kObjectsOnly does not use it, and leaves StoodUp::behind empty).
Result<StoodUp> standUpObjects(const cv::Mat& photo, const metrology::Measurement& measurement,
                               const std::vector<metrology::Cutout>& cutouts, CutOutCache* cache = nullptr,
                               StandUpParts parts = StandUpParts::kObjectsAndFill);

}  // namespace pw::modeling
