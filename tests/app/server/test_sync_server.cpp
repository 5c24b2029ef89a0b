// armtrack-server on loopback (issue 28; docs/sync.md): HTTPS only with a certificate the test
// makes, enrolment with valid, expired, reused and wrong codes, a session uploaded in chunks and
// found stored and analysed with the same rows and checksum, the same upload twice stored once, a
// connection cut mid-chunk and resumed, a tampered chunk, a revoked token, another patient's
// token, the size and rate limits; and the program's refusal to start without a certificate.
// test_sync_server_concurrency.cpp, in the same test program: completions off the event loop,
// two devices at once on PostgreSQL, the program's configuration file.
#include <gtest/gtest.h>

#include <QTcpSocket>

#include "core/storage/SyncSecrets.h"
#include "tests/app/server/SyncServerFixture.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;
using namespace armtrack::server;
using namespace armtrack::server::test;

TEST(SyncServer, HealthAnswersOverHttpsAndPlainHttpGetsNothing) {
  ServerFixture f;
  ASSERT_FALSE(f.certPath.isEmpty()) << "openssl could not make a certificate";
  ASSERT_NE(f.server->port(), 0);
  const Reply r = f.client().send("GET", "/api/v1/health");
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.json().value("status").toString(), "ok");
  EXPECT_FALSE(r.json().value("version").toString().isEmpty());
  // Plain HTTP on the same port: the TLS handshake fails and no byte of an answer comes back.
  QTcpSocket plain;
  plain.connectToHost(QHostAddress::LocalHost, f.server->port());
  ASSERT_TRUE(plain.waitForConnected(5000));
  plain.write("GET /api/v1/health HTTP/1.1\r\nHost: localhost\r\n\r\n");
  QByteArray got;
  QEventLoop loop;
  QObject::connect(&plain, &QTcpSocket::disconnected, &loop, &QEventLoop::quit);
  QObject::connect(&plain, &QTcpSocket::readyRead, &loop, [&] { got += plain.readAll(); });
  QTimer::singleShot(5000, &loop, &QEventLoop::quit);
  if (plain.state() == QAbstractSocket::ConnectedState) loop.exec();
  got += plain.readAll();
  EXPECT_FALSE(got.contains("HTTP/1.1 200")) << got.toStdString();
  EXPECT_FALSE(got.contains("\"ok\""));
  EXPECT_EQ(plain.state(), QAbstractSocket::UnconnectedState);
}

TEST(SyncServer, EnrolsWithAValidCodeOnlyAndTheTokenFetchesTheProgramme) {
  ServerFixture f;
  SyncTestClient c = f.client();
  const QString valid = f.store->createEnrolmentCode("home1", 600).code;
  const QString expired = f.store->createEnrolmentCode("home1", 600).code;
  f.db->exec("UPDATE enrolment_codes SET expires_at = '2020-01-01T00:00:00.000Z' WHERE id = 2");
  const auto enrol = [&](const QString& code) {
    return c.send("POST", "/api/v1/enrol", "{\"code\":\"" + code.toUtf8() + "\"}");
  };
  const Reply ok = enrol(valid);
  ASSERT_EQ(ok.status, 201) << ok.body.toStdString();
  EXPECT_EQ(ok.json().value("patient").toString(), "P1");
  const QByteArray token = ok.json().value("token").toString().toLatin1();
  EXPECT_EQ(token.size(), 43);
  const Reply reused = enrol(valid), late = enrol(expired), wrong = enrol("AAAA-BBBB-CCCC");
  for (const Reply& r : {reused, late, wrong}) {
    EXPECT_EQ(r.status, 401);
    EXPECT_EQ(r.body, wrong.body);  // one answer for all three
  }
  EXPECT_EQ(c.send("POST", "/api/v1/enrol", "not json").status, 400);
  EXPECT_EQ(f.count("SELECT count(*) FROM devices"), 1);
  c.token = token;
  const Reply programme = c.send("GET", "/api/v1/programme");
  ASSERT_EQ(programme.status, 200) << programme.body.toStdString();
  const QJsonArray exercises = programme.json().value("exercises").toArray();
  ASSERT_EQ(exercises.size(), 1);
  EXPECT_EQ(exercises[0].toObject().value("protocol").toString(), "reach");
  EXPECT_EQ(exercises[0].toObject().value("sets").toInt(), 3);
  EXPECT_EQ(exercises[0].toObject().value("repetitions").toInt(), 8);
  // No token, a made-up one: 401.
  SyncTestClient stranger = f.client();
  EXPECT_EQ(stranger.send("GET", "/api/v1/programme").status, 401);
  stranger.token = QByteArray(43, 'A');
  EXPECT_EQ(stranger.send("GET", "/api/v1/programme").status, 401);
  // The log names no patient: no code, no name, no token.
  for (const QString& line : f.logLines) {
    EXPECT_FALSE(line.contains("P1") || line.contains("Name of") || line.contains(token))
        << line.toStdString();
  }
}

