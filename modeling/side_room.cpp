#include "modeling/side_room.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <opencv2/imgproc.hpp>

#include "metrology/rectify.h"
#include "modeling/corridor_model.h"
#include "modeling/stand_up.h"

namespace pw::modeling {
namespace {

using metrology::Measurement;

constexpr double kReachM = 10.0;      // the room runs at most this far along the corridor beyond the opening
constexpr double kEndMarginM = 0.5;   // beyond what the photo sees through the opening
constexpr double kMinPxPerM = 16;
constexpr double kMaxTexturePixels = 2.5e5;
constexpr int kSeenMarginTexels = 2;

// Where the segment from the photo's camera to p crosses the wall plane x = wallX, in
// the wall's (s, t); nullopt where it does not cross it between them.
std::optional<glm::dvec2> throughWall(const Panel& wall, const glm::dvec3& eye, const glm::dvec3& p) {
  const double wallX = wall.origin.x;
  const double a = eye.x - wallX, b = p.x - wallX;
  if (!(a * b < 0)) return std::nullopt;
  const glm::dvec3 q = eye + (a / (a - b)) * (p - eye);
  return glm::dvec2(glm::dot(q - wall.origin, wall.sAxis), glm::dot(q - wall.origin, wall.tAxis));
}

bool inside(const Rect& r, const glm::dvec2& st) { return st.x >= r.s0 && st.x <= r.s1 && st.y >= r.t0 && st.y <= r.t1; }

// Seen by the photo's camera through the opening.
bool seenThrough(const Panel& wall, const Rect& opening, const glm::dvec3& eye, const glm::dvec3& p) {
  const auto st = throughWall(wall, eye, p);
  return st && inside(opening, *st);
}

// The panel's texture cut from the photo where the photo's camera sees it through the
// opening; elsewhere its mean colour there. Where it sees none of it: untextured, in
// `fallback`.
RoomPanel cutRoomPanel(metrology::PhotoPyramid& pyramid, const Measurement& m, const Panel& wall, const Rect& opening,
                       const std::string& label, const Panel& panel, const glm::vec3& fallback) {
  RoomPanel out;
  out.label = label;
  out.colour = fallback;
  out.panel = panel;
  out.panel.textureRect = panel.extent;
  const Rect& r = panel.extent;
  const double widthM = r.s1 - r.s0, heightM = r.t1 - r.t0;
  const cv::Matx33d photoFromMetric =
      metrology::photoFromPlane(m.camera, m.pose, panel.point(r.s0, r.t1), panel.sAxis, -panel.tAxis);
  metrology::RectifyOptions rectify;
  rectify.perAxisDensity = true;
  rectify.minPxPerM = kMinPxPerM;
  rectify.maxPixels = kMaxTexturePixels;
  rectify.outside = metrology::OutsidePhoto::kMeanColor;
  auto plane = metrology::rectifyPlane(pyramid, photoFromMetric, widthM, heightM, rectify);
  if (!plane) return out;  // untextured, in its colour
  cv::Mat& image = plane->image;
  cv::Mat seen(image.size(), CV_8U, cv::Scalar(0));
  const glm::dvec3 eye = m.pose.positionM;
  for (int row = 0; row < image.rows; ++row) {
    for (int col = 0; col < image.cols; ++col) {
      const glm::dvec3 p = panel.point(r.s0 + (col + 0.5) * widthM / image.cols, r.t1 - (row + 0.5) * heightM / image.rows);
      if (!seenThrough(wall, opening, eye, p)) continue;
      const glm::dvec3 px = metrology::projectWithMeasurement(m, p);
      if (px.z > 1e-3 && px.x >= -0.5 && px.y >= -0.5 && px.x <= pyramid.photo().cols - 0.5 && px.y <= pyramid.photo().rows - 0.5) {
        seen.at<uint8_t>(row, col) = 255;
      }
    }
  }
  out.seenFraction = static_cast<double>(cv::countNonZero(seen)) / seen.total();
  if (out.seenFraction == 0) return out;
  const cv::Scalar mean = cv::mean(image, seen);
  out.colour = glm::vec3(static_cast<float>(mean[2] / 255), static_cast<float>(mean[1] / 255), static_cast<float>(mean[0] / 255));
  // A texel at the edge of what is seen is seen in part: it keeps the photo's pixel, so
  // that from the photo's camera the opening's edge is the photo's, not a blend with the fill.
  cv::dilate(seen, seen, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * kSeenMarginTexels + 1, 2 * kSeenMarginTexels + 1)));
  image.setTo(mean, ~seen);
  out.image = imageFromBgr(image);
  out.sourceFromTexCoord = sourceFromTexCoord(photoFromMetric, widthM, heightM);
  return out;
}

