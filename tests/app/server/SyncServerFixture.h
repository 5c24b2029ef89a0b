// The sync server's test fixture (test_sync_server): records with two patients and their home
// accounts, armtrack-server's API on them behind TLS on loopback with a certificate the test
// makes, a simulated recording to upload, and armtrack-server as a child process.
#pragma once

#include <gtest/gtest.h>

#include <QCryptographicHash>
#include <QFile>
#include <QProcess>
#include <QTcpServer>
#include <QUuid>

#include "app/server/HttpsServer.h"
#include "app/server/SyncApi.h"
#include "app/server/Tls.h"
#include "core/storage/SyncUploads.h"
#include "tests/app/server/SyncTestClient.h"
#include "tests/app/server/TestCertificate.h"
#include "tests/core/storage/StorageTestSupport.h"

namespace armtrack::server::test {

using namespace armtrack::storage;
using namespace armtrack::storage::test;

inline constexpr const char* kHomePassword = "home password 123";

using armtrack::test::makeCertificate;

/// The records (SQLite) with patients P1 and P2 and their home accounts, a programme for P1,
/// and armtrack-server's API on them behind TLS on a free loopback port.
struct ServerFixture : Fixture {
  QString certPath, keyPath;
  std::unique_ptr<SyncApi> api;
  std::unique_ptr<HttpsServer> server;
  QStringList logLines;

