#include "modeling/stand_up.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <opencv2/imgproc.hpp>
#include <opencv2/photo.hpp>

#include "metrology/corridor_frame.h"
#include "metrology/distortion.h"
#include "metrology/rectify.h"

namespace pw::modeling {
namespace {

using metrology::Measurement;

// GrabCut works on the outline's box and this much around it (photo pixels, at least).
constexpr int kGrabCutMarginPx = 12;
constexpr int kGrabCutIterations = 5;
constexpr double kGrabCutMaxPixels = 250000;
constexpr double kMinPiecePx = 12;
constexpr double kMinPieceShare = 0.02;
// The cut-out's alpha reaches this far beyond the object's mask (photo pixels), and the
// fill behind it (its edge's blend) less far: from the photo's camera the cut-out covers
// every filled pixel with the photo's own.
constexpr int kHaloPx = 1;
constexpr int kFillMarginPx = kHaloPx - 1;
constexpr double kFillRadiusPx = 5.0;
// A box's pixels this near its outline in the photo keep the photo behind them.
constexpr int kSeamPx = 2;
// Cut-out texels per photo pixel at the object's distance (a second sampling blurs less).
constexpr double kTexelsPerPhotoPixel = 2.0;
constexpr int kMaxTextureSide = 4096;
// A box's depth where the photo shows none of its sides (a cabinet's).
constexpr double kDefaultDepthM = 0.5;
// How far (photo pixels) an object's outline in GrabCut's mask strays from its true edge,
// one standard deviation: what a box's depth seen along its side is good to (cabinets of
// the random TUNE scenes, exact corners: their depth errors, as pixels along the side,
// had a median of 2.5 px and a long tail).
constexpr double kOutlinePx = 4.0;
// A box-like object longer than this along the corridor is not a piece of furniture.
constexpr double kMaxDepthM = 3.0;

// The object inside the outline: GrabCut seeded with the outline's inside as probably
// the object and everything outside it as surely not; the outline's own pixels when
// GrabCut keeps nothing (a flat-coloured object on the same colour).
cv::Mat objectMask(const cv::Mat& photo, const std::vector<cv::Point>& outline) {
  cv::Mat inside = cv::Mat::zeros(photo.size(), CV_8U);
  cv::fillPoly(inside, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(255));
  const cv::Rect box = cv::boundingRect(outline);
  const int margin = std::max(kGrabCutMarginPx, std::max(box.width, box.height) / 10);
  const cv::Rect roi = (box + cv::Size(2 * margin, 2 * margin) - cv::Point(margin, margin)) & cv::Rect(0, 0, photo.cols, photo.rows);
  cv::Mat labels(roi.size(), CV_8U, cv::Scalar(cv::GC_BGD));
  labels.setTo(cv::GC_PR_FGD, inside(roi));
  cv::Mat mask = cv::Mat::zeros(photo.size(), CV_8U);
  // GrabCut needs both kinds among its pixels: an outline filling the whole ROI has no
  // background to learn from.
  const int insideCount = cv::countNonZero(inside(roi));
  if (insideCount > 0 && insideCount < roi.area()) {
    cv::Mat background, foreground;
    // GrabCut seeds its colour models from OpenCV's (thread's) random generator: seeded
    // here, the same photo and outline always give the same mask, whatever ran before.
    cv::theRNG().state = 0x12345678u;
    // On a large photo (a 12 MP phone's person is a few million pixels) GrabCut runs on
    // the region shrunk to kGrabCutMaxPixels, and its mask is taken back to full size
    // inside the outline: its time stays bounded, as the editor's rebuilds need.
    const double shrink = std::min(1.0, std::sqrt(kGrabCutMaxPixels / static_cast<double>(roi.area())));
    cv::Mat region = photo(roi), object;
    if (shrink < 1.0) {
      const cv::Size small(std::max(8, static_cast<int>(std::lround(roi.width * shrink))),
                           std::max(8, static_cast<int>(std::lround(roi.height * shrink))));
      cv::resize(region, region, small, 0, 0, cv::INTER_AREA);
      cv::resize(labels, labels, small, 0, 0, cv::INTER_NEAREST);
    }
    cv::grabCut(region, labels, cv::Rect(), background, foreground, kGrabCutIterations, cv::GC_INIT_WITH_MASK);
    object = (labels == cv::GC_FGD) | (labels == cv::GC_PR_FGD);
    if (shrink < 1.0) {
      cv::resize(object, object, roi.size(), 0, 0, cv::INTER_LINEAR);
      object = (object >= 128) & inside(roi);
    }
    object.copyTo(mask(roi));
  }
  if (cv::countNonZero(mask) == 0) inside.copyTo(mask);
  // Stray specks of the object's colours dropped: pieces under kMinPieceShare of the
  // largest (a person's head, apart from the body, stays).
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  double largest = 0;
  for (const auto& c : contours) largest = std::max(largest, cv::contourArea(c));
  cv::Mat kept = cv::Mat::zeros(mask.size(), CV_8U);
  for (size_t i = 0; i < contours.size(); ++i) {
    if (cv::contourArea(contours[i]) >= std::max(kMinPiecePx, kMinPieceShare * largest)) {
      cv::drawContours(kept, contours, static_cast<int>(i), cv::Scalar(255), cv::FILLED);
    }
  }
  mask &= kept;
  return mask;
}

// A face textured with the photo read through the camera at each texel's centre, its
// alpha the object's mask widened by kHaloPx (`halo`): there the face shows the photo's own
// pixels about the object, so that from the photo's camera its edge is the photo's (not a
// blend with the fill behind it); from elsewhere, a thin halo.
// A face the photo's camera does not see (a box's back, its far side) takes the object's
// colour instead, with the same alpha: where the box stands beyond the object's outline,
// its faces are clear, so that from the photo's camera the model still gives the photo.
void textureFace(const cv::Mat& photo, const Measurement& m, const cv::Mat& halo, bool seen, StandingFace& face) {
  const auto& c = face.cornersM;
  const double widthM = glm::length(c[1] - c[0]), heightM = glm::length(c[3] - c[0]);
  const glm::dvec3 right = (c[1] - c[0]) / widthM, up = (c[3] - c[0]) / heightM;
  const double depth = glm::length(0.25 * (c[0] + c[1] + c[2] + c[3]) - m.pose.positionM);
  const double pxPerM = kTexelsPerPhotoPixel * m.camera.focalPx / std::max(depth, 1e-3);
  const double scale = std::min({1.0, kMaxTextureSide / (pxPerM * widthM), kMaxTextureSide / (pxPerM * heightM)});
  const int w = std::max(2, static_cast<int>(std::ceil(pxPerM * scale * widthM)));
  const int h = std::max(2, static_cast<int>(std::ceil(pxPerM * scale * heightM)));
  cv::Mat mapX(h, w, CV_32F), mapY(h, w, CV_32F);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      const glm::dvec3 p = c[3] + (col + 0.5) / w * widthM * right - (row + 0.5) / h * heightM * up;
      const glm::dvec3 q = metrology::projectToPixel(m.camera, m.pose, p);
      const glm::dvec2 px = metrology::distortPixel(m.camera, glm::dvec2(q));
      mapX.at<float>(row, col) = static_cast<float>(px.x);
      mapY.at<float>(row, col) = static_cast<float>(px.y);
    }
  }
  cv::Mat colour, alpha, rgba;
  if (seen) {
    cv::remap(photo, colour, mapX, mapY, cv::INTER_CUBIC, cv::BORDER_REPLICATE);
  } else {
    colour = cv::Mat(h, w, CV_8UC3, cv::Scalar(255.0 * face.colour.b, 255.0 * face.colour.g, 255.0 * face.colour.r));
  }
  face.photo = seen;
  cv::remap(halo, alpha, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::cvtColor(colour, rgba, cv::COLOR_BGR2RGBA);
  cv::mixChannels(std::vector<cv::Mat>{alpha}, std::vector<cv::Mat>{rgba}, {0, 3});
  // Texture coordinates to the photo's pinhole pixels: metric x = s W, y = (1 - t) H
  // from the top-left corner, as the surfaces' textures (corridor_model.cpp).
  const cv::Matx33d photoFromMetric = metrology::photoFromPlane(m.camera, m.pose, c[3], right, -up);
  const cv::Matx33d photoFromTexCoord = photoFromMetric * cv::Matx33d(widthM, 0, 0, 0, -heightM, heightM, 0, 0, 1);
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) {
      face.sourceFromTexCoord[col][row] = static_cast<float>(photoFromTexCoord(row, col) / photoFromTexCoord(2, 2));
    }
  }
  face.image.width = w;
  face.image.height = h;
  face.image.rgba.assign(rgba.data, rgba.data + rgba.total() * 4);
}

