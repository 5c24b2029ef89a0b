// Shimmer3 stream parser against packets built byte by byte from the documented format.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "devices/shimmer3/Shimmer3Parser.h"

using namespace armtrack::devices::shimmer3;
using Bytes = std::vector<std::uint8_t>;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Inquiry response: 0x02, divider 64 (512 Hz) LE, config bytes (gyro range 0, WR accel range 0),
// 6 channels, buffer size 1, LN accel x y z, gyro x y z.
const Bytes kInquiry = {0x02, 0x40, 0x00, 0x00, 0x00, 0x00, 0x00, 0x06,
                        0x01, 0x00, 0x01, 0x02, 0x0A, 0x0B, 0x0C};

// A data packet for kInquiry: LN accel uint12 LE, gyro int16 BE.
Bytes packet(std::uint32_t ts, std::array<int, 3> ln, std::array<int, 3> gyro) {
  Bytes b = {0x00, static_cast<std::uint8_t>(ts), static_cast<std::uint8_t>(ts >> 8),
             static_cast<std::uint8_t>(ts >> 16)};
  for (int v : ln) {
    b.push_back(static_cast<std::uint8_t>(v));
    b.push_back(static_cast<std::uint8_t>(v >> 8));
  }
  for (int v : gyro) {
    const auto u = static_cast<std::uint16_t>(v);
    b.push_back(static_cast<std::uint8_t>(u >> 8));
    b.push_back(static_cast<std::uint8_t>(u));
  }
  return b;
}

void append(Bytes& a, const Bytes& b) {
  a.insert(a.end(), b.begin(), b.end());
}

// A realistic session: ACK + inquiry response, ACK for start, n packets 64 ticks apart, ACK stop.
Bytes session(int n, std::uint32_t ts0 = 1000) {
  Bytes s = {kAck};
  append(s, kInquiry);
  s.push_back(kAck);
  for (int k = 0; k < n; ++k)
    append(s, packet(ts0 + 64u * k, {2047 + k, 2047, 2130}, {k * 10, -k, 131}));
  s.push_back(kAck);
  return s;
}

std::vector<Sample> feedAll(Shimmer3Parser& p, const Bytes& b) {
  std::vector<Sample> out;
  p.feed(b, out);
  return out;
}

}  // namespace

TEST(Shimmer3Parser, HandComputedPacket) {
  // Timestamp 0x123456; accel raw x=2130, y=2047, z=1217; gyro raw x=131, y=-262, z=0.
  const Bytes bytes = {0xFF,  // ack
                       0x02, 0x40, 0x00, 0x00, 0x00, 0x00,
                       0x00, 0x06, 0x01,                    // inquiry response header
                       0x00, 0x01, 0x02, 0x0A, 0x0B, 0x0C,  // channel list
                       0x00, 0x56, 0x34, 0x12,              // data packet, timestamp LE
                       0x52, 0x08, 0xFF, 0x07, 0xC1, 0x04,  // LN accel, uint12 LE
                       0x00, 0x83, 0xFE, 0xFA, 0x00, 0x00,  // gyro, int16 BE
                       0xFF};                               // ack (stop)
  Shimmer3Parser p;
  const auto out = feedAll(p, bytes);
  ASSERT_EQ(out.size(), 1u);
  ASSERT_TRUE(p.config().has_value());
  EXPECT_DOUBLE_EQ(p.config()->samplingRateHz(), 512.0);
  const Sample& s = out[0];
  EXPECT_EQ(s.rawTimestamp, 0x123456u);
  EXPECT_EQ(s.ticks, 0x123456u);
  EXPECT_DOUBLE_EQ(s.t, 1193046.0 / 32768.0);
  // (raw - 2047) / 83 = (1, 0, -10) m/s^2; alignment [[0,-1,0],[-1,0,0],[0,0,-1]] -> (0, -1, 10).
  ASSERT_TRUE(s.hasAcc);
  EXPECT_NEAR(s.acc[0], 0.0, 1e-12);
  EXPECT_NEAR(s.acc[1], -1.0, 1e-12);
  EXPECT_NEAR(s.acc[2], 10.0, 1e-12);
  // raw / 131 = (1, -2, 0) deg/s; same alignment -> (2, -1, 0) deg/s.
  ASSERT_TRUE(s.hasGyro);
  EXPECT_NEAR(s.gyr[0], 2.0 * kDeg, 1e-12);
  EXPECT_NEAR(s.gyr[1], -1.0 * kDeg, 1e-12);
  EXPECT_NEAR(s.gyr[2], 0.0, 1e-12);
  EXPECT_EQ(p.acks(), 2u);
  EXPECT_EQ(p.inquiries(), 1u);
  EXPECT_EQ(p.errors().count(), 0u);
}

