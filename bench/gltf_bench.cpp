// glTF export speed: writeGltf on a corridor-sized scene (five photo textures, one
// rectified-wall-like texture and a 262k-vertex mesh), against baselines measured in
// the same run:
//   stb PNGs    embedding through stb_image_write's PNG encoder on one
//               thread, plus an atomic write as large as the .glb;
//   copy+write  for geometry only: copying the vertex arrays once and writing them;
//   stb decode  for reading: decoding the embedded PNGs, which any reader must do.
// Prints the median of several interleaved runs of each, in milliseconds.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "base/atomic_file.h"
#include "engine/gltf/gltf_reader.h"
#include "engine/gltf/gltf_writer.h"
#include <stb_image_write.h>
#include "engine/scene/image.h"
#include "engine/scene/scene.h"

namespace {

// The baseline: stb_image_write's PNG encoder (compiled into pw_scene), into memory.
std::vector<uint8_t> stbPng(const pw::engine::Image& image) {
  std::vector<uint8_t> out;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto* bytes = static_cast<std::vector<uint8_t>*>(context);
        bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
      },
      &out, image.width, image.height, 4, image.rgba.data(), image.width * 4);
  return out;
}

using namespace pw;
using namespace pw::engine;
namespace fs = std::filesystem;

// Runs every case once per round, round after round, so that a busy machine slows
// all of them alike, and returns each case's median in milliseconds.
std::vector<double> interleavedMediansMs(int rounds, const std::vector<std::function<void()>>& cases) {
  std::vector<std::vector<double>> ms(cases.size());
  for (int round = 0; round < rounds; ++round) {
    for (size_t c = 0; c < cases.size(); ++c) {
      const auto start = std::chrono::steady_clock::now();
      cases[c]();
      ms[c].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
  }
  std::vector<double> medians;
  for (auto& m : ms) {
    std::sort(m.begin(), m.end());
    medians.push_back(m[m.size() / 2]);
  }
  return medians;
}

// The ground-truth corridor photos (what photowalk textures its planes with), or a
// noisy stand-in of the same size when they are not there.
std::vector<std::shared_ptr<const Image>> photos() {
  std::vector<std::shared_ptr<const Image>> out;
  for (char c = 'a'; c <= 'e'; ++c) {
    auto image = loadImage(fs::path(PW_GROUNDTRUTH_DIR) / (std::string("corridor_") + c + ".png"));
    if (image) {
      out.push_back(std::make_shared<Image>(std::move(*image)));
      continue;
    }
    Image noise = makeImage(1024, 768);
    uint32_t state = 12345u + c;
    for (uint8_t& byte : noise.rgba) byte = static_cast<uint8_t>((state = state * 1664525u + 1013904223u) >> 24) | 3;
    for (size_t i = 3; i < noise.rgba.size(); i += 4) noise.rgba[i] = 255;
    out.push_back(std::make_shared<Image>(std::move(noise)));
  }
  // A rectified wall: photowalk stretches the photo's receding walls along the
  // corridor, so its wall textures are smooth along x. Stand-in: the first photo
  // stretched 5x along x (linear interpolation), 4000 px wide like a 19 m wall.
  const Image& photo = *out.front();
  Image wall = makeImage(photo.width * 5, photo.height);
  for (int y = 0; y < wall.height; ++y) {
    for (int x = 0; x < wall.width; ++x) {
      const float u = std::min((x + 0.5f) / 5.0f - 0.5f, photo.width - 1.0f);
      const int x0 = std::max(0, static_cast<int>(std::floor(u)));
      const int x1 = std::min(photo.width - 1, x0 + 1);
      const float f = std::clamp(u - x0, 0.0f, 1.0f);
      for (int c = 0; c < 4; ++c) {
        wall.pixel(x, y)[c] = static_cast<uint8_t>(std::lround(photo.pixel(x0, y)[c] * (1 - f) + photo.pixel(x1, y)[c] * f));
      }
    }
  }
  out.push_back(std::make_shared<Image>(std::move(wall)));
  return out;
}

Mesh grid(int side) {
  Mesh m;
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const float x = i / float(side - 1), z = j / float(side - 1);
      m.positions.push_back({20 * x, 0.1f * std::sin(40 * x) * std::cos(30 * z), -20 * z});
      m.texCoords.push_back({x, z});
    }
  }
  for (int j = 0; j + 1 < side; ++j) {
    for (int i = 0; i + 1 < side; ++i) {
      const uint32_t a = j * side + i, b = a + 1, c = a + side, d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
  }
  computeSmoothNormals(m);
  return m;
}

Scene corridorScene(bool withTextures) {
  Scene scene;
  const auto images = photos();
  for (size_t i = 0; i < images.size(); ++i) {
    Mesh plane;
    plane.positions = {{0, 0, -float(i)}, {2, 0, -float(i)}, {2, 3, -float(i)}, {0, 3, -float(i)}};
    plane.texCoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    plane.normals.assign(4, {0, 0, 1});
    plane.indices = {0, 1, 2, 0, 2, 3};
    auto appearance = std::make_shared<Appearance>();
    if (withTextures) {
      auto texture = std::make_shared<Texture>();
      texture->image = images[i];
      appearance->texture = texture;
    }
    Shape shape;
    shape.mesh = std::make_shared<Mesh>(std::move(plane));
    shape.appearance = appearance;
    scene.shapes.push_back(shape);
  }
  Shape floor;
  floor.mesh = std::make_shared<Mesh>(grid(512));
  auto lit = std::make_shared<Appearance>();
  lit->material = Material{};
  floor.appearance = lit;
  scene.shapes.push_back(floor);
  return scene;
}

}  // namespace