// Where the object's pixels show: its lowest one's foot point, or the error saying why
// the object does not stand on this corridor's floor.
struct Foot {
  glm::dvec2 px;
  glm::dvec3 m;
};

// The middle column of the mask's pixels in the band of rows [v0, v1) (a fiftieth of the
// object's height at its bottom or its top).
double middleColumn(const cv::Mat& mask, const cv::Rect& box, int v0, int v1) {
  double sumU = 0;
  int count = 0;
  for (int v = v0; v < v1; ++v) {
    for (int u = box.x; u < box.x + box.width; ++u) {
      if (mask.at<uint8_t>(v, u)) sumU += u, ++count;
    }
  }
  return sumU / std::max(1, count);
}

int bandRows(const cv::Rect& box) { return std::max(1, box.height / 50); }

// The outline's topmost and bottommost rows in the photo (its points' least and greatest v).
struct OutlineRows {
  double top = 1e300, bottom = -1e300;
};
OutlineRows outlineRows(const metrology::Cutout& cutout) {
  OutlineRows rows;
  for (const glm::dvec2& p : cutout.outlinePx) rows.top = std::min(rows.top, p.y), rows.bottom = std::max(rows.bottom, p.y);
  return rows;
}

// How far beyond the corridor's walls and far end a foot or a hanging place may fall (the
// corners' own rounding) before it is not this corridor's.
constexpr double kBeyondSlackM = 0.05;

// GrabCut can lose an object's lower part where it looks like what lies around it (a
// person's legs over a floor of their colours, TUNE seed 71: the mask stopped 54 px above
// the outline's bottom, 50 px above her feet, and she stood 10 m too far). Where the mask
// stops more than this above the outline's bottom (at least kLostFootPx), the outline,
// which a person draws down to where the object stands, places the foot instead.
constexpr double kLostFootShare = 0.2;  // of the outline's height
constexpr double kLostFootPx = 12;

