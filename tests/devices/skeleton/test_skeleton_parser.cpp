// Skeleton JSON datagrams: documented example, round trip, and malformed input.
#include <gtest/gtest.h>

#include <string>

#include "devices/skeleton/SkeletonParser.h"

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
