// Skeleton JSON datagrams: documented example, round trip, and malformed input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "devices/skeleton/SkeletonParser.h"
#include "devices/skeleton/StartOrigin.h"

using namespace armtrack::devices::skeleton;

TEST(SkeletonParser, DocumentedExample) {
  const std::string d =
      R"({"v":1,"t":12.345,"frame":17,"side":"right",)"
      R"("joints":{"shoulder":[0.1,0.2,2.0],"elbow":[0.15,-0.1,2.05],"wrist":[0.2,-0.35,1.9]},)"
      R"("confidence":{"shoulder":1.0,"elbow":0.9,"wrist":0.5}})";
  SkeletonParser p;
  const auto f = p.parseDatagram(d);
  ASSERT_TRUE(f) << p.errors().last();
  EXPECT_DOUBLE_EQ(f->t, 12.345);
  EXPECT_EQ(f->frame, 17u);
  EXPECT_EQ(f->side, Side::Right);
  ASSERT_TRUE(f->elbow && f->wrist && f->shoulder);
  EXPECT_DOUBLE_EQ(f->elbow->position[1], -0.1);
  EXPECT_DOUBLE_EQ(f->wrist->position[2], 1.9);
  EXPECT_DOUBLE_EQ(*f->wrist->confidence, 0.5);
}

TEST(SkeletonParser, RoundTripAndMissingJoints) {
  Frame f;
  f.t = 1.5;
  f.frame = 3;
  f.side = Side::Left;
  f.wrist = Joint{{0.1, 0.2, 0.3}, std::nullopt};
  SkeletonParser p;
  const auto g = p.parseDatagram(encode(f));
  ASSERT_TRUE(g);
  EXPECT_EQ(g->side, Side::Left);
  EXPECT_FALSE(g->elbow);
  EXPECT_FALSE(g->wrist->confidence);
  EXPECT_EQ(g->wrist->position, f.wrist->position);
  // A joint sent as null is untracked; unknown keys are ignored.
  EXPECT_TRUE(p.parseDatagram(
      R"({"v":1,"t":2,"frame":5,"side":"right","joints":{"elbow":null,"wrist":[0,0,1],"hand":[0,0,0]},"extra":true})"));
  EXPECT_EQ(p.droppedFrames(), 1u);  // frame 4 never came
  EXPECT_EQ(p.errors().count(), 0u);
}

TEST(SkeletonParser, OutOfOrderFramesAreReorderedNotDropped) {
  SkeletonParser p;
  const auto frame = [&](std::uint64_t n) {
    Frame f;
    f.t = 0.01 * static_cast<double>(n);
    f.frame = n;
    f.wrist = Joint{{0.1, 0.2, 0.3}, std::nullopt};
    return p.parseDatagram(encode(f));
  };
  // 10 11 13 12 15 14 14 17: two overtaken (12, 14), one duplicate (14), one lost (16). The
  // overtaken ones are not returned (time never goes back) but are not counted as dropped.
  for (std::uint64_t n : {10, 11, 13}) ASSERT_TRUE(frame(n));
  EXPECT_FALSE(frame(12));
  ASSERT_TRUE(frame(15));
  EXPECT_FALSE(frame(14));
  EXPECT_FALSE(frame(14));  // a duplicate
  ASSERT_TRUE(frame(17));
  EXPECT_EQ(p.droppedFrames() - p.reorderedFrames(), 1u);
  EXPECT_EQ(p.reorderedFrames(), 2u);
  EXPECT_EQ(p.duplicateFrames(), 1u);
  EXPECT_EQ(p.errors().count(), 0u);
  // A restarted tracker (frame 0 again, far behind) is followed anew, not counted.
  for (std::uint64_t n = 18; n < 200; ++n) ASSERT_TRUE(frame(n));
  ASSERT_TRUE(frame(0));
  ASSERT_TRUE(frame(1));
  EXPECT_EQ(p.droppedFrames() - p.reorderedFrames(), 1u);
}

