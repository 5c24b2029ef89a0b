// The "ngimu" plugin against a fake NGIMU on loopback UDP. OSC datagrams are encoded here, byte by
// byte from the OSC 1.0 layout; expected values use the documented units (deg/s, g, NTP time).
#include <gtest/gtest.h>

#include <QTest>
#include <QThread>
#include <QUdpSocket>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "devices/api/Device.h"
#include "tests/support/DeviceHarness.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices;
using Bytes = std::vector<std::uint8_t>;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kG = 9.80665;

void putString(Bytes& b, const std::string& s) {  // zero-terminated, padded to 4
  b.insert(b.end(), s.begin(), s.end());
  do b.push_back(0);
  while (b.size() % 4);
}
void putU32(Bytes& b, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) b.push_back(static_cast<std::uint8_t>(v >> shift));
}
Bytes message(const std::string& address, const std::vector<float>& args) {
  Bytes b;
  putString(b, address);
  putString(b, "," + std::string(args.size(), 'f'));
  for (float f : args) putU32(b, std::bit_cast<std::uint32_t>(f));
  return b;
}
Bytes bundle(std::uint32_t seconds, std::uint32_t fraction, const std::vector<Bytes>& elements) {
  Bytes b;
  putString(b, "#bundle");
  putU32(b, seconds);
  putU32(b, fraction);
  for (const Bytes& e : elements) {
    putU32(b, static_cast<std::uint32_t>(e.size()));
    b.insert(b.end(), e.begin(), e.end());
  }
  return b;
}

// The k-th measurement: floats exactly representable, so the expected SI values are exact.
std::vector<float> sensors(int k) {
  return {0.5f * k, -20.25f, 3.0f, 0.125f * k, -1.0f, 0.75f, 20.0f, 0.0f, -40.0f, 1013.25f};
}
constexpr std::uint32_t kSeconds = 3900000000u;  // a time tag in 2023
double tagTime(int k) {
  return kSeconds + 0.01 * k;
}
std::uint32_t tagFraction(int k) {  // 0.01 s steps: k * 2^32 / 100 (k < 100)
  return static_cast<std::uint32_t>((static_cast<std::uint64_t>(k) << 32) / 100);
}
Bytes sensorsBundle(int k) {
  return bundle(kSeconds, tagFraction(k), {message("/sensors", sensors(k))});
}

void expectSample(const DeviceSample& s, int k) {
  SCOPED_TRACE("measurement " + std::to_string(k));
  const std::vector<float> v = sensors(k);
  EXPECT_NEAR(s.deviceTime, tagTime(k), 1e-6);  // NTP fraction resolution and double at 3.9e9 s
  ASSERT_TRUE(std::holds_alternative<ImuReading>(s.payload));
  const ImuReading& r = std::get<ImuReading>(s.payload);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.gyr[i], v[i] * kDeg, 1e-12);
    EXPECT_NEAR(r.acc[i], v[3 + i] * kG, 1e-12);
  }
}

using Harness = test::DeviceHarness;

class NgimuDevice : public ::testing::Test {
 protected:
  void SetUp() override {
    m_plugin = test::loadPlugin(QStringLiteral("ngimu"));
    ASSERT_NE(m_plugin, nullptr);
    QUdpSocket probe;  // a port that was free a moment ago
    ASSERT_TRUE(probe.bind(QHostAddress::LocalHost, 0));
    m_port = probe.localPort();
  }
  std::unique_ptr<Harness> start(const QString& timeout = QStringLiteral("3"),
                                 const QString& role = QStringLiteral("upper")) {
    QString error;
    auto d = m_plugin->create({{QStringLiteral("port"), m_port},
                               {QStringLiteral("role"), role},
                               {QStringLiteral("timeout"), timeout}},
                              &error);
    EXPECT_TRUE(d) << error.toStdString();
    if (!d) return nullptr;
    auto h = std::make_unique<Harness>(std::move(d));
    EXPECT_TRUE(h->waitState(DeviceState::Connecting));
    return h;
  }
  void send(const Bytes& d) {
    ASSERT_EQ(m_tx.writeDatagram(reinterpret_cast<const char*>(d.data()),
                                 static_cast<qint64>(d.size()), QHostAddress::LocalHost, m_port),
              static_cast<qint64>(d.size()));
  }

  DevicePlugin* m_plugin = nullptr;
  std::uint16_t m_port = 0;
  QUdpSocket m_tx;
};

}  // namespace

