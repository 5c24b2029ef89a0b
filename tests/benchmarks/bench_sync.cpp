// armtrack-server under load (issue 28, acceptance 3; docs/sync.md, "Benchmark"): N simulated home
// devices (default 100), each with its own token and thread, upload the same simulated 10-minute
// session at once to armtrack-server, a child process, on a PostgreSQL server started here
// (durable, as bench_storage's). Prints the throughput (sessions/s, MB/s of recording) and the
// server's peak memory (VmHWM); exits 1 when a session is missing, stored twice or differs from
// what was sent (counts, checksums, and every sample read back from the records), or when the
// peak memory is over the limit. Figures, not a ctest test.
// Run: build/tests/benchmarks/bench_sync [--devices N] [--minutes M] [--imu-rate HZ]
//        [--chunk-kib K] [--memory-limit-mib L] [--server PATH]
#include <unistd.h>
#include <QCoreApplication>
#include <QCryptographicHash>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QSqlQuery>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QThread>
#include <QUuid>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/io/Recording.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/SyncUploads.h"
#include "tests/app/server/SyncTestClient.h"
#include "tests/support/PostgresServer.h"

using namespace armtrack;
using armtrack::server::test::Reply;
using armtrack::server::test::SyncTestClient;

namespace {

struct Options {
  int devices = 100;
  double minutes = 10;
  double imuRate = 100;  // Hz, both IMUs; the Kinect at its 30 Hz
  int chunkKib = 1024;
  double memoryLimitMib = 1024;
  QString server = ARMTRACK_SERVER;
};

/// A digest of every sample's time and readings, bit for bit: the same for the recording sent and
/// the one read back from the records when nothing was lost or changed.
QByteArray digest(const Recording& rec) {
  QCryptographicHash h(QCryptographicHash::Sha256);
  const auto add = [&h](const double* v, int n) {
    h.addData(QByteArrayView(reinterpret_cast<const char*>(v), n * sizeof(double)));
  };
  for (const ArmSample& s : rec.samples) {
    add(&s.t, 1);
    for (const auto* imu : {&s.upperArm, &s.forearm}) {
      h.addData(QByteArrayView(imu->has_value() ? "1" : "0"));
      if (*imu) {
        add((*imu)->gyr.data(), 3);
        add((*imu)->acc.data(), 3);
      }
    }
    for (const auto* p : {&s.elbow, &s.wrist}) {
      h.addData(QByteArrayView(p->has_value() ? "1" : "0"));
      if (*p) add((*p)->data(), 3);
    }
  }
  return h.result();
}

/// The server's peak resident memory (VmHWM, KiB) from /proc; -1 when it cannot be read.
long peakKib(qint64 pid) {
  QFile f(QString("/proc/%1/status").arg(pid));
  if (!f.open(QIODevice::ReadOnly)) return -1;
  for (const QByteArray& line : f.readAll().split('\n'))
    if (line.startsWith("VmHWM:")) return line.mid(6).trimmed().split(' ').value(0).toLong();
  return -1;
}

/// The server's CPU time (user + system, s) from /proc.
double cpuSeconds(qint64 pid) {
  QFile f(QString("/proc/%1/stat").arg(pid));
  if (!f.open(QIODevice::ReadOnly)) return -1;
  const QByteArray stat = f.readAll();
  const QList<QByteArray> fields = stat.mid(stat.lastIndexOf(')') + 2).split(' ');
  return (fields.value(11).toDouble() + fields.value(12).toDouble()) / sysconf(_SC_CLK_TCK);
}

struct Device {
  QByteArray token, uuid;
  int failures = 0;
  int retries = 0;  // requests sent again after no answer, 429 or 503
  QByteArray firstError;
  qint64 session = 0;
  double doneAt = 0;  // s after the start
};

int run(const Options& o) {
  QTemporaryDir dir;
  if (!dir.isValid()) throw std::runtime_error("no temporary folder");
  QElapsedTimer setup;
  setup.start();

  // One recording, sent by every device.
  SimulationParams sim;
  sim.duration = o.minutes * 60;
  sim.upperArm.rateHz = sim.forearm.rateHz = o.imuRate;
  sim.includeTruth = false;
  TrajectoryOptions to;
  to.seed = 11;
  const std::filesystem::path csvPath = dir.filePath("home.csv").toStdString();
  writeRecording(csvPath, simulateRecording(*makeTrajectory("multi-joint", to), sim));
  const Recording sent = readRecording(csvPath);
  QFile csvFile(dir.filePath("home.csv")), sideFile(dir.filePath("home.json"));
  if (!csvFile.open(QIODevice::ReadOnly) || !sideFile.open(QIODevice::ReadOnly))
    throw std::runtime_error("cannot read the simulated recording");
  const QByteArray csv = csvFile.readAll(), sidecar = sideFile.readAll();
  const QByteArray sha = storage::sha256Hex(csv).toLatin1();
  const QByteArray sentDigest = digest(sent);
  QList<QByteArray> chunks;
  for (qsizetype at = 0; at < csv.size(); at += qsizetype{o.chunkKib} * 1024)
    chunks << csv.mid(at, qsizetype{o.chunkKib} * 1024);
  QList<QByteArray> chunkSha;
  for (const QByteArray& c : chunks) chunkSha << storage::sha256Hex(c).toLatin1();
  const QByteArray meta = "{\"sha256\":\"" + sha +
                          "\",\"size_bytes\":" + QByteArray::number(csv.size()) +
                          ",\"chunks\":" + QByteArray::number(chunks.size()) +
                          ",\"protocol\":\"reach\",\"sidecar\":" + sidecar + "}";

  // The records: N patients, each with a home account and an enrolled device.
  test::PostgresServer pg(/*durable=*/true);
  const QString url = pg.createDatabase(test::PostgresServer::uniqueName("bench_sync"));
  std::vector<Device> devices(o.devices);
  {
    storage::Database db(storage::DatabaseUrl::parse(url), {true, false});
    storage::ClinicalStore store(db);
    store.initialise("admin", "correct horse battery");
    store.signIn("admin", "correct horse battery");
    storage::Protocol reach;
    reach.name = "reach";
    reach.angleKey = "shoulder_flexion";
    reach.targetMinDeg = 10;
    reach.targetMaxDeg = 110;
    reach.repetitions = 8;
    store.addProtocol(reach);
    storage::ClinicalStore enrol(db);
    for (int i = 0; i < o.devices; ++i) {
      const QString code = QString("P%1").arg(i, 3, 10, QChar('0'));
      storage::Patient p;
      p.code = code;
      p.name = "Bench " + code;
      p.birthDate = "1960-01-01";
      p.sex = "f";
      p.affectedSide = "right";
      store.addPatient(p);
      store.addUser("home" + code, storage::Role::Home, "home password 123", code);
      const QString once = store.createEnrolmentCode("home" + code, 600).code;
      devices[i].token = enrol.enrolDevice(once, "bench").token.toLatin1();
      devices[i].uuid = QUuid::createUuid().toString(QUuid::WithoutBraces).toLatin1();
    }
  }

  // A certificate, and the server on a free loopback port, its log in a file.
  const QString cert = dir.filePath("cert.pem"), key = dir.filePath("key.pem");
  QProcess openssl;
  openssl.start("openssl", {"req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:P-256",
                            "-nodes", "-keyout", key, "-out", cert, "-days", "1", "-subj",
                            "/CN=localhost", "-addext", "subjectAltName=DNS:localhost"});
  if (!openssl.waitForFinished(60000) || openssl.exitCode() != 0)
    throw std::runtime_error("openssl could not make a certificate");
  quint16 port = 0;
  {
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0)) throw std::runtime_error("no free port");
    port = probe.serverPort();
  }
  QProcess server;
  server.setStandardErrorFile(dir.filePath("server.log"));
  server.start(o.server, {"--db", url, "--port", QString::number(port), "--listen", "127.0.0.1",
                          "--cert", cert, "--key", key, "--rate", "1000"});
  QByteArray out;
  for (int i = 0; i < 300 && !out.contains("listening"); ++i) {
    server.waitForReadyRead(100);
    out += server.readAllStandardOutput();
    if (server.state() == QProcess::NotRunning) break;
  }
  if (!out.contains("listening"))
    throw std::runtime_error("armtrack-server did not start: " + o.server.toStdString());
  const QSslCertificate ca = QSslCertificate::fromPath(cert).value(0);
  std::printf(
      "bench_sync: %d devices, each a %.0f-minute session (IMUs at %.0f Hz): %.1f MB of CSV in "
      "%lld chunks of %d KiB; set up in %.1f s\n",
      o.devices, o.minutes, o.imuRate, csv.size() / 1e6, static_cast<long long>(chunks.size()),
      o.chunkKib, setup.elapsed() / 1e3);
  std::fflush(stdout);

  // All devices at once, each on its own thread: declare, send the chunks, complete.
  QElapsedTimer clock;
  clock.start();
  std::vector<std::unique_ptr<QThread>> threads;
  for (Device& d : devices) {
    threads.emplace_back(QThread::create([&, port] {
      SyncTestClient c(port, ca);
      c.token = d.token;
      c.answerTimeoutMs = 60 * 60 * 1000;  // a completion waits for the analyses queued before it
      // As a home device does: a request that got no answer (the connection refused, cut or
      // timed out) or was told to wait (429, 503) is sent again, a little later; every step is
      // idempotent.
      const auto send = [&](const QByteArray& method, const QByteArray& path,
                            const QByteArray& body, QList<QPair<QByteArray, QByteArray>> headers,
                            int want) {
        Reply r;
        for (int attempt = 1; attempt <= 8; ++attempt) {
          r = c.send(method, path, body, headers);
          if (r.status != 0 && r.status != 429 && r.status != 503) break;
          ++d.retries;
          QThread::msleep(500 * attempt);
        }
        if (r.status != want && !(want == 201 && r.status == 200) && d.failures++ == 0)
          d.firstError = method + ' ' + QByteArray::number(r.status) + ' ' + r.body;
        return r;
      };
      const QByteArray at = "/api/v1/sessions/" + d.uuid;
      if (send("PUT", at, meta, {}, 201).status / 100 != 2) return;
      for (int i = 0; i < chunks.size(); ++i) {
        send("PUT", at + "/chunks/" + QByteArray::number(i), chunks[i],
             {{"X-Chunk-Sha256", chunkSha[i]}}, 200);
      }
      const Reply done = send("POST", at + "/complete", {}, {}, 200);
      if (done.status == 200) d.session = done.json().value("session").toInteger();
      d.doneAt = clock.elapsed() / 1e3;
    }));
  }
  for (auto& t : threads) t->start();
  for (auto& t : threads) t->wait();
  const double seconds = clock.elapsed() / 1e3;
  const long peak = peakKib(server.processId());
  const double cpu = cpuSeconds(server.processId());
  server.terminate();
  server.waitForFinished(30000);

  // Everything stored once and whole: counts, the declared checksums, every sample.
  int failed = 0;
  for (const Device& d : devices) {
    if (d.failures) {
      if (failed++ < 5)
        std::printf("  device %s: %d failed requests, the first: %s\n", d.uuid.constData(),
                    d.failures, d.firstError.left(300).constData());
    }
  }
  storage::Database db(storage::DatabaseUrl::parse(url), {});
  const auto one = [&db](const QString& sql, const QVariantList& args = {}) {
    QSqlQuery q = db.exec(sql, args);
    return q.next() ? q.value(0).toLongLong() : -1;
  };
  const qint64 sessions = one("SELECT count(*) FROM sessions");
  const qint64 stored =
      one("SELECT count(*) FROM sync_uploads WHERE session_id IS NOT NULL AND sha256 = ? AND "
          "size_bytes = ?",
          {QString::fromLatin1(sha), csv.size()});
  const qint64 analysed = one("SELECT count(*) FROM sessions WHERE analysis = 'done'");
  const qint64 leftChunks = one("SELECT count(*) FROM sync_upload_chunks");
  storage::ClinicalStore store(db);
  store.signIn("admin", "correct horse battery");
  int same = 0;
  for (const Device& d : devices)
    if (d.session && digest(store.readRecording(d.session)) == sentDigest) ++same;

  const double mb = csv.size() / 1e6 * o.devices;
  std::printf("bench_sync: all uploads done in %.1f s: %.2f sessions/s, %.1f MB/s of recording\n",
              seconds, o.devices / seconds, mb / seconds);
  double first = seconds;
  int retries = 0;
  for (const Device& d : devices) {
    if (d.session) first = std::min(first, d.doneAt);
    retries += d.retries;
  }
  std::printf("bench_sync: first session stored and analysed after %.1f s, the last after %.1f s\n",
              first, seconds);
  std::printf(
      "bench_sync: server peak memory (VmHWM) %.0f MiB (limit %.0f MiB), CPU %.1f s; "
      "PostgreSQL on this machine, durable\n",
      peak / 1024.0, o.memoryLimitMib, cpu);
  std::printf(
      "bench_sync: stored %lld sessions (%lld analysed), %lld uploads with the declared checksum, "
      "%d read back sample for sample, %lld chunks left, %d devices with failed requests; %d "
      "requests sent again (no answer, 429 or 503)\n",
      static_cast<long long>(sessions), static_cast<long long>(analysed),
      static_cast<long long>(stored), same, static_cast<long long>(leftChunks), failed, retries);
  const bool ok = sessions == o.devices && stored == o.devices && same == o.devices &&
                  analysed == o.devices && leftChunks == 0 && failed == 0 && peak > 0 &&
                  peak / 1024.0 <= o.memoryLimitMib;
  std::printf("bench_sync: %s\n", ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  Options o;
  const QStringList args = app.arguments();
  for (qsizetype i = 1; i + 1 < args.size(); i += 2) {
    bool ok = true;
    const QString& a = args[i];
    if (a == "--devices")
      o.devices = args[i + 1].toInt(&ok);
    else if (a == "--minutes")
      o.minutes = args[i + 1].toDouble(&ok);
    else if (a == "--imu-rate")
      o.imuRate = args[i + 1].toDouble(&ok);
    else if (a == "--chunk-kib")
      o.chunkKib = args[i + 1].toInt(&ok);
    else if (a == "--memory-limit-mib")
      o.memoryLimitMib = args[i + 1].toDouble(&ok);
    else if (a == "--server")
      o.server = args[i + 1];
    else
      ok = false;
    if (!ok || o.devices < 1 || o.minutes <= 0 || o.imuRate <= 0 || o.chunkKib < 1 ||
        o.chunkKib > 8192) {
      std::fprintf(stderr,
                   "bench_sync: bad option '%s'. Options: --devices N --minutes M --imu-rate HZ "
                   "--chunk-kib 1..8192 --memory-limit-mib L --server PATH\n",
                   qPrintable(a));
      return 2;
    }
  }
  if (args.size() % 2 == 0) {
    std::fprintf(stderr, "bench_sync: '%s' needs a value\n", qPrintable(args.last()));
    return 2;
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_sync: %s\n", e.what());
    return 1;
  }
}
