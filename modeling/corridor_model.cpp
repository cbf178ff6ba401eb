#include "modeling/corridor_model.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "metrology/rectify.h"
#include "modeling/panel.h"

namespace pw::modeling {
namespace {

using metrology::Measurement;

constexpr double kBehindCameraM = 1.0;  // photo-only: untextured surfaces run on this far behind the eye
constexpr int kMaxExtensionColumns = 4096;
constexpr int kFaces = 5;               // far wall, left, right, floor, ceiling (Surface 0..4)
constexpr double kMinPxPerM = 16;       // a texture's least density, where the photo shows little
constexpr double kOverviewFieldOfViewDeg = 60.0;
constexpr double kOverviewElevationDeg = 25.0;  // how steeply the Overview looks down

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

// True where the measured camera sees model point p inside the photo.
bool visibleInPhoto(const Measurement& m, const glm::dvec3& p, int width, int height) {
  const glm::dvec3 px = metrology::projectWithMeasurement(m, p);
  return px.z > 1e-3 && px.x >= -0.5 && px.x <= width - 0.5 && px.y >= -0.5 && px.y <= height - 0.5;
}

// How far beyond the near end (z > 0) the photo still shows some of the floor, walls
// or ceiling: scanned in 2 cm steps towards the camera, or in kMaxNearSteps steps
// where the camera stands further back than that (the work does not grow with the
// shot's scale: a camera height of 1e7 m would be 5e8 steps of 2 cm).
constexpr int kMaxNearSteps = 4096;
double photoNearExtent(const Measurement& m, const metrology::Dimensions& box, int width, int height) {
  const double cameraZ = m.pose.positionM.z;
  if (!std::isfinite(cameraZ)) return 0;
  const double step = std::max(0.02, (cameraZ - 0.05) / kMaxNearSteps);
  double best = 0;
  for (int surface = 1; surface < kFaces; ++surface) {
    const Panel full = surfacePanel(static_cast<Surface>(surface), box, std::max(0.0, cameraZ));
    for (double z = step; z < cameraZ - 0.05; z += step) {
      const Panel at = surfacePanel(static_cast<Surface>(surface), box, z);
      // The cross-section at depth z is the extent's edge nearest the camera.
      const bool alongS = at.extent.s0 < 0 || full.extent.s1 > at.extent.s1 + 1e-9;
      bool any = false;
      for (int i = 0; i <= 16 && !any; ++i) {
        const double f = i / 16.0;
        double s, t;
        if (alongS) {
          s = at.extent.s0 < 0 ? at.extent.s0 : at.extent.s1;
          t = at.extent.t0 + f * (at.extent.t1 - at.extent.t0);
        } else {
          s = at.extent.s0 + f * (at.extent.s1 - at.extent.s0);
          t = at.extent.t0 < 0 ? at.extent.t0 : at.extent.t1;
        }
        any = visibleInPhoto(m, full.point(s, t), width, height);
      }
      if (!any) break;
      best = std::max(best, z);
    }
  }
  return best;
}


// Cuts one surface's texture out of the photo with metrology's rectifier, through the
// measured camera; what the photo does not show is filled with the mean colour of
// what it does.
Result<SurfaceTexture> cutTexture(metrology::PhotoPyramid& photo, const Measurement& m, Surface surface,
                                  const Panel& panel, const ModelOptions& options, glm::vec3& meanColor) {
  SurfaceTexture out;
  out.rect = panel.extent;
  const Rect& r = panel.extent;
  const double widthM = r.s1 - r.s0, heightM = r.t1 - r.t0;
  // Texture rows run from t1 (top) down to t0: the rectifier's metric (x, y) is the
  // surface's (s0 + x, t1 - y).
  const cv::Matx33d photoFromMetric =
      metrology::photoFromPlane(m.camera, m.pose, panel.point(r.s0, r.t1), panel.sAxis, -panel.tAxis);
  metrology::RectifyOptions rectify;
  rectify.pxPerM = options.pxPerM;
  rectify.perAxisDensity = true;
  rectify.minPxPerM = kMinPxPerM;
  rectify.maxSidePx = options.maxTextureSide;
  rectify.maxPixels = options.maxTexturePixels;
  rectify.outside = metrology::OutsidePhoto::kMeanColor;
  auto plane = metrology::rectifyPlane(photo, photoFromMetric, widthM, heightM, rectify);
  if (!plane) return makeError(std::string(surfaceName(surface)) + ": " + plane.message());
  out.pxPerM = plane->pxPerM;
  out.coveredFraction = plane->coverage;
  meanColor = glm::vec3(plane->meanColor[2], plane->meanColor[1], plane->meanColor[0]) / 255.0f;
  out.image = imageFromBgr(plane->image);
  out.sourceFromTexCoord = sourceFromTexCoord(photoFromMetric, widthM, heightM);
  return out;
}

// The part of `full` beyond `inner` (they share three edges): the untextured strip.
Rect stripBeyond(const Rect& full, const Rect& inner) {
  if (full.s0 < inner.s0 - 1e-9) return {full.s0, full.t0, inner.s0, full.t1};
  if (full.s1 > inner.s1 + 1e-9) return {inner.s1, full.t0, full.s1, full.t1};
  if (full.t0 < inner.t0 - 1e-9) return {full.s0, full.t0, full.s1, inner.t0};
  if (full.t1 > inner.t1 + 1e-9) return {full.s0, inner.t1, full.s1, full.t1};
  return {};
}

engine::Material litMaterial(const glm::vec3& diffuse) {
  engine::Material material;
  material.diffuseColor = diffuse;
  material.ambientIntensity = 0.35f;
  material.specularColor = glm::vec3(0.08f);
  material.shininess = 0.15f;
  return material;
}


// A surface's texture laid out depth-major for synthesis (synthesis.h: columns along the
// corridor, the one nearest the camera first) and back. The textures' own layouts
// (rectify.h, surfaces.h): the left wall's columns run from the near end, the right
// wall's towards it; the floor's rows run from the far end down, the ceiling's from the
// near end.
cv::Mat toDepthMajor(const cv::Mat& texture, Surface surface) {
  cv::Mat out;
  switch (surface) {
    case Surface::kLeftWall: out = texture.clone(); break;
    case Surface::kRightWall: cv::flip(texture, out, 1); break;
    case Surface::kFloor: cv::transpose(texture, out), cv::flip(out, out, 1); break;
    default: cv::transpose(texture, out); break;  // ceiling
  }
  return out;
}

cv::Mat fromDepthMajor(const cv::Mat& depthMajor, Surface surface) {
  cv::Mat out;
  switch (surface) {
    case Surface::kLeftWall: out = depthMajor.clone(); break;
    case Surface::kRightWall: cv::flip(depthMajor, out, 1); break;
    case Surface::kFloor: cv::flip(depthMajor, out, 1), cv::transpose(out, out); break;
    default: cv::transpose(depthMajor, out); break;
  }
  return out;
}

// The texel (i, j) of the surface's own texture (W x H) at depth-major (x, y).
glm::dvec2 ownTexel(Surface surface, double x, double y, int width, int height) {
  switch (surface) {
    case Surface::kLeftWall: return {x, y};
    case Surface::kRightWall: return {width - 1 - x, y};
    case Surface::kFloor: return {y, height - 1 - x};
    default: return {y, x};
  }
}

// The same surface's strip from the texture's near edge to `nearM`.
Rect stripTo(Surface surface, const metrology::Dimensions& box, double fromM, double nearM) {
  const Panel inner = surfacePanel(surface, box, fromM), outer = surfacePanel(surface, box, nearM);
  return stripBeyond(outer.extent, inner.extent);
}

// Detail where the photo saw the surface coarsely, and texture where it did not, with
// the surface continued by `extensionM` towards the camera (synthesis.h).
void synthesize(CorridorModel& model, Surface surface, double extensionM, const ModelOptions& options) {
  SurfaceTexture& tex = *model.textures[static_cast<int>(surface)];
  cv::Mat rgba(tex.image.height, tex.image.width, CV_8UC4, tex.image.rgba.data()), bgr;
  cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);
  cv::Mat depthMajor = toDepthMajor(bgr, surface);
  const bool depthAlongS = surface == Surface::kLeftWall || surface == Surface::kRightWall;
  const double depthM = depthAlongS ? tex.rect.s1 - tex.rect.s0 : tex.rect.t1 - tex.rect.t0;
  const int extension =
      extensionM > 0 ? std::clamp(static_cast<int>(std::lround(extensionM * depthMajor.cols / depthM)), 1, kMaxExtensionColumns) : 0;
  // The added columns start in the surface's mean colour (what stays where the photo
  // shows nothing of it to fill them from).
  const glm::vec3& mean = model.meanColor[static_cast<int>(surface)];
  cv::Mat canvas(depthMajor.rows, depthMajor.cols + extension, CV_8UC3,
                 cv::Scalar(255.0 * mean.b, 255.0 * mean.g, 255.0 * mean.r));
  depthMajor.copyTo(canvas(cv::Rect(extension, 0, depthMajor.cols, depthMajor.rows)));
  const glm::mat3 h = tex.sourceFromTexCoord;
  const int w = tex.image.width, ht = tex.image.height;
  const PhotoOfTexel photoOf = [&](double x, double y) -> std::optional<glm::dvec2> {
    if (x < extension - 0.5) return std::nullopt;
    const glm::dvec2 ij = ownTexel(surface, x - extension, y, w, ht);
    const glm::dvec3 p = glm::dmat3(h) * glm::dvec3((ij.x + 0.5) / w, 1.0 - (ij.y + 0.5) / ht, 1.0);
    if (!(p.z > 1e-9)) return std::nullopt;
    return glm::dvec2(p.x / p.z, p.y / p.z);
  };
  cv::Mat detail;
  model.synthesis[static_cast<int>(surface)] = synthesizeSurface(
      canvas, photoOf, cv::Size(model.photoWidth, model.photoHeight), SynthesisOptions{options.detail, true}, &detail);
  const cv::Rect photoPart(extension, 0, depthMajor.cols, depthMajor.rows);
  tex.image = imageFromBgr(fromDepthMajor(canvas(photoPart), surface));
  if (!detail.empty()) {
    cv::Mat codes = fromDepthMajor(detail(photoPart), surface), bgr;
    cv::cvtColor(codes, bgr, cv::COLOR_GRAY2BGR);
    tex.detail = imageFromBgr(bgr);
    tex.detail.grey = true;
  }
  if (extension > 0) {
    SurfaceTexture strip;
    strip.rect = stripTo(surface, model.box, model.photoNearM, model.untexturedNearM);
    strip.image = imageFromBgr(fromDepthMajor(canvas(cv::Rect(0, 0, extension, depthMajor.rows)), surface));
    strip.pxPerM = tex.pxPerM;
    model.extensions[static_cast<int>(surface)] = std::move(strip);
  }
}

// The median of each channel of an engine image (0..1).
glm::vec3 medianColor(const engine::Image& image) {
  std::array<std::vector<uint8_t>, 3> channels;
  const size_t step = std::max<size_t>(1, image.rgba.size() / 4 / 65536);  // a sample is plenty
  for (size_t i = 0; i * 4 < image.rgba.size(); i += step) {
    for (int c = 0; c < 3; ++c) channels[c].push_back(image.rgba[i * 4 + c]);
  }
  glm::vec3 out(0.5f);
  for (int c = 0; c < 3; ++c) {
    if (channels[c].empty()) continue;
    auto mid = channels[c].begin() + channels[c].size() / 2;
    std::nth_element(channels[c].begin(), mid, channels[c].end());
    out[c] = *mid / 255.0f;
  }
  return out;
}

glm::quat toQuat(const glm::dmat3& m) { return glm::normalize(glm::quat(glm::mat3(m))); }

}  // namespace