// The mean colour (RGB 0-1) of the photo's pixels inside the opening; nullopt where the
// photo shows none of it.
std::optional<glm::vec3> meanThrough(const cv::Mat& photo, const Measurement& m, const Panel& wall, const Rect& r) {
  std::vector<cv::Point> polygon;
  for (const glm::dvec2 st : {glm::dvec2(r.s0, r.t0), glm::dvec2(r.s1, r.t0), glm::dvec2(r.s1, r.t1), glm::dvec2(r.s0, r.t1)}) {
    const glm::dvec3 px = metrology::projectWithMeasurement(m, wall.point(st.x, st.y));
    if (!(px.z > 1e-3)) return std::nullopt;
    polygon.emplace_back(static_cast<int>(std::lround(std::clamp(px.x, -1.0, photo.cols + 0.0))),
                         static_cast<int>(std::lround(std::clamp(px.y, -1.0, photo.rows + 0.0))));
  }
  cv::Mat mask = cv::Mat::zeros(photo.size(), CV_8U);
  cv::fillConvexPoly(mask, polygon, cv::Scalar(255));
  if (cv::countNonZero(mask) == 0) return std::nullopt;
  const cv::Scalar mean = cv::mean(photo, mask);
  return glm::vec3(static_cast<float>(mean[2] / 255), static_cast<float>(mean[1] / 255), static_cast<float>(mean[0] / 255));
}

}  // namespace

Result<SideRoom> placeOpening(const Measurement& m, const metrology::Cutout& cutout, double nearM) {
  const std::string who = "cutout \"" + cutout.name + "\"";
  const metrology::Dimensions& box = m.size;
  // Which side wall: the one the outline's middle lies on, inside the wall.
  glm::dvec2 middle(0.0);
  for (const glm::dvec2& p : cutout.outlinePx) middle += p / static_cast<double>(cutout.outlinePx.size());
  SideRoom room;
  room.name = cutout.name;
  room.depthM = kRoomDepthM;
  std::optional<Panel> wall;
  for (const Surface surface : {Surface::kLeftWall, Surface::kRightWall}) {
    const Panel panel = surfacePanel(surface, box, nearM);
    const auto at = onPlane(m, middle, panel.origin, panel.normal());
    if (!at) continue;
    const glm::dvec2 st(glm::dot(*at - panel.origin, panel.sAxis), glm::dot(*at - panel.origin, panel.tAxis));
    if (st.y > -kFloorSnapM && st.y < box.heightM + kFloorSnapM && st.x >= panel.extent.s0 - 0.5 && st.x <= panel.extent.s1 + 0.5) {
      room.wall = surface;
      wall = panel;
      break;
    }
  }
  if (!wall) {
    return makeError(who + ": an opening is drawn on a side wall (a doorway or an opening into a room), and the middle of "
                           "this outline is on neither: outline the opening where the left or right wall shows it");
  }
  // The rectangle on the wall the outline's corners span.
  Rect& r = room.opening;
  r = {1e300, 1e300, -1e300, -1e300};
  int onWall = 0;
  for (const glm::dvec2& p : cutout.outlinePx) {
    const auto at = onPlane(m, p, wall->origin, wall->normal());
    if (!at) continue;
    const double s = glm::dot(*at - wall->origin, wall->sAxis), t = glm::dot(*at - wall->origin, wall->tAxis);
    r.s0 = std::min(r.s0, s), r.s1 = std::max(r.s1, s), r.t0 = std::min(r.t0, t), r.t1 = std::max(r.t1, t);
    ++onWall;
  }
  if (onWall < 3) return makeError(who + ": its outline's corners are not on the wall in front of the camera: redraw it on the wall");
  if (r.t0 < kFloorSnapM) r.t0 = 0;
  r = intersect(r, wall->extent);
  if (r.empty() || r.s1 - r.s0 < kMinOpeningM || r.t1 - r.t0 < kMinOpeningM) {
    return makeError(who + ": the opening it outlines on the " + surfaceName(room.wall) +
                     " is under 0.2 m across or runs off the wall: outline the whole opening");
  }
  return room;
}

