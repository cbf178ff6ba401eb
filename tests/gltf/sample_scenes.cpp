#include "tests/gltf/sample_scenes.h"

#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace pw::engine::samples {

namespace {

Mesh quad(float widthM, float heightM) {
  Mesh m;
  m.positions = {{0, 0, 0}, {widthM, 0, 0}, {widthM, heightM, 0}, {0, heightM, 0}};
  m.normals.assign(4, {0, 0, 1});
  m.texCoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

Mesh box(const glm::vec3& size) {
  Mesh m;
  // Six faces, four vertices each, split so that every face has its own normal.
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      const glm::vec3 n = axes[axis] * sign;
      const glm::vec3 u = axes[(axis + 1) % 3] * sign;
      const glm::vec3 v = axes[(axis + 2) % 3];
      const uint32_t base = static_cast<uint32_t>(m.positions.size());
      for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        m.positions.push_back(0.5f * size * (n + c.x * u + c.y * v));
        m.normals.push_back(n);
        m.texCoords.push_back(0.5f * (c + 1.0f));
      }
      m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  }
  return m;
}

Shape shapeOf(Mesh mesh, std::shared_ptr<const Appearance> appearance, std::string name,
              const glm::mat4& transform = glm::mat4(1.0f)) {
  Shape s;
  s.mesh = std::make_shared<Mesh>(std::move(mesh));
  s.appearance = std::move(appearance);
  s.name = std::move(name);
  s.transform = transform;
  return s;
}

}  // namespace

Image gradientImage() {
  Image image = makeImage(4, 2);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; ++x) {
      uint8_t* p = image.pixel(x, y);
      p[0] = uint8_t(40 * x + 10);
      p[1] = uint8_t(60 * y + 20);
      p[2] = uint8_t(200 - 30 * x);
      p[3] = 255;
    }
  }
  return image;
}

Scene texturedQuad() {
  auto texture = std::make_shared<Texture>();
  texture->image = std::make_shared<Image>(gradientImage());
  texture->url = "textures/far_wall.png";
  texture->wrapS = TextureWrap::kClamp;
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = texture;
  Mesh m = quad(2, 1);
  m.solid = false;
  Scene scene;
  scene.shapes.push_back(shapeOf(std::move(m), appearance, "far_wall"));
  return scene;
}

Scene litBox() {
  Material material;
  material.diffuseColor = {0.8f, 0.2f, 0.1f};
  material.shininess = 0.5f;
  material.emissiveColor = {0.1f, 0.0f, 0.0f};
  auto appearance = std::make_shared<Appearance>();
  appearance->material = material;
  Scene scene;
  scene.shapes.push_back(shapeOf(box({1, 2, 3}), appearance, "box",
                                 glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, -2))));
  return scene;
}

Scene transparentQuad() {
  Material material;
  material.diffuseColor = {0.2f, 0.4f, 0.9f};
  material.transparency = 0.4f;
  auto appearance = std::make_shared<Appearance>();
  appearance->material = material;
  Scene scene;
  scene.shapes.push_back(shapeOf(quad(1, 1), appearance, "glass"));
  return scene;
}

Scene sharedMesh() {
  auto mesh = std::make_shared<Mesh>(box({1, 1, 1}));
  auto red = std::make_shared<Appearance>();
  red->material = Material{};
  red->material->diffuseColor = {1, 0, 0};
  auto alsoRed = std::make_shared<Appearance>(*red);  // equal content, another object
  auto green = std::make_shared<Appearance>();
  green->material = Material{};
  green->material->diffuseColor = {0, 1, 0};
  Scene scene;
  auto add = [&](std::shared_ptr<const Appearance> appearance, std::string name, const glm::mat4& transform) {
    Shape s;
    s.mesh = mesh;
    s.appearance = std::move(appearance);
    s.name = std::move(name);
    s.transform = transform;
    scene.shapes.push_back(std::move(s));
  };
  add(red, "pillar_a", glm::translate(glm::mat4(1.0f), glm::vec3(-2, 0.5f, 0)));
  add(alsoRed, "pillar_b",
      glm::translate(glm::mat4(1.0f), glm::vec3(2, 1, 0)) *
          glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(0, 1, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(1, 2, 1)));
  add(green, "pillar_c", glm::translate(glm::mat4(1.0f), glm::vec3(0, 0.5f, -3)));
  glm::mat4 shear(1.0f);
  shear[1][0] = 0.5f;  // x += 0.5 y: no TRS form, so the mesh is written transformed
  add(red, "sheared", glm::translate(glm::mat4(1.0f), glm::vec3(0, 0.5f, 3)) * shear);
  return scene;
}

