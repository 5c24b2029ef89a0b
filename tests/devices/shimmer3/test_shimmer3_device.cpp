// The "shimmer3" plugin against a fake Shimmer3 on a pseudo-terminal: handshake, streaming across
// the 24-bit timestamp wrap, garbage and truncated packets, a dropped and restored link, stop.
// Expected values are computed here from the documented format and default calibration
// (docs/devices/shimmer3.md), not with the parser.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <QDir>
#include <QFile>
#include <QSocketNotifier>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <array>
#include <cerrno>
#include <cstdint>
#include <memory>
#include <numbers>
#include <set>
#include <vector>

#include "devices/api/Device.h"
#include "tests/support/DeviceHarness.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices;
using Bytes = std::vector<std::uint8_t>;

namespace {

constexpr std::uint32_t kDivider = 327;  // ~100 Hz at 32768 Hz
constexpr std::uint32_t kWrap = 1u << 24;
constexpr double kTick = 32768.0;
constexpr double kDeg = std::numbers::pi / 180.0;

// ACK, then the inquiry response: divider LE, config bytes (all ranges 0), 6 channels, buffer
// size 1, low-noise accel x y z and gyro x y z.
Bytes inquiryAnswer(bool withGyro = true) {
  Bytes b = {0xFF, 0x02, kDivider & 0xFF, kDivider >> 8, 0, 0, 0, 0, 6, 1, 0x00, 0x01, 0x02};
  const Bytes tail = withGyro ? Bytes{0x0A, 0x0B, 0x0C} : Bytes{0x07, 0x08, 0x09};  // or mag
  b.insert(b.end(), tail.begin(), tail.end());
  return b;
}

// The k-th packet's content: accelerometer and gyro values in output units (integers so that the
// raw counts are exact), and its raw 24-bit timestamp.
struct Truth {
  std::array<int, 3> accUnits;   // (raw - 2047) / 83, before alignment (m/s^2)
  std::array<int, 3> gyroUnits;  // raw / 131, before alignment (deg/s)
};
Truth truth(int k) {
  return {{k % 3 - 1, 2 - k % 5, 9 + k % 2}, {k % 7 - 3, 10 - k % 20, (2 * k) % 9}};
}
std::uint32_t rawTime(std::uint32_t raw0, int k) {
  return (raw0 + kDivider * k) % kWrap;
}

Bytes packet(std::uint32_t ts, const Truth& t) {
  Bytes b = {0x00, static_cast<std::uint8_t>(ts), static_cast<std::uint8_t>(ts >> 8),
             static_cast<std::uint8_t>(ts >> 16)};
  for (int v : t.accUnits) {  // uint12, little-endian
    const int raw = 2047 + 83 * v;
    b.push_back(static_cast<std::uint8_t>(raw));
    b.push_back(static_cast<std::uint8_t>(raw >> 8));
  }
  for (int v : t.gyroUnits) {  // int16, big-endian
    const auto raw = static_cast<std::uint16_t>(static_cast<std::int16_t>(131 * v));
    b.push_back(static_cast<std::uint8_t>(raw >> 8));
    b.push_back(static_cast<std::uint8_t>(raw));
  }
  return b;
}

// Checks one published sample against packet k. The default alignment of both sensors is
// [[0,-1,0],[-1,0,0],[0,0,-1]], its own inverse: out = (-y, -x, -z).
void expectSample(const DeviceSample& s, std::uint32_t raw0, int k, double timeOffset = 0.0) {
  SCOPED_TRACE("packet " + std::to_string(k));
  const Truth t = truth(k);
  EXPECT_EQ(s.stream, 0);
  EXPECT_NEAR(s.deviceTime, (raw0 + static_cast<double>(kDivider) * k) / kTick + timeOffset, 1e-9);
  ASSERT_TRUE(std::holds_alternative<ImuReading>(s.payload));
  const ImuReading& r = std::get<ImuReading>(s.payload);
  EXPECT_NEAR(r.acc.x(), -t.accUnits[1], 1e-12);
  EXPECT_NEAR(r.acc.y(), -t.accUnits[0], 1e-12);
  EXPECT_NEAR(r.acc.z(), -t.accUnits[2], 1e-12);
  EXPECT_NEAR(r.gyr.x(), -t.gyroUnits[1] * kDeg, 1e-12);
  EXPECT_NEAR(r.gyr.y(), -t.gyroUnits[0] * kDeg, 1e-12);
  EXPECT_NEAR(r.gyr.z(), -t.gyroUnits[2] * kDeg, 1e-12);
}

// A fake Shimmer3 on the master side of a pseudo-terminal, reachable through a symlink so that a
// "new" device can appear under the same name. It acks stop and start and answers the inquiry.
class FakeShimmer {
 public:
  explicit FakeShimmer(QString link) : m_link(std::move(link)) {}
  ~FakeShimmer() { unplug(); }

