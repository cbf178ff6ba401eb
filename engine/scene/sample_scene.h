// The built-in sample scene ("photowalk render sample"): a textured, lit room made in
// code, so that the renderer can be shown and tested before any file is read.
//
// A 6 m x 3 m x 8 m room (x -3..3, y 0..3, z -6..2) with a tiled floor, brick walls
// (textured with repeat), a lit plain ceiling, three textured crates (one rotated,
// one mirrored), a transparent glass pane (solid FALSE), a vertex-coloured pyramid,
// an unlit textured picture, a line outline and a few points; a warm point light and
// a cool spot light, no headlight; two viewpoints. Textures are procedural and
// deterministic, so frames of it can serve as golden images.
#pragma once

#include "engine/scene/scene.h"

namespace pw::engine {

Scene makeSampleScene();

}  // namespace pw::engine
