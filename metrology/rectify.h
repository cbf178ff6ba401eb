// Perspective elimination: each plane of the corridor as a fronto-parallel texture
// at true scale (the seed paper's section 2.2, with the true-length stretch it asks
// for after its figure 8).
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

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "metrology/measure.h"
#include "metrology/shot.h"

namespace pw::metrology {

struct RectifyOptions {
  // Texture resolution in pixels per metre; 0 picks the photo's own best resolution
  // on the plane: the largest number of photo pixels per metre anywhere on the part
  // of the plane the photo shows, so no detail of the photo is lost.
  double pxPerM = 0;
  // The longer side of a texture never exceeds this (the resolution is lowered).
  int maxSidePx = 4096;
};

struct RectifiedPlane {
  cv::Mat image;  // the photo's type (8-bit, 1, 3 or 4 channels), heightPx x widthPx
  double widthM = 0;
  double heightM = 0;
  double pxPerM = 0;  // resolution asked of it; widthPx = round(widthM * pxPerM) (at least 1)
  // Photo pixel of a texture pixel, both with pixel centres at integer coordinates.
  cv::Matx33d photoFromTexture = cv::Matx33d::eye();
  // Fraction of the texture whose source lies inside the photo; the rest repeats
  // the photo's border pixels.
  double coverage = 0;
  // Most photo pixels across one texture pixel anywhere on the texture (> 1: the
  // photo was shrunk there and prefiltered).
  double maxShrink = 0;
};

// Rectifies the plane whose corners appear at `quadPx` (TL, TR, BR, BL as above) to a
// widthM x heightM texture. Resampling is bilinear; where the texture shrinks the
// photo, each 64-px tile is filtered anisotropically along the texture's axes: it
// samples the Gaussian pyramid level (OpenCV pyrDown) of its lesser shrink and
// averages up to 8 bilinear supersamples per axis for the rest, so that fine detail
// becomes an average instead of aliasing, without blurring the other axis. Tiles
// run in parallel.
// Fails (one line) on an empty photo, sizes that are not positive, a degenerate
// quad, or a plane the photo does not show at all.
Result<RectifiedPlane> rectifyPlane(const cv::Mat& photo, const std::array<glm::dvec2, 4>& quadPx, double widthM,
                                    double heightM, const RectifyOptions& options = {});

// True width and height (metres) of a plane's texture for a corridor of `size`.
glm::dvec2 planeSizeM(Plane plane, const Dimensions& size);

// Model-frame positions of a plane's texture corners TL, TR, BR, BL (see above).
std::array<glm::dvec3, 4> planeCornersM(Plane plane, const Dimensions& size);

// All five planes of a measured corridor, in Plane order, from the measurement's
// fitted (reprojected) corners, so that the textures line up exactly with the box
// that measurement describes.
Result<std::array<RectifiedPlane, kPlaneCount>> rectifyCorridor(const cv::Mat& photo, const Measurement& measurement,
                                                                const RectifyOptions& options = {});

}  // namespace pw::metrology