Scene bigMesh() {
  constexpr int kSide = 301;
  Mesh m;
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      const float x = i / float(kSide - 1), z = j / float(kSide - 1);
      m.positions.push_back({10 * x - 5, 0.2f * std::sin(6 * x) * std::cos(5 * z), 10 * z - 5});
      m.texCoords.push_back({x, z});
    }
  }
  for (int j = 0; j + 1 < kSide; ++j) {
    for (int i = 0; i + 1 < kSide; ++i) {
      const uint32_t a = j * kSide + i, b = a + 1, c = a + kSide, d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
  }
  computeSmoothNormals(m);
  auto appearance = std::make_shared<Appearance>();
  appearance->material = Material{};
  Scene scene;
  scene.shapes.push_back(shapeOf(std::move(m), appearance, "terrain"));
  return scene;
}

Scene linesAndPoints() {
  Mesh lines;
  lines.topology = Topology::kLines;
  lines.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  lines.colors = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
  lines.indices = {0, 1, 1, 2, 2, 3};
  Mesh points;
  points.topology = Topology::kPoints;
  points.positions = {{0, 2, 0}, {1, 2, 0}, {2, 2, 0}};  // no indices: every vertex is a point
  Material glow;
  glow.emissiveColor = {1.0f, 0.5f, 0.0f};
  auto appearance = std::make_shared<Appearance>();
  appearance->material = glow;
  Scene scene;
  scene.shapes.push_back(shapeOf(std::move(lines), nullptr, "outline"));
  scene.shapes.push_back(shapeOf(std::move(points), appearance, "markers"));
  return scene;
}

Scene viewpoints() {
  Scene scene = litBox();
  Viewpoint entrance;
  entrance.description = "Entrance";
  entrance.position = {0, 1.6f, 5};
  entrance.fieldOfViewRad = 0.9f;
  // A photo's lens, principal point off centre (photowalk's extension, model_info.h).
  const double focalPx = 240.0 / std::tan(0.45);
  entrance.intrinsics = Intrinsics{focalPx, focalPx, 330.25, 231.5, 640, 480};
  Viewpoint side;
  side.description = "Side";
  side.position = {4, 1.6f, -2};
  side.orientation = {0, 1, 0, glm::half_pi<float>()};  // looks along -X
  scene.viewpoints = {entrance, side};
  scene.tour = {{0, 1.6f, 5}, {0, 1.6f, -1.25f}, {4, 1.6f, -2}};
  scene.navigation.avatarRadiusM = 0.3f;
  scene.navigation.visibilityLimitM = 80.0f;
  return scene;
}

Scene lights() {
  Scene scene = litBox();
  Light sun;
  sun.type = LightType::kDirectional;
  sun.direction = {0, -1, 0};
  sun.intensity = 0.5f;
  Light bulb;
  bulb.type = LightType::kPoint;
  bulb.position = {0, 2.5f, 0};
  bulb.color = {1.0f, 0.9f, 0.8f};
  bulb.attenuation = {0, 0, 1};  // inverse-square: maps exactly
  bulb.radius = 10;
  Light spot;
  spot.type = LightType::kSpot;
  spot.position = {0, 2.5f, -4};
  spot.direction = {0, -1, 0};
  spot.beamWidth = 0.3f;
  spot.cutOffAngle = 0.6f;
  Light off = bulb;
  off.on = false;
  scene.lights = {sun, bulb, spot, off};
  return scene;
}

Scene vertexColors() {
  Mesh m = quad(1, 1);
  m.colors = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 0.5f}};
  Scene scene;
  scene.shapes.push_back(shapeOf(std::move(m), nullptr, "painted"));
  return scene;
}

Scene everything() {
  Scene all;
  for (const NamedScene& sample : allSamples()) {
    if (sample.name == "everything") continue;
    Scene part = sample.make();
    all.shapes.insert(all.shapes.end(), part.shapes.begin(), part.shapes.end());
    all.lights.insert(all.lights.end(), part.lights.begin(), part.lights.end());
    all.viewpoints.insert(all.viewpoints.end(), part.viewpoints.begin(), part.viewpoints.end());
    if (!part.tour.empty()) all.tour = part.tour;
  }
  all.title = "photowalk sample scenes";
  all.info = {"written by the glTF tests"};
  return all;
}

const std::vector<NamedScene>& allSamples() {
  static const std::vector<NamedScene> kSamples = {
      {"textured_quad", texturedQuad}, {"lit_box", litBox},         {"transparent_quad", transparentQuad},
      {"shared_mesh", sharedMesh},     {"big_mesh", bigMesh},       {"lines_and_points", linesAndPoints},
      {"viewpoints", viewpoints},      {"lights", lights},          {"vertex_colors", vertexColors},
      {"everything", everything},
  };
  return kSamples;
}

}  // namespace pw::engine::samples