TEST(Shimmer3Parser, WideRangeAccelAndRanges) {
  // WR accel (int16 LE) only, range 2 (+-8 g, 408 LSB per m/s^2); gyro range 3 (16.4 LSB/deg/s).
  const Bytes inquiry = {0x02, 0x40, 0x00, 0x08, 0x00, 0x03, 0x00, 0x06,
                         0x01, 0x04, 0x05, 0x06, 0x0A, 0x0B, 0x0C};
  Bytes b = inquiry;
  auto wr = [](std::uint32_t ts) {
    Bytes p = {0x00, static_cast<std::uint8_t>(ts), 0, 0};
    const std::int16_t v[3] = {408, -816, 4080};
    for (std::int16_t x : v) {
      p.push_back(static_cast<std::uint8_t>(x));
      p.push_back(static_cast<std::uint8_t>(static_cast<std::uint16_t>(x) >> 8));
    }
    const std::int16_t g[3] = {164, 0, -82};
    for (std::int16_t x : g) {
      p.push_back(static_cast<std::uint8_t>(static_cast<std::uint16_t>(x) >> 8));
      p.push_back(static_cast<std::uint8_t>(x));
    }
    return p;
  };
  append(b, wr(10));
  b.push_back(kAck);
  Shimmer3Parser p;
  const auto out = feedAll(p, b);
  ASSERT_EQ(out.size(), 1u);
  // (1, -2, 10) m/s^2 through [[-1,0,0],[0,1,0],[0,0,-1]] -> (-1, -2, -10).
  EXPECT_NEAR(out[0].acc[0], -1.0, 1e-12);
  EXPECT_NEAR(out[0].acc[1], -2.0, 1e-12);
  EXPECT_NEAR(out[0].acc[2], -10.0, 1e-12);
  // (10, 0, -5) deg/s through [[0,-1,0],[-1,0,0],[0,0,-1]] -> (0, -10, 5).
  EXPECT_NEAR(out[0].gyr[0], 0.0, 1e-12);
  EXPECT_NEAR(out[0].gyr[1], -10.0 * kDeg, 1e-12);
  EXPECT_NEAR(out[0].gyr[2], 5.0 * kDeg, 1e-12);
}

TEST(Shimmer3Parser, OneByteChannelsAtThePacketEndAreSkippedWithoutReadingPastIt) {
  // The ExG status channels (0x1D, 0x20) are one byte each. With them last, the packet ends one
  // byte after each; the decoder once read a second byte for every channel, past the packet's end
  // (found by fuzz_shimmer3, kept as tests/fuzz/corpus/fuzz_shimmer3/exg_status_last). Here the
  // last packet is released by flush() from a buffer that ends exactly where the packet does.
  Bytes b = {0x02, 0x40, 0x00, 0x00, 0x00, 0x00, 0x00, 0x08, 0x01,
             0x00, 0x01, 0x02, 0x0A, 0x0B, 0x0C, 0x1D, 0x20};
  for (std::uint32_t ts : {100u, 164u}) {
    Bytes pk = packet(ts, {2047, 2047, 2130}, {131, 0, -131});
    pk.push_back(0xA5);  // ExG 1 status
    pk.push_back(0x5A);  // ExG 2 status
    append(b, pk);
  }
  Shimmer3Parser p;
  std::vector<Sample> out;
  p.feed(b, out);
  p.flush(out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1].rawTimestamp, 164u);
  // Gyro raw 131 at range 0 (131 LSB per deg/s) is 1 deg/s on the sensor's x axis, which the
  // default alignment [[0,-1,0],[-1,0,0],[0,0,-1]] turns into (0, -1, 1) deg/s.
  EXPECT_NEAR(out[1].gyr[0], 0.0, 1e-12);
  EXPECT_NEAR(out[1].gyr[1], -1.0 * kDeg, 1e-12);
  EXPECT_NEAR(out[1].gyr[2], 1.0 * kDeg, 1e-12);
  EXPECT_EQ(p.garbageBytes(), 0u);
}

