// A texture's detail layer (Texture::detail): detail synthesized finer than the photo
// it was cut from resolves (modeling/synthesis.h). Texture::image holds the composite,
// what every viewer shows; the detail layer says, per texel, how much of it is added:
// the composite's linear light is the photo's ("the base") times
//   ratio = 2^((code - 128) / 64)          code: the detail image's grey value
// on every channel alike (luminance detail; 128: none). photowalk's renderer divides
// the detail out where a view does not magnify the photo (scene.frag), so that from
// the photo's camera the view is the photo, and fades it in where a view comes closer
// than the photo was taken. Files keep the layer as an image of its own named after
// the texture's (detailUrl) and one info line per texture (model_info.h):
//   photowalk-texture-detail URL
#pragma once

#include <cstdint>
#include <string>

#include "engine/scene/image.h"
#include "engine/scene/scene.h"

namespace pw::engine {

inline constexpr const char* kTextureDetailTag = "photowalk-texture-detail";
inline constexpr uint8_t kNoDetail = 128;
inline constexpr float kDetailCodesPerOctave = 64.0f;  // shader_interface.h's PW_DETAIL_CODES_PER_OCTAVE

// The ratio a detail code stands for, and the nearest code to a ratio (clamped to the
// codes there are: ratios from 1/4 to nearly 4).
float detailRatio(uint8_t code);
uint8_t detailCode(float ratio);

// An sRGB-encoded 8-bit value's linear light (0..1), from a table.
float linearOfSrgbByte(uint8_t encoded);

// The largest code that leaves every channel of an sRGB-encoded RGB texel unclipped
// (at least kNoDetail): a composite that clips could not give its base back.
uint8_t detailCodeLimit(const uint8_t* rgb);

// The composite of one sRGB-encoded RGB texel: its linear light times the code's ratio.
void applyDetail(const uint8_t* baseRgb, uint8_t code, uint8_t* compositeRgb);

// A texture's detail layer, when it has a usable one: a grey image of the texture's size.
bool hasDetail(const Texture& texture);

// The texels the renderer uploads for a texture cut from a photo: the base (the
// composite with its detail divided out) and, in alpha, the detail code (kNoDetail
// everywhere for a texture without a layer). `out`: width * height * 4 bytes.
void stageBaseAndDetail(const Texture& texture, uint8_t* out);

// The name of a texture's detail image: URL's file name without its extension, then
// "_detail.png" (VRML: a file beside the texture; glTF: an image of that name).
std::string detailUrl(const std::string& url);

}  // namespace pw::engine