  /// A new pseudo-terminal behind the link.
  void plug(bool withGyro = true) {
    unplug();
    char name[256] = {};
    ASSERT_EQ(openpty(&m_master, &m_slave, name, nullptr, nullptr), 0);
    // Raw from the start: the port restores these settings when the device closes it, and an
    // echoing terminal would send the fake's own answers back to it.
    termios raw{};
    tcgetattr(m_slave, &raw);
    cfmakeraw(&raw);
    tcsetattr(m_slave, TCSANOW, &raw);
    fcntl(m_master, F_SETFL, fcntl(m_master, F_GETFL) | O_NONBLOCK);
    const QString tmp = m_link + QStringLiteral(".new");
    QFile::remove(tmp);
    ASSERT_TRUE(QFile::link(QString::fromLocal8Bit(name), tmp));
    ASSERT_EQ(::rename(QFile::encodeName(tmp).constData(), QFile::encodeName(m_link).constData()),
              0);
    m_withGyro = withGyro;
    m_streaming = false;
    m_notifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Read);
    QObject::connect(m_notifier.get(), &QSocketNotifier::activated, [this] { onCommand(); });
  }
  /// Closes both ends: the device sees its port fail.
  void unplug() {
    m_notifier.reset();
    // The link goes first: a freed /dev/pts/N is soon given to another process (tests run in
    // parallel), and the device, retrying, must not open that one.
    if (m_master >= 0) QFile::remove(m_link);
    if (m_master >= 0) ::close(m_master);
    if (m_slave >= 0) ::close(m_slave);
    m_master = m_slave = -1;
  }
  void send(const Bytes& b) {
    std::size_t done = 0;
    while (done < b.size()) {
      const ssize_t n = ::write(m_master, b.data() + done, b.size() - done);
      if (n > 0)
        done += static_cast<std::size_t>(n);
      else if (errno == EAGAIN)
        QTest::qWait(1);
      else
        FAIL() << "write to pty master failed";
    }
  }
  /// Sends the bytes in small writes with pauses, so that reads split packets anywhere.
  void sendSplit(const Bytes& b, std::size_t chunk) {
    for (std::size_t i = 0; i < b.size(); i += chunk) {
      send(Bytes(b.begin() + i, b.begin() + std::min(b.size(), i + chunk)));
      QTest::qWait(1);
    }
  }
  const Bytes& commands() const { return m_commands; }
  bool streaming() const { return m_streaming; }

 private:
  void onCommand() {
    std::uint8_t buf[64];
    const ssize_t n = ::read(m_master, buf, sizeof buf);
    for (ssize_t i = 0; i < n; ++i) {
      m_commands.push_back(buf[i]);
      if (buf[i] == 0x20) {  // stop
        m_streaming = false;
        send({0xFF});
      } else if (buf[i] == 0x01) {
        send(inquiryAnswer(m_withGyro));
      } else if (buf[i] == 0x07) {
        send({0xFF});
        m_streaming = true;
      }
    }
  }

