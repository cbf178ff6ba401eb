#include "metrology/sheet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "metrology/seed_method.h"

namespace pw::metrology {

namespace {

// BGR colours, chosen to stay apart on grey walls and wooden floors.
const cv::Scalar kWidthColour(80, 200, 255);    // amber
const cv::Scalar kHeightColour(120, 255, 120);  // green
const cv::Scalar kLengthColour(255, 170, 80);   // blue
const cv::Scalar kRecedingColour(0, 230, 255);  // yellow
const cv::Scalar kHorizonColour(255, 255, 0);   // cyan
const cv::Scalar kOutlineColour(235, 235, 235);
const cv::Scalar kFitColour(60, 60, 255);       // red
const cv::Scalar kInk(255, 255, 255);
const cv::Scalar kShadow(20, 20, 20);
const cv::Scalar kGroundLineColour(255, 80, 255);  // magenta

constexpr int kShift = 4;  // sub-pixel drawing: coordinates in 1/16 px
cv::Point fixed(const glm::dvec2& p) {
  return cv::Point(static_cast<int>(std::lround(p.x * (1 << kShift))), static_cast<int>(std::lround(p.y * (1 << kShift))));
}

struct Style {
  double fontScale = 0.6;
  int thickness = 1;
  int lineWidth = 2;
  double radius = 6;
};

void line(cv::Mat& canvas, const glm::dvec2& a, const glm::dvec2& b, const cv::Scalar& colour, int width) {
  cv::line(canvas, fixed(a), fixed(b), colour, width, cv::LINE_AA, kShift);
}

void dashedLine(cv::Mat& canvas, const glm::dvec2& a, const glm::dvec2& b, const cv::Scalar& colour, int width,
                double dashPx) {
  const double length = glm::length(b - a);
  if (!(length > 0)) return;
  const glm::dvec2 d = (b - a) / length;
  for (double t = 0; t < length; t += 2 * dashPx) line(canvas, a + d * t, a + d * std::min(length, t + dashPx), colour, width);
}

// Text with a dark outline, so that it reads on light and dark ground alike; moved
// inside the canvas where it would stick out.
void outlinedText(cv::Mat& canvas, const std::string& text, cv::Point origin, const Style& s, const cv::Scalar& colour) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, s.fontScale, s.thickness + 3, &baseline);
  origin.x = std::clamp(origin.x, 2, std::max(2, canvas.cols - size.width - 2));
  origin.y = std::clamp(origin.y, size.height + 2, std::max(size.height + 2, canvas.rows - baseline - 2));
  cv::putText(canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, s.fontScale, kShadow, s.thickness + 3, cv::LINE_AA);
  cv::putText(canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, s.fontScale, colour, s.thickness, cv::LINE_AA);
}