namespace {

// A name as a file name's part: letters, digits, '-' and '_' kept, anything else '_'.
std::string fileSafe(const std::string& name) {
  std::string out;
  for (unsigned char c : name) out += std::isalnum(c) || c == '-' || c == '_' ? static_cast<char>(c) : '_';
  return out.empty() ? "object" : out;
}

}  // namespace

glm::mat3 sourceFromTexCoord(const cv::Matx33d& photoFromMetric, double widthM, double heightM) {
  // Texture coordinates (0..1 over the rect, t = 0 at the bottom) to the photo's pixels:
  // metric x = s W, y = (1 - t) H.
  const cv::Matx33d photoFromTexCoord = photoFromMetric * cv::Matx33d(widthM, 0, 0, 0, -heightM, heightM, 0, 0, 1);
  glm::mat3 columns;
  for (int c = 0; c < 3; ++c) {
    for (int row = 0; row < 3; ++row) columns[c][row] = static_cast<float>(photoFromTexCoord(row, c) / photoFromTexCoord(2, 2));
  }
  return columns;
}

engine::Image imageFromBgr(const cv::Mat& bgr) {
  cv::Mat rgba;
  cv::cvtColor(bgr, rgba, cv::COLOR_BGR2RGBA);  // a new, continuous matrix
  engine::Image image;
  image.width = rgba.cols;
  image.height = rgba.rows;
  image.rgba.assign(rgba.data, rgba.data + rgba.total() * 4);
  return image;
}

