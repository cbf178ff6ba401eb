#include "modeling/corridor_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <opencv2/imgproc.hpp>

#include "modeling/panel.h"

namespace pw::modeling {
namespace {

using metrology::Measurement;

constexpr double kBehindCameraM = 1.0;  // untextured surfaces run on this far behind the eye
constexpr int kFaces = 5;               // far wall, left, right, floor, ceiling (Surface 0..4)

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

// The 3x3 map from a surface's (s, t, 1) to homogeneous photo pixels (u w, v w, w),
// w the depth in front of the camera: the plane homography of the measured camera.
cv::Matx33d planeToPhoto(const Measurement& m, const Panel& panel) {
  const glm::dmat3 cameraFromWorld = glm::transpose(m.pose.worldFromCamera);
  const glm::dvec3 sc = cameraFromWorld * panel.sAxis;
  const glm::dvec3 tc = cameraFromWorld * panel.tAxis;
  const glm::dvec3 oc = cameraFromWorld * (panel.origin - m.pose.positionM);
  const double f = m.camera.focalPx, cu = m.camera.principalPointPx.x, cv = m.camera.principalPointPx.y;
  // Camera looks along -Z, image v grows downwards: u w = f x - cu z, v w = -f y - cv z, w = -z.
  const cv::Matx33d k(f, 0, -cu, 0, -f, -cv, 0, 0, -1);
  const cv::Matx33d columns(sc.x, tc.x, oc.x, sc.y, tc.y, oc.y, sc.z, tc.z, oc.z);
  return k * columns;
}

// Photo pixels per metre on the surface at (s, t) along s and along t.
glm::dvec2 localScale(const cv::Matx33d& h, double s, double t) {
  const auto project = [&](double ss, double tt) {
    const cv::Vec3d p = h * cv::Vec3d(ss, tt, 1.0);
    return cv::Vec2d(p[0] / p[2], p[1] / p[2]);
  };
  const double d = 1e-3;
  const cv::Vec2d p = project(s, t);
  return glm::dvec2(cv::norm(project(s + d, t) - p), cv::norm(project(s, t + d) - p)) / d;
}

bool visibleInPhoto(const cv::Matx33d& h, double s, double t, int width, int height) {
  const cv::Vec3d p = h * cv::Vec3d(s, t, 1.0);
  if (p[2] <= 1e-3) return false;
  const double u = p[0] / p[2], v = p[1] / p[2];
  return u >= -0.5 && u <= width - 0.5 && v >= -0.5 && v <= height - 0.5;
}

// How far beyond the near end (z > 0) the photo still shows some of the floor, walls
// or ceiling: scanned in 2 cm steps towards the camera.
double photoNearExtent(const Measurement& m, const CorridorBox& box, int width, int height) {
  const double cameraZ = m.pose.positionM.z;
  double best = 0;
  for (int surface = 1; surface < kFaces; ++surface) {
    const Panel full = surfacePanel(static_cast<Surface>(surface), box, std::max(0.0, cameraZ));
    const cv::Matx33d h = planeToPhoto(m, full);
    for (double z = 0.02; z < cameraZ - 0.05; z += 0.02) {
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
        any = visibleInPhoto(h, s, t, width, height);
      }
      if (!any) break;
      best = std::max(best, z);
    }
  }
  return best;
}

engine::Image toImage(const cv::Mat& bgr) {
  cv::Mat rgba;
  cv::cvtColor(bgr, rgba, cv::COLOR_BGR2RGBA);
  engine::Image image;
  image.width = rgba.cols;
  image.height = rgba.rows;
  image.rgba.assign(rgba.data, rgba.data + rgba.total() * 4);
  return image;
}

// The photo at full size and halved again and again (Gaussian pyramid): a texture
// coarser than the photo is cut from the level nearest its resolution, so shrinking
// neither aliases nor costs a warp at the photo's full resolution.
std::vector<cv::Mat> photoPyramid(const cv::Mat& photo) {
  std::vector<cv::Mat> levels{photo};
  while (levels.size() < 6 && std::min(levels.back().cols, levels.back().rows) > 256) {
    cv::Mat next;
    cv::pyrDown(levels.back(), next);
    levels.push_back(next);
  }
  return levels;
}

// Cuts one surface's texture out of the photo; fills what the photo does not show
// with the mean colour of what it does.
SurfaceTexture cutTexture(const std::vector<cv::Mat>& pyramid, const Measurement& m, const Panel& panel,
                          const ModelOptions& options, glm::vec3& meanColor) {
  const cv::Mat& photo = pyramid.front();
  SurfaceTexture out;
  out.rect = panel.extent;
  const Rect& r = panel.extent;
  const double widthM = r.s1 - r.s0, heightM = r.t1 - r.t0;
  const cv::Matx33d h = planeToPhoto(m, panel);

  // The photo's own best resolution along s and along t on the part of the surface it
  // shows, and its least (for the pyramid level).
  glm::dvec2 photoScale(0.0), leastScale(std::numeric_limits<double>::max());
  for (int j = 0; j <= 24; ++j) {
    for (int i = 0; i <= 24; ++i) {
      const double s = r.s0 + widthM * i / 24.0, t = r.t0 + heightM * j / 24.0;
      if (!visibleInPhoto(h, s, t, photo.cols, photo.rows)) continue;
      const glm::dvec2 scale = localScale(h, s, t);
      photoScale = glm::max(photoScale, scale);
      leastScale = glm::min(leastScale, scale);
    }
  }
  if (photoScale.x == 0) leastScale = photoScale;
  // Each axis has the photo's best density along it: a wall seen at a grazing angle has
  // far more photo pixels per metre up than along, so texels need not be square (the
  // geometry, not the image, carries the scale) and no detail the photo has is lost.
  glm::dvec2 density = options.pxPerM > 0 ? glm::dvec2(options.pxPerM) : glm::max(photoScale, glm::dvec2(16.0));
  density = glm::min(density, glm::dvec2(options.maxTextureSide / widthM, options.maxTextureSide / heightM));
  const double texels = density.x * widthM * density.y * heightM;
  if (texels > options.maxTexturePixels) density *= std::sqrt(options.maxTexturePixels / texels);
  out.pxPerM = std::min(density.x, density.y);
  const int texW = std::max(2, static_cast<int>(std::lround(widthM * density.x)));
  const int texH = std::max(2, static_cast<int>(std::lround(heightM * density.y)));

  // Pyramid level L holds pixel centres at (u + 0.5) / 2^L - 0.5. The photo's scale
  // varies over the plane; a level coarser than the texture where the photo is at
  // its coarsest would lose detail there, so the level follows the least scale seen.
  const double shrink = std::min(leastScale.x / density.x, leastScale.y / density.y);
  const int level = std::clamp(static_cast<int>(std::floor(std::log2(std::max(1.0, shrink)))), 0,
                               static_cast<int>(pyramid.size()) - 1);
  const double k = 1.0 / (1 << level);
  const cv::Matx33d toLevel(k, 0, 0.5 * k - 0.5, 0, k, 0.5 * k - 0.5, 0, 0, 1);
  // Texture pixel (x, y) -> (s, t): pixel centres, rows top (t1) to bottom (t0).
  const cv::Matx33d pixelToPlane(widthM / texW, 0, r.s0 + 0.5 * widthM / texW, 0, -heightM / texH,
                                 r.t1 - 0.5 * heightM / texH, 0, 0, 1);
  const cv::Matx33d pixelToPhoto = toLevel * h * pixelToPlane;
  const cv::Mat& source = pyramid[level];

  cv::Mat warped, inside;
  // Bicubic: the renderer resamples the texture once more (bilinear, mipmapped), and
  // two bilinear steps in a row blur thin lines (mortar, tile joints) visibly.
  cv::warpPerspective(source, warped, cv::Mat(pixelToPhoto), {texW, texH}, cv::INTER_CUBIC | cv::WARP_INVERSE_MAP,
                      cv::BORDER_REPLICATE);
  cv::warpPerspective(cv::Mat(source.size(), CV_8U, cv::Scalar(255)), inside, cv::Mat(pixelToPhoto), {texW, texH},
                      cv::INTER_NEAREST | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, cv::Scalar(0));
  // Texels behind the camera map through the homography with w < 0: never valid. w is
  // affine in (x, y), so it is positive everywhere when it is at the four corners.
  const auto w = [&](double x, double y) { return pixelToPhoto(2, 0) * x + pixelToPhoto(2, 1) * y + pixelToPhoto(2, 2); };
  if (std::min({w(0, 0), w(texW - 1, 0), w(0, texH - 1), w(texW - 1, texH - 1)}) <= 1e-6) {
    for (int y = 0; y < texH; ++y) {
      uint8_t* row = inside.ptr<uint8_t>(y);
      for (int x = 0; x < texW; ++x) {
        if (w(x, y) <= 1e-6) row[x] = 0;
      }
    }
  }
  const int covered = cv::countNonZero(inside);
  out.coveredFraction = static_cast<double>(covered) / (texW * texH);
  const cv::Scalar mean = covered > 0 ? cv::mean(warped, inside) : cv::Scalar(128, 128, 128);
  meanColor = glm::vec3(mean[2], mean[1], mean[0]) / 255.0f;
  warped.setTo(mean, ~inside);
  out.image = toImage(warped);
  // Texture coordinates (0..1 over the rect) to the photo's full-resolution pixels.
  const cv::Matx33d photoFromTexCoord = h * cv::Matx33d(widthM, 0, r.s0, 0, heightM, r.t0, 0, 0, 1);
  glm::mat3 columns;
  for (int c = 0; c < 3; ++c) {
    for (int row = 0; row < 3; ++row) columns[c][row] = static_cast<float>(photoFromTexCoord(row, c) / photoFromTexCoord(2, 2));
  }
  out.sourceFromTexCoord = columns;
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

glm::quat toQuat(const glm::dmat3& m) { return glm::normalize(glm::quat(glm::mat3(m))); }

}  // namespace

Result<CorridorModel> makeCorridorModel(const std::string& name, const cv::Mat& photo, const Measurement& measurement,
                                        bool attached, const ModelOptions& options) {
  if (photo.empty() || photo.type() != CV_8UC3) return makeError(name + ": the photo must be an 8-bit colour image");
  CorridorModel model;
  model.name = name;
  model.measurement = measurement;
  model.photoWidth = photo.cols;
  model.photoHeight = photo.rows;
  model.box = {measurement.size.widthM, measurement.size.heightM, measurement.size.lengthM};
  const double cameraZ = measurement.pose.positionM.z;
  if (!attached && cameraZ > 0) {
    model.photoNearM = photoNearExtent(measurement, model.box, photo.cols, photo.rows);
    model.untexturedNearM = std::max(model.photoNearM, cameraZ + kBehindCameraM);
  }
  const std::vector<cv::Mat> pyramid = photoPyramid(photo);
  for (int surface = 0; surface < kFaces; ++surface) {
    const Panel panel = surfacePanel(static_cast<Surface>(surface), model.box, model.photoNearM);
    model.textures[surface] = cutTexture(pyramid, measurement, panel, options, model.meanColor[surface]);
  }
  return model;
}

engine::Camera photoCamera(const Measurement& m, const glm::dmat4& worldFromCorridor) {
  engine::Camera camera;
  camera.position = glm::vec3(apply(worldFromCorridor, m.pose.positionM));
  camera.orientation = toQuat(glm::dmat3(worldFromCorridor) * m.pose.worldFromCamera);
  camera.intrinsics = engine::Intrinsics{m.camera.focalPx, m.camera.focalPx, m.camera.principalPointPx.x,
                                         m.camera.principalPointPx.y};
  return camera;
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
      return rects;
    };
    const auto addShape = [&](engine::Mesh mesh, std::shared_ptr<const engine::Appearance> appearance,
                              const std::string& label) {
      if (mesh.indices.empty()) return;
      scene.shapes.push_back({std::make_shared<engine::Mesh>(std::move(mesh)), std::move(appearance), transform,
                              model.name + "_" + label});
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
      auto texture = std::make_shared<engine::Texture>();
      texture->image = std::make_shared<engine::Image>(tex.image);
      texture->url = model.name + "_" + surfaceName(surface) + ".png";
      // Clamp: a repeat would bleed the opposite edge into the seams between planes.
      texture->wrapS = texture->wrapT = engine::TextureWrap::kClamp;
      texture->sourceFromTexCoord = tex.sourceFromTexCoord;
      auto appearance = std::make_shared<engine::Appearance>();
      appearance->texture = texture;
      if (options.lit) appearance->material = litMaterial(glm::vec3(1.0f));
      addShape(panelMesh(textured), appearance, surfaceName(surface));

      if (model.untexturedNearM > model.photoNearM) {
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
  const auto fovOf = [](const CorridorModel& model, int width, int height) {
    return static_cast<float>(2.0 * std::atan(0.5 * std::min(width, height) / model.measurement.camera.focalPx));
  };
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
  const float photoFov = fovOf(first, first.photoWidth, first.photoHeight);
  {
    engine::Camera camera = photoCamera(m0, firstWorld);
    camera.fieldOfViewRad = photoFov;
    scene.viewpoints.push_back(engine::viewpointFromCamera(camera, "Photo"));
  }
  const double entranceZ = std::max(0.0, std::min(m0.pose.positionM.z, first.untexturedNearM - 0.5));
  addViewpoint("Entrance", {0, eye, entranceZ}, 0, 0, photoFov, firstWorld);
  addViewpoint("Far end looking back", {0, eye, -std::max(0.5, first.box.lengthM - 1.0)}, glm::pi<double>(), 0, photoFov,
               firstWorld);
  {
    const engine::Bounds bounds = engine::sceneBounds(scene);
    const glm::vec3 centre = bounds.center();
    const float radius = 0.5f * glm::length(bounds.size());
    // Above and behind the entrance, looking down the building; the ceiling and the
    // near walls face inwards, so from outside they do not hide the inside.
    const glm::vec3 eyePos = glm::vec3(apply(firstWorld, {0, 0, 0})) +
                             glm::vec3(glm::dmat3(firstWorld) * glm::dvec3(0.35 * radius, 1.1 * radius, 0.9 * radius));
    engine::Camera camera;
    camera.position = eyePos;
    camera.orientation = engine::lookAtOrientation(eyePos, centre);
    camera.fieldOfViewRad = glm::radians(60.0f);
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
