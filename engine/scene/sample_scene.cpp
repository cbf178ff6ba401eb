#include "engine/scene/sample_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>

namespace pw::engine {
namespace {

// Integer hash for deterministic per-tile variation (no RNG state, same on every platform).
uint32_t hash(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

void setPixel(Image& image, int x, int y, glm::vec3 rgb) {
  uint8_t* p = image.pixel(x, y);
  for (int c = 0; c < 3; ++c) p[c] = static_cast<uint8_t>(std::clamp(rgb[c], 0.0f, 1.0f) * 255.0f + 0.5f);
  p[3] = 255;
}

// Floor tiles: 4x4 tiles per texture with grout lines and a little per-tile tint.
std::shared_ptr<const Image> floorTiles() {
  auto image = std::make_shared<Image>(makeImage(256, 256));
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      const int tx = x / 64, ty = y / 64;
      const bool grout = x % 64 < 3 || y % 64 < 3;
      const float tint = (hash(uint32_t(tx * 7 + ty * 131)) % 100) / 100.0f * 0.08f;
      const glm::vec3 tile = ((tx + ty) % 2 == 0) ? glm::vec3(0.80f, 0.74f, 0.62f) : glm::vec3(0.45f, 0.36f, 0.28f);
      setPixel(*image, x, y, grout ? glm::vec3(0.25f) : tile + tint);
    }
  }
  return image;
}

// Running-bond bricks, 8 courses of 4 bricks, mortar between.
std::shared_ptr<const Image> bricks() {
  auto image = std::make_shared<Image>(makeImage(256, 256));
  for (int y = 0; y < 256; ++y) {
    const int course = y / 32;
    for (int x = 0; x < 256; ++x) {
      const int shifted = x + (course % 2) * 32;
      const int brick = shifted / 64;
      const bool mortar = y % 32 < 3 || shifted % 64 < 3;
      const float shade = (hash(uint32_t(course * 17 + brick * 1031)) % 100) / 100.0f * 0.15f;
      setPixel(*image, x, y, mortar ? glm::vec3(0.78f, 0.76f, 0.72f) : glm::vec3(0.62f + shade, 0.28f, 0.20f + shade * 0.5f));
    }
  }
  return image;
}

// Crate planks: a frame and diagonal brace on wood-coloured stripes.
std::shared_ptr<const Image> crate() {
  auto image = std::make_shared<Image>(makeImage(128, 128));
  for (int y = 0; y < 128; ++y) {
    for (int x = 0; x < 128; ++x) {
      const bool frame = x < 12 || x >= 116 || y < 12 || y >= 116;
      const bool brace = std::abs(x - y) < 9;
      const float grain = 0.06f * std::sin(float(y) * 0.9f + float(x / 32) * 2.0f);
      glm::vec3 wood(0.72f + grain, 0.52f + grain, 0.30f);
      if (frame || brace) wood *= 0.7f;
      if (y % 32 == 0) wood *= 0.6f;  // plank joints
      setPixel(*image, x, y, wood);
    }
  }
  return image;
}

// The picture on the far wall: a sunset-coloured gradient with a sun, drawn unlit.
std::shared_ptr<const Image> picture() {
  auto image = std::make_shared<Image>(makeImage(128, 96));
  for (int y = 0; y < 96; ++y) {
    for (int x = 0; x < 128; ++x) {
      const float t = float(y) / 95.0f;
      glm::vec3 c = glm::mix(glm::vec3(0.15f, 0.25f, 0.65f), glm::vec3(0.98f, 0.62f, 0.25f), t);
      if (y > 70) c = glm::vec3(0.10f, 0.30f, 0.15f);  // ground
      const float dx = float(x) - 84.0f, dy = float(y) - 58.0f;
      if (dx * dx + dy * dy < 144.0f) c = glm::vec3(1.0f, 0.92f, 0.55f);
      setPixel(*image, x, y, c);
    }
  }
  return image;
}

std::shared_ptr<const Texture> texture(std::shared_ptr<const Image> image, std::string url) {
  auto t = std::make_shared<Texture>();
  t->image = std::move(image);
  t->url = std::move(url);
  return t;
}

// A quad from `origin` along `u` and `v` (front side where u x v points), with
// texture coordinates (0,0) at the origin up to (repeatS, repeatT).
std::shared_ptr<const Mesh> quad(glm::vec3 origin, glm::vec3 u, glm::vec3 v, float repeatS = 1, float repeatT = 1) {
  auto mesh = std::make_shared<Mesh>();
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  mesh->positions = {origin, origin + u, origin + u + v, origin + v};
  mesh->normals = {n, n, n, n};
  mesh->texCoords = {{0, 0}, {repeatS, 0}, {repeatS, repeatT}, {0, repeatT}};
  mesh->indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

// A unit cube centred at the origin, 4 vertices per face, texture 0..1 on each face.
std::shared_ptr<const Mesh> cube() {
  auto mesh = std::make_shared<Mesh>();
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& n : normals) {
    // Two axes spanning the face so that u x v = n.
    const glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) * n.y : glm::cross(glm::vec3(0, 1, 0), n);
    const glm::vec3 v = glm::cross(n, u);
    const auto base = static_cast<uint32_t>(mesh->positions.size());
    const glm::vec3 c = n * 0.5f;
    mesh->positions.insert(mesh->positions.end(), {c - 0.5f * u - 0.5f * v, c + 0.5f * u - 0.5f * v,
                                                   c + 0.5f * u + 0.5f * v, c - 0.5f * u + 0.5f * v});
    mesh->normals.insert(mesh->normals.end(), 4, n);
    mesh->texCoords.insert(mesh->texCoords.end(), {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    mesh->indices.insert(mesh->indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return mesh;
}

// A square pyramid with a colour per vertex (flat-shaded: vertices split per face).
std::shared_ptr<const Mesh> colouredPyramid() {
  auto mesh = std::make_shared<Mesh>();
  const glm::vec3 apex(0, 1, 0);
  const glm::vec3 base[4] = {{-0.5f, 0, 0.5f}, {0.5f, 0, 0.5f}, {0.5f, 0, -0.5f}, {-0.5f, 0, -0.5f}};
  const glm::vec4 colours[4] = {{0.9f, 0.15f, 0.1f, 1}, {0.1f, 0.75f, 0.2f, 1}, {0.15f, 0.3f, 0.95f, 1}, {0.95f, 0.85f, 0.1f, 1}};
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 a = base[i], b = base[(i + 1) % 4];
    const glm::vec3 n = glm::normalize(glm::cross(b - a, apex - a));
    const auto first = static_cast<uint32_t>(mesh->positions.size());
    mesh->positions.insert(mesh->positions.end(), {a, b, apex});
    mesh->normals.insert(mesh->normals.end(), 3, n);
    mesh->colors.insert(mesh->colors.end(), {colours[i], colours[(i + 1) % 4], glm::vec4(1.0f)});
    mesh->indices.insert(mesh->indices.end(), {first, first + 1, first + 2});
  }
  mesh->texCoords.assign(mesh->positions.size(), glm::vec2(0.0f));
  return mesh;
}

std::shared_ptr<const Appearance> litAppearance(std::shared_ptr<const Texture> tex, Material material = {}) {
  auto a = std::make_shared<Appearance>();
  a->material = material;
  a->texture = std::move(tex);
  return a;
}

Shape shape(std::string name, std::shared_ptr<const Mesh> mesh, std::shared_ptr<const Appearance> appearance,
            glm::mat4 transform = glm::mat4(1.0f)) {
  Shape s;
  s.name = std::move(name);
  s.mesh = std::move(mesh);
  s.appearance = std::move(appearance);
  s.transform = transform;
  return s;
}

}  // namespace

Scene makeSampleScene() {
  Scene scene;
  scene.title = "photowalk sample room";
  scene.info = {"built in code by engine/scene/sample_scene.cpp"};
  scene.backgroundColor = glm::vec3(0.05f, 0.07f, 0.12f);
  scene.navigation.headlight = false;

  Material wallMaterial;
  wallMaterial.diffuseColor = glm::vec3(1.0f);
  wallMaterial.ambientIntensity = 0.35f;
  const auto floorTex = texture(floorTiles(), "sample:floor-tiles");
  const auto brickTex = texture(bricks(), "sample:bricks");
  const auto crateTex = texture(crate(), "sample:crate");
  const auto wall = litAppearance(brickTex, wallMaterial);

  // The room (x -3..3, y 0..3, z -6..2), faces pointing inwards; the front (z = 2) is open.
  scene.shapes.push_back(shape("floor", quad({-3, 0, 2}, {6, 0, 0}, {0, 0, -8}, 3, 4), litAppearance(floorTex, wallMaterial)));
  Material ceilingMaterial;
  ceilingMaterial.diffuseColor = glm::vec3(0.9f, 0.9f, 0.85f);
  ceilingMaterial.ambientIntensity = 0.4f;
  scene.shapes.push_back(shape("ceiling", quad({-3, 3, -6}, {6, 0, 0}, {0, 0, 8}), litAppearance(nullptr, ceilingMaterial)));
  scene.shapes.push_back(shape("far wall", quad({-3, 0, -6}, {6, 0, 0}, {0, 3, 0}, 3, 1.5f), wall));
  scene.shapes.push_back(shape("left wall", quad({-3, 0, 2}, {0, 0, -8}, {0, 3, 0}, 4, 1.5f), wall));
  scene.shapes.push_back(shape("right wall", quad({3, 0, -6}, {0, 0, 8}, {0, 3, 0}, 4, 1.5f), wall));

  // Crates: one plain, one rotated 30 degrees, one mirrored in x (negative determinant).
  Material crateMaterial;
  crateMaterial.specularColor = glm::vec3(0.25f);
  crateMaterial.shininess = 0.3f;
  const auto crateLook = litAppearance(crateTex, crateMaterial);
  const auto box = cube();
  scene.shapes.push_back(shape("crate", box, crateLook,
                               glm::scale(glm::translate(glm::mat4(1.0f), {-1.4f, 0.5f, -3.5f}), glm::vec3(1.0f))));
  scene.shapes.push_back(shape("rotated crate", box, crateLook,
                               glm::rotate(glm::translate(glm::mat4(1.0f), {1.5f, 0.35f, -4.2f}), glm::radians(30.0f),
                                           glm::vec3(0, 1, 0)) *
                                   glm::scale(glm::mat4(1.0f), glm::vec3(0.7f))));
  scene.shapes.push_back(shape("mirrored crate", box, crateLook,
                               glm::scale(glm::translate(glm::mat4(1.0f), {-1.4f, 1.3f, -3.5f}), glm::vec3(-0.6f, 0.6f, 0.6f))));

  // A vertex-coloured pyramid, lit and shiny.
  Material pyramidMaterial;
  pyramidMaterial.specularColor = glm::vec3(0.6f);
  pyramidMaterial.shininess = 0.5f;
  scene.shapes.push_back(shape("pyramid", colouredPyramid(), litAppearance(nullptr, pyramidMaterial),
                               glm::translate(glm::mat4(1.0f), {0.6f, 0.0f, -2.6f}) * glm::scale(glm::mat4(1.0f), glm::vec3(0.8f))));

  // The glass pane: transparent, visible from both sides, in front of the rotated crate.
  Material glass;
  glass.diffuseColor = glm::vec3(0.55f, 0.75f, 0.95f);
  glass.specularColor = glm::vec3(0.8f);
  glass.shininess = 0.8f;
  glass.transparency = 0.55f;
  auto pane = std::make_shared<Mesh>(*quad({0.4f, 0.1f, -3.0f}, {1.8f, 0, -0.6f}, {0, 1.6f, 0}));
  pane->solid = false;
  scene.shapes.push_back(shape("glass pane", pane, litAppearance(nullptr, glass)));

  // An unlit picture on the far wall (no Material: the texture at full intensity).
  auto pictureLook = std::make_shared<Appearance>();
  auto pictureTex = std::make_shared<Texture>();
  pictureTex->image = picture();
  pictureTex->url = "sample:picture";
  pictureTex->wrapS = pictureTex->wrapT = TextureWrap::kClamp;
  pictureLook->texture = pictureTex;
  scene.shapes.push_back(shape("picture", quad({-0.8f, 1.3f, -5.99f}, {1.6f, 0, 0}, {0, 1.2f, 0}), pictureLook));

  // The picture's frame as lines, in the emissive colour; a few points below the ceiling.
  Material frameColour;
  frameColour.emissiveColor = glm::vec3(0.95f, 0.85f, 0.3f);
  auto frame = std::make_shared<Mesh>();
  frame->topology = Topology::kLines;
  frame->positions = {{-0.85f, 1.25f, -5.98f}, {0.85f, 1.25f, -5.98f}, {0.85f, 2.55f, -5.98f}, {-0.85f, 2.55f, -5.98f}};
  frame->indices = {0, 1, 1, 2, 2, 3, 3, 0};
  scene.shapes.push_back(shape("picture frame", frame, litAppearance(nullptr, frameColour)));
  auto stars = std::make_shared<Mesh>();
  stars->topology = Topology::kPoints;
  for (int i = 0; i < 24; ++i) {
    stars->positions.push_back({-2.5f + 0.2f * float(i % 6) * 4.0f, 2.95f, -5.5f + float(i / 6) * 1.5f});
    stars->colors.push_back({1.0f, 1.0f, 0.8f, 1.0f});
    stars->indices.push_back(uint32_t(i));
  }
  scene.shapes.push_back(shape("ceiling points", stars, nullptr));

  // Lights: a warm point light high in the room, a cool spot light on the crates.
  Light lamp;
  lamp.type = LightType::kPoint;
  lamp.position = {0.5f, 2.7f, -1.5f};
  lamp.color = {1.0f, 0.92f, 0.8f};
  lamp.intensity = 0.9f;
  lamp.ambientIntensity = 0.35f;
  lamp.attenuation = {0.3f, 0.25f, 0.08f};
  lamp.radius = 20.0f;
  scene.lights.push_back(lamp);
  Light spot;
  spot.type = LightType::kSpot;
  spot.position = {2.5f, 2.9f, -1.0f};
  spot.direction = glm::vec3(-1.4f, 0.5f, -3.5f) - spot.position;
  spot.color = {0.7f, 0.8f, 1.0f};
  spot.intensity = 1.0f;
  spot.cutOffAngle = 0.45f;
  spot.beamWidth = 0.3f;
  spot.radius = 30.0f;
  scene.lights.push_back(spot);

  Viewpoint entrance;
  entrance.description = "Entrance";
  entrance.position = {0.0f, 1.6f, 1.5f};
  entrance.orientation = {1.0f, 0.0f, 0.0f, -0.12f};  // looking down the room, slightly down
  entrance.fieldOfViewRad = 0.9f;
  scene.viewpoints.push_back(entrance);
  Viewpoint corner;
  corner.description = "Corner";
  corner.position = {2.5f, 2.2f, 1.2f};
  corner.orientation = {-0.35f, 0.93f, 0.1f, 0.55f};
  corner.fieldOfViewRad = 0.8f;
  scene.viewpoints.push_back(corner);
  return scene;
}

}  // namespace pw::engine
