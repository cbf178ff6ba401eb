// Texture synthesis for views the photo was not taken from (issue 14). A texture cut
// from the photo is sharp where the photo saw its plane closely and an upsampled blur
// where it saw it from afar (a wall's far half has 10-20 times fewer photo pixels along
// the corridor than its near part); beyond the photo's frame it has no content at all.
//
// One plane at a time, in "depth-major" layout: columns run along the corridor, the
// one nearest the camera first; rows across it. Every texel knows its photo footprint
// (where it lands in the photo and how many texels one photo pixel covers along each
// axis). Where a texel is sharp is the exemplar, the photo's own view of this surface
// up close. Then:
//  - detail: each coarse tile takes the exemplar's detail (its difference from itself
//    blurred as the photo blurred the tile) from the same rows (a brick course stays a
//    brick course). On a surface that repeats along the depth (bricks, tiles, boards)
//    the lattice continues: the period is measured on the exemplar to a small fraction
//    of a texel, and the detail comes from whole periods away, shifted by the fraction.
//    Elsewhere the tile is matched against the exemplar, blurred likewise. The tile's
//    own low frequencies, its shading and colour, stay as the photo has them. The
//    detail goes into the texture's detail layer (engine/scene/texture_detail.h): it
//    is finer than the photo's pixels there, and photowalk's renderer shows it only
//    where a view comes closer than the photo did, so that from the photo's camera the
//    view is still the photo.
//  - fill: tiles the photo does not show (and any columns the caller adds before the
//    first, the surface running on towards and behind the camera) are copied from the
//    exemplar at the same rows, shifted along the depth by whole periods when the
//    surface repeats along it (the lattice continues without a seam), else tiled with
//    cross-faded joins.
#pragma once

#include <functional>
#include <optional>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

namespace pw::modeling {

struct SynthesisOptions {
  bool detail = false;  // add detail where the photo was coarse
  bool fill = true;    // fill what the photo did not see
};

struct SynthesisStats {
  double detailFraction = 0;  // of the texels: detail added
  double filledFraction = 0;  // of the texels: filled (no photo)
  int periodPx = 0;           // the period along the depth, texels (0: not periodic)
  int exemplarColumns = 0;    // how many columns the exemplar has (0: none, nothing done)
};

// Where texel (x, y) of the depth-major texture lands in the photo (pixel centres at
// integer coordinates), or nothing when it is behind the photo's camera or has no
// source (an added column).
using PhotoOfTexel = std::function<std::optional<glm::dvec2>(double x, double y)>;

// Synthesizes in place. `texture`: 8-bit BGR, depth-major. `photoSize`: the photo's.
// With detail added, `texture` is the composite and `detail` (when given) receives the
// detail layer (8-bit, one channel: engine/scene/texture_detail.h's codes); it is left
// empty when no detail was added.
SynthesisStats synthesizeSurface(cv::Mat& texture, const PhotoOfTexel& photoOf, cv::Size photoSize,
                                 const SynthesisOptions& options = {}, cv::Mat* detail = nullptr);

}  // namespace pw::modeling
