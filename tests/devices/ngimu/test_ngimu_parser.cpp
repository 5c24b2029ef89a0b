// NGIMU OSC datagrams built byte by byte from the OSC 1.0 layout.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "devices/ngimu/NgimuParser.h"

using namespace armtrack::devices;
using namespace armtrack::devices::ngimu;
using Bytes = std::vector<std::uint8_t>;

namespace {

std::vector<float> sensorArgs() {
  return {10, -20, 30, 0, 0, 1, 20, 0, -40, 1013.25f};
}

std::vector<SensorsSample> parse(NgimuParser& p, const Bytes& d) {
  std::vector<SensorsSample> out;
  p.parseDatagram(d, out);
  return out;
}

}  // namespace

TEST(NgimuParser, HandBuiltBundle) {
  // "#bundle\0", time tag (seconds 0xE0000000, fraction 0x80000000 = 0.5 s), one element of 56
  // bytes: "/sensors\0\0\0\0", ",ffffffffff\0", then ten big-endian float32.
  Bytes d = {'#', 'b', 'u', 'n', 'd', 'l', 'e', 0, 0xE0, 0, 0, 0, 0x80, 0, 0, 0, 0, 0, 0, 64};
  const Bytes msg = {'/',  's',  'e',  'n', 's', 'o', 'r', 's', 0, 0,    0,    0, ',', 'f', 'f',
                     'f',  'f',  'f',  'f', 'f', 'f', 'f', 'f', 0, 0x41, 0x20, 0, 0,  // 10.0 deg/s
                     0xC1, 0xA0, 0,    0,                                             // -20.0
                     0x41, 0xF0, 0,    0,                                             // 30.0
                     0,    0,    0,    0,                                             // 0 g
                     0,    0,    0,    0,                                             // 0 g
                     0x3F, 0x80, 0,    0,                                             // 1 g
                     0x41, 0xA0, 0,    0,                                             // 20 uT
                     0,    0,    0,    0,                                             // 0 uT
                     0xC2, 0x20, 0,    0,                                             // -40 uT
                     0x44, 0x7D, 0x50, 0};                                            // 1013.25 hPa
  ASSERT_EQ(msg.size(), 64u);
  d.insert(d.end(), msg.begin(), msg.end());
  EXPECT_EQ(
      d, osc::encodeBundle(0xE000000080000000ull, {osc::encodeMessage("/sensors", sensorArgs())}));

  NgimuParser p;
  const auto out = parse(p, d);
  ASSERT_EQ(out.size(), 1u);
  const SensorsSample& s = out[0];
  EXPECT_TRUE(s.hasTimetag);
  EXPECT_DOUBLE_EQ(s.t, 3758096384.0 + 0.5);
  constexpr double kDeg = std::numbers::pi / 180.0;
  EXPECT_NEAR(s.gyr[0], 10 * kDeg, 1e-12);
  EXPECT_NEAR(s.gyr[1], -20 * kDeg, 1e-12);
  EXPECT_NEAR(s.gyr[2], 30 * kDeg, 1e-12);
  EXPECT_NEAR(s.acc[2], 9.80665, 1e-12);
  EXPECT_NEAR(s.mag[0], 20e-6, 1e-15);
  EXPECT_NEAR(s.mag[2], -40e-6, 1e-15);
  EXPECT_NEAR(s.pressurePa, 101325.0, 1e-9);
  EXPECT_EQ(p.errors().count(), 0u);
}

TEST(NgimuParser, OtherMessagesNestedBundlesAndBareMessages) {
  const Bytes quat = osc::encodeMessage("/quaternion", {1, 0, 0, 0});
  const Bytes inner =
      osc::encodeBundle(0x100000000ull, {osc::encodeMessage("/sensors", sensorArgs())});
  const Bytes outer = osc::encodeBundle(0x200000000ull, {quat, inner});
  NgimuParser p;
  auto out = parse(p, outer);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_DOUBLE_EQ(out[0].t, 1.0);  // the inner bundle's time tag
  EXPECT_EQ(p.otherMessages(), 1u);
  out = parse(p, osc::encodeMessage("/sensors", sensorArgs()));  // no bundle: no time
  ASSERT_EQ(out.size(), 1u);
  EXPECT_FALSE(out[0].hasTimetag);
  EXPECT_EQ(p.errors().count(), 0u);
}

