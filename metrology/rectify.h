// Perspective elimination: each plane of the corridor as a fronto-parallel texture
// at true scale (the seed paper's section 2.2, with the true-length stretch it asks
// for after its figure 8). The one rectifier: `photowalk rectify` cuts the corridor's
// planes with it, and `photowalk build` (modeling/corridor_model.cpp) every texture of
// its models, through the plane homography of the measured camera.
//
// Texture orientation. Each texture is what a person standing in the corridor sees
// when facing that plane: its four corners are kPlaneCorners' order (shot.h) as
// top-left, top-right, bottom-right, bottom-left of the image. In the model frame of
// corridor_frame.h (W width, H height, L length):
//   far wall    W x H  TL P1 (-W/2, H, -L)  TR P2 ( W/2, H, -L)  BR P4 ( W/2, 0, -L)  BL P3 (-W/2, 0, -L)
//   left wall   L x H  TL P7 (-W/2, H,  0)  TR P1 (-W/2, H, -L)  BR P3 (-W/2, 0, -L)  BL P5 (-W/2, 0,  0)
//   right wall  L x H  TL P2 ( W/2, H, -L)  TR P8 ( W/2, H,  0)  BR P6 ( W/2, 0,  0)  BL P4 ( W/2, 0, -L)
//   floor       W x L  TL P3 (-W/2, 0, -L)  TR P4 ( W/2, 0, -L)  BR P6 ( W/2, 0,  0)  BL P5 (-W/2, 0,  0)
//   ceiling     W x L  TL P7 (-W/2, H,  0)  TR P8 ( W/2, H,  0)  BR P2 ( W/2, H, -L)  BL P1 (-W/2, H, -L)
// So walls are upright, the floor has its far edge at the top, and the ceiling is as
// seen looking up (near edge at the top, left wall on the left). The corner TL is
// the outer corner of the texture's top-left pixel: texture pixel (i, j) covers
// [i, i+1] x [j, j+1] in texel units with (0, 0) at TL, i.e. its centre is at
// fraction ((i + 0.5) / widthPx, (j + 0.5) / heightPx) from TL towards TR and BL.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/measure.h"
#include "metrology/shot.h"

namespace pw::metrology {

// What a texel whose source lies outside the photo (or behind the camera) holds.
enum class OutsidePhoto {
  kRepeatBorder,  // the photo's border pixels, repeated (a plane the photo shows whole)
  kMeanColor,     // the mean colour of the texels the photo shows (a model's surface
                  // running on beyond the photo; a plane it does not show at all is grey)
};

struct RectifyOptions {
  // Texture resolution in pixels per metre; 0 picks the photo's own best resolution
  // on the plane: the largest number of photo pixels per metre anywhere on the part
  // of the plane the photo shows, so no detail of the photo is lost.
  double pxPerM = 0;
  // With pxPerM = 0: false, one density for both axes (square texels, the photo's most
  // along any direction); true, each axis the photo's best along it (a wall seen at a
  // grazing angle has far more photo pixels per metre up than along, so its texels need
  // not be square: the geometry, not the image, carries the scale).
  bool perAxisDensity = false;
  double minPxPerM = 0;  // the automatic density is at least this
  // The longer side of a texture never exceeds this (the resolution is lowered).
  int maxSidePx = 4096;
  // Texels per texture at most (0: only the 2^28 that any texture is refused beyond);
  // the density is scaled down evenly beyond it.
  double maxPixels = 0;
  OutsidePhoto outside = OutsidePhoto::kRepeatBorder;
};

struct RectifiedPlane {
  cv::Mat image;  // the photo's type (8-bit, 1, 3 or 4 channels), heightPx x widthPx
  double widthM = 0;
  double heightM = 0;
  // Resolution: along the width and along the height (widthPx = round(widthM *
  // pxPerMAxes.x), at least 1), and the lesser of the two (both, with square texels).
  double pxPerM = 0;
  glm::dvec2 pxPerMAxes{0.0};
  // Photo pixel of a texture pixel, both with pixel centres at integer coordinates.
  cv::Matx33d photoFromTexture = cv::Matx33d::eye();
  // Fraction of the texels whose source lies inside the photo (in front of the camera).
  double coverage = 0;
  // Most photo pixels across one texture pixel anywhere the photo shows (> 1: the
  // photo was shrunk there and prefiltered).
  double maxShrink = 0;
  // Mean of the texels the photo shows, in the photo's channel order (128 grey when it
  // shows none).
  cv::Scalar meanColor = cv::Scalar::all(128);
};

// The photo and its Gaussian pyramid (OpenCV pyrDown), grown as planes need it: one
// per photo when several planes are cut from it; with the lens that took it, whose
// distortion (corridor_frame.h's Intrinsics) every plane's pinhole pixel goes through
// before the photo is sampled (none: the pinhole's pixel itself). Not for use by two
// threads at once.
class PhotoPyramid {
 public:
  explicit PhotoPyramid(const cv::Mat& photo, const Intrinsics& lens = {});
  const cv::Mat& photo() const { return levels_.front(); }
  const Intrinsics& lens() const { return lens_; }
  int deepest() const;  // the coarsest level there may be
  const cv::Mat& level(int i);  // i <= deepest()