TEST(Shimmer3Parser, SplitAnywhereGivesTheSameSamples) {
  const Bytes s = session(60);
  Shimmer3Parser whole;
  const auto ref = feedAll(whole, s);
  ASSERT_EQ(ref.size(), 60u);
  EXPECT_EQ(whole.errors().count(), 0u);

  Shimmer3Parser bytewise;
  std::vector<Sample> out;
  for (std::uint8_t b : s) bytewise.feed(std::span(&b, 1), out);
  ASSERT_EQ(out.size(), ref.size());

  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    Shimmer3Parser p;
    std::vector<Sample> o;
    for (std::size_t k = 0; k < s.size();) {
      const std::size_t n = std::min<std::size_t>(s.size() - k, rng() % 40 + 1);
      p.feed(std::span(s.data() + k, n), o);
      k += n;
    }
    ASSERT_EQ(o.size(), ref.size());
    for (std::size_t k = 0; k < o.size(); ++k) {
      EXPECT_EQ(o[k].ticks, ref[k].ticks);
      EXPECT_EQ(o[k].acc, ref[k].acc);
      EXPECT_EQ(o[k].gyr, ref[k].gyr);
    }
    EXPECT_EQ(p.errors().count(), 0u);
  }
}

TEST(Shimmer3Parser, TimestampWrapIsUnwrapped) {
  Shimmer3Parser p;
  Bytes b = kInquiry;
  const std::uint32_t ts0 = (1u << 24) - 5 * 64;
  for (int k = 0; k < 12; ++k)
    append(b, packet((ts0 + 64u * k) & 0xFFFFFF, {2047, 2047, 2047}, {0, 0, 0}));
  b.push_back(kAck);
  const auto out = feedAll(p, b);
  ASSERT_EQ(out.size(), 12u);
  for (int k = 0; k < 12; ++k) {
    EXPECT_EQ(out[k].ticks, ts0 + 64u * k);
    EXPECT_EQ(out[k].rawTimestamp, (ts0 + 64u * k) & 0xFFFFFF);
  }
  EXPECT_GT(out[11].t, 512.0);  // past 2^24 ticks = 512 s
  EXPECT_EQ(p.droppedPackets(), 0u);
}

TEST(Shimmer3Parser, GapsCountAsDroppedPackets) {
  Shimmer3Parser p;
  Bytes b = kInquiry;
  append(b, packet(0, {2047, 2047, 2047}, {0, 0, 0}));
  append(b, packet(64, {2047, 2047, 2047}, {0, 0, 0}));
  append(b, packet(64 * 4, {2047, 2047, 2047}, {0, 0, 0}));  // two lost
  b.push_back(kAck);
  EXPECT_EQ(feedAll(p, b).size(), 3u);
  EXPECT_EQ(p.droppedPackets(), 2u);
}

TEST(Shimmer3Parser, GarbageLosesNoPacketThatFollowsIt) {
  std::mt19937 rng(42);
  auto garbage = [&](int n) {
    Bytes g;
    for (int k = 0; k < n; ++k) g.push_back(static_cast<std::uint8_t>(rng()));
    return g;
  };
  Bytes b = kInquiry;
  std::vector<std::uint32_t> expected;
  std::uint32_t ts = 500;
  for (int block = 0; block < 10; ++block) {
    append(b, garbage(37 + block * 13));
    for (int k = 0; k < 5; ++k, ts += 64) {
      append(b, packet(ts, {2047, 2100, 1990}, {5, -5, 50}));
      // Without length or checksum, the packet just before garbage cannot be framed.
      if (k < 4 || block == 9) expected.push_back(ts);
    }
  }
  b.push_back(kAck);
  for (int chunk : {1, 3, 64, 100000}) {
    Shimmer3Parser p;
    std::vector<Sample> out;
    for (std::size_t k = 0; k < b.size(); k += chunk)
      p.feed(std::span(b.data() + k, std::min<std::size_t>(chunk, b.size() - k)), out);
    std::vector<std::uint32_t> got;
    for (const Sample& s : out) got.push_back(s.rawTimestamp);
    // Every good packet comes out, in order; garbage never yields a packet here.
    ASSERT_EQ(got, expected) << "chunk " << chunk;
    EXPECT_GE(p.errors().count(), 10u);
    EXPECT_GT(p.garbageBytes(), 0u);
    EXPECT_NE(p.errors().last().find("byte"), std::string::npos);
  }
}