TEST(NgimuParser, EveryTruncationIsAnErrorNotACrash) {
  const Bytes d = osc::encodeBundle(0x100000000ull, {osc::encodeMessage("/sensors", sensorArgs())});
  for (std::size_t n = 0; n < d.size(); ++n) {
    if (n == 16) continue;  // "#bundle" + time tag alone is a valid, empty bundle
    NgimuParser p;
    const auto out = parse(p, Bytes(d.begin(), d.begin() + n));
    EXPECT_TRUE(out.empty()) << n;
    EXPECT_GE(p.errors().count(), 1u) << n;
  }
}

TEST(NgimuParser, MalformedDatagrams) {
  const Bytes good =
      osc::encodeBundle(0x100000000ull, {osc::encodeMessage("/sensors", sensorArgs())});
  std::vector<Bytes> bad;
  auto args = sensorArgs();
  args[4] = std::numeric_limits<float>::quiet_NaN();
  bad.push_back(osc::encodeMessage("/sensors", args));
  args[4] = std::numeric_limits<float>::infinity();
  bad.push_back(osc::encodeMessage("/sensors", args));
  bad.push_back(osc::encodeMessage("/sensors", {1, 2, 3}));    // too few arguments
  bad.push_back(osc::encodeMessage("sensors", sensorArgs()));  // address without '/'
  Bytes noTags;
  osc::appendString(noTags, "/sensors");
  osc::appendString(noTags, "fff");  // type tags without ','
  bad.push_back(noTags);
  Bytes unknownTag;
  osc::appendString(unknownTag, "/sensors");
  osc::appendString(unknownTag, ",q");
  bad.push_back(unknownTag);
  Bytes badSize = good;
  badSize[19] = 0xFC;  // element size too large
  bad.push_back(badSize);
  Bytes badPad = osc::encodeMessage("/sensors", sensorArgs());
  badPad[10] = 'x';  // non-zero string padding
  bad.push_back(badPad);
  bad.push_back(Bytes{'#', 'b', 'u', 'n', 'd', 'l', 'e', 0});  // bundle without time tag
  Bytes deep = good;
  for (int k = 0; k < 12; ++k) deep = osc::encodeBundle(1, {deep});  // too deeply nested
  bad.push_back(deep);
  Bytes stray = osc::encodeMessage("/sensors", sensorArgs());
  stray.insert(stray.end(), 4, 0);  // bytes after the arguments
  bad.push_back(stray);
  for (std::size_t k = 0; k < bad.size(); ++k) {
    NgimuParser p;
    EXPECT_TRUE(parse(p, bad[k]).empty()) << k;
    EXPECT_GE(p.errors().count(), 1u) << k;
    EXPECT_NE(p.errors().last().find("datagram 0"), std::string::npos) << k;
    // The next good datagram is decoded.
    EXPECT_EQ(parse(p, good).size(), 1u) << k;
  }
}

TEST(NgimuParser, GoodElementsOfABundleSurviveABadOne) {
  auto args = sensorArgs();
  args[0] = std::numeric_limits<float>::quiet_NaN();
  const Bytes d = osc::encodeBundle(0x100000000ull, {osc::encodeMessage("/sensors", sensorArgs()),
                                                     osc::encodeMessage("/sensors", args),
                                                     osc::encodeMessage("/sensors", sensorArgs())});
  NgimuParser p;
  EXPECT_EQ(parse(p, d).size(), 2u);
  EXPECT_EQ(p.errors().count(), 1u);
}
