// The "line-imu" plugin against a fake device at the byte level: a pseudo-terminal for the serial
// transport, loopback datagrams for UDP. Sentences are built here (checksum computed here, values
// formatted from known numbers) and every published sample is compared with what was sent.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <pty.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <QUdpSocket>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "devices/api/Device.h"
#include "tests/support/DeviceHarness.h"
#include "tests/support/LoadPlugin.h"

using namespace armtrack;
using namespace armtrack::devices;

namespace {

// "$<body>*HH\n" with HH the XOR of the body's bytes (docs/devices/line-protocol.md).
std::string sentence(const std::string& body) {
  unsigned x = 0;
  for (char c : body) x ^= static_cast<unsigned char>(c);
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\n", x);
  return "$" + body + tail;
}

struct Imu {
  std::uint32_t seq;
  std::uint32_t us;
  double g[3], a[3];
};
Imu imu(std::uint32_t seq, std::uint32_t us) {
  const double k = seq;
  return {seq, us, {0.001 * k, -0.5, 0.25 + k}, {0.125, -9.81, 1e-3 * k}};
}
std::string imuSentence(const Imu& m) {
  char body[200];
  std::snprintf(body, sizeof body, "IMU,%u,%u,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f", m.seq, m.us, m.g[0],
                m.g[1], m.g[2], m.a[0], m.a[1], m.a[2]);
  return sentence(body);
}

void expectSample(const DeviceSample& s, const Imu& m, double deviceTime) {
  SCOPED_TRACE("seq " + std::to_string(m.seq));
  EXPECT_EQ(s.stream, 0);
  EXPECT_NEAR(s.deviceTime, deviceTime, 1e-9);
  ASSERT_TRUE(std::holds_alternative<ImuReading>(s.payload));
  const ImuReading& r = std::get<ImuReading>(s.payload);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.gyr[i], m.g[i], 1e-9);
    EXPECT_NEAR(r.acc[i], m.a[i], 1e-9);
  }
}

// A fake serial device: the master side of a pseudo-terminal behind a stable symlink.
class FakeSerial {
 public:
  explicit FakeSerial(QString link) : m_link(std::move(link)) {}
  ~FakeSerial() { unplug(); }
  void plug() {
    unplug();
    char name[256] = {};
    ASSERT_EQ(openpty(&m_master, &m_slave, name, nullptr, nullptr), 0);
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
  }
  void unplug() {
    // The link goes first: a freed /dev/pts/N is soon given to another process (tests run in
    // parallel), and the device, retrying, must not open that one.
    if (m_master >= 0) QFile::remove(m_link);
    if (m_master >= 0) ::close(m_master);
    if (m_slave >= 0) ::close(m_slave);
    m_master = m_slave = -1;
  }
  void send(const std::string& b) {
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
  void sendSplit(const std::string& b, std::size_t chunk) {
    for (std::size_t i = 0; i < b.size(); i += chunk) {
      send(b.substr(i, chunk));
      QTest::qWait(1);
    }
  }

 private:
  QString m_link;
  int m_master = -1, m_slave = -1;
};

using Harness = test::DeviceHarness;

// A UDP port that was free a moment ago.
std::uint16_t freeUdpPort() {
  QUdpSocket s;
  EXPECT_TRUE(s.bind(QHostAddress::LocalHost, 0));
  return s.localPort();
}

class LineImuDevice : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(m_dir.isValid());
    m_link = m_dir.filePath(QStringLiteral("imu-%1").arg(QDir(m_dir.path()).dirName()));
    m_plugin = test::loadPlugin(QStringLiteral("line-imu"));
    ASSERT_NE(m_plugin, nullptr);
  }
  std::unique_ptr<Device> create(const QVariantMap& options) {
    QString error;
    auto d = m_plugin->create(options, &error);
    EXPECT_TRUE(d) << error.toStdString();
    return d;
  }
  QVariantMap serialOptions() const {
    return {{QStringLiteral("port"), m_link},
            {QStringLiteral("role"), QStringLiteral("upper")},
            {QStringLiteral("retry"), QStringLiteral("0.1")}};
  }
  QString createError(const QVariantMap& options) {
    QString error;
    EXPECT_FALSE(m_plugin->create(options, &error));
    return error;
  }

  QTemporaryDir m_dir;
  QString m_link;
  DevicePlugin* m_plugin = nullptr;
};

}  // namespace