Result<CorridorModel> makeCorridorModel(const std::string& name, const cv::Mat& photo, const Measurement& measurement,
                                        bool attached, const ModelOptions& options) {
  if (photo.empty() || photo.type() != CV_8UC3) return makeError(name + ": the photo must be an 8-bit colour image");
  CorridorModel model;
  model.name = name;
  model.measurement = measurement;
  model.photoWidth = photo.cols;
  model.photoHeight = photo.rows;
  model.box = measurement.size;
  const double cameraZ = measurement.pose.positionM.z;
  if (!attached && cameraZ > 0) {
    model.photoNearM = photoNearExtent(measurement, model.box, photo.cols, photo.rows);
    model.untexturedNearM = std::max(model.photoNearM, cameraZ + (options.photoOnly ? kBehindCameraM : kClosedBehindCameraM));
    model.closed = !options.photoOnly;
  }
  metrology::PhotoPyramid pyramid(photo, measurement.camera);  // through the lens's distortion
  for (int s = 0; s < kFaces; ++s) {
    const Surface surface = static_cast<Surface>(s);
    const Panel panel = surfacePanel(surface, model.box, model.photoNearM);
    auto texture = cutTexture(pyramid, measurement, surface, panel, options, model.meanColor[s]);
    if (!texture) return makeError(name + ": " + texture.message());
    model.textures[s] = std::move(*texture);
  }
  if (!options.photoOnly) {
    // The four surfaces are independent: one thread each (OpenCV's pool).
    const Surface surfaces[] = {Surface::kLeftWall, Surface::kRightWall, Surface::kFloor, Surface::kCeiling};
    cv::parallel_for_(cv::Range(0, 4), [&](const cv::Range& range) {
      for (int i = range.start; i < range.end; ++i) synthesize(model, surfaces[i], model.untexturedNearM - model.photoNearM, options);
    });
    model.nearEndColor = medianColor(model.textures[0]->image);
  }
  return model;
}

