// Running `photowalk walk` from a test (under xvfb-run) and reading what it leaves:
// the trace (--trace) and the captured frames.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/run_command.h"

namespace pw::walk {

inline test::CommandRun photowalk(const std::string& arguments) {
  return test::runCommand(std::string(PW_PHOTOWALK) + " " + arguments);
}

// One row of a --trace file: the camera after each simulated frame.
struct TraceRow {
  long frame;
  double x, y, z, yawDeg, pitchDeg;
};

inline std::vector<TraceRow> readTrace(const std::filesystem::path& path) {
  std::vector<TraceRow> rows;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    TraceRow r{};
    if (std::sscanf(line.c_str(), "%ld,%lf,%lf,%lf,%lf,%lf", &r.frame, &r.x, &r.y, &r.z, &r.yawDeg, &r.pitchDeg) == 6) {
      rows.push_back(r);
    }
  }
  return rows;
}

}  // namespace pw::walk