TEST(SyncServer, AChunkedUploadIsStoredAnalysedAndWholeOnceEvenWhenSentTwice) {
  ServerFixture f;
  SyncTestClient c = f.device("home1");
  const TestRecording t = makeRecording(f);
  const QList<QByteArray> chunks = t.chunks(5);
  const QByteArray uuid = newUuid();
  const Reply declared = c.send("PUT", "/api/v1/sessions/" + uuid, t.meta(chunks.size()));
  ASSERT_EQ(declared.status, 201) << declared.body.toStdString();
  EXPECT_EQ(declared.json().value("missing").toArray().size(), 5);
  sendChunks(c, uuid, chunks);
  const Reply done = c.send("POST", "/api/v1/sessions/" + uuid + "/complete");
  ASSERT_EQ(done.status, 200) << done.body.toStdString();
  const qint64 id = done.json().value("session").toInteger();
  EXPECT_EQ(done.json().value("analysis").toString(), "done");
  const SessionInfo s = f.store->session(id);
  EXPECT_EQ(s.patientCode, "P1");
  EXPECT_EQ(s.setting, kSettingHome);
  EXPECT_EQ(s.protocolName, "reach");
  EXPECT_EQ(s.analysis, kAnalysisDone);
  EXPECT_EQ(s.painScore, 2);
  EXPECT_EQ(s.patientComment, "ok");
  EXPECT_TRUE(f.store->latestMetrics(id).has_value());
  expectSameRows(*f.store, id, t.rec);
  EXPECT_EQ(rawQuery(f.path, "SELECT sha256 FROM sync_uploads")[0][0].toString().toLatin1(), t.sha);
  // The same upload again, whole: the same session, nothing stored twice.
  EXPECT_EQ(c.send("PUT", "/api/v1/sessions/" + uuid, t.meta(chunks.size())).status, 200);
  sendChunks(c, uuid, chunks);
  const Reply again = c.send("POST", "/api/v1/sessions/" + uuid + "/complete");
  EXPECT_EQ(again.status, 200);
  EXPECT_EQ(again.json().value("session").toInteger(), id);
  EXPECT_EQ(f.store->listSessions("P1").size(), 1u);
  EXPECT_EQ(f.count("SELECT count(*) FROM sync_upload_chunks"), 0);
  // The same UUID with another checksum: a conflict.
  EXPECT_EQ(
      c.send("PUT", "/api/v1/sessions/" + uuid, t.meta(chunks.size(), QByteArray(64, 'a'))).status,
      409);
}

TEST(SyncServer, AConnectionCutMidChunkResumesAndTheSessionIsStoredOnceAndWhole) {
  ServerFixture f;
  SyncTestClient c = f.device("home1");
  const TestRecording t = makeRecording(f);
  const QList<QByteArray> chunks = t.chunks(6);
  const QByteArray uuid = newUuid();
  ASSERT_EQ(c.send("PUT", "/api/v1/sessions/" + uuid, t.meta(chunks.size())).status, 201);
  sendChunks(c, uuid, chunks, {0, 1});
  // Chunk 2 cut half-way (the connection dies), then chunk 4 cut after its headers.
  c.send("PUT", "/api/v1/sessions/" + uuid + "/chunks/2", chunks[2],
         {{"X-Chunk-Sha256", sha256Hex(chunks[2]).toLatin1()}}, chunks[2].size() / 2);
  c.send("PUT", "/api/v1/sessions/" + uuid + "/chunks/4", chunks[4],
         {{"X-Chunk-Sha256", sha256Hex(chunks[4]).toLatin1()}}, 0);
  EXPECT_EQ(f.count("SELECT count(*) FROM sync_upload_chunks"), 2);
  EXPECT_EQ(c.send("POST", "/api/v1/sessions/" + uuid + "/complete").status, 400);
  EXPECT_TRUE(f.store->listSessions("P1").empty());
  // Resumed: the server says what is missing, the device sends just that.
  const Reply state = c.send("GET", "/api/v1/sessions/" + uuid);
  ASSERT_EQ(state.status, 200);
  std::vector<int> missing;
  for (const QJsonValue& v : state.json().value("missing").toArray()) missing.push_back(v.toInt());
  EXPECT_EQ(missing, (std::vector<int>{2, 3, 4, 5}));
  sendChunks(c, uuid, chunks, missing);
  const Reply done = c.send("POST", "/api/v1/sessions/" + uuid + "/complete");
  ASSERT_EQ(done.status, 200) << done.body.toStdString();
  ASSERT_EQ(f.store->listSessions("P1").size(), 1u);
  expectSameRows(*f.store, done.json().value("session").toInteger(), t.rec);
}