TEST_F(NgimuDevice, OptionsSayWhatToChange) {
  EXPECT_EQ(m_plugin->name(), QStringLiteral("ngimu"));
  QString error;
  EXPECT_FALSE(m_plugin->create({{QStringLiteral("role"), QStringLiteral("upper")}}, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("'port' is required"))) << error.toStdString();
  EXPECT_FALSE(m_plugin->create({{QStringLiteral("port"), 8001}}, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("'role' is required"))) << error.toStdString();
  EXPECT_FALSE(m_plugin->create({{QStringLiteral("port"), QStringLiteral("eight")},
                                 {QStringLiteral("role"), QStringLiteral("upper")},
                                 {QStringLiteral("host"), QStringLiteral("x")}},
                                &error));
  EXPECT_TRUE(error.contains(QStringLiteral("option 'port' must be a whole number")))
      << error.toStdString();
  EXPECT_TRUE(error.contains(QStringLiteral("unknown option 'host'"))) << error.toStdString();
}

TEST_F(NgimuDevice, SensorsBundlesBecomeExactSamples) {
  auto h = start();
  ASSERT_TRUE(h);
  const double before = hostNow();
  for (int k = 0; k < 20; ++k) send(sensorsBundle(k));
  ASSERT_TRUE(h->waitSamples(20));
  const double after = hostNow();
  ASSERT_EQ(h->samples.size(), 20u);
  for (int k = 0; k < 20; ++k) {
    expectSample(h->samples[k], k);
    EXPECT_GE(h->samples[k].arrivalTime, before);
    EXPECT_LE(h->samples[k].arrivalTime, after);
  }
  EXPECT_EQ(h->state(), DeviceState::Streaming);
  EXPECT_TRUE(h->problems.isEmpty()) << h->problems.join(u'\n').toStdString();
  EXPECT_EQ(h->device->health().streams[0].samples, 20u);
}

TEST_F(NgimuDevice, MalformedDatagramsAreReportedAndGoodOnesAroundThemKept) {
  auto h = start();
  ASSERT_TRUE(h);
  std::vector<int> good;
  auto sendGood = [&](int k) {
    good.push_back(k);
    send(sensorsBundle(k));
  };
  sendGood(0);
  send({0xDE, 0xAD, 0xBE, 0xEF, 0x01, 0x02, 0x03});  // 1: garbage, size not a multiple of 4
  sendGood(1);
  const Bytes full = sensorsBundle(2);
  send(Bytes(full.begin(), full.begin() + 40));  // 2: truncated
  sendGood(3);
  send(bundle(kSeconds, 0, {message("/sensors", {1, 2, 3, 4, 5, 6, 7, 8, 9})}));  // 3: 9 args
  std::vector<float> nan = sensors(4);
  nan[4] = std::numeric_limits<float>::quiet_NaN();
  send(bundle(kSeconds, tagFraction(4), {message("/sensors", nan)}));  // 4: NaN
  // 5: a bundle whose first element is broken; its second, good element is kept.
  Bytes broken = message("/sensors", sensors(5));
  broken[0] = 's';  // address without '/'
  good.push_back(5);
  send(bundle(kSeconds, tagFraction(5), {broken, message("/sensors", sensors(5))}));
  // Other NGIMU messages are not errors and not samples.
  send(bundle(kSeconds, tagFraction(6), {message("/quaternion", {1, 0, 0, 0})}));
  send(bundle(kSeconds, tagFraction(6), {message("/battery", {87, 3600, 4.1f, 0})}));
  sendGood(7);
  sendGood(8);

  ASSERT_TRUE(h->waitSamples(good.size()));
  QTest::qWait(50);
  ASSERT_EQ(h->samples.size(), good.size());
  for (std::size_t i = 0; i < good.size(); ++i) expectSample(h->samples[i], good[i]);
  const DeviceHealth health = h->device->health();
  EXPECT_GE(health.streams[0].corrupt, 5u);
  EXPECT_LE(health.streams[0].corrupt, 10u);  // one or two messages per bad datagram
  ASSERT_FALSE(h->problems.isEmpty());
  EXPECT_TRUE(h->problems.front().contains(QStringLiteral("datagram")))
      << h->problems.front().toStdString();
  EXPECT_LE(h->problems.size(), 2);
  EXPECT_FALSE(health.batteryPercent.has_value());  // the parser does not read /battery
  EXPECT_EQ(h->state(), DeviceState::Streaming);
}

TEST_F(NgimuDevice, SilenceGoesConnectingAndTheSensorComesBack) {
  auto h = start(QStringLiteral("0.3"));
  ASSERT_TRUE(h);
  send(sensorsBundle(0));
  ASSERT_TRUE(h->waitState(DeviceState::Streaming));
  ASSERT_TRUE(h->waitState(DeviceState::Connecting, 1500));
  EXPECT_TRUE(h->reason().contains(QStringLiteral("no /sensors"))) << h->reason().toStdString();
  send(Bytes{1, 2, 3, 4});  // garbage alone does not make it streaming
  QTest::qWait(50);
  EXPECT_EQ(h->state(), DeviceState::Connecting);
  send(sensorsBundle(1));
  ASSERT_TRUE(h->waitState(DeviceState::Streaming));
  ASSERT_TRUE(h->waitSamples(2));
  expectSample(h->samples[1], 1);
  EXPECT_EQ(h->device->health().reconnects, 1u);
}

