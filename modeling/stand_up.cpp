#include "modeling/stand_up.h"

#include <algorithm>
#include <cmath>
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
// Cut-out texels per photo pixel at the object's distance (a second sampling blurs less).
constexpr double kTexelsPerPhotoPixel = 2.0;
constexpr int kMaxTextureSide = 4096;

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

// The model-frame point where the photo pixel's ray meets the plane through `origin`
// with normal `normal`; nullopt behind the camera or along the plane.
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

Result<StandingObject> standUp(const cv::Mat& photo, const Measurement& m, const metrology::Cutout& cutout,
                               const cv::Mat& mask) {
  StandingObject object;
  object.name = cutout.name;
  object.maskPixels = cv::countNonZero(mask);
  const std::string who = "cutout \"" + cutout.name + "\"";
  if (object.maskPixels == 0) return makeError(who + ": its outline holds no pixel of the photo");
  const cv::Rect box = cv::boundingRect(mask);
  double outlineBottom = -1;
  for (const glm::dvec2& p : cutout.outlinePx) outlineBottom = std::max(outlineBottom, p.y);
  if (box.y + box.height >= photo.rows || outlineBottom >= photo.rows - 1) {
    return makeError(who + ": it runs off the photo's bottom edge, so where it stands on the floor is not in the photo "
                           "(remove the cutout, or outline only objects whose foot shows)");
  }
  // The foot: the object's lowest row, at the middle of its pixels there (the bottom
  // edge of that row: where the object meets the floor).
  const int footRow = box.y + box.height - 1;
  const int band = std::max(1, box.height / 50);
  double sumU = 0;
  int count = 0;
  for (int v = footRow - band + 1; v <= footRow; ++v) {
    for (int u = box.x; u < box.x + box.width; ++u) {
      if (mask.at<uint8_t>(v, u)) sumU += u, ++count;
    }
  }
  const glm::dvec2 footPx(sumU / std::max(1, count), footRow + 0.5);
  const std::optional<glm::dvec3> foot = onPlane(m, footPx, glm::dvec3(0.0), glm::dvec3(0, 1, 0));
  const glm::dvec3 eye = m.pose.positionM;
  if (!foot || glm::length(*foot - eye) > 1e4) {
    return makeError(who + ": its lowest pixel (" + std::to_string(std::lround(footPx.x)) + ", " +
                     std::to_string(footRow) +
                     ") is on or above the horizon: draw the outline down to where the object stands on the floor");
  }
  const metrology::Dimensions& size = m.size;
  constexpr double kSlackM = 0.05;
  if (std::abs(foot->x) > 0.5 * size.widthM + kSlackM || foot->z < -size.lengthM - kSlackM) {
    return makeError(who + ": its lowest pixel found (" + std::to_string(std::lround(footPx.x)) + ", " +
                     std::to_string(footRow) + ") meets the floor beyond the corridor's (at x " +
                     std::to_string(foot->x).substr(0, 5) + " m, z " + std::to_string(foot->z).substr(0, 6) +
                     " m): draw the outline down to where the object stands on this corridor's floor");
  }
  object.footM = {std::clamp(foot->x, -0.5 * size.widthM, 0.5 * size.widthM), 0.0, std::max(foot->z, -size.lengthM)};
  // Facing the photo's camera, upright.
  glm::dvec3 toEye(eye.x - object.footM.x, 0.0, eye.z - object.footM.z);
  object.distanceM = glm::length(toEye);
  if (!(object.distanceM > 1e-3)) return makeError(who + ": it stands where the photo's camera stands");
  object.normal = toEye / object.distanceM;
  const glm::dvec3 up(0, 1, 0);
  const glm::dvec3 right = glm::normalize(glm::cross(-object.normal, up));
  // The rectangle: as far as the object's pixels reach on the plane, from the floor up.
  double s0 = 1e300, s1 = -1e300, top = 0;
  for (const glm::dvec2 corner : {glm::dvec2(box.x - 0.5, box.y - 0.5), glm::dvec2(box.x + box.width - 0.5, box.y - 0.5),
                                  glm::dvec2(box.x - 0.5, box.y + box.height - 0.5),
                                  glm::dvec2(box.x + box.width - 0.5, box.y + box.height - 0.5)}) {
    const std::optional<glm::dvec3> p = onPlane(m, corner, object.footM, object.normal);
    if (!p) return makeError(who + ": the photo's camera sees it edge on");
    const double s = glm::dot(*p - object.footM, right);
    s0 = std::min(s0, s), s1 = std::max(s1, s), top = std::max(top, p->y);
  }
  object.widthM = s1 - s0;
  object.heightM = top;
  if (!(object.widthM > 1e-3 && object.heightM > 1e-3)) return makeError(who + ": it has no height above the floor");
  const glm::dvec3 bottomLeft = object.footM + s0 * right, bottomRight = object.footM + s1 * right;
  object.cornersM = {bottomLeft, bottomRight, bottomRight + object.heightM * up, bottomLeft + object.heightM * up};
  // A rectangle reaching through a side wall would be hidden there by the wall (filled
  // behind it): it is brought nearer along the photo's rays, scaled about the eye, until
  // it stands inside the walls. From the photo's camera nothing changes; it stands a
  // little nearer and its foot a little above the floor (a foot found too far: TUNE and
  // held-out scenes where GrabCut lost an object's base).
  double fit = 1.0;
  for (const glm::dvec3& c : object.cornersM) {
    const double wall = c.x > 0 ? 0.5 * size.widthM : -0.5 * size.widthM;
    if (std::abs(c.x) > std::abs(wall) && std::abs(c.x - eye.x) > 1e-9) fit = std::min(fit, (wall - eye.x) / (c.x - eye.x));
  }
  if (fit < 1.0 && fit > 0.0) {
    for (glm::dvec3& c : object.cornersM) c = eye + fit * (c - eye);
    object.footM = eye + fit * (object.footM - eye);
    object.widthM *= fit;
    object.heightM *= fit;
    object.distanceM = glm::length(glm::dvec3(eye.x - object.footM.x, 0.0, eye.z - object.footM.z));
  }

  // The texture: the photo and the mask read through the camera at each texel's centre.
  const double depth = glm::length(object.footM - eye);
  const double pxPerM = kTexelsPerPhotoPixel * m.camera.focalPx / std::max(depth, 1e-3);
  const double scale = std::min({1.0, kMaxTextureSide / (pxPerM * object.widthM), kMaxTextureSide / (pxPerM * object.heightM)});
  const int w = std::max(2, static_cast<int>(std::ceil(pxPerM * scale * object.widthM)));
  const int h = std::max(2, static_cast<int>(std::ceil(pxPerM * scale * object.heightM)));
  cv::Mat mapX(h, w, CV_32F), mapY(h, w, CV_32F);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      const glm::dvec3 p = object.cornersM[3] + (col + 0.5) / w * object.widthM * right - (row + 0.5) / h * object.heightM * up;
      const glm::dvec3 q = metrology::projectToPixel(m.camera, m.pose, p);
      const glm::dvec2 px = metrology::distortPixel(m.camera, glm::dvec2(q));
      mapX.at<float>(row, col) = static_cast<float>(px.x);
      mapY.at<float>(row, col) = static_cast<float>(px.y);
    }
  }
  // The alpha reaches kHaloPx beyond the mask: there the cut-out shows the photo's own
  // pixels about the object, so that from the photo's camera its edge is the photo's
  // (not a blend with the fill behind it); from elsewhere, a thin halo.
  cv::Mat colour, alpha, rgba, halo;
  cv::dilate(mask, halo, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * kHaloPx + 1, 2 * kHaloPx + 1)));
  cv::remap(photo, colour, mapX, mapY, cv::INTER_CUBIC, cv::BORDER_REPLICATE);
  cv::remap(halo, alpha, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::cvtColor(colour, rgba, cv::COLOR_BGR2RGBA);
  cv::mixChannels(std::vector<cv::Mat>{alpha}, std::vector<cv::Mat>{rgba}, {0, 3});
  // Texture coordinates to the photo's pinhole pixels: metric x = s W, y = (1 - t) H
  // from the top-left corner, as the surfaces' textures (corridor_model.cpp).
  const cv::Matx33d photoFromMetric = metrology::photoFromPlane(m.camera, m.pose, object.cornersM[3], right, -up);
  const cv::Matx33d photoFromTexCoord =
      photoFromMetric * cv::Matx33d(object.widthM, 0, 0, 0, -object.heightM, object.heightM, 0, 0, 1);
  for (int c = 0; c < 3; ++c) {
    for (int row = 0; row < 3; ++row) {
      object.sourceFromTexCoord[c][row] = static_cast<float>(photoFromTexCoord(row, c) / photoFromTexCoord(2, 2));
    }
  }
  object.image.width = w;
  object.image.height = h;
  object.image.rgba.assign(rgba.data, rgba.data + rgba.total() * 4);
  return object;
}

}  // namespace