Result<Foot> footOf(const Measurement& m, const metrology::Cutout& cutout, const cv::Mat& mask, const cv::Rect& box) {
  const std::string who = "cutout \"" + cutout.name + "\"";
  // The object's lowest row, at the middle of its pixels there (the bottom edge of that
  // row: where the object meets the floor).
  const int footRow = box.y + box.height - 1;
  glm::dvec2 footPx(middleColumn(mask, box, footRow - bandRows(box) + 1, footRow + 1), footRow + 0.5);
  const OutlineRows outline = outlineRows(cutout);
  if (outline.bottom - footPx.y > std::max(kLostFootPx, kLostFootShare * (outline.bottom - outline.top))) footPx.y = outline.bottom;
  const std::optional<glm::dvec3> foot = onPlane(m, footPx, glm::dvec3(0.0), glm::dvec3(0, 1, 0));
  const std::string where =
      "(" + std::to_string(std::lround(footPx.x)) + ", " + std::to_string(static_cast<int>(std::floor(footPx.y))) + ")";
  if (!foot || glm::length(*foot - m.pose.positionM) > 1e4) {
    return makeError(who + ": its lowest pixel " + where +
                     " is on or above the horizon: draw the outline down to where the object stands on the floor");
  }
  if (std::abs(foot->x) > 0.5 * m.size.widthM + kBeyondSlackM || foot->z < -m.size.lengthM - kBeyondSlackM) {
    return makeError(who + ": its lowest pixel found " + where + " meets the floor beyond the corridor's (at x " +
                     std::to_string(foot->x).substr(0, 5) + " m, z " + std::to_string(foot->z).substr(0, 6) +
                     " m): draw the outline down to where the object stands on this corridor's floor");
  }
  return Foot{footPx, *foot};
}

constexpr double kHangingSlackPx = 4;
constexpr double kHangingPlaceShare = 0.1;

// A hanging object's top: where the outline's top row (a person draws it up to where
// the object hangs; GrabCut may lose a thin rod), at the middle of the object's topmost
// pixels, meets the ceiling; or the error saying why it does not hang from this
// corridor's ceiling. `m` of the result is the point on the floor below it.
Result<Foot> hangingPointOf(const Measurement& m, const metrology::Cutout& cutout, const cv::Mat& mask, const cv::Rect& box) {
  const std::string who = "cutout \"" + cutout.name + "\"";
  const glm::dvec2 topPx(middleColumn(mask, box, box.y, box.y + bandRows(box)), std::max(outlineRows(cutout).top, -0.5));
  const std::optional<glm::dvec3> top = onPlane(m, topPx, glm::dvec3(0, m.size.heightM, 0), glm::dvec3(0, 1, 0));
  const std::string where = "(" + std::to_string(std::lround(topPx.x)) + ", " + std::to_string(std::lround(topPx.y)) + ")";
  if (!top || glm::length(*top - m.pose.positionM) > 1e4) {
    return makeError(who + ": its top " + where +
                     " is on or below the horizon: draw the outline up to where the object hangs from the ceiling");
  }
  if (std::abs(top->x) > 0.5 * m.size.widthM + kBeyondSlackM || top->z < -m.size.lengthM - kBeyondSlackM) {
    return makeError(who + ": its top " + where + " meets the ceiling beyond the corridor's (at x " +
                     std::to_string(top->x).substr(0, 5) + " m, z " + std::to_string(top->z).substr(0, 6) +
                     " m): draw the outline up to where the object hangs from this corridor's ceiling");
  }
  // Where the ceiling is seen nearly edge on (far down a low corridor), a few pixels of the
  // top row are metres along it: the place moved by kHangingSlackPx of the row (a person's
  // outline is that loose) over kHangingPlaceShare of its distance is not in the photo.
  const glm::dvec2 eyeXZ(m.pose.positionM.x, m.pose.positionM.z);
  const double distance = glm::length(glm::dvec2(top->x, top->z) - eyeXZ);
  const std::optional<glm::dvec3> lower =
      onPlane(m, topPx + glm::dvec2(0, kHangingSlackPx), glm::dvec3(0, m.size.heightM, 0), glm::dvec3(0, 1, 0));
  const double moved = lower ? glm::length(glm::dvec2(lower->x - top->x, lower->z - top->z)) : 1e300;
  if (moved > kHangingPlaceShare * distance) {
    char why[200];
    std::snprintf(why, sizeof why, ": where it hangs is not in the photo (%.0f px of its top move it %.1f m of %.1f m): "
                  "the ceiling is seen too nearly edge on there; leave it painted",
                  kHangingSlackPx, std::min(moved, 1e4), distance);
    return makeError(who + why);
  }
  return Foot{topPx, {top->x, 0.0, top->z}};
}

