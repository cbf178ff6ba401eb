// Decoding a photo file (PNG, JPEG, and what else OpenCV reads) with the C decoders'
// own complaints caught: libpng and libjpeg print them on stderr themselves, which
// would put a second, foreign line beside photowalk's one-line error. What they said
// is quoted in photowalk's words instead, and a JPEG cut short (a partial download or
// copy: libjpeg fills what is missing with grey and says "Premature end of JPEG file")
// is refused rather than measured.
//
//   auto image = modeling::decodeImage(path, cv::IMREAD_COLOR);
//   if (!image) return makeError(path.string() + ": " + image.message());
//   if (image->decoderWarning) warnings.push_back(*image->decoderWarning);
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <opencv2/core/mat.hpp>

#include "base/result.h"

namespace pw::modeling {

struct DecodedImage {
  cv::Mat image;
  // What the decoder complained of in a file it still decoded (a JPEG's "Corrupt JPEG
  // data: premature end of data segment": some of its blocks may be damaged), as a
  // line naming the file for the caller to show as a warning; unset when it said
  // nothing.
  std::optional<std::string> decoderWarning;
};

// The error for a file no decoder reads (then the decoder's first line in brackets).
inline constexpr const char* kUnreadableImage = "not a readable PNG/JPEG image";

// cv::imread(path, flags), its decoder's stderr caught. Errors (without the path, for
// the caller to put it first): kUnreadableImage (with the decoder's first line), or
// the JPEG cut short. The catch is process-wide while it decodes (one
// decode at a time): a line in photowalk's own form ("error: ", "warning: ", "note: ")
// that another thread prints then is passed on to stderr after it, never taken for
// the decoder's.
Result<DecodedImage> decodeImage(const std::filesystem::path& path, int flags);

}  // namespace pw::modeling