 private:
  std::vector<cv::Mat> levels_;
  Intrinsics lens_;
};

// Rectifies the plane whose point at metric coordinates (x, y) (metres from the
// texture's top-left corner, x to the right along widthM, y down along heightM) lands
// on the pinhole's homogeneous pixel photoFromPlane · (x, y, 1) = (u w, v w, w), w > 0 in
// front of the camera (photoFromPlane() below gives it for a measured camera), and
// through the pyramid's lens on the photo. photoFromTexture, coverage and the
// resolution are the pinhole's (a lens's distortion changes the density by a few
// percent; the photo's outline through it decides what is shown).
// Resampling is bicubic (the renderer filters a texture once more, and two bilinear
// steps in a row blur thin lines such as mortar and tile joints: 3.5-6 dB in the
// reprojection test); where the texture shrinks the photo, each 64-px tile is filtered
// anisotropically along the texture's axes: it samples the pyramid level of its lesser
// shrink and averages up to 8 bilinear supersamples per axis for the rest, so that fine
// detail becomes an average instead of aliasing, without blurring the other axis. The
// shrink is taken where the photo shows the tile. Tiles run in parallel; tiles the
// photo does not show at all are not sampled when options.outside is kMeanColor.
// Fails (one line) on an empty photo, sizes that are not positive, a homography that
// is not finite, or (with kRepeatBorder) a plane the photo does not show at all.
Result<RectifiedPlane> rectifyPlane(PhotoPyramid& photo, const cv::Matx33d& photoFromPlane, double widthM,
                                    double heightM, const RectifyOptions& options = {});

// The same for the plane whose corners appear at `quadPx` (TL, TR, BR, BL as above, all
// in front of the camera); also fails on a degenerate quad.
Result<RectifiedPlane> rectifyPlane(const cv::Mat& photo, const std::array<glm::dvec2, 4>& quadPx, double widthM,
                                    double heightM, const RectifyOptions& options = {});

// The homography from a plane's own metric coordinates (x, y), the model-frame point
// origin + x xAxis + y yAxis, to the photo's homogeneous pixels (u w, v w, w) with w the
// point's depth in front of the camera: corridor_frame.h's projectToPixel as a matrix.
cv::Matx33d photoFromPlane(const Intrinsics& camera, const CameraPose& pose, const glm::dvec3& origin,
                           const glm::dvec3& xAxis, const glm::dvec3& yAxis);

// True width and height (metres) of a plane's texture for a corridor of `size`.
glm::dvec2 planeSizeM(Plane plane, const Dimensions& size);

// Model-frame positions of a plane's texture corners TL, TR, BR, BL (see above).
std::array<glm::dvec3, 4> planeCornersM(Plane plane, const Dimensions& size);

// All five planes of a measured corridor, in Plane order, through the measured
// camera (photoFromPlane), so that the textures line up exactly with the box that
// measurement describes.
Result<std::array<RectifiedPlane, kPlaneCount>> rectifyCorridor(const cv::Mat& photo, const Measurement& measurement,
                                                                const RectifyOptions& options = {});

}  // namespace pw::metrology