namespace {

// The room behind `room`'s opening, no further along the corridor than [zMin, zMax] (the
// neighbouring openings' rooms on the same wall).
void buildRoom(metrology::PhotoPyramid& pyramid, const Measurement& m, double nearM,
               const RoomColours& colours, double zMin, double zMax, SideRoom& room) {
  const metrology::Dimensions& box = m.size;
  const glm::dvec3 eye = m.pose.positionM;
  const std::optional<Panel> wall = surfacePanel(room.wall, box, nearM);
  const Rect& r = room.opening;
  const double side = room.wall == Surface::kLeftWall ? -1.0 : 1.0;
  const double wallX = wall->origin.x;

  const double backX = wallX + side * room.depthM;

  // Along the corridor: the opening, and what the photo's camera sees through it on the
  // back wall and the floor, kEndMarginM more, at most kReachM beyond the opening.
  const double za = std::min(wall->point(r.s0, 0).z, wall->point(r.s1, 0).z);
  const double zb = std::max(wall->point(r.s0, 0).z, wall->point(r.s1, 0).z);
  double z0 = za, z1 = zb;
  for (double s : {r.s0, r.s1}) {
    for (double t : {r.t0, r.t1}) {
      const glm::dvec3 q = wall->point(s, t);
      const glm::dvec3 ray = q - eye;
      if (std::abs(ray.x) < 1e-9) continue;
      const double k = (backX - eye.x) / ray.x;  // on the back wall's plane
      if (k > 1) {
        const double z = eye.z + k * ray.z;
        z0 = std::min(z0, z), z1 = std::max(z1, z);
      }
    }
  }
  z0 = std::max({z0 - kEndMarginM, za - kReachM, zMin});
  z1 = std::min({z1 + kEndMarginM, zb + kReachM, zMax});
  const double height = std::max(box.heightM, r.t1);
  const double x0 = std::min(wallX, backX), x1 = std::max(wallX, backX);

  const auto add = [&](const std::string& label, glm::dvec3 origin, glm::dvec3 sAxis, glm::dvec3 tAxis, Rect extent,
                       const glm::vec3& fallback) {
    Panel panel;
    panel.origin = origin, panel.sAxis = sAxis, panel.tAxis = tAxis, panel.extent = extent;
    room.panels.push_back(cutRoomPanel(pyramid, m, *wall, r, label, panel, fallback));
  };
  // What the photo does not see of the room's walls and ceiling: the mean of what it
  // shows through the opening (a room glowing white through a doorway is a white room);
  // of its floor, the corridor's floor (a floor often runs on).
  const glm::vec3 wallColour = room.wall == Surface::kLeftWall ? colours.leftWall : colours.rightWall;
  const glm::vec3 through = meanThrough(pyramid.photo(), m, *wall, r).value_or(wallColour);
  // Each facing into the room (panel.h: the front faces cross(sAxis, tAxis)).
  if (side < 0) {
    add("back", {backX, 0, 0}, {0, 0, -1}, {0, 1, 0}, {-z1, 0, -z0, height}, through);
  } else {
    add("back", {backX, 0, 0}, {0, 0, 1}, {0, 1, 0}, {z0, 0, z1, height}, through);
  }
  add("floor", {0, 0, 0}, {1, 0, 0}, {0, 0, -1}, {x0, -z1, x1, -z0}, colours.floor);
  add("ceiling", {0, height, 0}, {1, 0, 0}, {0, 0, 1}, {x0, z0, x1, z1}, through);
  add("far_end", {0, 0, z0}, {1, 0, 0}, {0, 1, 0}, {x0, 0, x1, height}, through);
  add("near_end", {0, 0, z1}, {-1, 0, 0}, {0, 1, 0}, {-x1, 0, -x0, height}, through);
  // The corridor's wall seen from the room, around the opening: untextured.
  RoomPanel& back = room.panels.emplace_back();
  back.label = "wall_back";
  back.panel.origin = {wallX, 0, 0};
  back.panel.sAxis = {0, 0, side < 0 ? 1.0 : -1.0};
  back.panel.tAxis = {0, 1, 0};
  back.panel.extent = side < 0 ? Rect{z0, 0, z1, height} : Rect{-z1, 0, -z0, height};
  Rect hole{1e300, r.t0, -1e300, r.t1};
  for (double s : {r.s0, r.s1}) {
    const double z = wall->point(s, 0).z;
    const double sBack = side < 0 ? z : -z;
    hole.s0 = std::min(hole.s0, sBack), hole.s1 = std::max(hole.s1, sBack);
  }
  back.panel.openings = {hole};
  back.colour = wallColour;
}

}  // namespace

