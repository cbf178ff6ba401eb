// photowalk's own ground truth: the POV-Ray corridors tests/groundtruth/make_corridors.py
// writes into PW_GROUNDTRUTH_DIR at build time (NAME.png, NAME.json with the shot
// part and the exact answers). Every test that reads them fails, never skips, when
// one is missing.
#pragma once

#include <array>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace pw::groundtruth {

struct GroundTruth {
  std::string name;            // corridor_a ... corridor_h, clutter_1 ... clutter_9
  std::filesystem::path shot;  // NAME.json: a shot file photowalk reads (answers are extra fields)
  std::filesystem::path image;
  int imageWidth = 0, imageHeight = 0;
  double focalPx = 0;
  glm::dvec2 principalPointPx{0.0};
  double cameraHeightM = 0;
  // The answers.
  double widthM = 0, heightM = 0, lengthM = 0;
  double farWallDistanceM = 0;  // from the camera's plane z = eye.z to the far wall, along the corridor
  glm::dvec3 cameraPositionM{0.0};  // model frame (corridor_frame.h)
  double yawDeg = 0, pitchDeg = 0, rollDeg = 0;
  std::array<glm::dvec2, 8> cornersPx{};  // P1..P8, exact projections
  std::string walls, floor;             // materials
  bool straightAhead() const { return yawDeg == 0 && pitchDeg == 0 && rollDeg == 0; }
};

// The scenes make_corridors.py renders (tests/groundtruth/CMakeLists.txt lists them too).
inline const std::vector<std::string>& groundTruthNames() {
  static const std::vector<std::string> names = {"corridor_a", "corridor_b", "corridor_c", "corridor_d",
                                                 "corridor_e", "corridor_f", "corridor_g", "corridor_h"};
  return names;
}

// The cluttered corridors (issue 15): furniture, people, posters, side doors, lamps,
// uneven light, roll up to 10 degrees; clutter_9 pale with little contrast. Not in
// loadAllGroundTruth: the tests of the clean corridors stay as they were.
inline const std::vector<std::string>& clutterNames() {
  static const std::vector<std::string> names = {"clutter_1", "clutter_2", "clutter_3", "clutter_4", "clutter_5",
                                                 "clutter_6", "clutter_7", "clutter_8", "clutter_9"};
  return names;
}

inline std::filesystem::path groundTruthShot(const std::string& name) {
  return std::filesystem::path(PW_GROUNDTRUTH_DIR) / (name + ".json");
}

// Throws std::runtime_error when the scene's files are not there (GoogleTest reports
// it as a failure).
inline GroundTruth loadGroundTruth(const std::string& name) {
  GroundTruth g;
  g.name = name;
  g.shot = groundTruthShot(name);
  std::ifstream in(g.shot);
  if (!in) throw std::runtime_error("no " + g.shot.string() + " (the build renders it: target groundtruth)");
  const nlohmann::json j = nlohmann::json::parse(in);
  g.image = g.shot.parent_path() / j.at("image").get<std::string>();
  if (!std::filesystem::exists(g.image)) throw std::runtime_error("no " + g.image.string());
  g.imageWidth = j.at("image_size")[0], g.imageHeight = j.at("image_size")[1];
  g.focalPx = j.at("focal_px");
  g.principalPointPx = {j.at("principal_point")[0], j.at("principal_point")[1]};
  g.cameraHeightM = j.at("camera_height_m");
  g.widthM = j.at("width_m"), g.heightM = j.at("height_m"), g.lengthM = j.at("length_m");
  g.farWallDistanceM = j.at("far_wall_distance_m");
  const auto& eye = j.at("camera_position_m");
  g.cameraPositionM = {eye[0], eye[1], eye[2]};
  g.yawDeg = j.at("yaw_deg"), g.pitchDeg = j.at("pitch_deg"), g.rollDeg = j.at("roll_deg");
  for (int k = 0; k < 8; ++k) {
    const auto& p = j.at("corners_px").at("P" + std::to_string(k + 1));
    g.cornersPx[k] = {p[0], p[1]};
  }
  g.walls = j.at("materials").at("walls"), g.floor = j.at("materials").at("floor");
  return g;
}

inline std::vector<GroundTruth> loadAllGroundTruth() {
  std::vector<GroundTruth> all;
  for (const std::string& name : groundTruthNames()) all.push_back(loadGroundTruth(name));
  return all;
}

}  // namespace pw::groundtruth