TEST_F(NgimuDevice, BareMessagesGetTheArrivalTimeAndOneNotice) {
  auto h = start();
  ASSERT_TRUE(h);
  const double before = hostNow();
  send(message("/sensors", sensors(0)));
  send(message("/sensors", sensors(1)));
  ASSERT_TRUE(h->waitSamples(2));
  for (const DeviceSample& s : h->samples) {
    EXPECT_EQ(s.deviceTime, s.arrivalTime);
    EXPECT_GE(s.arrivalTime, before);
  }
  ASSERT_EQ(h->problems.size(), 1);
  EXPECT_TRUE(h->problems[0].contains(QStringLiteral("time tag"))) << h->problems[0].toStdString();
  EXPECT_EQ(h->device->health().streams[0].corrupt, 0u);
}

TEST_F(NgimuDevice, PortInUseIsAnError) {
  QUdpSocket other;
  ASSERT_TRUE(other.bind(QHostAddress::Any, m_port));
  QString error;
  Harness h(m_plugin->create(
      {{QStringLiteral("port"), m_port}, {QStringLiteral("role"), QStringLiteral("forearm")}},
      &error));
  ASSERT_TRUE(h.waitState(DeviceState::Error));
  EXPECT_TRUE(h.reason().contains(QStringLiteral("already in use"))) << h.reason().toStdString();
  h.stop();
  EXPECT_EQ(h.state(), DeviceState::Disconnected);
}

TEST_F(NgimuDevice, LossesAndReorderingAreCountedFromTheTimeTags) {
  // /sensors has no sequence number: a time tag three periods after the last means two lost
  // messages, one behind the newest a reordered message (not published, time never goes back,
  // but not lost either), one seen before a duplicate.
  auto h = start();
  ASSERT_TRUE(h);
  for (int k : {0, 1, 2, 4, 3, 5, 5, 8, 9}) {
    send(sensorsBundle(k));
    QTest::qWait(2);  // keep the order on the wire
  }
  ASSERT_TRUE(h->waitSamples(7));
  QTest::qWait(50);
  ASSERT_EQ(h->samples.size(), 7u);
  const std::vector<int> published = {0, 1, 2, 4, 5, 8, 9};
  for (std::size_t i = 0; i < published.size(); ++i) expectSample(h->samples[i], published[i]);
  const StreamHealth s = h->device->health().streams[0];
  EXPECT_EQ(s.dropped, 2u);  // 6 and 7
  EXPECT_EQ(s.reordered, 1u);
  EXPECT_FALSE(h->problems.isEmpty());  // the duplicate is reported
}

// A third NGIMU on the sternum: role=trunk makes its stream the trunk IMU. A /sensors message with
// NaN is refused and counted; one at the sensor's full scale (saturated, 2000 deg/s and 16 g) is a
// reading and passes unchanged: the estimator judges it.
TEST_F(NgimuDevice, TrunkRoleStreamsTheSternumSensorAndRefusesNaN) {
  auto h = start(QStringLiteral("3"), QStringLiteral("Trunk"));
  ASSERT_TRUE(h);
  ASSERT_EQ(h->device->streams().size(), 1u);
  EXPECT_EQ(h->device->streams()[0].role, StreamRole::TrunkImu);
  EXPECT_EQ(h->device->streams()[0].name, "trunk NGIMU");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> saturated = {2000.0f, -2000.0f, 2000.0f, 16.0f, -16.0f,
                                        16.0f,   0.0f,     0.0f,    0.0f,  1013.25f};
  send(sensorsBundle(0));
  QTest::qWait(2);
  send(bundle(kSeconds, tagFraction(1),
              {message("/sensors", {nan, 0.0f, 0.0f, 0.0f, -1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f})}));
  QTest::qWait(2);
  send(bundle(kSeconds, tagFraction(2), {message("/sensors", saturated)}));
  QTest::qWait(2);
  send(sensorsBundle(3));
  ASSERT_TRUE(h->waitSamples(3));
  QTest::qWait(50);
  ASSERT_EQ(h->samples.size(), 3u);
  expectSample(h->samples[0], 0);
  expectSample(h->samples[2], 3);
  const ImuReading& r = std::get<ImuReading>(h->samples[1].payload);
  EXPECT_NEAR(r.gyr.x(), 2000.0 * kDeg, 1e-9);
  EXPECT_NEAR(r.gyr.y(), -2000.0 * kDeg, 1e-9);
  EXPECT_NEAR(r.acc.z(), 16.0 * kG, 1e-9);
  EXPECT_EQ(h->device->health().streams[0].corrupt, 1u);
  EXPECT_FALSE(h->problems.isEmpty());
}