Result<std::vector<SideRoom>> openSideRooms(const cv::Mat& photo, const Measurement& m,
                                            const std::vector<metrology::Cutout>& openings, double nearM,
                                            const RoomColours& colours) {
  if (photo.empty() || photo.type() != CV_8UC3) return makeError("opening side walls needs an 8-bit colour photo");
  std::vector<SideRoom> rooms;
  for (const metrology::Cutout& cutout : openings) {
    auto room = placeOpening(m, cutout, nearM);
    if (!room) return room.error();
    rooms.push_back(std::move(*room));
  }
  // Along the corridor (z), each opening's span; openings on one wall must not overlap,
  // and each room reaches no further than half way to its neighbours' openings.
  const auto span = [&](const SideRoom& room) {
    const Panel wall = surfacePanel(room.wall, m.size, nearM);
    const double a = wall.point(room.opening.s0, 0).z, b = wall.point(room.opening.s1, 0).z;
    return std::pair(std::min(a, b), std::max(a, b));
  };
  metrology::PhotoPyramid pyramid(photo, m.camera);
  for (size_t i = 0; i < rooms.size(); ++i) {
    const auto [za, zb] = span(rooms[i]);
    double zMin = -1e300, zMax = 1e300;
    for (size_t j = 0; j < rooms.size(); ++j) {
      if (j == i || rooms[j].wall != rooms[i].wall) continue;
      const auto [ya, yb] = span(rooms[j]);
      if (ya < zb && yb > za) {
        return makeError("cutouts \"" + rooms[std::min(i, j)].name + "\" and \"" + rooms[std::max(i, j)].name +
                         "\": two openings overlap on the " + surfaceName(rooms[i].wall) + ": make them one");
      }
      // Half way to a neighbour's opening: the two rooms meet there and do not overlap.
      if (yb <= za) zMin = std::max(zMin, 0.5 * (yb + za));
      if (ya >= zb) zMax = std::min(zMax, 0.5 * (ya + zb));
    }
    buildRoom(pyramid, m, nearM, colours, zMin, zMax, rooms[i]);
  }
  return rooms;
}

}  // namespace pw::modeling
