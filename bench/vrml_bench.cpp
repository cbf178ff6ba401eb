// vrml_bench: reading and writing VRML97, medians of several runs.
//
// Model: a terrain of 1024x512 quads as one IndexedFaceSet with normals and texture
// coordinates (about a million triangles, 53 MB of text), as photowalk's writer
// writes it, plus the same file gzip-compressed.
// Baselines, in the same run, on the same text: for reading, only scanning its
// numbers with std::from_chars (a lower bound for any text parser, no nodes, no
// mesh); for writing, only formatting the same floats and indices with std::to_chars.
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <vector>

#include "base/atomic_file.h"
#include "bench/bench_timing.h"
#include "engine/vrml/gzip.h"
#include "engine/vrml/vrml_reader.h"
#include "engine/vrml/vrml_writer.h"

namespace {

using namespace pw::engine;
using pw::bench::medianMs;

Scene terrain(int columns, int rows) {
  auto mesh = std::make_shared<Mesh>();
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      const float x = i * 0.1f, z = j * 0.1f;
      const float y = 0.3f * std::sin(x * 0.7f) * std::cos(z * 0.5f);
      mesh->positions.push_back({x, y, z});
      mesh->normals.push_back(glm::normalize(glm::vec3(-0.21f * std::cos(x * 0.7f), 1.0f, 0.15f * std::sin(z * 0.5f))));
      mesh->texCoords.push_back({static_cast<float>(i) / columns, static_cast<float>(j) / rows});
    }
  }
  const uint32_t stride = static_cast<uint32_t>(columns + 1);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const uint32_t a = j * stride + i;
      mesh->indices.insert(mesh->indices.end(), {a, a + stride, a + stride + 1, a, a + stride + 1, a + 1});
    }
  }
  auto texture = std::make_shared<Texture>();
  texture->image = std::make_shared<Image>(makeImage(4, 4, 0x808080ff));
  texture->url = "ground.png";
  auto appearance = std::make_shared<Appearance>();
  appearance->texture = texture;
  appearance->material = Material{};
  Scene scene;
  Shape shape;
  shape.mesh = mesh;
  shape.appearance = appearance;
  shape.name = "Terrain";
  scene.shapes.push_back(shape);
  return scene;
}

// The baseline reader: every number in the text through std::from_chars, nothing else.
double scanNumbers(const std::string& text) {
  double sum = 0;
  const char* p = text.data();
  const char* end = p + text.size();
  while (p < end) {
    if ((*p >= '0' && *p <= '9') || *p == '-') {
      double v = 0;
      auto r = std::from_chars(p, end, v);
      sum += v;
      p = r.ptr == p ? p + 1 : r.ptr;
    } else {
      ++p;
    }
  }
  return sum;
}

// The baseline writer: the mesh's numbers through std::to_chars into one string.
size_t formatNumbers(const Mesh& m) {
  std::string out;
  out.reserve(64u << 20);
  char buffer[32];
  auto put = [&](float v) {
    out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
    out += ' ';
  };
  for (const auto& p : m.positions) { put(p.x); put(p.y); put(p.z); }
  for (const auto& n : m.normals) { put(n.x); put(n.y); put(n.z); }
  for (const auto& t : m.texCoords) { put(t.x); put(t.y); }
  for (uint32_t i : m.indices) {
    out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, i).ptr);
    out += ' ';
  }
  return out.size();
}

}  // namespace

