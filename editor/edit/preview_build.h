// Building the editor's 3D preview (preview.h) off the UI thread: the corridor model
// of a shot (model_walk.h's buildCorridorScene), cut from a reduced photo while a
// corner is dragged (about 1024 px on its longest side, so that a rebuild keeps up)
// or from the full photo once it is let go, and staged for the GPU
// (Renderer::stageScene) on a worker thread, so that the frame only swaps it in.
//
//   PreviewBuilder builder(renderer);
//   builder.request({.id = 1, .documentId = 1, .shot = s, .photo = photo, .reducedOnly = true});
//   for (PreviewBuilder::Done& done : builder.takeDone()) renderer.replaceScene(h, std::move(done.model->staged));
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include "base/result.h"
#include "editor/edit/latest_worker.h"
#include "engine/gpu/renderer.h"
#include "engine/scene/camera.h"
#include "engine/scene/scene.h"
#include "metrology/shot.h"
#include "modeling/corridor_model.h"

namespace pw::edit {

// The longest side of the photo a preview is cut from while a corner is dragged.
inline constexpr int kReducedPhotoSidePx = 1024;

// `photo` (BGR) resized with area averaging so that its longest side is at most
// `longestSidePx`; the photo itself (shared, not copied) when it is no larger.
cv::Mat reducePhoto(const cv::Mat& photo, int longestSidePx);

// `shot` in the pixels of its photo resized to `size` (pixel centres scaled:
// (p + 0.5) * size / imageSize - 0.5, the corners and the cutouts' outlines; the focal
// length in pixels with the width).
// Dimensions in metres measure the same; focalMm is dropped (focalPx says it).
metrology::Shot scaledShot(const metrology::Shot& shot, glm::ivec2 size);

enum class PreviewResolution { kReduced, kFull };
const char* resolutionName(PreviewResolution resolution);  // "reduced", "full"

// A model ready to be swapped in (Renderer::addScene or replaceScene), with what the
// preview's camera needs of it.
struct PreviewModel {
  engine::StagedScene staged;
  // The scene staged (its textures shared, not copied): the walk's model when the
  // preview's is of the full photo (EditMode::walk, so that W does not build it again).
  std::shared_ptr<const engine::Scene> scene;
  engine::Camera photoCamera;  // the scene's "Photo" viewpoint: the photo's camera
  engine::Bounds bounds;       // of the whole scene, world metres
  glm::ivec2 photoSizePx{0};   // of the photo it was cut from
  double buildMs = 0;          // measuring, cutting and staging, wall clock
};

// The model's texture budget: kFull, the walk's and `photowalk build`'s (up to 3
// megapixels a surface); kReduced, enough for a pane a few hundred pixels wide
// (0.08 megapixels a surface), since the texels, not the photo's size, cost the time.
modeling::ModelOptions previewModelOptions(PreviewResolution resolution);

// Measures `shot` (in the pixels of the document's full photo) again in the pixels of
// `photo` (BGR; the full photo or a reduced one), builds its corridor model with
// previewModelOptions(resolution) and stages it on `renderer`. Any thread (`cutOuts`,
// where the objects' cut-outs are kept between builds, one thread at a time). Errors:
// the corners cannot be measured or modelled (the message says why), the staging failing.
Result<PreviewModel> buildPreviewModel(const engine::Renderer& renderer, const metrology::Shot& shot,
                                       const cv::Mat& photo, PreviewResolution resolution,
                                       modeling::CutOutCache* cutOuts = nullptr);

// One worker thread that builds what is asked last. A request waiting is replaced by a
// newer one, so a drag's steps never queue up; the worker builds one at a time (a full
// build is not interrupted: a newer request waits for it, up to about a second).
class PreviewBuilder {
 public:
  struct Request {
    uint64_t id = 0;          // increasing; Done::id says which request a result is of
    uint64_t documentId = 0;  // the photo's: the reduced photo is made once per document
    metrology::Shot shot;
    cv::Mat photo;            // the document's full photo, BGR (shared; never written)
    bool reducedOnly = false;   // a drag step: the reduced photo only
    bool reducedFirst = false;  // else: a reduced model first, then the full one (unless a newer request came)
    // (A photo no larger than the reduced side is its own reduced photo; the reduced
    // model still has the smaller texture budget.)
  };
  struct Done {
    uint64_t id = 0;
    uint64_t documentId = 0;
    metrology::Shot shot;
    PreviewResolution from = PreviewResolution::kFull;
    Result<PreviewModel> model = makeError("not built");
  };

  // `renderer` is borrowed (stageScene only) and must outlive the builder.
  explicit PreviewBuilder(const engine::Renderer& renderer, int reducedSidePx = kReducedPhotoSidePx);
  ~PreviewBuilder();  // waits for the build in progress, then stops
  PreviewBuilder(const PreviewBuilder&) = delete;
  PreviewBuilder& operator=(const PreviewBuilder&) = delete;

  void request(Request request) { worker_.request(std::move(request)); }
  // What finished since the last call, oldest first. Never waits for a build.
  std::vector<Done> takeDone() { return worker_.takeDone(); }
  // A request waits or is being built.
  bool busy() const { return worker_.busy(); }

 private:
  void build(Request& request, const LatestWorker<Request, Done>::Emit& emit,
             const LatestWorker<Request, Done>::Superseded& superseded);  // worker thread
  const cv::Mat& reducedFor(const Request& request);  // worker thread only

  const engine::Renderer& renderer_;
  const int reducedSidePx_;
  // The worker's own: the reduced photo of the document last built.
  uint64_t reducedDocument_ = 0;
  cv::Mat reduced_;
  modeling::CutOutCache cutOuts_;  // the worker's: GrabCut and the fill once per photo and outlines
  LatestWorker<Request, Done> worker_;  // last: its thread starts once the rest exists
};

// The model a preview shows: which document's, which request's, from which photo.
struct ShownBuild {
  uint64_t documentId = 0;
  uint64_t request = 0;
  PreviewResolution from = PreviewResolution::kFull;
};

// Whether a finished build takes the place of the one shown: it is of the document
// open, newer than the one shown (by request; of one request, the reduced model comes
// before the full one), and, if built from the full photo, of the shot as it is now
// (else a newer build has been asked for; a reduced model of a drag's earlier step
// is still shown, so that the preview follows the drag).
bool takesPlaceOf(const PreviewBuilder::Done& done, uint64_t openDocumentId, const std::optional<ShownBuild>& shown,
                  const metrology::Shot& current);

}  // namespace pw::edit