TEST(SyncServer, ATamperedChunkIsRefusedAndNothingIsStored) {
  ServerFixture f;
  SyncTestClient c = f.device("home1");
  const TestRecording t = makeRecording(f);
  const QList<QByteArray> chunks = t.chunks(3);
  const QByteArray uuid = newUuid();
  ASSERT_EQ(c.send("PUT", "/api/v1/sessions/" + uuid, t.meta(chunks.size())).status, 201);
  QByteArray tampered = chunks[1];
  tampered[100] = tampered[100] == '7' ? '8' : '7';
  const Reply r = c.send("PUT", "/api/v1/sessions/" + uuid + "/chunks/1", tampered,
                         {{"X-Chunk-Sha256", sha256Hex(chunks[1]).toLatin1()}});
  EXPECT_EQ(r.status, 422) << r.body.toStdString();
  EXPECT_EQ(f.count("SELECT count(*) FROM sync_upload_chunks"), 0);
  // Chunks that each fit their own checksum but not the declared whole: refused at the end.
  const QByteArray other = newUuid();
  QList<QByteArray> forged = chunks;
  forged[2] = tampered;
  ASSERT_EQ(c.send("PUT", "/api/v1/sessions/" + other, t.meta(forged.size())).status, 201);
  sendChunks(c, other, forged);
  EXPECT_EQ(c.send("POST", "/api/v1/sessions/" + other + "/complete").status, 422);
  EXPECT_TRUE(f.store->listSessions("P1").empty());
  EXPECT_EQ(f.count("SELECT count(*) FROM sync_upload_chunks"), 0);
}

TEST(SyncServer, ARevokedTokenGets401AndAnotherPatientsTokenSeesNothing) {
  ServerFixture f;
  SyncTestClient mine = f.device("home1"), theirs = f.device("home2");
  const TestRecording t = makeRecording(f);
  const QByteArray uuid = newUuid();
  ASSERT_EQ(mine.send("PUT", "/api/v1/sessions/" + uuid, t.meta(1)).status, 201);
  // Another patient's device: the same answer as for a session that does not exist.
  const Reply absent = theirs.send("GET", "/api/v1/sessions/" + newUuid());
  EXPECT_EQ(absent.status, 404);
  for (const Reply& r : {theirs.send("GET", "/api/v1/sessions/" + uuid),
                         theirs.send("PUT", "/api/v1/sessions/" + uuid, t.meta(1)),
                         theirs.send("PUT", "/api/v1/sessions/" + uuid + "/chunks/0", t.csv,
                                     {{"X-Chunk-Sha256", t.sha}}),
                         theirs.send("POST", "/api/v1/sessions/" + uuid + "/complete")}) {
    EXPECT_EQ(r.status, 404);
    EXPECT_EQ(r.body, absent.body);
  }
  EXPECT_EQ(f.count("SELECT count(*) FROM sync_upload_chunks"), 0);
  // Revoked: 401 from then on.
  f.store->revokeDevice(f.store->listDevices("home1")[0].id);
  EXPECT_EQ(mine.send("GET", "/api/v1/sessions/" + uuid).status, 401);
  EXPECT_EQ(mine.send("GET", "/api/v1/programme").status, 401);
}

TEST(SyncServer, OversizedBodiesGet413AndFastDevices429) {
  SyncApi::Options options;
  options.ratePerSecond = 1;
  options.burst = 5;
  ServerFixture f(options);
  SyncTestClient c = f.device("home1");
  // A body over the limit is refused from its Content-Length, before it is sent.
  const Reply big = c.send("PUT", "/api/v1/sessions/" + newUuid() + "/chunks/0", {},
                           {{"Content-Length", QByteArray::number(2 << 20)}});
  EXPECT_EQ(big.status, 413);
  int limited = 0;
  for (int i = 0; i < 10; ++i) limited += c.send("GET", "/api/v1/programme").status == 429;
  EXPECT_GE(limited, 4);
  SyncTestClient other = f.device("home2");  // another device has its own budget
  EXPECT_EQ(other.send("GET", "/api/v1/programme").status, 200);
  // Made-up tokens: each refusal is audited, so an address gets 10 a minute, then 429.
  SyncTestClient stranger = f.client();
  std::vector<int> statuses;
  for (int i = 0; i < 12; ++i) {
    stranger.token = newDeviceToken().toLatin1();
    statuses.push_back(stranger.send("GET", "/api/v1/programme").status);
  }
  EXPECT_EQ(std::count(statuses.begin(), statuses.end(), 401), 10);
  EXPECT_EQ(std::count(statuses.begin(), statuses.end(), 429), 2);
}

