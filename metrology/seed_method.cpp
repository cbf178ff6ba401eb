#include "metrology/seed_method.h"

#include <cmath>
#include <string>

#include "metrology/vanishing.h"

namespace pw::metrology {

namespace {

// Where the line a1-a2 meets the line b1-b2 (homogeneous cross products); none when
// they are parallel within 1e-12 of their lengths.
std::optional<glm::dvec2> meet(const glm::dvec2& a1, const glm::dvec2& a2, const glm::dvec2& b1, const glm::dvec2& b2) {
  const glm::dvec3 la = glm::cross(glm::dvec3(a1, 1.0), glm::dvec3(a2, 1.0));
  const glm::dvec3 lb = glm::cross(glm::dvec3(b1, 1.0), glm::dvec3(b2, 1.0));
  const glm::dvec3 x = glm::cross(la, lb);
  const double scale = glm::length(glm::dvec2(la)) * glm::length(glm::dvec2(lb));
  if (!(std::abs(x.z) > 1e-12 * scale)) return std::nullopt;
  return glm::dvec2(x) / x.z;
}

glm::dvec2 rotateAbout(const glm::dvec2& p, const glm::dvec2& centre, double angleRad) {
  const double c = std::cos(angleRad), s = std::sin(angleRad);
  const glm::dvec2 d = p - centre;
  return centre + glm::dvec2(c * d.x - s * d.y, s * d.x + c * d.y);
}

// Step 4, 2.1.1: extend VP->P to the ground line.
std::optional<glm::dvec2> extendToGroundLine(const glm::dvec2& vp, const glm::dvec2& p, double groundLineV) {
  return meet(vp, p, glm::dvec2(0.0, groundLineV), glm::dvec2(1.0, groundLineV));
}

constexpr int kFloorCorners[4] = {P3, P4, P5, P6};
constexpr int kTopOver[4][2] = {{P1, P3}, {P2, P4}, {P7, P5}, {P8, P6}};  // top corner, floor corner below it

}  // namespace

Result<SeedConstruction> seedConstruct(const std::array<glm::dvec2, kCornerCount>& cornersPx, double focalPx,
                                       double cameraHeightM) {
  if (!(focalPx > 0) || !(cameraHeightM > 0)) return makeError("the focal length and camera height must be positive");
  SeedConstruction c;
  // Step 1: VP as the least-squares meet of the four receding edges, and the horizon.
  auto vanishing = corridorVanishing(cornersPx);
  if (!vanishing) return vanishing.error();
  const glm::dvec2 vp = vanishing->corridor.px;
  c.vanishingPointPx = vp;
  c.rollDeg = vanishing->rollDeg;
  // Work with the horizon horizontal: rotate the image by -roll about VP.
  for (int i = 0; i < kCornerCount; ++i) c.rotatedPx[i] = rotateAbout(cornersPx[i], vp, -glm::radians(c.rollDeg));
  for (int corner : kFloorCorners) {
    if (!(c.rotatedPx[corner].y - vp.y > 0.5)) {
      return makeError(std::string("floor corner ") + cornerName(corner) +
                       " is not below the horizon; the floor corners must lie below the vanishing point");
    }
  }
  for (int i = 0; i < kCornerCount; ++i) {
    if (glm::length(c.rotatedPx[i] - vp) < 0.5) {
      return makeError(std::string("corner ") + cornerName(i) + " lies on the vanishing point; it has no depth");
    }
  }
  // Any positive drawing scale gives the same answers; this one puts GL a fifth
  // below the lowest floor corner, so that the construction is visible when drawn
  // over the photo.
  double lowest = 0;
  for (int corner : kFloorCorners) lowest = std::max(lowest, c.rotatedPx[corner].y - vp.y);
  const double s = 1.2 * lowest / cameraHeightM;
  c.drawingScalePxPerM = s;
  // Step 2: the ground line, s·h below the horizon.
  c.groundLineV = vp.y + s * cameraHeightM;
  // Step 3: the picture plane line, f above VP (ST placed at VP).
  c.picturePlaneV = vp.y - focalPx;
  const glm::dvec2 station = vp;

  // Step 4, 2.1.1 and 2.1.3 for each floor corner.
  for (int k = 0; k < 4; ++k) {
    const int corner = kFloorCorners[k];
    const glm::dvec2 p = c.rotatedPx[corner];
    SeedFloorPoint& f = c.floor[k];
    auto pg = extendToGroundLine(vp, p, c.groundLineV);
    if (!pg) return makeError(std::string("floor corner ") + cornerName(corner) + " lies on the horizon");
    f.groundPoint = *pg;
    f.lateralM = (pg->x - vp.x) / s;
    f.picturePoint = glm::dvec2(pg->x, c.picturePlaneV);     // Pp: foot of Pg on PP
    f.cornerOnPicture = glm::dvec2(p.x, c.picturePlaneV);    // P1p1: foot of P on PP
    // ST->P1p1 meets the vertical Pg-Pp at Pa, the point's plan position. A corner
    // straight below VP gives a vertical ST->P1p1 that never meets it.
    if (std::abs(p.x - vp.x) > 0.5) {
      f.planPoint = meet(station, f.cornerOnPicture, f.groundPoint, f.picturePoint);
      if (f.planPoint) {
        // Signed distance beyond the picture plane (Pa above PP), plus f/s.
        f.depthM = (f.picturePoint.y - f.planPoint->y) / s + focalPx / s;
      }
    }
  }

  // 2.1.1: width from the floor corners at the same depth, P3-P4 and P5-P6.
  c.widthM = 0.5 * ((c.floor[1].groundPoint.x - c.floor[0].groundPoint.x) +
                    (c.floor[3].groundPoint.x - c.floor[2].groundPoint.x)) / s;
  // 2.1.2: height of each top corner over the floor corner below it.
  double heightSum = 0;
  for (int k = 0; k < 4; ++k) {
    const SeedFloorPoint& f = c.floor[k];  // kTopOver[k][1] is kFloorCorners[k]
    const glm::dvec2 top = c.rotatedPx[kTopOver[k][0]];
    auto pgp = meet(vp, top, f.groundPoint, f.picturePoint);
    if (!pgp) {
      return makeError(std::string("corner ") + cornerName(kTopOver[k][0]) + " lies on the line from the vanishing point to " +
                       cornerName(kTopOver[k][1]) + "'s ground point; its height cannot be constructed");
    }
    c.heightPoint[k] = *pgp;
    c.heightsM[k] = (f.groundPoint.y - pgp->y) / s;
    heightSum += c.heightsM[k];
  }
  c.heightM = heightSum / 4;
  // 2.1.3: length as the difference of depths, far minus near, from the pairs that allow it.
  double lengthSum = 0, nearSum = 0;
  int pairs = 0;
  for (int side = 0; side < 2; ++side) {
    const SeedFloorPoint& far = c.floor[side];
    const SeedFloorPoint& near = c.floor[2 + side];
    if (!far.depthM || !near.depthM) continue;
    lengthSum += *far.depthM - *near.depthM;
    nearSum += *near.depthM;
    ++pairs;
  }
  if (pairs == 0) {
    return makeError("the floor corners lie straight below the vanishing point on both walls; the seed construction "
                     "cannot find the depth (use --method general)");
  }
  c.lengthM = lengthSum / pairs;
  c.nearDepthM = nearSum / pairs;
  c.cameraXM = -0.25 * (c.floor[0].lateralM + c.floor[1].lateralM + c.floor[2].lateralM + c.floor[3].lateralM);
  if (!(c.widthM > 0) || !(c.heightM > 0) || !(c.lengthM > 0) || !std::isfinite(c.widthM + c.heightM + c.lengthM)) {
    return makeError("the seed construction gives a non-positive width, height or length; check the corner order");
  }
  return c;
}

}  // namespace pw::metrology