// A flat cut-out: the upright rectangle through the foot facing the photo's camera, as far
// as the object's pixels reach on it, from the floor up (hanging: from the ceiling down).
Result<StandingObject> standUpFlat(const Measurement& m, const std::string& who, const cv::Rect& box, const Foot& foot,
                                   bool hanging, StandingObject object) {
  const metrology::Dimensions& size = m.size;
  const glm::dvec3 eye = m.pose.positionM;
  object.footM = {std::clamp(foot.m.x, -0.5 * size.widthM, 0.5 * size.widthM), 0.0, std::max(foot.m.z, -size.lengthM)};
  // Facing the photo's camera, upright.
  glm::dvec3 toEye(eye.x - object.footM.x, 0.0, eye.z - object.footM.z);
  object.distanceM = glm::length(toEye);
  if (!(object.distanceM > 1e-3)) return makeError(who + ": it stands where the photo's camera stands");
  StandingFace& face = object.faces.emplace_back();
  face.normal = toEye / object.distanceM;
  const glm::dvec3 up(0, 1, 0);
  const glm::dvec3 right = glm::normalize(glm::cross(-face.normal, up));
  // The rectangle: as far as the object's pixels reach on the plane, from the floor up
  // (hanging: from the ceiling down).
  double s0 = 1e300, s1 = -1e300, top = 0, bottom = size.heightM;
  for (const glm::dvec2 corner : {glm::dvec2(box.x - 0.5, box.y - 0.5), glm::dvec2(box.x + box.width - 0.5, box.y - 0.5),
                                  glm::dvec2(box.x - 0.5, box.y + box.height - 0.5),
                                  glm::dvec2(box.x + box.width - 0.5, box.y + box.height - 0.5)}) {
    const std::optional<glm::dvec3> p = onPlane(m, corner, object.footM, face.normal);
    if (!p) return makeError(who + ": the photo's camera sees it edge on");
    const double s = glm::dot(*p - object.footM, right);
    s0 = std::min(s0, s), s1 = std::max(s1, s), top = std::max(top, p->y), bottom = std::min(bottom, p->y);
  }
  const double base = hanging ? std::max(0.0, bottom) : 0.0;
  object.widthM = s1 - s0;
  object.heightM = hanging ? size.heightM - base : top;
  if (!(object.widthM > 1e-3 && object.heightM > 1e-3)) {
    return makeError(who + (hanging ? ": it has no height below the ceiling" : ": it has no height above the floor"));
  }
  const glm::dvec3 lift(0, base, 0);
  const glm::dvec3 bottomLeft = object.footM + s0 * right + lift, bottomRight = object.footM + s1 * right + lift;
  face.cornersM = {bottomLeft, bottomRight, bottomRight + object.heightM * up, bottomLeft + object.heightM * up};
  // A rectangle reaching through a side wall would be hidden there by the wall (filled
  // behind it): it is brought nearer along the photo's rays, scaled about the eye, until
  // it stands inside the walls. From the photo's camera nothing changes; it stands a
  // little nearer and its foot a little above the floor (a foot found too far: TUNE and
  // held-out scenes where GrabCut lost an object's base).
  double fit = 1.0;
  for (const glm::dvec3& c : face.cornersM) {
    const double wall = c.x > 0 ? 0.5 * size.widthM : -0.5 * size.widthM;
    if (std::abs(c.x) > std::abs(wall) && std::abs(c.x - eye.x) > 1e-9) fit = std::min(fit, (wall - eye.x) / (c.x - eye.x));
  }
  if (fit < 1.0 && fit > 0.0) {
    for (glm::dvec3& c : face.cornersM) c = eye + fit * (c - eye);
    object.footM = eye + fit * (object.footM - eye);
    object.widthM *= fit;
    object.heightM *= fit;
    object.distanceM = glm::length(glm::dvec3(eye.x - object.footM.x, 0.0, eye.z - object.footM.z));
  }
  return object;
}

// A box on the floor, sides along the corridor's axes: x across [x0, x1], z along
// [z0, z1] (z1 the nearer the photo's camera), from the floor to `h`.
struct BoxM {
  double x0 = 0, x1 = 0, z0 = 0, z1 = 0, h = 0;
};

std::array<glm::dvec3, 8> boxCorners(const BoxM& b) {
  std::array<glm::dvec3, 8> c;
  for (int i = 0; i < 8; ++i) c[i] = {i & 1 ? b.x1 : b.x0, i & 2 ? b.h : 0.0, i & 4 ? b.z1 : b.z0};
  return c;
}

// The convex hull, in photo pixels, of model-frame points as the photo's camera sees
// them; empty where one of them is behind the camera.
std::vector<cv::Point2f> hullInPhoto(const Measurement& m, const std::vector<glm::dvec3>& points) {
  std::vector<cv::Point2f> pts;
  for (const glm::dvec3& c : points) {
    const glm::dvec3 q = metrology::projectToPixel(m.camera, m.pose, c);
    if (!(q.z > 1e-3)) return {};
    const glm::dvec2 px = metrology::distortPixel(m.camera, glm::dvec2(q));
    pts.emplace_back(static_cast<float>(px.x), static_cast<float>(px.y));
  }
  std::vector<cv::Point2f> hull;
  cv::convexHull(pts, hull);
  return hull;
}

// A convex polygon filled into `mask` (255), its corners at sixteenth-pixel precision.
void fillHull(cv::Mat& mask, const std::vector<cv::Point2f>& hull) {
  if (hull.size() < 3) return;
  std::vector<cv::Point> poly;
  for (const cv::Point2f& p : hull) poly.emplace_back(cvRound(p.x * 16), cvRound(p.y * 16));
  cv::fillConvexPoly(mask, poly, cv::Scalar(255), cv::LINE_8, 4);
}

