// Small scenes that exercise each part of the glTF mapping. The tests check the
// files written from them; write_samples writes them all for the Khronos validator.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/scene/scene.h"

namespace pw::engine::samples {

// A 4x2 texture whose pixels all differ: (x, y) -> (40 x + 10, 60 y + 20, 200 - 30 x, 255).
Image gradientImage();

Scene texturedQuad();     // 2 x 1 m quad, no Material: unlit, clamped texture, double-sided
Scene litBox();           // 1 x 2 x 3 m box with normals and a Material
Scene transparentQuad();  // Material with transparency 0.4
Scene sharedMesh();       // one mesh and appearance under three transforms (one sheared)
Scene bigMesh();          // 301 x 301 grid: 90601 vertices, uint32 indices
Scene linesAndPoints();   // coloured line strip and points, emissive material
Scene viewpoints();       // two viewpoints, NavigationInfo with clip planes
Scene lights();           // directional, point, spot and a switched-off light
Scene vertexColors();     // unlit triangles coloured per vertex, one translucent
Scene everything();       // all of the above in one scene

struct NamedScene {
  std::string name;
  std::function<Scene()> make;
};
const std::vector<NamedScene>& allSamples();

}  // namespace pw::engine::samples
