#include "modeling/image_decode.h"

#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

namespace pw::modeling {
namespace {

// Sends what is written to stderr (file descriptor 2, where C decoders print) to a
// temporary file while it lives, then restores it. One at a time (decodeImage's lock):
// two redirections at once would restore each other's file.
class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    saved_ = file_ ? ::dup(2) : -1;
    if (saved_ >= 0) ::dup2(::fileno(file_), 2);
  }
  ~StderrCapture() {
    restore();
    if (file_) std::fclose(file_);
  }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  // The non-empty lines written so far (restores stderr first).
  std::vector<std::string> lines() {
    restore();
    std::vector<std::string> out;
    if (!file_) return out;
    std::rewind(file_);
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, file_)) {
      std::string line(buffer);
      while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
      if (!line.empty()) out.push_back(std::move(line));
    }
    return out;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
    saved_ = -1;
  }
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

// A line photowalk itself prints (from another thread while the photo decoded: the
// editor's workers), not the decoder's.
bool isOurs(const std::string& line) {
  for (const char* prefix : {"error: ", "warning: ", "note: "}) {
    if (line.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

// libjpeg's warning where the file ends before the image does (JWRN_JPEG_EOF).
constexpr const char* kJpegCutShort = "Premature end of JPEG file";
// libjpeg's warning where it skipped damaged data (JWRN_JPEG_CORRUPT and others).
constexpr const char* kJpegDamaged = "Corrupt JPEG data";

}  // namespace

Result<DecodedImage> decodeImage(const std::filesystem::path& path, int flags) {
  DecodedImage out;
  std::string decoderSaid;
  {
    static std::mutex decoding;
    const std::lock_guard<std::mutex> lock(decoding);
    StderrCapture capture;
    try {
      out.image = cv::imread(path.string(), flags);
    } catch (const cv::Exception&) {
      out.image.release();
    }
    // The decoder's first complaint is quoted (its others left out, as libjpeg itself
    // leaves out all but its first warning); a line of photowalk's goes on to stderr.
    for (std::string& line : capture.lines()) {
      if (isOurs(line)) {
        std::fprintf(stderr, "%s\n", line.c_str());
      } else if (decoderSaid.empty()) {
        decoderSaid = std::move(line);
      }
    }
  }
  if (out.image.empty()) {
    return makeError(kUnreadableImage + (decoderSaid.empty() ? std::string() : " (" + decoderSaid + ")"));
  }
  if (decoderSaid.rfind(kJpegCutShort, 0) == 0) {
    return makeError("the JPEG ends before its last row (the decoder: \"" + decoderSaid +
                     "\"): the file was cut short, so copy or download the photo again");
  }
  if (!decoderSaid.empty()) {
    // libjpeg's "Corrupt JPEG data: ..." (it resynchronized past a damaged block) is
    // the one that changes pixels; libpng's warnings are of metadata ("iCCP: known
    // incorrect sRGB profile").
    const bool damaged = decoderSaid.rfind(kJpegDamaged, 0) == 0;
    out.decoderWarning = path.string() + ": the image decoder said \"" + decoderSaid + "\"" +
                         (damaged ? ": parts of the photo may be damaged" : "");
  }
  return out;
}

}  // namespace pw::modeling