int main() {
  constexpr int kRounds = 7;
  const fs::path dir = fs::path(PW_BINARY_DIR) / "bench" / "out";
  fs::create_directories(dir);
  const Scene textured = corridorScene(true);
  const Scene geometry = corridorScene(false);
  std::vector<const Image*> images;
  size_t pixels = 0;
  for (const Shape& s : textured.shapes) {
    if (!s.appearance || !s.appearance->texture) continue;
    images.push_back(s.appearance->texture->image.get());
    pixels += images.back()->rgba.size() / 4;
  }
  std::printf("scene: %zu textures (%.2f Mpixel in all), %zu shapes, %zu vertices in the big mesh\n",
              images.size(), pixels / 1e6, textured.shapes.size(), geometry.shapes.back().mesh->positions.size());

  auto glbBytes = encodeGltf(textured, GltfContainer::kGlb);
  auto geometryBytes = encodeGltf(geometry, GltfContainer::kGlb);
  if (!glbBytes || !geometryBytes) return std::fprintf(stderr, "error: export failed\n"), 1;
  size_t stbBytes = 0, ourBytes = 0;
  for (const Image* image : images) {
    stbBytes += stbPng(*image).size();
    ourBytes += encodePng(*image)->size();
  }
  const std::string filler(glbBytes->size(), 'x');
  std::vector<std::vector<uint8_t>> pngs;
  for (const Image* image : images) pngs.push_back(*encodePng(*image));
  const Mesh& big = *geometry.shapes.back().mesh;

  const std::vector<double> ms = interleavedMediansMs(kRounds, {
      [&] { if (!writeGltf(textured, dir / "corridor.glb")) std::abort(); },
      [&] { if (!writeGltf(textured, dir / "corridor.gltf")) std::abort(); },
      // Baseline 1: stb's PNG encoder (engine/scene encodePng) on one thread, plus writing
      // a file as large as the .glb: what embedding through the existing encoder costs.
      [&] {
        for (const Image* image : images) if (stbPng(*image).empty()) std::abort();
        if (!writeFileAtomic(dir / "floor.bin", filler)) std::abort();
      },
      [&] { for (const Image* image : images) if (!encodePng(*image)) std::abort(); },
      [&] { for (const Image* image : images) if (stbPng(*image).empty()) std::abort(); },
      [&] { if (!writeGltf(geometry, dir / "geometry.glb")) std::abort(); },
      // Baseline 2: copying the big mesh's arrays once and writing them: the I/O floor.
      [&] {
        std::vector<char> copy;
        copy.reserve(geometryBytes->size());
        auto append = [&](const auto& v) {
          const char* p = reinterpret_cast<const char*>(v.data());
          copy.insert(copy.end(), p, p + v.size() * sizeof(v[0]));
        };
        append(big.positions);
        append(big.normals);
        append(big.texCoords);
        append(big.indices);
        if (!writeFileAtomic(dir / "floor.bin", std::span<const char>(copy.data(), copy.size()))) std::abort();
      },
      [&] { if (!parseGltf(*glbBytes, {}, "corridor.glb")) std::abort(); },
      // Baseline 3: decoding the same PNGs with stb (what any reader must do).
      [&] { for (const auto& png : pngs) if (!decodeImage(png.data(), png.size(), "png")) std::abort(); },
  });

  std::printf("median of %d interleaved rounds, ms (%u hardware threads):\n", kRounds, std::thread::hardware_concurrency());
  std::printf("  writeGltf .glb, textures + mesh          %8.1f  (%.1f MB)\n", ms[0], glbBytes->size() / 1e6);
  std::printf("  writeGltf .gltf, textures + mesh         %8.1f\n", ms[1]);
  std::printf("  baseline: stb PNGs + same-size write     %8.1f  -> writeGltf is %.2fx faster\n", ms[2], ms[2] / ms[0]);
  std::printf("  PNGs only, one thread: encodePng         %8.1f  (%.2f MB)\n", ms[3], ourBytes / 1e6);
  std::printf("  PNGs only, one thread: stb_image_write   %8.1f  (%.2f MB)  -> %.2fx slower\n", ms[4], stbBytes / 1e6,
              ms[4] / ms[3]);
  std::printf("  writeGltf .glb, geometry only            %8.1f  (%.1f MB)\n", ms[5], geometryBytes->size() / 1e6);
  std::printf("  baseline: copy arrays + write            %8.1f  -> writeGltf takes %.2fx\n", ms[6], ms[5] / ms[6]);
  std::printf("  parseGltf .glb, textures + mesh          %8.1f\n", ms[7]);
  std::printf("  baseline: stb decode of its PNGs         %8.1f  -> parseGltf takes %.2fx\n", ms[8], ms[7] / ms[8]);
  return 0;
}