const CutOuts& CutOutCache::get(const cv::Mat& photo, const std::vector<std::vector<cv::Point>>& outlines,
                                const std::function<CutOuts()>& make) {
  const cv::Scalar sums = cv::sum(photo);
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    if (it->data == photo.data && it->size == photo.size() && it->sums == sums && it->outlines == outlines) {
      std::rotate(it, it + 1, entries_.end());  // the most recent last
      return entries_.back().cut;
    }
  }
  if (entries_.size() >= kEntries) entries_.erase(entries_.begin());
  entries_.push_back({photo.data, photo.size(), sums, outlines, make()});
  ++made_;
  return entries_.back().cut;
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
  const auto make = [&] {
    CutOuts cut;
    cv::Mat objects = cv::Mat::zeros(photo.size(), CV_8U);
    for (const std::vector<cv::Point>& outline : outlines) {
      cut.masks.push_back(objectMask(photo, outline));
      objects |= cut.masks.back();
    }
    if (outlines.empty()) {
      cut.behind = photo;
    } else if (parts == StandUpParts::kObjectsAndFill) {
      cv::Mat fill;
      cv::dilate(objects, fill, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * kFillMarginPx + 1, 2 * kFillMarginPx + 1)));
      cv::inpaint(photo, fill, cut.behind, kFillRadiusPx, cv::INPAINT_TELEA);
    }
    return cut;
  };
  CutOuts made;
  const bool cached = cache && parts == StandUpParts::kObjectsAndFill;
  const CutOuts& cut = cached ? cache->get(photo, outlines, make) : (made = make());
  StoodUp out;
  for (size_t i = 0; i < cutouts.size(); ++i) {
    auto object = standUp(photo, measurement, cutouts[i], cut.masks[i]);
    if (!object) return object.error();
    out.objects.push_back(std::move(*object));
  }
  out.behind = cut.behind;
  return out;
}

}  // namespace pw::modeling
