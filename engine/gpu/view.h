// What a frame draws: views. A SceneView draws an uploaded scene from a camera into a
// rectangle of the frame (or of a render-target texture); an ImageView draws an
// uploaded 2D image (a photo, or a render target) under a pan/zoom transform into a
// rectangle of the frame. A frame is a list of views drawn in order, each over what
// the ones before it left, then the overlay (ImGui) on top (presenter.h).
//
// Coordinates: frame (window) pixels have their origin at the top-left corner of the
// frame, x right, y down; pixel (i, j) covers [i, i+1) x [j, j+1), so its centre is
// (i + 0.5, j + 0.5) (Vulkan's framebuffer and ImGui's convention). Image pixels
// follow the photo's convention (engine/scene/camera.h): the centre of the image's
// top-left pixel is (0, 0).
#pragma once

#include <cstdint>
#include <optional>
#include <variant>

#include <glm/glm.hpp>

#include "engine/scene/camera.h"

namespace pw::engine {

struct FrameSettings {
  std::optional<bool> headlight;  // unset: the scene's NavigationInfo.headlight
  std::optional<glm::vec3> backgroundColor;  // sRGB-encoded like scene colours; unset: the scene's
};

// A scene uploaded to the Renderer (Renderer::addScene). Ids are never reused: a removed
// handle stays invalid.
struct SceneHandle {
  uint64_t id = 0;
  explicit operator bool() const { return id != 0; }
  bool operator==(const SceneHandle&) const = default;
};

// A 2D image on the GPU: a photo (Renderer::addImage) or a render target that scene
// views draw into (Renderer::addRenderTarget). Ids are never reused.
struct ImageHandle {
  uint64_t id = 0;
  explicit operator bool() const { return id != 0; }
  bool operator==(const ImageHandle&) const = default;
};

// A rectangle in pixels of the target. Width or height 0: the whole target. It may
// reach beyond the target's edges; only the part inside is drawn.
struct PixelRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
  bool whole() const { return width == 0 || height == 0; }
};

// The scene from `camera`, drawn into `rect`: the rectangle is the viewport (the
// projection's aspect and, with Camera::intrinsics, its pixel grid are the
// rectangle's: a camera made for a W x H photo lines up with it in a W x H
// rectangle) and the scissor. The rectangle is first cleared to the scene's
// background; other pixels keep what earlier views drew.
struct SceneView {
  SceneHandle scene;
  Camera camera;
  PixelRect rect;
  FrameSettings settings;
  // Unset: the frame. Else a render target (Renderer::addRenderTarget), which a later
  // ImageView of the same or a later frame shows; `rect` is then in its pixels.
  ImageHandle target;
};

// Where an image lies in the frame: the image point p (image pixels) is drawn at
// frame position offset + scale * p. So with scale 1 and offset (0.5, 0.5) image
// pixel (i, j) covers frame pixel (i, j) exactly; with scale s each image pixel
// covers an s x s square of frame pixels centred at offset + s * (i, j).
struct ImageTransform {
  double scale = 1.0;  // frame pixels per image pixel, > 0
  glm::dvec2 offset{0.0};
};

enum class ImageFilter {
  kAuto,     // kNearest from 4 frame pixels per image pixel up, else kSmooth
  kSmooth,   // trilinear: bilinear within the mip level, blended between levels
  kNearest,  // every image pixel a sharp square (a loupe)
};

// An image under a pan/zoom transform, drawn into `rect` of the frame. Filtering is
// done on linear light (the image is sRGB; minified through mipmaps made on the GPU).
// Where the rectangle shows no image (beyond its edges), `background` is drawn.
// Images with alpha, and the background, are blended over what is already there.
struct ImageView {
  ImageHandle image;
  ImageTransform transform;
  PixelRect rect;
  ImageFilter filter = ImageFilter::kAuto;
  glm::vec4 background{0.0f};  // sRGB-encoded RGB and alpha; alpha 0: leave those pixels as they are
};

using View = std::variant<SceneView, ImageView>;

// The filter kAuto resolves to at `scale` frame pixels per image pixel.
inline ImageFilter resolvedFilter(ImageFilter filter, double scale) {
  if (filter != ImageFilter::kAuto) return filter;
  return scale >= 4.0 ? ImageFilter::kNearest : ImageFilter::kSmooth;
}

}  // namespace pw::engine
