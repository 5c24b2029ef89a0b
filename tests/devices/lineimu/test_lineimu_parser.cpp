// DIY IMU line protocol: sentences built by hand, split anywhere, and broken in every way.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "devices/lineimu/LineImuParser.h"

using namespace armtrack::devices::lineimu;

namespace {

std::string imu(std::uint32_t seq, std::uint32_t us, double gx = 0.1) {
  return makeSentence("IMU," + std::to_string(seq) + "," + std::to_string(us) + "," +
                      std::to_string(gx) + ",-0.2,0.3,0.5,-9.81,1.25");
}

std::vector<Sample> parse(LineImuParser& p, const std::string& s) {
  std::vector<Sample> out;
  p.feed(s, out);
  return out;
}

}  // namespace

TEST(LineImuParser, HandComputedSentence) {
  // XOR of "IMU,7,1000,0.5,-0.25,1,0,0,9.81" computed by hand is 0x7C... checked below both ways.
  const std::string body = "IMU,7,1000,0.5,-0.25,1,0,0,9.81";
  std::uint8_t x = 0;
  for (char c : body) x ^= static_cast<std::uint8_t>(c);
  EXPECT_EQ(checksum(body), x);
  char hex[3];
  std::snprintf(hex, sizeof hex, "%02x", x);  // lower-case hex is accepted too
  LineImuParser p;
  const auto out = parse(
      p, "$HELLO,1,esp32-forearm,100*" +
             [] {
               char h[3];
               std::snprintf(h, sizeof h, "%02X", checksum("HELLO,1,esp32-forearm,100"));
               return std::string(h);
             }() +
             "\r\n$" + body + "*" + hex + "\r\n");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].seq, 7u);
  EXPECT_EQ(out[0].deviceTimeUs, 1000u);
  EXPECT_DOUBLE_EQ(out[0].t, 0.001);
  EXPECT_DOUBLE_EQ(out[0].gyr[0], 0.5);
  EXPECT_DOUBLE_EQ(out[0].gyr[1], -0.25);
  EXPECT_DOUBLE_EQ(out[0].gyr[2], 1.0);
  EXPECT_DOUBLE_EQ(out[0].acc[2], 9.81);
  ASSERT_TRUE(p.hello());
  EXPECT_EQ(p.hello()->device, "esp32-forearm");
  EXPECT_DOUBLE_EQ(p.hello()->rateHz, 100.0);
  EXPECT_EQ(p.errors().count(), 0u);
}

TEST(LineImuParser, SplitAnywhere) {
  std::string s;
  for (std::uint32_t k = 0; k < 100; ++k) s += imu(k, 1000 * k, 0.01 * k);
  std::mt19937 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    LineImuParser p;
    std::vector<Sample> out;
    for (std::size_t k = 0; k < s.size();) {
      const std::size_t n = std::min<std::size_t>(s.size() - k, trial == 0 ? 1 : rng() % 50 + 1);
      p.feed(std::string_view(s).substr(k, n), out);
      k += n;
    }
    ASSERT_EQ(out.size(), 100u);
    for (std::uint32_t k = 0; k < 100; ++k) EXPECT_EQ(out[k].seq, k);
    EXPECT_EQ(p.errors().count(), 0u);
    EXPECT_EQ(p.droppedSamples(), 0u);
  }
}

TEST(LineImuParser, TimeWrapAndDrops) {
  LineImuParser p;
  const std::uint32_t t0 = 0xFFFFFFFFu - 1500;
  std::string s = imu(0xFFFFFFFEu, t0) + imu(0xFFFFFFFFu, t0 + 1000) + imu(0, t0 + 2000) +
                  imu(4, t0 + 6000);  // seq 1..3 lost
  const auto out = parse(p, s);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[2].deviceTimeUs, std::uint64_t{t0} + 2000);
  EXPECT_EQ(out[3].deviceTimeUs, std::uint64_t{t0} + 6000);
  EXPECT_EQ(p.droppedSamples(), 3u);
}