int main() {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(PW_BINARY_DIR) / "bench_output" / "vrml";
  fs::create_directories(dir);
  const Scene scene = terrain(1024, 512);
  const fs::path plain = dir / "terrain.wrl", packed = dir / "terrain.wrl.gz";
  if (auto s = writeVrml(scene, plain); !s || !writeVrml(scene, packed)) {
    std::fprintf(stderr, "error: cannot write the benchmark model: %s\n", s ? "gzip" : s.message().c_str());
    return 1;
  }
  auto text = pw::readFile(plain);
  if (!text) return 1;
  const double megabytes = static_cast<double>(text->size()) / (1 << 20);
  const size_t triangles = scene.shapes[0].mesh->indices.size() / 3;
  std::printf("model: %zu triangles, %zu vertices, %.1f MB of VRML (%.1f MB gzip)\n", triangles,
              scene.shapes[0].mesh->positions.size(), megabytes, static_cast<double>(fs::file_size(packed)) / (1 << 20));

  constexpr int kRuns = 5;
  volatile double sink = 0;
  const double scanMs = medianMs(kRuns, [&] { sink = sink + scanNumbers(*text); });
  size_t shapes = 0;
  const double readMs = medianMs(kRuns, [&] {
    auto s = readVrml(plain, nullptr);
    shapes += s ? s->shapes.size() : 0;
  });
  const double readGzMs = medianMs(kRuns, [&] {
    auto s = readVrml(packed, nullptr);
    shapes += s ? s->shapes.size() : 0;
  });
  const double gunzipMs = medianMs(kRuns, [&] {
    auto bytes = pw::readFile(packed);
    auto t = gunzip(*bytes, "bench", kMaxVrmlBytes);
    sink = sink + static_cast<double>(t ? t->size() : 0);
  });
  std::printf("read  .wrl     median %8.1f ms  %6.1f MB/s   baseline (from_chars over the numbers) %7.1f ms  x%.2f\n",
              readMs, megabytes / readMs * 1000, scanMs, readMs / scanMs);
  std::printf("read  .wrl.gz  median %8.1f ms  (of which inflate %.1f ms)\n", readGzMs, gunzipMs);

  const double formatMs = medianMs(kRuns, [&] { sink = sink + static_cast<double>(formatNumbers(*scene.shapes[0].mesh)); });
  const double textMs = medianMs(kRuns, [&] {
    auto t = vrmlText(scene, {}, {});
    sink = sink + static_cast<double>(t ? t->size() : 0);
  });
  const double writeMs = medianMs(kRuns, [&] { sink = sink + (writeVrml(scene, plain).ok() ? 1 : 0); });
  const double writeGzMs = medianMs(kRuns, [&] { sink = sink + (writeVrml(scene, packed).ok() ? 1 : 0); });
  // Crease-angle normals where 200000 triangles meet at one point (a fan), which the
  // clustered path keeps linear; baseline: the same fan with its normals in the file.
  std::string fanPoints = "0 0 0", fanNormals = "0 0 1", fanIndex;
  constexpr int kFan = 200000;
  for (int i = 0; i < kFan; ++i) {
    const double a = 6.283185307179586 * i / kFan;
    fanPoints += ", " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " " + std::to_string(0.1 * (i % 7));
    fanNormals += ", 0 0 1";
    fanIndex += "0 " + std::to_string(i + 1) + " " + std::to_string((i + 1) % kFan + 1) + " -1 ";
  }
  const std::string fanHead = "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [ " +
                              fanPoints + " ] } coordIndex [ " + fanIndex + " ] ";
  const std::string smoothFan = fanHead + "creaseAngle 0.5 } }\n";
  const std::string givenFan = fanHead + "normal Normal { vector [ " + fanNormals + " ] } } }\n";
  const double smoothMs = medianMs(kRuns, [&] { shapes += readVrmlString(smoothFan, ".", nullptr)->shapes.size(); });
  const double givenMs = medianMs(kRuns, [&] { shapes += readVrmlString(givenFan, ".", nullptr)->shapes.size(); });
  std::printf("read  fan of %d triangles, creaseAngle 0.5: median %.1f ms   baseline (normals given) %.1f ms  x%.2f\n",
              kFan, smoothMs, givenMs, smoothMs / givenMs);

  std::printf("write text     median %8.1f ms  %6.1f MB/s   baseline (to_chars of the numbers) %7.1f ms  x%.2f\n", textMs,
              megabytes / textMs * 1000, formatMs, textMs / formatMs);
  std::printf("write .wrl     median %8.1f ms  (text, texture PNG, atomic file)\n", writeMs);
  std::printf("write .wrl.gz  median %8.1f ms  (zlib level 4)\n", writeGzMs);
  if (shapes != 4 * kRuns) {
    std::fprintf(stderr, "error: the benchmark model did not read back\n");
    return 1;
  }
  return 0;
}