// A label on a dark box, centred at `centre` and turned to `angleDeg` (screen angle,
// v down), composited with antialiasing.
void rotatedLabel(cv::Mat& canvas, const std::string& text, const glm::dvec2& centre, double angleDeg, const Style& s,
                  const cv::Scalar& colour) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, s.fontScale, s.thickness, &baseline);
  const int pad = std::max(3, size.height / 3);
  const cv::Size patch(size.width + 2 * pad, size.height + baseline + 2 * pad);
  cv::Mat box(patch, CV_8U, cv::Scalar(255)), ink(patch, CV_8U, cv::Scalar(0));
  cv::putText(ink, text, cv::Point(pad, pad + size.height), cv::FONT_HERSHEY_SIMPLEX, s.fontScale, cv::Scalar(255),
              s.thickness, cv::LINE_AA);
  // Rotation about the patch centre, then into the canvas region around `centre`.
  const double radius = 0.5 * std::hypot(patch.width, patch.height) + 2;
  const cv::Rect region(static_cast<int>(std::floor(centre.x - radius)), static_cast<int>(std::floor(centre.y - radius)),
                        static_cast<int>(2 * radius) + 2, static_cast<int>(2 * radius) + 2);
  const cv::Rect clipped = region & cv::Rect(0, 0, canvas.cols, canvas.rows);
  if (clipped.empty()) return;
  cv::Mat m = cv::getRotationMatrix2D(cv::Point2f(0.5f * patch.width, 0.5f * patch.height), -angleDeg, 1.0);
  m.at<double>(0, 2) += centre.x - 0.5 * patch.width - clipped.x;
  m.at<double>(1, 2) += centre.y - 0.5 * patch.height - clipped.y;
  cv::Mat boxMask, inkMask;
  cv::warpAffine(box, boxMask, m, clipped.size(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::warpAffine(ink, inkMask, m, clipped.size(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::Mat roi = canvas(clipped);
  for (int y = 0; y < roi.rows; ++y) {
    cv::Vec3b* px = roi.ptr<cv::Vec3b>(y);
    const uchar* b = boxMask.ptr<uchar>(y);
    const uchar* t = inkMask.ptr<uchar>(y);
    for (int x = 0; x < roi.cols; ++x) {
      for (int c = 0; c < 3; ++c) {
        double v = px[x][c];
        v = v * (1.0 - 0.7 * b[x] / 255.0) + 15.0 * 0.7 * b[x] / 255.0;  // darken under the box
        v = v * (1.0 - t[x] / 255.0) + colour[c] * t[x] / 255.0;
        px[x][c] = cv::saturate_cast<uchar>(v);
      }
    }
  }
}

// Writes `text` along the edge a-b, on the side away from `awayFrom`.
void edgeLabel(cv::Mat& canvas, const std::string& text, const glm::dvec2& a, const glm::dvec2& b,
               const glm::dvec2& awayFrom, const Style& s, const cv::Scalar& colour) {
  glm::dvec2 d = b - a;
  const double length = glm::length(d);
  if (!(length > 1)) return;
  d /= length;
  if (d.x < -1e-9 || (std::abs(d.x) <= 1e-9 && d.y > 0)) d = -d;  // read left to right (or bottom to top)
  glm::dvec2 n(-d.y, d.x);
  const glm::dvec2 mid = 0.5 * (a + b);
  if (glm::dot(n, awayFrom - mid) > 0) n = -n;
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, s.fontScale, s.thickness, &baseline);
  const double offset = 0.5 * (size.height + baseline) + std::max(3, size.height / 3) + s.lineWidth + 2;
  rotatedLabel(canvas, text, mid + n * offset, glm::degrees(std::atan2(d.y, d.x)), s, colour);
}

// Rounds what would print as -0.00 to 0.
double tidy(double v) { return std::abs(v) < 0.005 ? 0.0 : v; }

// "W 2.6 m +/- 0.3" (the Hershey font has no ±).
std::string edgeText(const char* name, double valueM, double sigmaM) {
  return std::string(name) + " " + dimensionText(valueM, sigmaM, "+/-");
}

cv::Mat toBgr(const cv::Mat& photo) {
  cv::Mat bgr;
  if (photo.channels() == 1) cv::cvtColor(photo, bgr, cv::COLOR_GRAY2BGR);
  else if (photo.channels() == 4) cv::cvtColor(photo, bgr, cv::COLOR_BGRA2BGR);
  else bgr = photo.clone();
  if (bgr.depth() != CV_8U) bgr.convertTo(bgr, CV_8U);
  return bgr;
}

}  // namespace

Result<cv::Mat> drawMeasurementSheet(const cv::Mat& photo, const Shot& shot, const Measurement& m,
                                     const std::vector<SheetPoint>& points, const std::vector<SheetObject>& objects) {
  if (photo.empty()) return makeError("the photo is empty");
  if (photo.depth() != CV_8U || (photo.channels() != 1 && photo.channels() != 3 && photo.channels() != 4)) {
    return makeError("the photo must be 8-bit grey, BGR or BGRA");
  }
  // Canvas: the photo plus whatever of the corners and VP lies outside it (at most one
  // image size each way), with a margin.
  const double w = photo.cols, h = photo.rows;
  glm::dvec2 lo(0.0), hi(w - 1, h - 1);
  auto include = [&](const glm::dvec2& p) {
    lo = glm::min(lo, glm::max(p, glm::dvec2(-w, -h)));
    hi = glm::max(hi, glm::min(p, glm::dvec2(2 * w, 2 * h)));
  };
  for (const glm::dvec2& p : shot.cornersPx) include(p);
  include(m.vanishing.corridor.px);
  const bool grown = lo.x < 0 || lo.y < 0 || hi.x > w - 1 || hi.y > h - 1;
  const double margin = grown ? 0.04 * std::hypot(w, h) : 0.0;
  lo -= margin;
  hi += margin;
  const glm::dvec2 origin = glm::floor(lo);
  const cv::Size size(static_cast<int>(std::ceil(hi.x - origin.x)) + 1, static_cast<int>(std::ceil(hi.y - origin.y)) + 1);
  cv::Mat canvas(size, CV_8UC3, cv::Scalar(48, 48, 48));
  cv::Mat bgr = toBgr(photo);
  // Slightly dimmed so that the drawing stands out.
  bgr.convertTo(canvas(cv::Rect(static_cast<int>(-origin.x), static_cast<int>(-origin.y), photo.cols, photo.rows)), CV_8U,
                0.8, 0);
  auto at = [&](const glm::dvec2& p) { return p - origin; };

  Style s;
  const double diag = std::hypot(size.width, size.height);
  s.fontScale = std::max(0.45, diag / 1700.0);
  s.thickness = std::max(1, static_cast<int>(std::lround(s.fontScale * 1.6)));
  s.lineWidth = std::max(1, static_cast<int>(std::lround(diag / 700.0)));
  s.radius = std::max(4.0, diag / 180.0);

  const auto& c = shot.cornersPx;
  const glm::dvec2 vp = m.vanishing.corridor.px;

  // Horizon across the whole canvas.
  {
    const ImageLine& l = m.horizon;
    const glm::dvec2 dir(-l.y, l.x), foot = -l.z * glm::dvec2(l.x, l.y);
    const double reach = 2 * diag;
    line(canvas, at(foot - dir * reach), at(foot + dir * reach), kHorizonColour, s.lineWidth);
    // Name it near the right edge of the canvas, just above the line.
    const glm::dvec2 right = dir.x >= 0 ? dir : -dir;
    if (std::abs(right.x) > 0.2) {
      const double t = (origin.x + size.width - 0.12 * size.width - foot.x) / right.x;
      const glm::dvec2 p = at(foot + right * t);
      outlinedText(canvas, "horizon", cv::Point(static_cast<int>(p.x), static_cast<int>(p.y - 1.2 * s.radius)), s,
                   kHorizonColour);
    }
  }
  // Receding edges, extended (dashed) from the far corners to VP.
  constexpr int kReceding[4][2] = {{P7, P1}, {P8, P2}, {P5, P3}, {P6, P4}};
  for (const auto& e : kReceding) dashedLine(canvas, at(c[e[1]]), at(vp), kRecedingColour, s.lineWidth, 4.0 * s.radius / 3);
  // Plane outlines, then the measured edges in their dimension's colour.
  for (const auto& quad : kPlaneCorners) {
    for (int i = 0; i < 4; ++i) line(canvas, at(c[quad[i]]), at(c[quad[(i + 1) % 4]]), kOutlineColour, s.lineWidth);
  }
  line(canvas, at(c[P5]), at(c[P6]), kWidthColour, 2 * s.lineWidth);
  line(canvas, at(c[P6]), at(c[P8]), kHeightColour, 2 * s.lineWidth);
  line(canvas, at(c[P5]), at(c[P3]), kLengthColour, 2 * s.lineWidth);

  // VP.
  cv::drawMarker(canvas, fixed(at(vp)) / (1 << kShift), kRecedingColour, cv::MARKER_TILTED_CROSS,
                 static_cast<int>(3 * s.radius), s.lineWidth + 1, cv::LINE_AA);
  outlinedText(canvas, "VP", cv::Point(static_cast<int>(at(vp).x + 1.5 * s.radius), static_cast<int>(at(vp).y - 1.5 * s.radius)),
               s, kRecedingColour);

  // The seed paper's construction (its figure 2): the ground line GL, s·h below the
  // horizon, and each floor corner extended from VP to GL (2.1.1).
  if (m.method == Method::kSeed) {
    auto seed = seedConstruct(shot.cornersPx, m.camera.focalPx, m.cameraHeightM);
    if (seed) {
      const double roll = glm::radians(seed->rollDeg);
      auto unrotate = [&](const glm::dvec2& p) {  // the construction's frame back to the photo
        const glm::dvec2 d = p - vp;
        return vp + glm::dvec2(std::cos(roll) * d.x - std::sin(roll) * d.y, std::sin(roll) * d.x + std::cos(roll) * d.y);
      };
      line(canvas, at(unrotate({vp.x - 2 * diag, seed->groundLineV})), at(unrotate({vp.x + 2 * diag, seed->groundLineV})),
           kGroundLineColour, s.lineWidth);
      for (int k = 0; k < 4; ++k) {
        const glm::dvec2 pg = unrotate(seed->floor[k].groundPoint);
        dashedLine(canvas, at(c[P3 + k]), at(pg), kGroundLineColour, std::max(1, s.lineWidth / 2), s.radius);
        cv::circle(canvas, fixed(at(pg)), static_cast<int>(0.6 * s.radius * (1 << kShift)), kGroundLineColour, -1, cv::LINE_AA,
                   kShift);
      }
      const glm::dvec2 label = at(unrotate({vp.x + 0.12 * diag, seed->groundLineV})) + glm::dvec2(0, 2.5 * s.radius);
      outlinedText(canvas, "GL: ground line, h below the horizon", cv::Point(static_cast<int>(label.x), static_cast<int>(label.y)), s,
                   kGroundLineColour);
    }
  }

  // Corners: clicked (circles, labelled) and fitted (crosses).
  const glm::dvec2 centre = 0.125 * (c[0] + c[1] + c[2] + c[3] + c[4] + c[5] + c[6] + c[7]);
  for (int i = 0; i < kCornerCount; ++i) {
    cv::circle(canvas, fixed(at(c[i])), static_cast<int>(s.radius * (1 << kShift)), kInk, s.lineWidth, cv::LINE_AA, kShift);
    cv::drawMarker(canvas, fixed(at(m.reprojectedPx[i])) / (1 << kShift), kFitColour, cv::MARKER_CROSS,
                   static_cast<int>(2 * s.radius), s.lineWidth, cv::LINE_AA);
    glm::dvec2 away = c[i] - centre;
    away = glm::length(away) > 1e-9 ? away / glm::length(away) : glm::dvec2(1, 0);
    const glm::dvec2 labelAt = at(c[i]) + away * (2.2 * s.radius) + glm::dvec2(-0.6 * s.radius, 0.6 * s.radius);
    outlinedText(canvas, cornerName(i), cv::Point(static_cast<int>(labelAt.x), static_cast<int>(labelAt.y)), s, kInk);
  }

  // Each dimension on its edge.
  edgeLabel(canvas, edgeText("W", m.size.widthM, m.sigma.widthM), at(c[P5]), at(c[P6]), at(vp), s, kWidthColour);
  edgeLabel(canvas, edgeText("H", m.size.heightM, m.sigma.heightM), at(c[P6]), at(c[P8]), at(vp), s, kHeightColour);
  edgeLabel(canvas, edgeText("L", m.size.lengthM, m.sigma.lengthM), at(c[P5]), at(c[P3]), at(c[P6]), s,
            kLengthColour);

  // The objects measured: a line between their points, the value along it; the points
  // as small rings with their names.
  const cv::Scalar kObjectColour(60, 230, 255);
  Style small = s;
  small.fontScale = 0.75 * s.fontScale;
  small.thickness = std::max(1, s.thickness - 1);
  for (const SheetObject& o : objects) {
    line(canvas, at(o.fromPx), at(o.toPx), kObjectColour, 2 * s.lineWidth);
    edgeLabel(canvas, o.text, at(o.fromPx), at(o.toPx), at(vp), small, kObjectColour);
  }
  for (const SheetPoint& p : points) {
    cv::circle(canvas, fixed(at(p.px)), static_cast<int>(0.6 * s.radius * (1 << kShift)), kObjectColour, s.lineWidth,
               cv::LINE_AA, kShift);
    const glm::dvec2 labelAt = at(p.px) + glm::dvec2(1.2 * s.radius, -0.8 * s.radius);
    outlinedText(canvas, p.name, cv::Point(static_cast<int>(labelAt.x), static_cast<int>(labelAt.y)), small, kObjectColour);
  }

  // Legend.
  char lines[4][160];
  const SigmaSource* mostly = dominantSigmaSource(m, 2);
  std::snprintf(lines[0], sizeof lines[0], "photowalk measure (%s)   +/- 1 sigma of every input, mostly %s",
                methodName(m.method), mostly ? mostly->name.c_str() : "the corners");
  std::snprintf(lines[1], sizeof lines[1], "%s   %s   %s", edgeText("W", m.size.widthM, m.sigma.widthM).c_str(),
                edgeText("H", m.size.heightM, m.sigma.heightM).c_str(),
                edgeText("L", m.size.lengthM, m.sigma.lengthM).c_str());
  std::snprintf(lines[2], sizeof lines[2], "camera f %.1f px  h %.3f m  yaw %.2f  pitch %.2f  roll %.2f deg", m.camera.focalPx,
                m.cameraHeightM, tidy(m.pose.yawDeg), tidy(m.pose.pitchDeg), tidy(m.pose.rollDeg));
  std::snprintf(lines[3], sizeof lines[3], "reprojection RMS %.2f px   VP (%.1f, %.1f)   o clicked  + fitted",
                m.reprojectionRmsPx, vp.x, vp.y);
  int baseline = 0;
  const cv::Size lineSize = cv::getTextSize("Hg", cv::FONT_HERSHEY_SIMPLEX, s.fontScale * 0.8, s.thickness, &baseline);
  const int step = lineSize.height + baseline + 4;
  int widest = 0;
  for (const auto& text : lines) {
    widest = std::max(widest, cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, s.fontScale * 0.8, s.thickness, &baseline).width);
  }
  // The legend goes in a strip under the picture, never over it.
  const int stripHeight = 4 * step + 12;
  cv::Mat sheet(size.height + stripHeight, std::max(size.width, widest + 16), CV_8UC3, cv::Scalar(32, 32, 32));
  canvas.copyTo(sheet(cv::Rect(0, 0, size.width, size.height)));
  Style legend = s;
  legend.fontScale = s.fontScale * 0.8;
  for (int i = 0; i < 4; ++i) {
    outlinedText(sheet, lines[i], cv::Point(8, size.height + 6 + lineSize.height + i * step), legend, kInk);
  }
  return sheet;
}

}  // namespace pw::metrology