  QString m_link;
  int m_master = -1, m_slave = -1;
  bool m_withGyro = true;
  bool m_streaming = false;
  Bytes m_commands;
  std::unique_ptr<QSocketNotifier> m_notifier;
};

using Harness = test::DeviceHarness;

class Shimmer3Device : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(m_dir.isValid());
    // Unique name: QSerialPort locks ports by their base name.
    m_link = m_dir.filePath(QStringLiteral("shimmer-%1").arg(QDir(m_dir.path()).dirName()));
    m_plugin = test::loadPlugin(QStringLiteral("shimmer3"));
    ASSERT_NE(m_plugin, nullptr);
  }
  std::unique_ptr<Device> create(QVariantMap extra = {}) {
    QVariantMap o{{QStringLiteral("port"), m_link},
                  {QStringLiteral("role"), QStringLiteral("forearm")},
                  {QStringLiteral("retry"), QStringLiteral("0.1")}};
    for (auto it = extra.cbegin(); it != extra.cend(); ++it) o.insert(it.key(), it.value());
    QString error;
    auto d = m_plugin->create(o, &error);
    EXPECT_TRUE(d) << error.toStdString();
    return d;
  }
  bool handshake(FakeShimmer& fake, int ms = 2000) {
    return QTest::qWaitFor([&] { return fake.streaming(); }, ms);
  }

  QTemporaryDir m_dir;
  QString m_link;
  DevicePlugin* m_plugin = nullptr;
};

}  // namespace

TEST_F(Shimmer3Device, PluginDescribesItselfAndChecksOptions) {
  EXPECT_EQ(m_plugin->name(), QStringLiteral("shimmer3"));
  EXPECT_EQ(m_plugin->apiVersion(), kDeviceApiVersion);
  EXPECT_TRUE(m_plugin->optionsHelp().contains(QStringLiteral("role=")));
  QString error;
  EXPECT_FALSE(m_plugin->create({{QStringLiteral("port"), m_link}}, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("role=upper, role=forearm or role=trunk")))
      << error.toStdString();
  EXPECT_FALSE(m_plugin->create({{QStringLiteral("role"), QStringLiteral("upper")}}, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("'port' is required"))) << error.toStdString();
  EXPECT_FALSE(m_plugin->create(
      {{QStringLiteral("port"), m_link}, {QStringLiteral("role"), QStringLiteral("elbow")}},
      &error));
  EXPECT_TRUE(error.contains(QStringLiteral("not 'elbow'"))) << error.toStdString();
  EXPECT_FALSE(m_plugin->create({{QStringLiteral("port"), m_link},
                                 {QStringLiteral("role"), QStringLiteral("upper")},
                                 {QStringLiteral("baud"), QStringLiteral("9600")}},
                                &error));
  EXPECT_TRUE(error.contains(QStringLiteral("unknown option 'baud'"))) << error.toStdString();
  auto d = m_plugin->create(
      {{QStringLiteral("port"), m_link}, {QStringLiteral("role"), QStringLiteral("upper")}},
      &error);
  ASSERT_TRUE(d);
  ASSERT_EQ(d->streams().size(), 1u);
  EXPECT_EQ(d->streams()[0].role, StreamRole::UpperArmImu);
  EXPECT_EQ(d->streams()[0].wrapPeriod, 0.0);  // the time is unwrapped by the device
  EXPECT_EQ(d->streams()[0].name, "upper-arm Shimmer3");
  // A third Shimmer on the sternum is the trunk IMU, named for it.
  auto trunk = m_plugin->create(
      {{QStringLiteral("port"), m_link}, {QStringLiteral("role"), QStringLiteral("trunk")}},
      &error);
  ASSERT_TRUE(trunk) << error.toStdString();
  ASSERT_EQ(trunk->streams().size(), 1u);
  EXPECT_EQ(trunk->streams()[0].role, StreamRole::TrunkImu);
  EXPECT_EQ(trunk->streams()[0].name, "trunk Shimmer3");
}