TEST_F(LineImuDevice, OptionsSayWhatToChange) {
  EXPECT_EQ(m_plugin->name(), QStringLiteral("line-imu"));
  const QString role = QStringLiteral("role"), upper = QStringLiteral("upper");
  EXPECT_TRUE(createError({{role, upper}}).contains(QStringLiteral("not neither")));
  EXPECT_TRUE(
      createError({{role, upper}, {QStringLiteral("port"), m_link}, {QStringLiteral("udp"), 9871}})
          .contains(QStringLiteral("not both")));
  EXPECT_TRUE(
      createError({{role, upper}, {QStringLiteral("udp"), 9871}, {QStringLiteral("baud"), 9600}})
          .contains(QStringLiteral("'baud' is for a serial port")));
  EXPECT_TRUE(
      createError({{QStringLiteral("udp"), 9871}}).contains(QStringLiteral("'role' is required")));
  EXPECT_TRUE(createError({{role, upper}, {QStringLiteral("udp"), 70000}})
                  .contains(QStringLiteral("option 'udp'")));
  EXPECT_TRUE(
      createError({{role, upper}, {QStringLiteral("udp"), 9871}, {QStringLiteral("rate"), 100}})
          .contains(QStringLiteral("unknown option 'rate'")));
  auto d = create({{role, QStringLiteral("forearm")}, {QStringLiteral("udp"), 9871}});
  ASSERT_TRUE(d);
  EXPECT_EQ(d->streams().at(0).role, StreamRole::ForearmImu);
}

TEST_F(LineImuDevice, SerialSamplesAcrossTheMicrosecondWrapAreExact) {
  FakeSerial fake(m_link);
  fake.plug();
  Harness h(create(serialOptions()));
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  QTest::qWait(50);  // let the device open the port before bytes flow

  const std::uint32_t t0 = 4294967295u - 95000u;  // micros() wraps after the 10th sample
  std::string text = sentence("HELLO,1,esp32-upper,100");
  std::vector<Imu> sent;
  for (std::uint32_t k = 0; k < 30; ++k) {
    sent.push_back(imu(k, t0 + 10000u * k));  // uint32 arithmetic wraps like the device's
    text += imuSentence(sent.back());
  }
  const double before = hostNow();
  fake.sendSplit(text, 17);
  ASSERT_TRUE(h.waitSamples(30));
  const double after = hostNow();
  EXPECT_EQ(h.state(), DeviceState::Streaming);
  ASSERT_EQ(h.samples.size(), 30u);
  for (std::size_t k = 0; k < 30; ++k) {
    expectSample(h.samples[k], sent[k], (static_cast<double>(t0) + 10000.0 * k) * 1e-6);
    EXPECT_GE(h.samples[k].arrivalTime, before);
    EXPECT_LE(h.samples[k].arrivalTime, after);
  }
  EXPECT_TRUE(h.problems.isEmpty()) << h.problems.join(u'\n').toStdString();
  EXPECT_EQ(h.device->health().streams[0].corrupt, 0u);
}