TEST(Shimmer3Parser, TruncatedPacketMidStreamLosesOnlyItself) {
  Bytes b = kInquiry;
  append(b, packet(100, {2047, 2047, 2047}, {1, 2, 3}));
  Bytes cut = packet(164, {2047, 2047, 2047}, {1, 2, 3});
  cut.resize(7);  // the link lost the rest
  append(b, cut);
  for (std::uint32_t ts : {228u, 292u, 356u}) append(b, packet(ts, {2047, 2047, 2047}, {1, 2, 3}));
  b.push_back(kAck);
  Shimmer3Parser p;
  const auto out = feedAll(p, b);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].rawTimestamp, 100u);
  EXPECT_EQ(out[1].rawTimestamp, 228u);
  EXPECT_EQ(out[3].rawTimestamp, 356u);
  EXPECT_GE(p.errors().count(), 1u);
}

TEST(Shimmer3Parser, DataBeforeInquiryIsReportedAndFlushReleasesTheLastPacket) {
  Shimmer3Parser p;
  std::vector<Sample> out;
  const Bytes early = packet(1, {2047, 2047, 2047}, {0, 0, 0});
  p.feed(early, out);
  EXPECT_TRUE(out.empty());
  Bytes b = kInquiry;
  append(b, packet(64, {2047, 2047, 2047}, {0, 0, 0}));
  p.feed(b, out);
  EXPECT_TRUE(out.empty());  // waits for its successor
  p.flush(out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_GE(p.errors().count(), 1u);
  EXPECT_NE(p.errors().recent().front().message.find("inquiry"), std::string::npos);
}

TEST(Shimmer3Parser, MalformedInquiryAndImplausibleValuesAreRejected) {
  Shimmer3Parser p;
  // Channel 0x7F does not exist; a zero divider is invalid; duplicate channels are invalid.
  const Bytes bad1 = {0x02, 0x40, 0x00, 0, 0, 0, 0, 0x01, 0x01, 0x7F};
  const Bytes bad2 = {0x02, 0x00, 0x00, 0, 0, 0, 0, 0x01, 0x01, 0x00};
  const Bytes bad3 = {0x02, 0x40, 0x00, 0, 0, 0, 0, 0x02, 0x01, 0x0A, 0x0A};
  EXPECT_FALSE(parseInquiryResponse(bad1));
  EXPECT_FALSE(parseInquiryResponse(bad2));
  EXPECT_FALSE(parseInquiryResponse(bad3));
  Bytes b = bad1;
  append(b, bad2);
  append(b, bad3);
  std::vector<Sample> none;
  p.feed(b, none);
  p.flush(none);
  EXPECT_TRUE(none.empty());
  EXPECT_FALSE(p.config().has_value());
  EXPECT_GE(p.errors().count(), 1u);

  // A low-noise accelerometer value above 12 bits cannot be a real packet.
  Shimmer3Parser q;
  Bytes s = kInquiry;
  append(s, packet(0, {0x1000, 2047, 2047}, {0, 0, 0}));
  append(s, packet(64, {2047, 2047, 2047}, {0, 0, 0}));
  append(s, packet(128, {2047, 2047, 2047}, {0, 0, 0}));
  s.push_back(kAck);
  const auto out = feedAll(q, s);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].rawTimestamp, 64u);
  EXPECT_EQ(out[1].rawTimestamp, 128u);
}

TEST(Shimmer3Parser, BoundedBufferOnEndlessGarbage) {
  Shimmer3Parser p;
  p.setConfig(*parseInquiryResponse(kInquiry));
  std::vector<Sample> out;
  Bytes zeros(100000, 0x00);  // every byte looks like a packet start
  p.feed(zeros, out);
  Bytes noise(100000, 0x55);
  p.feed(noise, out);
  EXPECT_TRUE(out.empty());
  EXPECT_GT(p.garbageBytes(), 100000u);
}