// How a box's outline in the photo covers the object's mask, on a region of the photo
// shrunk to about kFitPixels (the box's outline is the convex hull of its corners).
class BoxSilhouette {
 public:
  static constexpr double kFitPixels = 40000;
  BoxSilhouette(const Measurement& m, const cv::Mat& mask, const cv::Rect& box) : m_(m) {
    const int margin = std::max(box.width, box.height) / 4 + 2;
    roi_ = (box + cv::Size(2 * margin, 2 * margin) - cv::Point(margin, margin)) & cv::Rect(0, 0, mask.cols, mask.rows);
    scale_ = std::min(1.0, std::sqrt(kFitPixels / static_cast<double>(roi_.area())));
    cv::resize(mask(roi_), mask_, cv::Size(), scale_, scale_, cv::INTER_AREA);
    mask_ = mask_ >= 128;
    maskCount_ = cv::countNonZero(mask_);
  }
  // The share of the mask the box covers and of the box the mask fills; nullopt where a
  // corner is behind the camera.
  std::optional<std::pair<double, double>> cover(const BoxM& b) const {
    const std::array<glm::dvec3, 8> corners = boxCorners(b);
    std::vector<cv::Point2f> hull = hullInPhoto(m_, {corners.begin(), corners.end()});
    if (hull.empty()) return std::nullopt;
    // (Half a shrunk pixel right and down of where a resize puts the photo pixel's centre,
    // (x + 0.5) s - 0.5: put there, the held-out figures moved both ways, width 5.7% ->
    // 4.7%, depth 13.9% -> 8.2%, TUNE's width 59 -> 57 within 10%, and the synthetic
    // test's far cabinet 0.458 -> 0.493 m wide for 0.45; left as measured.)
    for (cv::Point2f& p : hull) {
      p = {static_cast<float>((p.x + 0.5 - roi_.x) * scale_), static_cast<float>((p.y + 0.5 - roi_.y) * scale_)};
    }
    cv::Mat drawn = cv::Mat::zeros(mask_.size(), CV_8U);
    fillHull(drawn, hull);
    const int both = cv::countNonZero(drawn & mask_);
    const double area = std::abs(cv::contourArea(hull)) + 1.0;
    return std::pair{both / std::max(1.0, static_cast<double>(maskCount_)), std::min(1.0, both / area)};
  }
  double score(const BoxM& b) const {
    const auto c = cover(b);
    return c ? c->first * c->second : -1.0;  // both: a box neither too small nor too large
  }

 private:
  const Measurement& m_;
  cv::Rect roi_;
  double scale_ = 1;
  cv::Mat mask_;
  int maskCount_ = 0;
};

