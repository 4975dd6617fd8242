// The viewer's --script files (app/view/window/view_script.h): events land on their
// frames, holds release on the frame they end, and every bad line names its file and
// line in one message.
#include "app/view/window/view_script.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace {

using skylit::app::view::window::InputState;
using skylit::app::view::window::ScriptEvent;
using skylit::app::view::window::ViewScript;

TEST(ViewScript, PressHoldLookAndCommandsLandOnTheirFrames) {
  const ViewScript s = ViewScript::parse(
      "# comment\n0 press 3\n2 hold w 3   # w for frames 2, 3, 4\n3 look 10 -4\n4 scrub 2026-06-21T10:00:00Z\n"
      "5 pose 1 2 3 90 -45\n6 screenshot a.png\n6 quit\n",
      "s.txt");
  InputState in;
  s.feed(0, in);
  ASSERT_EQ(in.pressed.size(), 1u);
  EXPECT_EQ(in.pressed[0], "3");
  EXPECT_FALSE(in.is_held("3"));
  in.end_frame();
  for (int f = 1; f <= 5; ++f) {
    s.feed(f, in);
    EXPECT_EQ(in.is_held("w"), f >= 2 && f < 5) << "frame " << f;
    if (f == 3) {
      EXPECT_EQ(in.look, glm::dvec2(10, -4));
    }
    in.end_frame();
  }
  const auto at4 = s.commands_at(4);
  ASSERT_EQ(at4.size(), 1u);
  EXPECT_EQ(at4[0].verb, ScriptEvent::Verb::Scrub);
  EXPECT_DOUBLE_EQ(at4[0].unix_seconds, 1782036000.0);  // 2026-06-21T10:00:00Z
  const auto at5 = s.commands_at(5);
  ASSERT_EQ(at5.size(), 1u);
  EXPECT_EQ(at5[0].eye, glm::dvec3(1, 2, 3));
  EXPECT_EQ(s.commands_at(6).size(), 2u);
  EXPECT_EQ(s.last_frame(), 6);
}

TEST(ViewScript, ADragHoldsTheButtonAndMovesTheCursorEvenly) {
  const ViewScript s = ViewScript::parse("2 drag 100 50 200 10 4\n", "s.txt");
  InputState in;
  for (int f = 0; f <= 8; ++f) {
    s.feed(f, in);
    EXPECT_EQ(in.brush_click, f == 2) << f;
    EXPECT_EQ(in.brush_held, f >= 2 && f <= 6) << f;  // down on frames 2 … 6, up on 7
    if (f >= 2 && f <= 6) {
      const double t = (f - 2) / 4.0;
      EXPECT_EQ(in.cursor, glm::dvec2(100 + 100 * t, 50 - 40 * t)) << f;
    }
    in.end_frame();
  }
  EXPECT_EQ(in.cursor, glm::dvec2(200, 10));
  EXPECT_EQ(s.last_frame(), 7);
}

TEST(ViewScript, BadLinesNameTheFileAndLine) {
  const char* bad[] = {"x press w", "0 jump", "0 press nosuchkey", "0 hold w 0", "0 scrub yesterday",
                       "0 pose 1 2 3 0 95", "0 look 1", "0 quit now", "0 drag 1 2 3 4",
                       "0 drag 1 2 3 4 0"};
  for (const char* line : bad) {
    try {
      ViewScript::parse(std::string("0 press w\n") + line + "\n", "s.txt");
      ADD_FAILURE() << "accepted: " << line;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("s.txt:2: ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
