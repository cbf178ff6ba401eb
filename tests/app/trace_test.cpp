// Traces: CSV with the walk's columns as it always wrote them, JSON lines for runs with
// several modes, and errors for rows a CSV cannot hold.
#include "editor/app/trace.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

namespace pw::app {
namespace {
namespace fs = std::filesystem;

fs::path outputDir() {
  const fs::path dir = fs::path(PW_BINARY_DIR) / "test-output" / "app";
  fs::create_directories(dir);
  return dir;
}

std::string readAll(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TraceRow walkRow(double z) {
  TraceRow row;
  row.add("x", 0.0);
  row.add("y", 1.7);
  row.add("z", z);
  row.add("yaw_deg", -0.00001, 4);
  row.add("pitch_deg", 12.345678, 4);
  return row;
}

TEST(Trace, CsvHasAHeaderAndEachNumberAtItsDecimals) {
  const fs::path path = outputDir() / "trace.csv";
  {
    auto trace = Trace::open(path, TraceFormat::kCsv);
    ASSERT_TRUE(trace.ok()) << trace.message();
    ASSERT_TRUE((*trace)->write(0, "walk", walkRow(-0.0233333)).ok());
    ASSERT_TRUE((*trace)->write(1, "walk", walkRow(-0.0466667)).ok());
    // Another mode's columns do not fit the header.
    TraceRow other;
    other.add("zoom", 2.0);
    auto refused = (*trace)->write(2, "edit", other);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.message().find("mode 'edit' traces other columns"), std::string::npos) << refused.message();
    // Nor does a value that is not a number.
    TraceRow text = walkRow(0);
    text.add("name", nlohmann::ordered_json("a,b"));
    EXPECT_FALSE((*trace)->write(3, "walk", text).ok());
  }
  EXPECT_EQ(readAll(path),
            "frame,x,y,z,yaw_deg,pitch_deg\n"
            "0,0.000000,1.700000,-0.023333,-0.0000,12.3457\n"
            "1,0.000000,1.700000,-0.046667,-0.0000,12.3457\n");
}

TEST(Trace, JsonLinesCarryTheModeAndStructuredFields) {
  const fs::path path = outputDir() / "trace.jsonl";
  {
    auto trace = Trace::open(path, TraceFormat::kJsonLines);
    ASSERT_TRUE(trace.ok()) << trace.message();
    ASSERT_TRUE((*trace)->write(7, "walk", walkRow(-1.5)).ok());
    TraceRow edit;
    edit.add("image_to_window", nlohmann::ordered_json{{"scale", 2.0}, {"offset", {10, 20}}});
    edit.add("selected", nlohmann::ordered_json(nullptr));
    ASSERT_TRUE((*trace)->write(8, "edit", edit).ok());
  }
  std::ifstream in(path);
  std::string first, second, third;
  ASSERT_TRUE(std::getline(in, first));
  ASSERT_TRUE(std::getline(in, second));
  EXPECT_FALSE(std::getline(in, third));
  const auto a = nlohmann::json::parse(first), b = nlohmann::json::parse(second);
  EXPECT_EQ(a["frame"], 7);
  EXPECT_EQ(a["mode"], "walk");
  EXPECT_DOUBLE_EQ(a["z"].get<double>(), -1.5);
  EXPECT_DOUBLE_EQ(a["pitch_deg"].get<double>(), 12.345678);  // JSON keeps every digit
  EXPECT_EQ(second, R"({"frame":8,"mode":"edit","image_to_window":{"scale":2.0,"offset":[10,20]},"selected":null})");
  EXPECT_EQ(b["mode"], "edit");
}

TEST(Trace, UnwritablePathIsAnError) {
  auto trace = Trace::open(outputDir() / "no_such_folder" / "t.csv", TraceFormat::kCsv);
  ASSERT_FALSE(trace.ok());
  EXPECT_NE(trace.message().find("cannot write the trace"), std::string::npos) << trace.message();
}

}  // namespace
}  // namespace pw::app