// A box: its footprint from where the mask's lowest pixels in each column meet the floor
// (the front edge at one depth, the side the camera sees at one x, meeting at the
// nearest), then every side moved to where the box's outline in the photo best covers
// the mask (coordinate descent, halving steps).
Result<StandingObject> standUpBox(const Measurement& m, const std::string& who, const cv::Mat& mask, const cv::Rect& box,
                                  StandingObject object) {
  const glm::dvec3 eye = m.pose.positionM;
  const double halfWidth = 0.5 * m.size.widthM;
  struct Ground {
    int u;
    glm::dvec3 p;
  };
  std::vector<Ground> ground;
  for (int u = box.x; u < box.x + box.width; ++u) {
    for (int v = box.y + box.height - 1; v >= box.y; --v) {
      if (!mask.at<uint8_t>(v, u)) continue;
      const auto p = onPlane(m, {u, v + 0.5}, glm::dvec3(0.0), glm::dvec3(0, 1, 0));
      if (p && glm::length(*p - eye) < 1e4) ground.push_back({u, *p});
      break;
    }
  }
  if (ground.size() < 3) return makeError(who + ": too few of its pixels meet the floor to stand it up as a box");
  // The nearest ground point is the footprint's corner nearest the camera.
  const auto percentile = [](std::vector<double> v, double q) {  // 0.5: the median
    const auto at = v.begin() + static_cast<std::ptrdiff_t>(std::lround(q * (v.size() - 1)));
    std::nth_element(v.begin(), at, v.end());
    return *at;
  };
  const auto nearest = std::max_element(ground.begin(), ground.end(), [](const Ground& a, const Ground& b) { return a.p.z < b.p.z; });
  const glm::dvec3 corner = nearest->p;
  // The camera sees the box's side facing it: the right side of a box left of the camera,
  // and it shows right of the corner in the photo (towards the vanishing point).
  const bool leftOfEye = corner.x < eye.x;
  std::vector<double> frontZ, sideX, frontX, sideZ;
  for (const Ground& g : ground) {
    const bool front = leftOfEye ? g.u <= nearest->u : g.u >= nearest->u;
    if (front) frontZ.push_back(g.p.z), frontX.push_back(g.p.x);
    else sideX.push_back(g.p.x), sideZ.push_back(g.p.z);
  }
  // Where to start: the footprint the ground points give, and boxes of a few sizes from
  // the nearest corner (a ground point on the far side may be the top of the box or a
  // shadow GrabCut kept); the best after the descent is taken.
  const auto fromCorner = [&](double width, double depth) {
    BoxM x;
    x.z1 = corner.z, x.z0 = corner.z - depth;
    x.x0 = leftOfEye ? corner.x - width : corner.x;
    x.x1 = leftOfEye ? corner.x : corner.x + width;
    return x;
  };
  std::vector<BoxM> starts;
  {
    BoxM x;
    x.z1 = percentile(frontZ, 0.5);
    const double farX = leftOfEye ? percentile(frontX, 0.1) : percentile(frontX, 0.9);
    const double sideAt = sideX.size() >= 3 ? percentile(sideX, 0.5) : corner.x;
    x.x0 = leftOfEye ? farX : sideAt;
    x.x1 = leftOfEye ? sideAt : farX;
    x.z0 = sideZ.size() >= 3 ? percentile(sideZ, 0.1) : x.z1 - kDefaultDepthM;
    starts.push_back(x);
  }
  for (double width : {0.3, 0.6, 1.0})
    for (double depth : {0.3, 0.6, 1.2, 2.0}) starts.push_back(fromCorner(width, depth));
  const auto keepInside = [&](BoxM& x) {
    constexpr double kLeastM = 0.05;
    x.x0 = std::clamp(x.x0, -halfWidth, halfWidth - kLeastM);
    x.x1 = std::clamp(x.x1, x.x0 + kLeastM, halfWidth);
    x.z0 = std::clamp(x.z0, x.z1 - kMaxDepthM, x.z1);
    x.z0 = std::max(x.z0, -m.size.lengthM);
    x.z1 = std::clamp(x.z1, x.z0 + kLeastM, std::max(x.z0 + kLeastM, eye.z - 0.2));
    x.h = std::clamp(x.h, kLeastM, m.size.heightM);
  };
  const BoxSilhouette silhouette(m, mask, box);
  // Each start's height first (its footprint fixes the rest roughly), then every side
  // together.
  const auto descend = [&](BoxM b, double& best) {
    keepInside(b);
    best = -1;
    for (double h = 0.05; h <= m.size.heightM; h += 0.05) {
      BoxM t = b;
      t.h = h;
      const double s = silhouette.score(t);
      if (s > best) best = s, b.h = h;
    }
    const double size = std::max({b.x1 - b.x0, b.z1 - b.z0, b.h});
    for (double step = 0.1 * size; step > 0.002; step *= 0.5) {
      for (bool moved = true; moved;) {
        moved = false;
        for (double BoxM::*side : {&BoxM::x0, &BoxM::x1, &BoxM::z0, &BoxM::z1, &BoxM::h}) {
          for (double sign : {-1.0, 1.0}) {
            BoxM t = b;
            t.*side += sign * step;
            keepInside(t);
            const double s = silhouette.score(t);
            if (s > best + 1e-9) best = s, b = t, moved = true;
          }
        }
      }
    }
    return b;
  };
  BoxM b;
  double best = -1;
  for (const BoxM& start : starts) {
    double score = -1;
    const BoxM fitted = descend(start, score);
    if (score > best) best = score, b = fitted;
  }
  if (!(best > 0)) return makeError(who + ": no box on the floor covers it (is it on the floor?)");
  // How well the photo sees its depth: the far end of the side it shows moves this many
  // pixels per metre; the mask's edge is good to about kOutlinePx. A side seen so nearly
  // edge on that this gives more than half the depth found says nothing of it, and the
  // box takes a cabinet's depth instead (the far end away from the camera).
  const auto pixelOf = [&](glm::dvec3 p) {
    return metrology::distortPixel(m.camera, glm::dvec2(metrology::projectToPixel(m.camera, m.pose, p)));
  };
  // (Taken at the far end found and at a cabinet's depth, the larger: a far end run off
  // towards the vanishing point moves few pixels per metre wherever it stops.)
  const double seenX = b.x0 <= eye.x && eye.x <= b.x1 ? 0.5 * (b.x0 + b.x1) : leftOfEye ? b.x1 : b.x0;
  object.depthSigmaM = 0;
  for (const double z : {b.z0, b.z1 - kDefaultDepthM}) {
    const glm::dvec3 end(seenX, 0.5 * b.h, z);
    const double pxPerM = glm::length(pixelOf(end) - pixelOf(end - glm::dvec3(0, 0, 0.01))) / 0.01;
    object.depthSigmaM = std::max(object.depthSigmaM, kOutlinePx / std::max(pxPerM, 1e-9));
  }
  if (object.depthSigmaM > 0.5 * (b.z1 - b.z0)) {
    object.depthSeen = false;
    b.z0 = std::max(b.z1 - kDefaultDepthM, -m.size.lengthM);
  }
  object.widthM = b.x1 - b.x0, object.depthM = b.z1 - b.z0, object.heightM = b.h;
  object.footM = {0.5 * (b.x0 + b.x1), 0.0, 0.5 * (b.z0 + b.z1)};
  object.distanceM = glm::length(glm::dvec3(eye.x - object.footM.x, 0.0, eye.z - object.footM.z));
  // Five faces, each as seen from outside: bottom-left, bottom-right, top-right, top-left.
  const std::array<glm::dvec3, 8> c = boxCorners(b);  // index: x1 ? 1 : 0, top ? 2 : 0, near ? 4 : 0
  const struct {
    std::array<int, 4> corners;
    glm::dvec3 normal;
  } sides[] = {
      {{4, 5, 7, 6}, {0, 0, 1}},   // front (nearest the photo's camera's end)
      {{1, 0, 2, 3}, {0, 0, -1}},  // back
      {{0, 4, 6, 2}, {-1, 0, 0}},  // left
      {{5, 1, 3, 7}, {1, 0, 0}},   // right
      {{6, 7, 3, 2}, {0, 1, 0}},   // top (bottom-left is the front's top-left)
  };
  for (const auto& side : sides) {
    StandingFace& face = object.faces.emplace_back();
    for (int k = 0; k < 4; ++k) face.cornersM[k] = c[side.corners[k]];
    face.normal = side.normal;
  }
  return object;
}

