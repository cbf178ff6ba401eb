#include "editor/edit/preview_build.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <opencv2/imgproc.hpp>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include "editor/edit/document.h"
#include "editor/edit/model_walk.h"
#include "metrology/measure.h"

namespace pw::edit {

cv::Mat reducePhoto(const cv::Mat& photo, int longestSidePx) {
  const int side = std::max(photo.cols, photo.rows);
  if (photo.empty() || side <= longestSidePx) return photo;
  const double k = double(longestSidePx) / side;
  cv::Mat reduced;
  cv::resize(photo, reduced, cv::Size(std::max(1, int(std::lround(photo.cols * k))), std::max(1, int(std::lround(photo.rows * k)))),
             0, 0, cv::INTER_AREA);
  return reduced;
}

metrology::Shot scaledShot(const metrology::Shot& shot, glm::ivec2 size) {
  if (shot.imageWidth == size.x && shot.imageHeight == size.y) return shot;
  const glm::dvec2 k = glm::dvec2(size) / glm::dvec2(shot.imageWidth, shot.imageHeight);
  const auto scale = [&](const glm::dvec2& p) { return (p + 0.5) * k - 0.5; };
  metrology::Shot scaled = shot;
  scaled.principalPointPx = scale(shot.principalPoint());
  scaled.imageWidth = size.x;
  scaled.imageHeight = size.y;
  scaled.focalPx = shot.focalPx * k.x;
  scaled.focalMm.reset();
  for (glm::dvec2& corner : scaled.cornersPx) corner = scale(corner);
  for (metrology::Cutout& cutout : scaled.cutouts) {
    for (glm::dvec2& p : cutout.outlinePx) p = scale(p);
  }
  return scaled;
}

bool takesPlaceOf(const PreviewBuilder::Done& done, uint64_t openDocumentId, const std::optional<ShownBuild>& shown,
                  const metrology::Shot& current) {
  if (done.documentId != openDocumentId) return false;
  const auto order = [](uint64_t request, PreviewResolution from) {
    return 2 * request + (from == PreviewResolution::kFull ? 1 : 0);
  };
  if (shown && shown->documentId == openDocumentId && order(done.id, done.from) <= order(shown->request, shown->from)) {
    return false;
  }
  return done.from == PreviewResolution::kReduced || done.shot == current;
}

const char* resolutionName(PreviewResolution resolution) {
  return resolution == PreviewResolution::kReduced ? "reduced" : "full";
}

modeling::ModelOptions previewModelOptions(PreviewResolution resolution) {
  modeling::ModelOptions options;
  if (resolution == PreviewResolution::kReduced) {
    options.maxTextureSide = 1024;
    options.maxTexturePixels = 0.08e6;
    options.photoOnly = true;  // the drag's model: as fast as it can be; the full one has everything
  }
  return options;
}

Result<PreviewModel> buildPreviewModel(const engine::Renderer& renderer, const metrology::Shot& shot,
                                       const cv::Mat& photo, PreviewResolution resolution,
                                       modeling::CutOutCache* cutOuts) {
  const auto start = std::chrono::steady_clock::now();
  const metrology::Shot inPhoto = scaledShot(shot, {photo.cols, photo.rows});
  auto measurement = metrology::measureCorridor(inPhoto);
  if (!measurement) return measurement.error();
  modeling::ModelOptions options = previewModelOptions(resolution);
  options.cutOutCache = cutOuts;
  auto scene = buildCorridorScene(inPhoto, photo, *measurement, options);
  if (!scene) return scene.error();
  if (scene->viewpoints.empty()) return makeError("the model has no Photo viewpoint");
  const engine::Camera photoCamera = engine::cameraFromViewpoint(scene->viewpoints.front());
  const engine::Bounds bounds = engine::sceneBounds(*scene);
  auto staged = renderer.stageScene(*scene);
  if (!staged) return staged.error();
  PreviewModel model{std::move(*staged), std::make_shared<const engine::Scene>(std::move(*scene)), photoCamera,
                     bounds, {photo.cols, photo.rows}, 0.0};
  model.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return model;
}

PreviewBuilder::PreviewBuilder(const engine::Renderer& renderer, int reducedSidePx)
    : renderer_(renderer),
      reducedSidePx_(reducedSidePx),
      worker_([this](Request& request, const auto& emit, const auto& superseded) { build(request, emit, superseded); }) {}

PreviewBuilder::~PreviewBuilder() = default;

const cv::Mat& PreviewBuilder::reducedFor(const Request& request) {
  if (reducedDocument_ != request.documentId || reduced_.empty()) {
    reduced_ = reducePhoto(request.photo, reducedSidePx_);
    reducedDocument_ = request.documentId;
  }
  return reduced_;
}

void lowerThreadPriority() {
#ifdef __linux__
  (void)setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 5);
#endif
}

void PreviewBuilder::build(Request& request, const LatestWorker<Request, Done>::Emit& emit,
                           const LatestWorker<Request, Done>::Superseded& superseded) {
  const auto finish = [&](PreviewResolution from, Result<PreviewModel> model) {
    emit({request.id, request.documentId, request.shot, from, std::move(model)});
  };
  const cv::Mat& reduced = reducedFor(request);
  if (request.reducedOnly || request.reducedFirst) {
    finish(PreviewResolution::kReduced, buildPreviewModel(renderer_, request.shot, reduced, PreviewResolution::kReduced, &cutOuts_));
    if (superseded()) return;  // a newer shot came meanwhile: build that instead
  }
  if (!request.reducedOnly) {
    finish(PreviewResolution::kFull, buildPreviewModel(renderer_, request.shot, request.photo, PreviewResolution::kFull, &cutOuts_));
  }
}

}  // namespace pw::edit
