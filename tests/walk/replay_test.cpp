#include "editor/walk/replay.h"

#include <gtest/gtest.h>

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
  EXPECT_EQ((*events)[0].kind, ReplayEvent::Kind::kMouse);
  EXPECT_DOUBLE_EQ((*events)[0].dx, 12.5);
  EXPECT_EQ((*events)[1].name, "W");
  EXPECT_TRUE((*events)[1].down);
  EXPECT_EQ((*events)[5].name, "/tmp/base/shots/a.png");
  EXPECT_EQ((*events)[6].kind, ReplayEvent::Kind::kQuit);
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
  EXPECT_EQ(keyCodeFromName("W"), 87);
  EXPECT_EQ(keyCodeFromName("LEFT_SHIFT"), 340);
  EXPECT_EQ(keyCodeFromName("PAGE_UP"), 266);
  EXPECT_EQ(keyCodeFromName("F12"), 301);
  EXPECT_EQ(keyCodeFromName("w"), -1);
}

}  // namespace
}  // namespace pw::walk