Result<StandingObject> standUp(const cv::Mat& photo, const Measurement& m, const metrology::Cutout& cutout,
                               const cv::Mat& mask) {
  StandingObject object;
  object.name = cutout.name;
  object.shape = cutout.shape;
  object.maskPixels = cv::countNonZero(mask);
  const std::string who = "cutout \"" + cutout.name + "\"";
  // (The outline lies in the photo: an empty mask is GrabCut's pieces all specks and
  // lines, dropped. Stood up as they are they gave no novel view anything and cost the
  // photo's camera up to 0.5 dB, TUNE seeds 36 and 63's far lamps: they stay painted.)
  if (object.maskPixels == 0) {
    return makeError(who + ": GrabCut finds no piece of an object in it large enough to stand up (a small, far object "
                           "stays painted; outline it more tightly to try again)");
  }
  const cv::Rect box = cv::boundingRect(mask);
  const bool hanging = cutout.shape == metrology::CutoutShape::kHanging;
  const OutlineRows outline = outlineRows(cutout);
  if (hanging && (box.y <= 0 || outline.top <= 0)) {
    return makeError(who + ": it runs off the photo's top edge, so where it hangs from the ceiling is not in the photo "
                           "(remove the cutout, or outline only objects whose top shows)");
  }
  if (!hanging && (box.y + box.height >= photo.rows || outline.bottom >= photo.rows - 1)) {
    return makeError(who + ": it runs off the photo's bottom edge, so where it stands on the floor is not in the photo "
                           "(remove the cutout, or outline only objects whose foot shows)");
  }
  const Result<Foot> foot = hanging ? hangingPointOf(m, cutout, mask, box) : footOf(m, cutout, mask, box);
  if (!foot) return foot.error();
  // (A box's foot is checked too: its lowest pixel stands on this corridor's floor.)
  auto stood = cutout.shape == metrology::CutoutShape::kBox ? standUpBox(m, who, mask, box, std::move(object))
                                                             : standUpFlat(m, who, box, *foot, hanging, std::move(object));
  if (!stood) return stood;
  // The faces the photo's camera sees carry the photo; the others the object's colour;
  // all of them the object's outline as alpha.
  const cv::Scalar mean = cv::mean(photo, mask);
  const glm::vec3 colour(static_cast<float>(mean[2] / 255), static_cast<float>(mean[1] / 255), static_cast<float>(mean[0] / 255));
  cv::Mat halo;
  cv::dilate(mask, halo, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * kHaloPx + 1, 2 * kHaloPx + 1)));
  for (StandingFace& face : stood->faces) {
    face.colour = colour;
    const glm::dvec3 middle = 0.25 * (face.cornersM[0] + face.cornersM[1] + face.cornersM[2] + face.cornersM[3]);
    const bool seen = stood->shape != metrology::CutoutShape::kBox || glm::dot(m.pose.positionM - middle, face.normal) > 1e-6;
    textureFace(photo, m, halo, seen, face);
  }
  return stood;
}

}  // namespace

std::optional<glm::dvec3> onPlane(const Measurement& m, glm::dvec2 photoPx, glm::dvec3 origin, glm::dvec3 normal) {
  const std::optional<glm::dvec2> pinhole = metrology::undistortPixel(m.camera, photoPx);
  if (!pinhole) return std::nullopt;
  const glm::dvec3 ray = metrology::rayThroughPixel(m.camera, m.pose.worldFromCamera, *pinhole);
  const double along = glm::dot(ray, normal);
  if (std::abs(along) < 1e-9) return std::nullopt;
  const double t = glm::dot(origin - m.pose.positionM, normal) / along;
  if (!(t > 0)) return std::nullopt;
  return m.pose.positionM + t * ray;
}

namespace {

// The entry of `entries` (most recent last) that `matches`, made the most recent; else the
// one `make` returns, added last, the oldest dropped beyond `capacity`. `made` counts the
// entries made.
template <class Entry, class Matches, class Make>
Entry& mostRecent(std::vector<Entry>& entries, size_t capacity, const Matches& matches, const Make& make, int& made) {
  for (auto it = entries.begin(); it != entries.end(); ++it) {
    if (matches(*it)) {
      std::rotate(it, it + 1, entries.end());
      return entries.back();
    }
  }
  if (entries.size() >= capacity) entries.erase(entries.begin());
  entries.push_back(make());
  ++made;
  return entries.back();
}

}  // namespace

const CutOuts& CutOutCache::get(const cv::Mat& photo, const std::vector<std::vector<cv::Point>>& outlines,
                                const std::function<CutOuts()>& make) {
  const cv::Scalar sums = cv::sum(photo);
  const auto matches = [&](const Entry& e) {
    return e.data == photo.data && e.size == photo.size() && e.sums == sums && e.outlines == outlines;
  };
  return mostRecent(entries_, kEntries, matches, [&] { return Entry{photo.data, photo.size(), sums, outlines, make(), {}}; },
                    made_)
      .cut;
}