  explicit ServerFixture(SyncApi::Options options = {}, Engine engine = Engine::Sqlite)
      : Fixture(engine) {
    store->addPatient(makePatient("P1"));
    store->addPatient(makePatient("P2"));
    store->addUser("home1", Role::Home, kHomePassword, "P1");
    store->addUser("home2", Role::Home, kHomePassword, "P2");
    store->addProtocol(makeProtocol("reach", "shoulder_flexion", 10, 110, 8));
    ProgrammeItem item;
    item.protocolName = "reach";
    item.sets = 3;
    store->setProgrammeExercise("P1", item);
    std::tie(certPath, keyPath) = makeCertificate(dir);
    api = std::make_unique<SyncApi>(*db, options);
    api->log = [this](const QString& line) { logLines << line; };
    HttpsServer::Limits limits;
    limits.maxBodyBytes = 1 << 20;
    // As armtrack-server runs it: completions on a worker, answered when done.
    server = std::make_unique<HttpsServer>(
        serverTls(certPath, keyPath), limits,
        [this](const HttpRequest& r, HttpsServer::Responder done) { api->handle(r, done); });
    server->listen(QHostAddress::LocalHost, 0);
  }
  SyncTestClient client() const {
    return SyncTestClient(server->port(), QSslCertificate::fromPath(certPath).value(0));
  }
  /// A client enrolled as the account's device (its token set).
  SyncTestClient device(const QString& account) {
    SyncTestClient c = client();
    const QByteArray code = store->createEnrolmentCode(account, 600).code.toUtf8();
    const Reply r = c.send("POST", "/api/v1/enrol", "{\"code\":\"" + code + "\"}");
    EXPECT_EQ(r.status, 201) << r.body.toStdString();
    c.token = r.json().value("token").toString().toLatin1();
    return c;
  }
  int count(const QString& sql) { return rawQuery(path, sql)[0][0].toInt(); }
};

/// A 10 s recording (100 Hz IMUs) as bytes, with its sidecar as JSON.
struct TestRecording {
  QByteArray csv, sidecar;
  Recording rec;
  QByteArray sha;
  QList<QByteArray> chunks(int n) const {
    QList<QByteArray> out;
    const qsizetype step = (csv.size() + n - 1) / n;
    for (qsizetype at = 0; at < csv.size(); at += step) out << csv.mid(at, step);
    return out;
  }
  QByteArray meta(int chunkCount, const QByteArray& sha256 = {}) const {
    return "{\"sha256\":\"" + (sha256.isEmpty() ? sha : sha256) +
           "\",\"size_bytes\":" + QByteArray::number(csv.size()) +
           ",\"chunks\":" + QByteArray::number(chunkCount) +
           ",\"protocol\":\"reach\",\"sidecar\":" + sidecar +
           ",\"outcome\":{\"pain_score\":2,\"comment\":\"ok\",\"summary\":{\"sets\":3}}}";
  }
};
inline TestRecording makeRecording(const Fixture& f) {
  TestRecording t;
  const std::filesystem::path csv = f.file("home.csv");
  t.rec = simulateTo(csv, 10.0, 100.0);
  t.csv = QByteArray::fromStdString(fileBytes(csv));
  t.sidecar = QByteArray::fromStdString(fileBytes(f.file("home.json")));
  t.sha = sha256Hex(t.csv).toLatin1();
  return t;
}

inline QByteArray newUuid() {
  return QUuid::createUuid().toString(QUuid::WithoutBraces).toLatin1();
}

/// Sends chunks (all, or those in only) of an upload.
inline void sendChunks(SyncTestClient& c, const QByteArray& uuid, const QList<QByteArray>& chunks,
                       std::vector<int> only = {}) {
  if (only.empty())
    for (int i = 0; i < chunks.size(); ++i) only.push_back(i);
  for (int i : only) {
    const Reply r = c.send("PUT", "/api/v1/sessions/" + uuid + "/chunks/" + QByteArray::number(i),
                           chunks[i], {{"X-Chunk-Sha256", sha256Hex(chunks[i]).toLatin1()}});
    EXPECT_EQ(r.status, 200) << i << ": " << r.body.toStdString();
  }
}

/// The stored session's rows are the recording's, bit for bit.
inline void expectSameRows(ClinicalStore& store, qint64 id, const Recording& original) {
  const Recording stored = store.readRecording(id);
  ASSERT_EQ(stored.samples.size(), original.samples.size());
  for (std::size_t i = 0; i < stored.samples.size(); ++i) {
    ASSERT_TRUE(sameBits(stored.samples[i].t, original.samples[i].t)) << i;
    const ArmSample &a = stored.samples[i], &b = original.samples[i];
    ASSERT_EQ(a.upperArm.has_value(), b.upperArm.has_value()) << i;
    ASSERT_EQ(a.forearm.has_value(), b.forearm.has_value()) << i;
    ASSERT_EQ(a.elbow.has_value(), b.elbow.has_value()) << i;
    for (int k = 0; k < 3; ++k) {
      if (a.upperArm) {
        ASSERT_TRUE(sameBits(a.upperArm->gyr[k], b.upperArm->gyr[k])) << i;
      }
      if (a.forearm) {
        ASSERT_TRUE(sameBits(a.forearm->acc[k], b.forearm->acc[k])) << i;
      }
      if (a.elbow) {
        ASSERT_TRUE(sameBits((*a.elbow)[k], (*b.elbow)[k])) << i;
      }
    }
  }
}

/// armtrack-server as a process on the fixture's records, on port (0: a free one, found first).
struct ServerProcess {
  QProcess process;
  quint16 port = 0;
  bool start(const ServerFixture& f, quint16 wanted) {
    port = wanted;
    if (port == 0) {
      QTcpServer probe;
      if (!probe.listen(QHostAddress::LocalHost, 0)) return false;
      port = probe.serverPort();
    }
    process.start(ARMTRACK_SERVER, {"--db", f.path, "--port", QString::number(port), "--listen",
                                    "127.0.0.1", "--cert", f.certPath, "--key", f.keyPath});
    QByteArray out;
    for (int i = 0; i < 100 && !out.contains("listening"); ++i) {
      process.waitForReadyRead(100);
      out += process.readAllStandardOutput();
      if (process.state() == QProcess::NotRunning) return false;
    }
    return out.contains("listening on https://127.0.0.1:" + QByteArray::number(port));
  }
};

}  // namespace armtrack::server::test