TEST_F(LineImuDevice, SerialBadInputIsCountedAndReportedButGoodSentencesAllArrive) {
  FakeSerial fake(m_link);
  fake.plug();
  Harness h(create(serialOptions()));
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  QTest::qWait(50);

  std::vector<Imu> good;
  std::string text;
  auto goodOne = [&](std::uint32_t seq) {
    good.push_back(imu(seq, 1000u + 10000u * seq));
    text += imuSentence(good.back());
  };
  goodOne(0);
  goodOne(1);
  text += "\x01\x02garbage\xff\xfe\r\n";  // 1: bytes outside a sentence
  goodOne(2);
  std::string bad = imuSentence(imu(3, 31000));
  bad[bad.size() - 3] ^= 1;  // 2: checksum digit changed
  text += bad;
  goodOne(4);                                        // seq 3 missing: 1 dropped
  text += imuSentence(imu(5, 51000)).substr(0, 20);  // 3: truncated by the next '$'
  goodOne(6);
  text += sentence("IMU,7,71000,nan,0,0,0,0,9.81");  // 4: NaN
  text += sentence("IMU,8,81000,0,0,0,0,9.81");      // 5: a field missing
  text += "$IMU,9," + std::string(300, '1') + "\n";  // 6: too long
  text += sentence("GPS,1,2");                       // 7: unknown sentence
  goodOne(10);
  goodOne(11);
  fake.sendSplit(text, 23);

  ASSERT_TRUE(h.waitSamples(good.size()));
  QTest::qWait(50);
  ASSERT_EQ(h.samples.size(), good.size());
  for (std::size_t i = 0; i < good.size(); ++i)
    expectSample(h.samples[i], good[i], (1000.0 + 10000.0 * good[i].seq) * 1e-6);
  const DeviceHealth health = h.device->health();
  EXPECT_EQ(health.streams[0].corrupt, 7u);  // one per bad sentence or run of stray bytes
  EXPECT_EQ(health.streams[0].dropped, 5u);  // sequence gaps: 3, 5, and 7-9
  ASSERT_FALSE(h.problems.isEmpty());
  EXPECT_TRUE(h.problems.front().contains(QStringLiteral("byte")))
      << h.problems.front().toStdString();
  EXPECT_LE(h.problems.size(), 2);  // rate-limited: the rest are summed up a second later
  EXPECT_EQ(h.state(), DeviceState::Streaming);
}

TEST_F(LineImuDevice, AFloodOfGarbageGivesOneMessagePerSecondAndLosesNothingAfter) {
  FakeSerial fake(m_link);
  fake.plug();
  Harness h(create(serialOptions()));
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  QTest::qWait(50);
  std::string flood;
  for (int i = 0; i < 200; ++i) flood += sentence("IMU,1,2,3") + "\x07noise\n";  // 2 problems each
  std::vector<Imu> good;
  for (std::uint32_t k = 0; k < 5; ++k) {
    good.push_back(imu(100 + k, 5000u * k));
    flood += imuSentence(good.back());
  }
  fake.sendSplit(flood, 512);
  ASSERT_TRUE(h.waitSamples(5));
  ASSERT_EQ(h.samples.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) expectSample(h.samples[i], good[i], 5000e-6 * i);
  EXPECT_EQ(h.device->health().streams[0].corrupt, 400u);
  EXPECT_LE(h.problems.size(), 1);
  // When the second is over, the rest are summed up in one message.
  ASSERT_TRUE(QTest::qWaitFor([&] { return h.problems.size() == 2; }, 1500));
  EXPECT_TRUE(h.problems[1].contains(QStringLiteral("more problems in the last second")))
      << h.problems[1].toStdString();
  QTest::qWait(1100);
  EXPECT_EQ(h.problems.size(), 2);  // nothing new, nothing more said
}

TEST_F(LineImuDevice, SerialUnplugGoesConnectingAndComesBack) {
  FakeSerial fake(m_link);
  fake.plug();
  Harness h(create(serialOptions()));
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  QTest::qWait(50);
  fake.send(imuSentence(imu(0, 0)) + imuSentence(imu(1, 10000)));
  ASSERT_TRUE(h.waitState(DeviceState::Streaming));
  ASSERT_TRUE(h.waitSamples(2));

  fake.unplug();
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  EXPECT_TRUE(h.reason().contains(QStringLiteral("closed"))) << h.reason().toStdString();
  QTest::qWait(150);  // the port is missing for a while: still connecting, no crash
  EXPECT_EQ(h.state(), DeviceState::Connecting);

  fake.plug();
  QTest::qWait(300);  // retry=0.1: the device reopens the port within this time
  fake.send(sentence("HELLO,1,esp32-upper,100") + imuSentence(imu(0, 500)));
  ASSERT_TRUE(h.waitState(DeviceState::Streaming));
  ASSERT_TRUE(h.waitSamples(3));
  expectSample(h.samples[2], imu(0, 500), 500e-6);
  EXPECT_EQ(h.device->health().reconnects, 1u);
}