TEST_F(Shimmer3Device, HandshakeThenEveryPacketAcrossTheTimestampWrap) {
  FakeShimmer fake(m_link);
  fake.plug();
  Harness h(create());
  ASSERT_TRUE(handshake(fake));
  EXPECT_EQ(fake.commands(), (Bytes{0x20, 0x01, 0x07}));  // stop, inquiry, start
  ASSERT_FALSE(h.states.empty());
  EXPECT_EQ(h.states.front().first, DeviceState::Connecting);
  EXPECT_EQ(h.state(), DeviceState::Connecting);  // no sample yet

  const std::uint32_t raw0 = kWrap - 20 * kDivider + 5;  // wraps at packet 20
  const double before = hostNow();
  Bytes stream;
  for (int k = 0; k < 40; ++k) {
    const Bytes p = packet(rawTime(raw0, k), truth(k));
    stream.insert(stream.end(), p.begin(), p.end());
  }
  fake.sendSplit(stream, 7);
  // A packet is framed by its successor: the 40th waits for the 41st.
  ASSERT_TRUE(h.waitSamples(39));
  QTest::qWait(50);
  const double after = hostNow();
  ASSERT_EQ(h.samples.size(), 39u);
  EXPECT_EQ(h.state(), DeviceState::Streaming);
  for (int k = 0; k < 39; ++k) {
    expectSample(h.samples[k], raw0, k);
    EXPECT_GE(h.samples[k].arrivalTime, before);
    EXPECT_LE(h.samples[k].arrivalTime, after);
  }
  EXPECT_GT(h.samples[38].deviceTime, static_cast<double>(kWrap) / kTick);  // past the wrap

  const DeviceHealth health = h.device->health();
  EXPECT_EQ(health.streams[0].samples, 39u);
  EXPECT_EQ(health.streams[0].corrupt, 0u);
  EXPECT_EQ(health.streams[0].dropped, 0u);
  EXPECT_TRUE(h.problems.isEmpty()) << h.problems.join(u'\n').toStdString();

  h.stop();
  QTest::qWait(20);
  QCoreApplication::processEvents();
  EXPECT_EQ(fake.commands().back(), 0x20);  // stop streaming was sent
  EXPECT_EQ(h.state(), DeviceState::Disconnected);
}

TEST_F(Shimmer3Device, GarbageAndTruncatedPacketsAreReportedAndLaterPacketsKept) {
  FakeShimmer fake(m_link);
  fake.plug();
  Harness h(create());
  ASSERT_TRUE(handshake(fake));

  const std::uint32_t raw0 = 123456;
  auto p = [&](int k) { return packet(rawTime(raw0, k), truth(k)); };
  Bytes stream;
  auto add = [&stream](const Bytes& b) { stream.insert(stream.end(), b.begin(), b.end()); };
  for (int k = 0; k < 10; ++k) add(p(k));
  add({0x13, 0x37, 0xAB, 0x00, 0x42, 0x00, 0x00, 0x99, 0x02, 0x11, 0xFE});  // line noise
  for (int k = 10; k < 30; ++k) add(p(k));
  const Bytes cut = p(30);
  add(Bytes(cut.begin(), cut.begin() + 7));  // packet 30 loses its last 9 bytes
  for (int k = 31; k < 50; ++k) add(p(k));
  fake.sendSplit(stream, 13);

  // Lost by design: packet 9 (its successor is noise, so it cannot be framed), packet 30 (cut)
  // and packet 49 (waits for a successor). Every other packet arrives intact and in order.
  std::vector<int> expected;
  for (int k = 0; k < 49; ++k)
    if (k != 9 && k != 30) expected.push_back(k);
  ASSERT_TRUE(h.waitSamples(expected.size()));
  QTest::qWait(50);
  ASSERT_EQ(h.samples.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) expectSample(h.samples[i], raw0, expected[i]);

  const DeviceHealth health = h.device->health();
  EXPECT_GE(health.streams[0].corrupt, 2u);  // the noise and the cut packet
  EXPECT_EQ(health.streams[0].dropped, 2u);  // timestamp gaps 8->10 and 29->31
  ASSERT_FALSE(h.problems.isEmpty());
  EXPECT_TRUE(h.problems.front().contains(QStringLiteral("byte")))
      << h.problems.front().toStdString();
  EXPECT_FALSE(health.lastProblem.empty());
  EXPECT_EQ(h.state(), DeviceState::Streaming);
}