TEST(LineImuParser, BadSentencesAreCountedAndGoodOnesSurvive) {
  const std::string good1 = imu(1, 100), good2 = imu(2, 200), good3 = imu(3, 300);
  std::string badChecksum = imu(9, 900);
  badChecksum[badChecksum.size() - 2] = badChecksum[badChecksum.size() - 2] == '0' ? '1' : '0';
  const std::string cases[] = {
      badChecksum,
      makeSentence("IMU,1,2,3"),                      // too few fields
      makeSentence("IMU,1,2,nan,0,0,0,0,0"),          // NaN
      makeSentence("IMU,1,2,inf,0,0,0,0,0"),          // infinity
      makeSentence("IMU,1,2,1e999,0,0,0,0,0"),        // out of range
      makeSentence("IMU,1,2,0x10,0,0,0,0,0"),         // hex
      makeSentence("IMU,-1,2,0,0,0,0,0,0"),           // negative seq
      makeSentence("IMU,1,99999999999,0,0,0,0,0,0"),  // time beyond 32 bits
      makeSentence("IMU,1,2,,0,0,0,0,0"),             // empty field
      makeSentence("FOO,1"),                          // unknown type
      makeSentence("HELLO,2,x,100"),                  // unsupported version
      "$IMU,1,2,0,0,0,0,0,0\n",                       // no checksum
      "$IMU,1,2,0,0,0,0,0,0*ZZ\n",                    // checksum not hex
      "garbage without dollar\n",                     // outside any sentence
      "$IMU,5,500,0.1,0.2",                           // truncated by the next '$'
      "$" + std::string(5000, 'A') + "\n",            // huge line
      std::string("\x00\xff\x01$$$\n", 8),            // binary noise
  };
  for (const std::string& bad : cases) {
    LineImuParser p;
    const auto out = parse(p, good1 + bad + good2 + good3);
    ASSERT_EQ(out.size(), 3u) << bad.substr(0, 60);
    EXPECT_EQ(out[1].seq, 2u);
    EXPECT_GE(p.errors().count(), 1u) << bad.substr(0, 60);
    EXPECT_FALSE(p.errors().last().empty());
  }
}

TEST(LineImuParser, ErrorsNameTheByteOffset) {
  LineImuParser p;
  std::string bad = imu(1, 1);
  bad[bad.size() - 2] ^= 1;
  parse(p, imu(0, 0) + bad);
  ASSERT_EQ(p.errors().count(), 1u);
  const std::size_t at = imu(0, 0).size();
  EXPECT_EQ(p.errors().recent().back().offset, at);
  EXPECT_NE(p.errors().last().find("checksum"), std::string::npos);
  EXPECT_NE(p.errors().last().find(std::to_string(at)), std::string::npos);
}

TEST(LineImuParser, DatagramsEndSentences) {
  LineImuParser p;
  std::vector<Sample> out;
  const std::string whole = imu(1, 1);
  p.feed(std::string_view(whole).substr(0, 10), out);
  p.endOfDatagram();                                // a UDP datagram carrying half a sentence
  p.feed(std::string_view(whole).substr(10), out);  // the rest alone is garbage
  p.endOfDatagram();
  p.feed(imu(2, 2) + imu(3, 3), out);
  p.endOfDatagram();
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(p.errors().count(), 2u);
}

TEST(LineImuParser, DocumentedExampleParses) {
  LineImuParser p;
  const auto out = parse(p,
                         "$HELLO,1,esp32-forearm,100*44\n"
                         "$IMU,0,1000,0.012,-0.003,0.250,0.12,-9.79,0.31*51\n");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_DOUBLE_EQ(out[0].acc[1], -9.79);
  EXPECT_EQ(p.errors().count(), 0u);
}

TEST(LineImuParser, HelloStartsANewEpoch) {
  LineImuParser p;
  const auto out = parse(p, imu(1, 5000) + makeSentence("HELLO,1,x,100") + imu(1, 100));
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].epoch, 0u);
  EXPECT_EQ(out[1].epoch, 1u);
  EXPECT_EQ(out[1].deviceTimeUs, 100u);  // the restarted device's clock, not a wrap
}