TEST_F(LineImuDevice, UdpDatagramsGarbageAndSilence) {
  const std::uint16_t port = freeUdpPort();
  Harness h(create({{QStringLiteral("udp"), port},
                    {QStringLiteral("role"), QStringLiteral("forearm")},
                    {QStringLiteral("timeout"), QStringLiteral("0.3")}}));
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  EXPECT_TRUE(h.reason().contains(QString::number(port))) << h.reason().toStdString();
  QUdpSocket tx;
  auto sendDatagram = [&](const std::string& d) {
    ASSERT_EQ(
        tx.writeDatagram(d.data(), static_cast<qint64>(d.size()), QHostAddress::LocalHost, port),
        static_cast<qint64>(d.size()));
  };
  std::vector<Imu> good;
  auto goodDatagram = [&](std::uint32_t first, int n) {
    std::string d;
    for (int i = 0; i < n; ++i) {
      good.push_back(imu(first + i, 20000u * (first + i)));
      d += imuSentence(good.back());
    }
    sendDatagram(d);
  };
  goodDatagram(0, 3);
  sendDatagram(std::string("\x00\x01\x02\xff binary noise", 18));  // 1 problem
  const std::string split = imuSentence(imu(3, 60000));
  sendDatagram(split.substr(0, 25));  // 2: ends inside a sentence
  sendDatagram(split.substr(25));     // 3: stray bytes, no '$'
  goodDatagram(4, 2);
  sendDatagram(sentence("IMU,6,1,2"));  // 4: field count
  goodDatagram(7, 1);
  ASSERT_TRUE(h.waitSamples(good.size()));
  QTest::qWait(50);
  ASSERT_EQ(h.samples.size(), good.size());
  for (std::size_t i = 0; i < good.size(); ++i)
    expectSample(h.samples[i], good[i], 20000e-6 * good[i].seq);
  EXPECT_EQ(h.state(), DeviceState::Streaming);
  EXPECT_EQ(h.device->health().streams[0].corrupt, 4u);
  EXPECT_EQ(h.device->health().streams[0].dropped, 2u);  // seq 3 and 6
  EXPECT_FALSE(h.problems.isEmpty());

  // The sender goes quiet: connecting after the timeout, streaming again when it returns.
  ASSERT_TRUE(h.waitState(DeviceState::Connecting, 1500));
  EXPECT_TRUE(h.reason().contains(QStringLiteral("no $IMU"))) << h.reason().toStdString();
  goodDatagram(8, 1);
  ASSERT_TRUE(h.waitState(DeviceState::Streaming));
  EXPECT_EQ(h.device->health().reconnects, 1u);
}

TEST_F(LineImuDevice, UdpOutOfOrderDatagramsAreCountedReorderedNotDropped) {
  const std::uint16_t port = freeUdpPort();
  Harness h(
      create({{QStringLiteral("udp"), port}, {QStringLiteral("role"), QStringLiteral("upper")}}));
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  QUdpSocket tx;
  // 0 1 3 2 5 4 4 7: two overtaken (2, 4), one duplicate (4), one really lost (6). Overtaken
  // sentences are not published (device time never goes back) but are not counted as dropped.
  const std::vector<std::uint32_t> order = {0, 1, 3, 2, 5, 4, 4, 7};
  for (std::uint32_t k : order) {
    const std::string d = imuSentence(imu(k, 20000u * k));
    ASSERT_EQ(
        tx.writeDatagram(d.data(), static_cast<qint64>(d.size()), QHostAddress::LocalHost, port),
        static_cast<qint64>(d.size()));
    QTest::qWait(2);  // keep the order on the wire
  }
  ASSERT_TRUE(h.waitSamples(5));
  QTest::qWait(50);
  ASSERT_EQ(h.samples.size(), 5u);
  const std::vector<std::uint32_t> published = {0, 1, 3, 5, 7};
  for (std::size_t i = 0; i < published.size(); ++i)
    expectSample(h.samples[i], imu(published[i], 20000u * published[i]), 0.02 * published[i]);
  const StreamHealth s = h.device->health().streams[0];
  EXPECT_EQ(s.dropped, 1u);  // seq 6 only
  EXPECT_EQ(s.reordered, 2u);
  EXPECT_EQ(s.samples + s.dropped + s.reordered, 8u);  // every distinct seq 0-7 accounted for
  EXPECT_FALSE(h.problems.isEmpty());                  // the duplicate is reported
}