TEST_F(Shimmer3Device, LinkDropGoesConnectingThenReconnectsWithContinuousTime) {
  FakeShimmer fake(m_link);
  fake.plug();
  Harness h(create());
  ASSERT_TRUE(handshake(fake));
  const std::uint32_t raw0 = kWrap - 5 * kDivider;  // wraps during the first connection
  Bytes stream;
  for (int k = 0; k < 10; ++k) {
    const Bytes pk = packet(rawTime(raw0, k), truth(k));
    stream.insert(stream.end(), pk.begin(), pk.end());
  }
  fake.send(stream);
  ASSERT_TRUE(h.waitSamples(9));

  fake.unplug();  // the Bluetooth link drops
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  EXPECT_TRUE(h.states.back().second.contains(m_link)) << h.states.back().second.toStdString();
  // The last packet, complete but unframed, is released when the link ends.
  ASSERT_EQ(h.samples.size(), 10u);
  for (int k = 0; k < 10; ++k) expectSample(h.samples[k], raw0, k);

  // The Shimmer comes back; its clock ran on (packets 10.. continue the timestamps).
  QTest::qWait(150);
  fake.plug();
  ASSERT_TRUE(handshake(fake));
  stream.clear();
  for (int k = 10; k < 20; ++k) {
    const Bytes pk = packet(rawTime(raw0, k), truth(k));
    stream.insert(stream.end(), pk.begin(), pk.end());
  }
  fake.send(stream);
  ASSERT_TRUE(h.waitSamples(19));
  EXPECT_EQ(h.state(), DeviceState::Streaming);
  for (int k = 10; k < 19; ++k) expectSample(h.samples[k], raw0, k);
  EXPECT_EQ(h.device->health().reconnects, 1u);
  EXPECT_EQ(h.device->health().streams[0].samples, 19u);
}

TEST_F(Shimmer3Device, MissingPortIsAwaitedAndSilenceReopens) {
  Harness h(create({{QStringLiteral("timeout"), QStringLiteral("0.3")}}));
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  EXPECT_TRUE(h.states.back().second.contains(QStringLiteral("does not exist")))
      << h.states.back().second.toStdString();
  FakeShimmer fake(m_link);
  fake.plug();
  ASSERT_TRUE(handshake(fake));
  fake.send(packet(rawTime(1000, 0), truth(0)));
  fake.send(packet(rawTime(1000, 1), truth(1)));
  ASSERT_TRUE(h.waitState(DeviceState::Streaming));
  // Nothing more comes: after 0.3 s the device reopens the port and asks again.
  ASSERT_TRUE(h.waitState(DeviceState::Connecting, 1500));
  EXPECT_TRUE(h.states.back().second.contains(QStringLiteral("no data")))
      << h.states.back().second.toStdString();
  ASSERT_TRUE(QTest::qWaitFor([&] { return fake.commands().size() >= 6; }, 1500));
  EXPECT_EQ(fake.commands(), (Bytes{0x20, 0x01, 0x07, 0x20, 0x01, 0x07}));
}

TEST_F(Shimmer3Device, ShimmerWithoutGyroscopeIsAnError) {
  FakeShimmer fake(m_link);
  fake.plug(/*withGyro=*/false);
  Harness h(create());
  ASSERT_TRUE(h.waitState(DeviceState::Error));
  EXPECT_TRUE(h.states.back().second.contains(QStringLiteral("gyroscope")))
      << h.states.back().second.toStdString();
  EXPECT_FALSE(fake.streaming());
  h.stop();
  EXPECT_EQ(h.state(), DeviceState::Disconnected);
}