TEST(SyncServerProgram, RefusesToStartWithoutACertificateAndExplainsItself) {
  QProcess p;
  p.start(ARMTRACK_SERVER, {"--db", "x.db", "--port", "8443"});
  ASSERT_TRUE(p.waitForFinished(10000));
  EXPECT_EQ(p.exitCode(), 2);
  EXPECT_TRUE(p.readAllStandardError().contains("--cert and --key are required"));
  p.start(ARMTRACK_SERVER, {"--help"});
  ASSERT_TRUE(p.waitForFinished(10000));
  EXPECT_EQ(p.exitCode(), 0);
  const QByteArray help = p.readAllStandardOutput();
  for (const char* option : {"--db", "--port", "--cert", "--key"})
    EXPECT_TRUE(help.contains(option)) << option;
  QTemporaryDir dir;
  QFile bad(dir.filePath("bad.pem"));
  ASSERT_TRUE(bad.open(QIODevice::WriteOnly));
  bad.write("not a certificate");
  bad.close();
  p.start(ARMTRACK_SERVER, {"--db", dir.filePath("x.db"), "--port", "8443", "--cert",
                            bad.fileName(), "--key", bad.fileName()});
  ASSERT_TRUE(p.waitForFinished(10000));
  EXPECT_EQ(p.exitCode(), 1);
  EXPECT_TRUE(p.readAllStandardError().contains("no PEM certificate"));
}

// The server process killed (SIGKILL) mid-chunk and started again: the device asks what is
// missing, sends it, and the session is stored once and whole.
TEST(SyncServerProgram, KilledMidUploadAndRestartedTheUploadResumes) {
  ServerFixture f;
  ServerProcess first;
  ASSERT_TRUE(first.start(f, 0)) << first.process.readAllStandardError().toStdString();
  SyncTestClient c(first.port, QSslCertificate::fromPath(f.certPath).value(0));
  const QByteArray code = f.store->createEnrolmentCode("home1", 600).code.toUtf8();
  const Reply enrolled = c.send("POST", "/api/v1/enrol", "{\"code\":\"" + code + "\"}");
  ASSERT_EQ(enrolled.status, 201) << enrolled.body.toStdString();
  c.token = enrolled.json().value("token").toString().toLatin1();
  const TestRecording t = makeRecording(f);
  const QList<QByteArray> chunks = t.chunks(6);
  const QByteArray uuid = newUuid();
  ASSERT_EQ(c.send("PUT", "/api/v1/sessions/" + uuid, t.meta(chunks.size())).status, 201);
  sendChunks(c, uuid, chunks, {0, 1, 2});
  c.send("PUT", "/api/v1/sessions/" + uuid + "/chunks/3", chunks[3],
         {{"X-Chunk-Sha256", sha256Hex(chunks[3]).toLatin1()}}, chunks[3].size() / 3);
  first.process.kill();
  ASSERT_TRUE(first.process.waitForFinished(10000));
  EXPECT_EQ(c.send("GET", "/api/v1/sessions/" + uuid).status, 0);  // nobody answers

  ServerProcess second;
  ASSERT_TRUE(second.start(f, first.port)) << second.process.readAllStandardError().toStdString();
  const Reply state = c.send("GET", "/api/v1/sessions/" + uuid);
  ASSERT_EQ(state.status, 200) << state.body.toStdString();
  std::vector<int> missing;
  for (const QJsonValue& v : state.json().value("missing").toArray()) missing.push_back(v.toInt());
  EXPECT_EQ(missing, (std::vector<int>{3, 4, 5}));
  sendChunks(c, uuid, chunks, missing);
  const Reply done = c.send("POST", "/api/v1/sessions/" + uuid + "/complete");
  ASSERT_EQ(done.status, 200) << done.body.toStdString();
  EXPECT_EQ(done.json().value("analysis").toString(), "done");
  ASSERT_EQ(f.store->listSessions("P1").size(), 1u);
  expectSameRows(*f.store, done.json().value("session").toInteger(), t.rec);
  second.process.terminate();
  second.process.waitForFinished(10000);
  // The log of a real run names no patient.
  const QByteArray log = second.process.readAllStandardError();
  EXPECT_TRUE(log.contains("POST /api/v1/sessions/" + uuid + "/complete 200")) << log.toStdString();
  EXPECT_FALSE(log.contains("P1") || log.contains("Name of")) << log.toStdString();
}