TEST_F(LineImuDevice, UdpPortInUseIsAnErrorTheUserMustFix) {
  QUdpSocket other;
  ASSERT_TRUE(other.bind(QHostAddress::Any, 0));
  Harness h(create({{QStringLiteral("udp"), other.localPort()},
                    {QStringLiteral("role"), QStringLiteral("upper")}}));
  ASSERT_TRUE(h.waitState(DeviceState::Error));
  EXPECT_TRUE(h.reason().contains(QStringLiteral("already in use"))) << h.reason().toStdString();
}

TEST_F(LineImuDevice, ARestartedDeviceIsReported) {
  const std::uint16_t port = freeUdpPort();
  Harness h(
      create({{QStringLiteral("udp"), port}, {QStringLiteral("role"), QStringLiteral("upper")}}));
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  QUdpSocket tx;
  const std::string before = sentence("HELLO,1,esp32,100") + imuSentence(imu(0, 900000));
  const std::string after = sentence("HELLO,1,esp32,100") + imuSentence(imu(0, 1000));
  tx.writeDatagram(before.data(), static_cast<qint64>(before.size()), QHostAddress::LocalHost,
                   port);
  ASSERT_TRUE(h.waitSamples(1));
  tx.writeDatagram(after.data(), static_cast<qint64>(after.size()), QHostAddress::LocalHost, port);
  ASSERT_TRUE(h.waitSamples(2));
  expectSample(h.samples[1], imu(0, 1000), 1000e-6);  // the new epoch's own time
  ASSERT_EQ(h.problems.size(), 1);
  EXPECT_TRUE(h.problems[0].contains(QStringLiteral("esp32 restarted")))
      << h.problems[0].toStdString();
  EXPECT_EQ(h.device->health().streams[0].corrupt, 0u);
}

// ---------------------------------------------------------------------------------------------
// A flood on the port: good $IMU datagrams at 500 Hz, for 2 s buried under as many junk datagrams
// as one sender thread can push to 127.0.0.1 (about 100k per second), then 1 s of good ones
// alone. Every good datagram must be either published or counted as dropped, and no sample may
// be stamped as arriving before it was sent.

