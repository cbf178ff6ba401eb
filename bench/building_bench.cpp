// building_bench: building mode's costs (editor/edit/building_mode.h), medians.
//  - one plan drag step (what a mouse move costs the plan: the snap search, the layout
//    attached or placed, every corridor placed again, modeling::planBuilding's check)
//    for 2 and 20 corridors, against placing the corridors alone;
//  - opening a two-corridor layout of ground-truth shots (Building::open: two shot files,
//    their photos, two measurements), against opening one of its shots alone;
//  - W in the plan: the whole building's model from the shots in memory
//    (Building::buildModel: modeling::buildModel), against one corridor's (buildCorridorScene, the shot
//    editor's W);
//  - building mode's 3D preview pane: the same model with the preview's reduced texture
//    budget (buildBuildingModel, what its worker thread builds before staging it),
//    against W's.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "bench/bench_timing.h"
#include "editor/edit/building.h"
#include "editor/edit/model_walk.h"
#include "editor/edit/plan.h"
#include "editor/edit/preview_build.h"
#include "tests/support/groundtruth.h"

namespace {

using namespace pw;
using namespace pw::edit;
namespace fs = std::filesystem;

constexpr int kRuns = 7;
constexpr int kSteps = 60;  // a one-second drag

// `n` corridors in a row along x, 3 x 14.5 m, the last one dragged.
modeling::Layout row(int n) {
  modeling::Layout layout;
  for (int i = 0; i < n; ++i) {
    modeling::LayoutEntry e;
    e.name = "c" + std::to_string(i);
    e.position = {5.0 * i, 0, 0};
    layout.corridors.push_back(e);
  }
  return layout;
}

// A drag of the last corridor onto the first's far wall, kSteps steps.
void drag(const modeling::Layout& before, const std::vector<metrology::Dimensions>& boxes, bool snapAndCheck) {
  const int guest = int(before.corridors.size()) - 1;
  const PlanPose from = poseOf(placeCorridors(before, boxes)[guest]);
  const PlanPose to{{0.1, -14.4}, 0};
  for (int s = 1; s <= kSteps; ++s) {
    const double t = double(s) / kSteps;
    const PlanPose pose{from.nearCentre + t * (to.nearCentre - from.nearCentre), 0};
    if (!snapAndCheck) {
      volatile double x = placeCorridors(placeCorridor(before, guest, pose), boxes)[guest][3].x;
      (void)x;
      continue;
    }
    const auto world = placeCorridors(before, boxes);
    const auto snap = findSnap(before, boxes, world, guest, pose, 0.8);
    const modeling::Layout live =
        snap ? attachCorridor(before, guest, snap->attach, nullptr) : placeCorridor(before, guest, pose);
    volatile double x = placeCorridors(live, boxes)[guest][3].x;
    (void)x;
    volatile bool ok = modeling::planBuilding(live, boxes).ok();
    (void)ok;
  }
}

}  // namespace

int main() {
  std::printf("building_bench: medians of %d runs\n", kRuns);
  for (const int n : {2, 20}) {
    const modeling::Layout layout = row(n);
    const std::vector<metrology::Dimensions> boxes(n, metrology::Dimensions{3.0, 3.2, 14.5});
    const double placing = bench::medianMs(kRuns, [&] { drag(layout, boxes, false); }) / kSteps;
    const double step = bench::medianMs(kRuns, [&] { drag(layout, boxes, true); }) / kSteps;
    std::printf("plan drag step, %2d corridors: %.4f ms (baseline, placing alone: %.4f ms)\n", n, step, placing);
  }

  const fs::path dir = fs::path(PW_BINARY_DIR) / "bench-output" / "building";
  fs::create_directories(dir);
  for (const char* name : {"corridor_b", "corridor_a"}) {
    const groundtruth::GroundTruth truth = groundtruth::loadGroundTruth(name);
    fs::copy_file(truth.image, dir / truth.image.filename(), fs::copy_options::overwrite_existing);
    fs::copy_file(truth.shot, dir / truth.shot.filename(), fs::copy_options::overwrite_existing);
  }
  const fs::path path = dir / "building.json";
  std::ofstream(path) << R"({"corridors": [{"name": "hall", "shot": "corridor_b.json"},
    {"name": "wing", "shot": "corridor_a.json", "attach": {"to": "hall", "side": "far", "offset_m": 0}}]})";
  const double oneShot = bench::medianMs(kRuns, [&] { (void)Document::open(dir / "corridor_b.json"); });
  const double opening = bench::medianMs(kRuns, [&] { (void)Building::open(path); });
  std::printf("open a 2-corridor layout: %.1f ms (baseline, one of its shots: %.1f ms)\n", opening, oneShot);

  auto building = Building::open(path);
  if (!building) {
    std::fprintf(stderr, "error: %s\n", building.message().c_str());
    return 1;
  }
  auto shots = building->measuredShots(nullptr);
  if (!shots) {
    std::fprintf(stderr, "error: %s\n", shots.message().c_str());
    return 1;
  }
  const modeling::MeasuredShot& hall = shots->front();
  const double single = bench::medianMs(kRuns, [&] {
    (void)buildCorridorScene(hall.loaded.shot, hall.loaded.image, hall.measurement);
  });
  const double whole = bench::medianMs(kRuns, [&] { (void)building->buildModel(nullptr); });
  std::printf("W in the plan, the building's model: %.1f ms (baseline, one corridor's: %.1f ms)\n", whole, single);
  const modeling::ModelOptions reduced = previewModelOptions(PreviewResolution::kReduced);
  const double pane = bench::medianMs(kRuns, [&] { (void)buildBuildingModel(building->layout(), *shots, reduced, "b"); });
  std::printf("the plan's 3D preview, the building's reduced model: %.1f ms (baseline, W's: %.1f ms)\n", pane, whole);
  return 0;
}