const cv::Mat& CutOutCache::behindStood(const std::vector<bool>& stood, const std::function<cv::Mat()>& fill) {
  using StoodFill = std::pair<std::vector<bool>, cv::Mat>;
  return mostRecent(entries_.back().stoodFills, kStoodFills, [&](const StoodFill& f) { return f.first == stood; },
                    [&] { return StoodFill{stood, fill()}; }, made_)
      .second;
}

Result<StoodUp> standUpObjects(const cv::Mat& photo, const Measurement& measurement,
                               const std::vector<metrology::Cutout>& cutouts, CutOutCache* cache, StandUpParts parts) {
  if (photo.empty() || photo.type() != CV_8UC3) return makeError("standing objects up needs an 8-bit colour photo");
  const cv::Rect frame(0, 0, photo.cols, photo.rows);
  std::vector<std::vector<cv::Point>> outlines;
  for (const metrology::Cutout& cutout : cutouts) {
    std::vector<cv::Point>& outline = outlines.emplace_back();
    for (const glm::dvec2& p : cutout.outlinePx) {
      if (!(std::isfinite(p.x) && std::isfinite(p.y))) return makeError("cutout \"" + cutout.name + "\": an outline point is not a number");
      outline.emplace_back(static_cast<int>(std::lround(std::clamp(p.x, -1.0, photo.cols + 0.0))),
                           static_cast<int>(std::lround(std::clamp(p.y, -1.0, photo.rows + 0.0))));
    }
    if (outline.size() < 3 || (cv::boundingRect(outline) & frame).area() == 0) {
      return makeError("cutout \"" + cutout.name + "\": its outline is not inside the " + std::to_string(photo.cols) + "x" +
                       std::to_string(photo.rows) + " photo");
    }
  }
  // The photo with `masks`' pixels (and a margin about them) filled from their surroundings.
  const auto fillBehind = [&](const std::vector<cv::Mat>& masks) {
    if (masks.empty()) return photo;
    cv::Mat objects = cv::Mat::zeros(photo.size(), CV_8U), fill, behind;
    for (const cv::Mat& mask : masks) objects |= mask;
    cv::dilate(objects, fill, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * kFillMarginPx + 1, 2 * kFillMarginPx + 1)));
    cv::inpaint(photo, fill, behind, kFillRadiusPx, cv::INPAINT_TELEA);
    return behind;
  };
  const auto make = [&] {
    CutOuts cut;
    for (const std::vector<cv::Point>& outline : outlines) cut.masks.push_back(objectMask(photo, outline));
    if (outlines.empty() || parts == StandUpParts::kObjectsAndFill) cut.behind = fillBehind(cut.masks);
    return cut;
  };
  CutOuts made;
  const bool cached = cache && parts == StandUpParts::kObjectsAndFill;
  const CutOuts& cut = cached ? cache->get(photo, outlines, make) : (made = make());
  StoodUp out;
  std::vector<cv::Mat> masks;  // the stood objects', in out.objects' order
  std::vector<bool> stood(cutouts.size(), false);
  for (size_t i = 0; i < cutouts.size(); ++i) {
    auto object = standUp(photo, measurement, cutouts[i], cut.masks[i]);
    if (!object) {
      out.leftPainted.push_back(object.message());
      continue;
    }
    out.objects.push_back(std::move(*object));
    masks.push_back(cut.masks[i]);
    stood[i] = true;
  }
  // Those left painted keep the photo's pixels: filled only about the others.
  if (out.leftPainted.empty() || cut.behind.empty()) {
    out.behind = cut.behind;
  } else {
    const auto fill = [&] { return fillBehind(masks); };
    out.behind = cached ? cache->behindStood(stood, fill) : fill();
  }
  // A box's outline need not hold every pixel of its object (a box is not the object's
  // exact shape): those it leaves out, and those along its edge, stay painted where the
  // photo shows them, not filled, so that from the photo's camera the model still gives
  // the photo.
  if (!cut.behind.empty()) {
    cv::Mat outside;
    for (size_t i = 0; i < out.objects.size(); ++i) {
      if (out.objects[i].shape != metrology::CutoutShape::kBox) continue;
      std::vector<glm::dvec3> corners;
      for (const StandingFace& face : out.objects[i].faces) corners.insert(corners.end(), face.cornersM.begin(), face.cornersM.end());
      cv::Mat inside = cv::Mat::zeros(photo.size(), CV_8U);
      fillHull(inside, hullInPhoto(measurement, corners));
      // Along the outline's edge the box covers a pixel only in part (the renderer blends
      // it with what lies behind): those keep the photo's pixel behind too.
      cv::erode(inside, inside, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * kSeamPx + 1, 2 * kSeamPx + 1)));
      cv::Mat left = masks[i] & ~inside;
      outside = outside.empty() ? left : (outside | left);
    }
    if (!outside.empty() && cv::countNonZero(outside) > 0) {
      out.behind = out.behind.clone();
      photo.copyTo(out.behind, outside);
    }
  }
  return out;
}

}  // namespace pw::modeling