namespace {

struct FloodResult {
  std::uint32_t goodSent = 0;
  std::uint64_t junkSent = 0;
  std::vector<double> sentAt;  // hostNow() just before each good datagram was sent
};

// Sends to 127.0.0.1:port from this thread; returns when done (about 3.5 s).
FloodResult floodUdp(std::uint16_t port, const std::function<std::string(std::uint32_t)>& good) {
  FloodResult r;
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  EXPECT_GE(fd, 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(port);
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const auto send = [&](const std::string& d) {
    return ::sendto(fd, d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to) ==
           static_cast<ssize_t>(d.size());
  };
  const std::string junk(120, 'x');  // no '$': one corrupt datagram each
  const double start = hostNow(), period = 0.002;
  const double floodFrom = 0.5, floodTo = 2.5, end = 3.5;
  for (;;) {
    const double now = hostNow() - start;
    if (now >= end) break;
    if (now >= r.goodSent * period) {
      r.sentAt.push_back(hostNow());
      EXPECT_TRUE(send(good(r.goodSent)));
      ++r.goodSent;
    } else if (now >= floodFrom && now < floodTo) {
      r.junkSent += send(junk);
    } else {
      ::usleep(200);
    }
  }
  ::close(fd);
  return r;
}

}  // namespace

TEST_F(LineImuDevice, UdpFloodLosesNoGoodSampleUncountedAndStampsArrivalsHonestly) {
  const std::uint16_t port = freeUdpPort();
  Harness h(
      create({{QStringLiteral("udp"), port}, {QStringLiteral("role"), QStringLiteral("upper")}}));
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  FloodResult flood;
  std::atomic<bool> done{false};
  std::thread sender([&] {
    flood = floodUdp(port, [](std::uint32_t k) { return imuSentence(imu(k, 2000u * k)); });
    done = true;
  });
  // The device's samples are delivered to this thread while it waits.
  EXPECT_TRUE(QTest::qWaitFor([&] { return done.load(); }, 10000));
  sender.join();
  const auto accounted = [&] { return h.samples.size() + h.device->health().streams[0].dropped; };
  EXPECT_TRUE(QTest::qWaitFor([&] { return accounted() >= flood.goodSent; }, 3000));
  h.stop();
  const StreamHealth s = h.device->health().streams[0];
  std::printf(
      "line-imu flood: %u good and %llu junk datagrams sent; %zu published, %llu counted "
      "dropped (%.1f %%), %llu corrupt\n",
      flood.goodSent, static_cast<unsigned long long>(flood.junkSent), h.samples.size(),
      static_cast<unsigned long long>(s.dropped), 100.0 * s.dropped / flood.goodSent,
      static_cast<unsigned long long>(s.corrupt));
  EXPECT_GT(flood.junkSent, 10000u);
  EXPECT_EQ(h.samples.size() + s.dropped, flood.goodSent);
  // Arrival stamps: never before the datagram was sent.
  std::size_t early = 0;
  for (const DeviceSample& d : h.samples) {
    const auto k = static_cast<std::size_t>(std::lround(d.deviceTime / 0.002));
    if (k < flood.sentAt.size() && d.arrivalTime < flood.sentAt[k]) ++early;
  }
  EXPECT_EQ(early, 0u);
}

// A third sensor on the sternum: role=trunk makes the stream the trunk IMU, named for it. NaN and
// numbers beyond a double are refused like any bad sentence; a reading at a sensor's full scale
// (saturated) is a reading, passed on as sent: the estimator judges it (docs/estimator.md).
TEST_F(LineImuDevice, TrunkRoleStreamsTheSternumSensorAndRefusesNaN) {
  const std::uint16_t port = freeUdpPort();
  Harness h(
      create({{QStringLiteral("udp"), port}, {QStringLiteral("role"), QStringLiteral("trunk")}}));
  ASSERT_EQ(h.device->streams().size(), 1u);
  EXPECT_EQ(h.device->streams()[0].role, StreamRole::TrunkImu);
  EXPECT_EQ(h.device->streams()[0].name, "trunk line IMU");
  ASSERT_TRUE(h.waitState(DeviceState::Connecting));
  QUdpSocket tx;
  auto sendDatagram = [&](const std::string& d) {
    ASSERT_EQ(
        tx.writeDatagram(d.data(), static_cast<qint64>(d.size()), QHostAddress::LocalHost, port),
        static_cast<qint64>(d.size()));
  };
  std::vector<Imu> good{imu(0, 0), imu(1, 10000)};
  Imu saturated{4, 40000, {34.9, -34.9, 34.9}, {156.9, -156.9, 156.9}};  // 2000 deg/s, 16 g
  sendDatagram(imuSentence(good[0]) + imuSentence(good[1]));
  sendDatagram(sentence("IMU,2,20000,nan,0,0,0,-9.81,0"));    // refused: NaN
  sendDatagram(sentence("IMU,3,30000,0,0,0,1e400,-9.81,0"));  // refused: beyond a double
  sendDatagram(sentence("IMU,3,30000,0,0,inf,0,-9.81,0"));    // refused: infinite
  sendDatagram(imuSentence(saturated));
  good.push_back(saturated);
  ASSERT_TRUE(h.waitSamples(good.size()));
  QTest::qWait(50);
  ASSERT_EQ(h.samples.size(), good.size());
  for (std::size_t i = 0; i < good.size(); ++i)
    expectSample(h.samples[i], good[i], 1e-6 * good[i].us);
  EXPECT_EQ(h.state(), DeviceState::Streaming);
  EXPECT_EQ(h.device->health().streams[0].corrupt, 3u);
  EXPECT_FALSE(h.problems.isEmpty());
}
