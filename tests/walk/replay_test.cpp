#include "editor/walk/replay.h"

#include <gtest/gtest.h>

#include "editor/app/key_names.h"

namespace pw::walk {
namespace {

TEST(Replay, ParsesEveryEventKind) {
  auto events = parseReplay(
      "# walk\n10 key W down\n70 key W up\n5 mouse 12.5 -3\n80 viewpoint 2\n90 resize 640 480\n"
      "100 capture shots/a.png\n120 quit\n",
      "r.txt", "/tmp/base");
  ASSERT_TRUE(events.ok()) << events.message();
  ASSERT_EQ(events->size(), 7u);
  EXPECT_EQ((*events)[0].frame, 5);  // sorted by frame
  ASSERT_TRUE(std::holds_alternative<app::PointerMotionEvent>((*events)[0].what));
  EXPECT_DOUBLE_EQ(std::get<app::PointerMotionEvent>((*events)[0].what).dxPx, 12.5);
  ASSERT_TRUE(std::holds_alternative<app::KeyEvent>((*events)[1].what));
  EXPECT_EQ(std::get<app::KeyEvent>((*events)[1].what).key, app::keyCodeFromName("W"));
  EXPECT_TRUE(std::get<app::KeyEvent>((*events)[1].what).down);
  ASSERT_TRUE(std::holds_alternative<app::CaptureRequest>((*events)[5].what));
  EXPECT_EQ(std::get<app::CaptureRequest>((*events)[5].what).path, "/tmp/base/shots/a.png");
  EXPECT_TRUE(std::holds_alternative<app::QuitRequest>((*events)[6].what));
}

TEST(Replay, ErrorsGiveLineAndWhatWasExpected) {
  auto bad = parseReplay("1 key W down\n2 key NOPE down\n", "r.txt", ".");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("r.txt:2:"), std::string::npos);
  EXPECT_NE(bad.message().find("NOPE"), std::string::npos);
  EXPECT_FALSE(parseReplay("x key W down\n", "r", ".").ok());
  EXPECT_FALSE(parseReplay("3 jump\n", "r", ".").ok());
  EXPECT_FALSE(parseReplay("3 resize 0 10\n", "r", ".").ok());
  EXPECT_FALSE(parseReplay("3 key W sideways\n", "r", ".").ok());
  EXPECT_FALSE(parseReplay("3 quit now\n", "r", ".").ok());
}

TEST(Replay, KeyNamesFollowGlfw) {
  EXPECT_EQ(app::keyCodeFromName("W"), 87);
  EXPECT_EQ(app::keyCodeFromName("LEFT_SHIFT"), 340);
  EXPECT_EQ(app::keyCodeFromName("PAGE_UP"), 266);
  EXPECT_EQ(app::keyCodeFromName("F12"), 301);
  EXPECT_EQ(app::keyCodeFromName("w"), -1);
}

}  // namespace
}  // namespace pw::walk