Result<CorridorModel> makeCorridorModel(const std::string& name, const cv::Mat& photo, const Measurement& measurement,
                                        const std::vector<metrology::Cutout>& cutouts, bool attached,
                                        const ModelOptions& options) {
  std::vector<metrology::Cutout> objects, openings;
  for (const metrology::Cutout& cutout : cutouts) {
    (cutout.shape == metrology::CutoutShape::kOpening ? openings : objects).push_back(cutout);
  }
  if (cutouts.empty()) return makeCorridorModel(name, photo, measurement, attached, options);
  Result<StoodUp> stood = StoodUp{{}, photo};
  if (!objects.empty()) stood = standUpObjects(photo, measurement, objects, options.cutOutCache);
  if (!stood) return makeError(name + ": " + stood.message());
  auto model = makeCorridorModel(name, stood->behind, measurement, attached, options);
  if (!model) return model;
  model->standing = std::move(stood->objects);
  model->leftPainted = std::move(stood->leftPainted);
  if (openings.empty()) return model;
  const auto colourOf = [&](Surface s) { return model->meanColor[static_cast<int>(s)]; };
  const RoomColours colours{colourOf(Surface::kLeftWall), colourOf(Surface::kRightWall), colourOf(Surface::kFloor)};
  auto rooms = openSideRooms(photo, measurement, openings, model->untexturedNearM, colours);
  if (!rooms) return makeError(name + ": " + rooms.message());
  model->rooms = std::move(*rooms);
  return model;
}

engine::Camera photoCamera(const Measurement& m, int imageWidth, int imageHeight, const glm::dmat4& worldFromCorridor) {
  engine::Camera camera;
  camera.position = glm::vec3(apply(worldFromCorridor, m.pose.positionM));
  camera.orientation = toQuat(glm::dmat3(worldFromCorridor) * m.pose.worldFromCamera);
  // metrology's camera has square pixels: one focal length for both axes.
  camera.intrinsics = engine::Intrinsics{m.camera.focalPx,           m.camera.focalPx, m.camera.principalPointPx.x,
                                         m.camera.principalPointPx.y, imageWidth,       imageHeight};
  camera.fieldOfViewRad = engine::fieldOfViewOf(*camera.intrinsics);
  return camera;
}

