// The shaders' SPIR-V, compiled from shaders/*.vert|frag at build time and embedded
// (see shaders/CMakeLists.txt). Each span is valid for the program's lifetime.
#pragma once

#include <cstdint>
#include <span>

namespace pw::shaders {

std::span<const uint32_t> sceneVertSpirv();  // scene.vert: every scene pipeline
std::span<const uint32_t> sceneFragSpirv();  // scene.frag: VRML97 lighting
std::span<const uint32_t> imageVertSpirv();  // image.vert: an ImageView's rectangle
std::span<const uint32_t> imageFragSpirv();  // image.frag: an image under a pan/zoom transform

}  // namespace pw::shaders