TEST(SkeletonParser, MalformedDatagramsAreErrors) {
  const std::string bad[] = {
      "",
      "{",
      "[1,2,3]",
      R"({"v":2,"t":1,"frame":1,"side":"right","joints":{"wrist":[0,0,1]}})",
      R"({"v":1,"t":"x","frame":1,"side":"right","joints":{"wrist":[0,0,1]}})",
      R"({"v":1,"t":1,"frame":-1,"side":"right","joints":{"wrist":[0,0,1]}})",
      R"({"v":1,"t":1,"frame":1,"side":"up","joints":{"wrist":[0,0,1]}})",
      R"({"v":1,"t":1,"frame":1,"side":"right","joints":{"wrist":[0,0]}})",
      R"({"v":1,"t":1,"frame":1,"side":"right","joints":{"wrist":[0,0,"a"]}})",
      R"({"v":1,"t":1,"frame":1,"side":"right","joints":{"wrist":[0,0,NaN]}})",
      R"({"v":1,"t":1,"frame":1,"side":"right","joints":{"wrist":[0,0,1e999]}})",
      R"({"v":1,"t":1,"frame":1,"side":"right","joints":{"wrist":[0,0,100]}})",
      R"({"v":1,"t":1,"frame":1,"side":"right","joints":{}})",
      R"({"v":1,"t":1,"frame":1,"side":"right","joints":{"wrist":[0,0,1]},"confidence":{"wrist":2}})",
      R"({"v":1,"t":1,"frame":1,"side":"right","joints":{"wrist":[0,0,1]}} trailing)",
      std::string(10000, ' '),
      std::string("{\"v\":1\0}", 8),
  };
  const std::string good = R"({"v":1,"t":1,"frame":1,"side":"right","joints":{"wrist":[0,0,1]}})";
  for (const std::string& d : bad) {
    SkeletonParser p;
    EXPECT_FALSE(p.parseDatagram(d)) << d.substr(0, 80);
    EXPECT_EQ(p.errors().count(), 1u) << d.substr(0, 80);
    EXPECT_NE(p.errors().last().find("datagram 0"), std::string::npos);
    EXPECT_TRUE(p.parseDatagram(good));
  }
}

TEST(SkeletonParser, ParseErrorsGiveTheByteOffset) {
  SkeletonParser p;
  EXPECT_FALSE(p.parseDatagram(R"({"v":1,"t":1,)"));
  EXPECT_GT(p.errors().recent().back().offset, 0u);
}

// The world origin of origin=start: the shoulder's per-axis median over the first second, then
// fixed. A wild first frame (a tracker locking on) moves it only until the median outvotes it.
TEST(StartOrigin, MedianOfTheFirstSecondThenFixed) {
  StartOrigin o(1.0);
  EXPECT_FALSE(o.origin());
  const std::array<double, 3> wild{0.6, -0.4, 2.5}, still{0.25, 0.5, 2.0};
  o.add(10.0, wild);
  ASSERT_TRUE(o.origin());
  EXPECT_EQ(*o.origin(), wild);  // the first frame's own shoulder until more arrive
  for (int k = 1; k <= 30; ++k) {
    // Noise of +-1 cm about the still shoulder, symmetric, so the median is the still shoulder.
    const double n = (k % 2 ? 0.01 : -0.01) * ((k % 4) < 2 ? 1.0 : 0.5);
    o.add(10.0 + k / 31.0, {still[0] + n, still[1] - n, still[2] + n});
  }
  EXPECT_FALSE(o.fixed());
  const std::array<double, 3> before = *o.origin();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(before[i], still[i], 0.0051) << i;
  // After the window a leaning trunk's shoulder no longer moves the origin.
  o.add(11.2, {0.3, 0.6, 1.95});
  EXPECT_TRUE(o.fixed());
  for (int k = 0; k < 100; ++k) o.add(11.3 + k, {0.4, 0.7, 1.9});
  EXPECT_EQ(*o.origin(), before);
  o.reset();
  EXPECT_FALSE(o.origin());
  EXPECT_FALSE(o.fixed());
}

// A tracker clock that goes back, or a flood of frames within the window, ends the window early;
// memory stays bounded.
TEST(StartOrigin, ClockGoingBackOrAFloodFixesIt) {
  StartOrigin a(1.0);
  a.add(5.0, {0.1, 0.2, 0.3});
  a.add(5.1, {0.1, 0.2, 0.5});
  a.add(1.0, {9.0, 9.0, 9.0});  // restarted clock
  EXPECT_TRUE(a.fixed());
  EXPECT_DOUBLE_EQ((*a.origin())[2], 0.4);
  StartOrigin b(1.0);
  for (std::size_t k = 0; k < StartOrigin::kMaxFrames + 10; ++k)
    b.add(1e-6 * static_cast<double>(k), {0.0, 0.0, static_cast<double>(k % 2)});
  EXPECT_TRUE(b.fixed());
  EXPECT_DOUBLE_EQ((*b.origin())[2], 0.5);
}