// The info line of a cutout left painted: this, then its reason (StoodUp::leftPainted,
// which starts "cutout "NAME": ").
const std::string kLeftPaintedInfo = "left painted: ";

std::optional<std::string> leftPaintedReason(const engine::Scene& scene, const std::string& cutoutName) {
  const std::string prefix = kLeftPaintedInfo + "cutout \"" + cutoutName + "\": ";
  for (const std::string& line : scene.info) {
    if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
  }
  return std::nullopt;
}

engine::Scene makeBuildingScene(const std::vector<CorridorModel>& corridors, const BuildingPlan& plan,
                                const ModelOptions& options) {
  engine::Scene scene;
  scene.title = corridors.size() == 1 ? "photowalk: " + corridors[0].name
                                      : "photowalk: building of " + std::to_string(corridors.size()) + " corridors";
  scene.backgroundColor = glm::vec3(0.0f);

  // Lit: 1 m cells, so that viewers and renderers that light per vertex (Gouraud,
  // as VRML97 browsers did; photowalk walk on a CPU) show each lamp's pool of light.
  const double cellM = options.lit ? 1.0 : 0.0;
  for (size_t c = 0; c < corridors.size(); ++c) {
    const CorridorModel& model = corridors[c];
    const glm::mat4 transform(plan.worldFromCorridor[c]);
    const auto openingsOf = [&](Surface surface) {
      std::vector<Rect> rects;
      for (const Opening& o : plan.openings) {
        if (o.corridor == static_cast<int>(c) && o.surface == surface) rects.push_back(o.rect);
      }
      for (const SideRoom& room : model.rooms) {
        if (room.wall == surface) rects.push_back(room.opening);
      }
      return rects;
    };
    const auto addShape = [&](engine::Mesh mesh, std::shared_ptr<const engine::Appearance> appearance,
                              const std::string& label) {
      if (mesh.indices.empty()) return;
      scene.shapes.push_back({std::make_shared<engine::Mesh>(std::move(mesh)), std::move(appearance), transform,
                              model.name + "_" + label});
    };
    // A texture cut from the photo (clamped: a repeat would bleed the opposite edge into
    // the seams between planes); `source`: how the photo saw it, where it did.
    const auto photoAppearance = [&](const engine::Image& image, const std::string& url, const std::optional<glm::mat3>& source,
                              const engine::Image* detail = nullptr) {
      auto texture = std::make_shared<engine::Texture>();
      texture->image = std::make_shared<engine::Image>(image);
      texture->url = url;
      texture->wrapS = texture->wrapT = engine::TextureWrap::kClamp;
      if (source) texture->sourceFromTexCoord = *source;
      if (detail && !detail->empty()) texture->detail = std::make_shared<engine::Image>(*detail);
      auto appearance = std::make_shared<engine::Appearance>();
      appearance->texture = texture;
      if (options.lit) appearance->material = litMaterial(glm::vec3(1.0f));
      return appearance;
    };
    const auto untextured = [&](const glm::vec3& color) {
      auto appearance = std::make_shared<engine::Appearance>();
      if (options.lit) appearance->material = litMaterial(color);
      return appearance;
    };

    for (int s = 0; s < kFaces; ++s) {
      const Surface surface = static_cast<Surface>(s);
      const SurfaceTexture& tex = *model.textures[s];
      Panel textured = surfacePanel(surface, model.box, model.photoNearM);
      textured.textureRect = tex.rect;
      textured.openings = openingsOf(surface);
      textured.maxCellM = cellM;
      addShape(panelMesh(textured),
               photoAppearance(tex.image, model.name + "_" + surfaceName(surface) + ".png", tex.sourceFromTexCoord, &tex.detail),
               surfaceName(surface));

      if (const auto& extension = model.extensions[s]) {
        Panel strip = surfacePanel(surface, model.box, model.untexturedNearM);
        strip.extent = extension->rect;
        strip.textureRect = extension->rect;
        strip.openings = textured.openings;
        strip.maxCellM = cellM;
        addShape(panelMesh(strip),
                 photoAppearance(extension->image, model.name + "_" + surfaceName(surface) + "_near.png", std::nullopt),
                 std::string(surfaceName(surface)) + "_near");
      } else if (model.untexturedNearM > model.photoNearM) {
        Panel strip = surfacePanel(surface, model.box, model.untexturedNearM);
        strip.extent = stripBeyond(strip.extent, textured.extent);
        strip.openings = textured.openings;
        strip.maxCellM = cellM;
        if (!strip.extent.empty()) {
          const glm::vec4 color(model.meanColor[s], 1.0f);
          addShape(panelMesh(strip, options.lit ? std::nullopt : std::optional(color)), untextured(model.meanColor[s]),
                   std::string(surfaceName(surface)) + "_near");
        }
      }
    }
    // Objects stood up: a vertical cut-out on the floor or a box, each face the photo sees
    // textured with the photo, the others with the object's colour, all with the object's
    // mask as alpha, seen from both sides.
    for (const StandingObject& object : model.standing) {
      const std::string label = "standing_" + fileSafe(object.name);
      static constexpr const char* kFaceNames[] = {"front", "back", "left", "right", "top"};
      for (size_t f = 0; f < object.faces.size(); ++f) {
        const StandingFace& face = object.faces[f];
        const std::string faceLabel =
            object.shape == metrology::CutoutShape::kBox ? label + "_" + kFaceNames[std::min<size_t>(f, 4)] : label;
        engine::Mesh mesh;
        for (const glm::dvec3& corner : face.cornersM) mesh.positions.emplace_back(corner);
        mesh.normals.assign(4, glm::vec3(face.normal));
        mesh.indices = {0, 1, 2, 0, 2, 3};
        mesh.solid = false;
        mesh.texCoords = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
        addShape(std::move(mesh),
                 photoAppearance(face.image, model.name + "_" + faceLabel + ".png",
                                 face.photo ? std::optional(face.sourceFromTexCoord) : std::nullopt),
                 faceLabel);
      }
      char line[480];
      if (object.shape == metrology::CutoutShape::kBox) {
        char depth[96];
        if (object.depthSeen) {
          std::snprintf(depth, sizeof depth, "its depth \u00b1 %.2f m", object.depthSigmaM);
        } else {
          std::snprintf(depth, sizeof depth, "its depth not seen in the photo (its side edge on), a cabinet's taken");
        }
        std::snprintf(line, sizeof line,
                      "stood up: %s (%s_%s_*), a box %.2f m wide, %.2f m deep and %.2f m high (%s) on the floor at x "
                      "%.2f m, z %.2f m, %.2f m from the photo's camera",
                      object.name.c_str(), model.name.c_str(), label.c_str(), object.widthM, object.depthM, object.heightM,
                      depth, object.footM.x, object.footM.z, object.distanceM);
      } else if (object.shape == metrology::CutoutShape::kHanging) {
        std::snprintf(line, sizeof line,
                      "stood up: %s (%s_%s), a cut-out %.2f m wide and %.2f m high hanging from the ceiling above x %.2f m, "
                      "z %.2f m, %.2f m from the photo's camera",
                      object.name.c_str(), model.name.c_str(), label.c_str(), object.widthM, object.heightM,
                      object.footM.x, object.footM.z, object.distanceM);
      } else {
        std::snprintf(line, sizeof line,
                      "stood up: %s (%s_%s), a cut-out %.2f m wide and %.2f m high on the floor at x %.2f m, z %.2f m, "
                      "%.2f m from the photo's camera",
                      object.name.c_str(), model.name.c_str(), label.c_str(), object.widthM, object.heightM,
                      object.footM.x, object.footM.z, object.distanceM);
      }
      scene.info.push_back(line);
    }
    for (const std::string& reason : model.leftPainted) scene.info.push_back(kLeftPaintedInfo + reason);
    // Side openings: the room behind each, its surfaces textured where the photo sees
    // them through the opening.
    for (const SideRoom& room : model.rooms) {
      const std::string label = "room_" + fileSafe(room.name);
      for (const RoomPanel& part : room.panels) {
        Panel panel = part.panel;
        panel.maxCellM = cellM;
        if (part.image.empty()) {
          const glm::vec4 color(part.colour, 1.0f);
          addShape(panelMesh(panel, options.lit ? std::nullopt : std::optional(color)), untextured(part.colour),
                   label + "_" + part.label);
          continue;
        }
        addShape(panelMesh(panel),
                 photoAppearance(part.image, model.name + "_" + label + "_" + part.label + ".png", part.sourceFromTexCoord),
                 label + "_" + part.label);
      }
      char line[400];
      const Rect& o = room.opening;
      std::snprintf(line, sizeof line,
                    "opened: %s (%s_%s_*), an opening %.2f m wide and %.2f m high in the %s, %.2f m above the floor, "
                    "with a room behind it %.1f m deep (taken: the photo does not show it)",
                    room.name.c_str(), model.name.c_str(), label.c_str(), o.s1 - o.s0, o.t1 - o.t0,
                    room.wall == Surface::kLeftWall ? "left wall" : "right wall", o.t0, room.depthM);
      scene.info.push_back(line);
    }
    // Which parts are synthesized, for people and other viewers (WorldInfo info text).
    for (int s = 1; s < kFaces; ++s) {
      const SynthesisStats& st = model.synthesis[s];
      const std::string texture = model.name + "_" + surfaceName(static_cast<Surface>(s));
      if (st.detailFraction > 0 || st.filledFraction > 0) {
        char line[256];
        std::snprintf(line, sizeof line,
                      "synthesized: %s: detail added to %.0f%% of the texels (the photo saw them coarsely), "
                      "%.0f%% filled (the photo did not see them)",
                      texture.c_str(), 100 * st.detailFraction, 100 * st.filledFraction);
        scene.info.push_back(line);
      }
      if (model.extensions[s]) scene.info.push_back("synthesized: " + texture + "_near, all of it (the photo did not see it)");
    }
    if (model.closed && !plan.attached[c]) {
      scene.info.push_back("synthesized: " + model.name + "_near_end, the wall closing the corridor " +
                           std::to_string(static_cast<int>(std::lround(kClosedBehindCameraM))) +
                           " m behind the photo's camera, in the far wall's colour");
    }
    if (model.closed && !plan.attached[c]) {  // the wall closing the corridor behind the camera
      Panel nearEnd = surfacePanel(Surface::kNearEnd, model.box);
      nearEnd.origin.z = model.untexturedNearM;
      nearEnd.maxCellM = cellM;
      const glm::vec4 color(model.nearEndColor, 1.0f);
      addShape(panelMesh(nearEnd, options.lit ? std::nullopt : std::optional(color)), untextured(model.nearEndColor),
               "near_end");
    }
    if (plan.attached[c]) {  // close the near end around the opening into the host
      Panel nearEnd = surfacePanel(Surface::kNearEnd, model.box);
      nearEnd.openings = openingsOf(Surface::kNearEnd);
      nearEnd.maxCellM = cellM;
      const glm::vec4 color(model.meanColor[0], 1.0f);
      addShape(panelMesh(nearEnd, options.lit ? std::nullopt : std::optional(color)), untextured(model.meanColor[0]),
               "near_end");
    }

    if (options.lit) {  // the seed paper's rendering step: lights along the ceiling
      const int count = std::max(1, static_cast<int>(std::round(model.box.lengthM / 4.0)));
      for (int i = 0; i < count; ++i) {
        engine::Light light;
        light.type = engine::LightType::kPoint;
        light.intensity = 0.8f;
        light.ambientIntensity = 0.25f;
        light.attenuation = {1.0f, 0.0f, 0.06f};
        light.radius = static_cast<float>(std::max(8.0, 3.0 * model.box.heightM));
        light.position = glm::vec3(apply(plan.worldFromCorridor[c],
                                         {0.0, model.box.heightM - 0.25, -model.box.lengthM * (i + 0.5) / count}));
        scene.lights.push_back(light);
      }
    }
  }

  // Viewpoints: the photo's camera first, then a person's views of the first corridor,
  // then the other corridors' photo cameras.
  const CorridorModel& first = corridors.front();
  const glm::dmat4& firstWorld = plan.worldFromCorridor.front();
  const Measurement& m0 = first.measurement;
  const float eye = static_cast<float>(m0.cameraHeightM);
  const auto addViewpoint = [&](const std::string& description, const glm::dvec3& positionLocal, double yawRad,
                                double pitchRad, float fov, const glm::dmat4& world) {
    engine::Camera camera;
    camera.position = glm::vec3(apply(world, positionLocal));
    const glm::dmat3 rotation = glm::dmat3(world) * glm::dmat3(glm::mat3_cast(glm::angleAxis(yawRad, glm::dvec3(0, 1, 0)) *
                                                                                glm::angleAxis(pitchRad, glm::dvec3(1, 0, 0))));
    camera.orientation = toQuat(rotation);
    camera.fieldOfViewRad = fov;
    scene.viewpoints.push_back(engine::viewpointFromCamera(camera, description));
  };
  // The Photo viewpoint keeps the photo's exact lens (principal point included); the
  // others look through the same field of view, centred.
  const engine::Camera photo = photoCamera(m0, first.photoWidth, first.photoHeight, firstWorld);
  const float photoFov = photo.fieldOfViewRad;
  scene.viewpoints.push_back(engine::viewpointFromCamera(photo, "Photo"));
  const double entranceZ = std::max(0.0, std::min(m0.pose.positionM.z, first.untexturedNearM - 0.5));
  addViewpoint("Entrance", {0, eye, entranceZ}, 0, 0, photoFov, firstWorld);
  addViewpoint("Far end looking back", {0, eye, -std::max(0.5, first.box.lengthM - 1.0)}, glm::pi<double>(), 0, photoFov,
               firstWorld);
  {
    // Overview: a cutaway from above. The eye is over the first corridor's centre line,
    // behind its near end and above every ceiling, looking down at the building's
    // centre. Faces are one-sided (seen only from inside), so from there the ceiling
    // and any wall seen from behind are not drawn, and the floor, both walls of the
    // first corridor, its far wall and every wall facing the eye show, as in an
    // architect's cutaway. The eye is as near as it can be with every corner of the
    // building's bounds inside the field of view (a cone: any frame's shape).
    const engine::Bounds bounds = engine::sceneBounds(scene);
    const glm::dmat4 corridorFromWorld = glm::inverse(firstWorld);
    std::vector<glm::dvec3> corners;
    double top = -std::numeric_limits<double>::max();
    for (int i = 0; i < 8; ++i) {
      const glm::dvec3 p(i & 1 ? bounds.max.x : bounds.min.x, i & 2 ? bounds.max.y : bounds.min.y,
                         i & 4 ? bounds.max.z : bounds.min.z);
      corners.push_back(glm::dvec3(corridorFromWorld * glm::dvec4(p, 1.0)));
      top = std::max(top, corners.back().y);
    }
    const glm::dvec3 centre = glm::dvec3(corridorFromWorld * glm::dvec4(glm::dvec3(bounds.center()), 1.0));
    const double halfFov = 0.5 * glm::radians(kOverviewFieldOfViewDeg);
    const double elevation = glm::radians(kOverviewElevationDeg);
    const glm::dvec3 target(0.0, centre.y, centre.z);
    const glm::dvec3 back(0.0, std::sin(elevation), std::cos(elevation));  // from the target to the eye
    const auto fits = [&](double distance) {
      const glm::dvec3 eye = target + distance * back;
      if (eye.y < top + 0.5) return false;  // above every ceiling, so none hides the floor
      for (const glm::dvec3& c : corners) {
        if (glm::dot(glm::normalize(c - eye), -back) < std::cos(halfFov)) return false;
      }
      return true;
    };
    double near = 0, far = 1.0;
    while (!fits(far) && far < 1e6) far *= 2;
    for (int i = 0; i < 40; ++i) (fits(0.5 * (near + far)) ? far : near) = 0.5 * (near + far);
    const glm::dvec3 eyeLocal = target + far * back;
    const double fov = 2 * halfFov;
    engine::Camera camera;
    camera.position = glm::vec3(apply(firstWorld, eyeLocal));
    camera.orientation = engine::lookAtOrientation(camera.position, glm::vec3(apply(firstWorld, target)));
    camera.fieldOfViewRad = static_cast<float>(fov);
    scene.viewpoints.push_back(engine::viewpointFromCamera(camera, "Overview"));
  }
  for (size_t c = 1; c < corridors.size(); ++c) {
    addViewpoint(corridors[c].name + ": entrance", {0, corridors[c].measurement.cameraHeightM, 0}, 0, 0, photoFov,
                 plan.worldFromCorridor[c]);
  }

  scene.navigation.headlight = options.lit;
  scene.navigation.type = {"WALK", "ANY"};
  scene.navigation.avatarHeightM = eye;
  scene.navigation.avatarRadiusM = 0.25f;
  scene.navigation.stepHeightM = std::min(0.4f, 0.25f * eye);
  scene.navigation.speedMps = 1.4f;
  return scene;
}

}  // namespace pw::modeling
