// Radial lens distortion: OpenCV's model with k1 and k2 (no tangential terms, no k3),
// in coordinates normalised by the focal length about the principal point. A point
// the pinhole would put at x = (u - cu) / f, y = (v - cv) / f appears in the photo at
//   x_d = x (1 + k1 r² + k2 r⁴),  r² = x² + y²
// (OpenCV's calib3d documentation, "Detailed description"; k1 < 0 is barrel
// distortion, a wide lens that bows straight lines outwards). Photos without
// distortion (k1 = k2 = 0) take exactly the pinhole paths everywhere.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"

namespace pw::metrology {

struct Intrinsics;

struct RadialDistortion {
  double k1 = 0;
  double k2 = 0;
  bool isNone() const { return k1 == 0 && k2 == 0; }
  bool operator==(const RadialDistortion&) const = default;
};

// The functions below take the camera (corridor_frame.h's Intrinsics: focal length,
// principal point) and its `distortion`.

// The photo pixel where the lens puts what the pinhole puts at `pinholePx`.
glm::dvec2 distortPixel(const Intrinsics& camera, const glm::dvec2& pinholePx);

// The inverse: the pinhole pixel of what the photo shows at `photoPx` (OpenCV's
// undistortPoints, iterated to 1e-9 of the focal length). None where the model does not
// invert (beyond the radius at which it folds back) or the iteration does not settle.
std::optional<glm::dvec2> undistortPixel(const Intrinsics& camera, const glm::dvec2& photoPx);

// The largest |k1| or |k2| a shot file, `detect --distortion` and the editor take
// (focal-normalised: far beyond any real lens).
inline constexpr double kMaxDistortionCoefficient = 2.0;

// Checks that the coefficients are finite; the message names them.
Status checkDistortion(const RadialDistortion& lens);

// True where the lens maps pinhole pixel `pinholePx` one-to-one: within the radius at
// which the model folds back (its radial slope turns negative). A strong barrel
// distortion folds within the photo's corners; beyond the fold it shows nothing of
// the pinhole's image.
bool insideFold(const Intrinsics& camera, const glm::dvec2& pinholePx);

// "k1 -0.100, k2 0.000" for messages.
std::string distortionText(const RadialDistortion& lens);

// Maps (CV_32FC1 x and y) for cv::remap that make the distorted photo into
// the pinhole image of `pinholeSize` whose principal point sits `offsetPx` further
// right and down than the camera's (a larger canvas keeps what barrel distortion
// squeezed in at the edges): pinhole pixel p samples the photo at
// distortPixel(camera, p - offsetPx).
void undistortionMaps(const Intrinsics& camera, cv::Size pinholeSize,
                      const glm::dvec2& offsetPx, cv::Mat& mapX, cv::Mat& mapY);

// The reverse maps: for each pixel of a `photoSize` distorted photo, where to sample a
// pinhole image whose principal point sits `offsetPx` from the camera's (as above);
// pixels where the model does not invert get -1 (outside any image).
void distortionMaps(const Intrinsics& camera, cv::Size photoSize,
                    const glm::dvec2& offsetPx, cv::Mat& mapX, cv::Mat& mapY);

}  // namespace pw::metrology
