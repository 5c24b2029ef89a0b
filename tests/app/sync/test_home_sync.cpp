// The home install's sync client (app/sync, docs/sync.md "The home install") against the real
// armtrack-server code on loopback with certificates the test makes: enrolment pins the
// certificate; sessions recorded with the server down wait and are sent once it is up, stored
// at the clinic once each with the CSV's SHA-256 of the local copy; a connection cut between
// chunks resumes without duplicates; another certificate is refused; a programme changed at the
// clinic reaches the local records at the next sync.
#include <gtest/gtest.h>

#include <QCryptographicHash>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTcpServer>

#include "app/server/HttpsServer.h"
#include "app/server/SyncApi.h"
#include "app/server/Tls.h"
#include "app/sync/HomeSyncClient.h"
#include "app/sync/SyncState.h"
#include "tests/app/server/TestCertificate.h"
#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;
using namespace armtrack::server;
using namespace armtrack::sync;

namespace {

constexpr const char* kHomePassword = "home password 123";

using armtrack::test::fileSha256;
using armtrack::test::makeCertificate;

/// The clinic's records behind armtrack-server's code (started and stopped at will on one
/// port), and a home install's own records with the same patient and home account.
struct HomeSyncFixture {
  Fixture clinic, home;
  QTemporaryDir certs, stateDir;
  std::pair<QString, QString> certA, certB;
  std::unique_ptr<SyncApi> api;
  std::unique_ptr<HttpsServer> server;
  QStringList serverLog;
  quint16 port = 0;

  HomeSyncFixture() {
    for (Fixture* f : {&clinic, &home}) {
      f->store->addPatient(makePatient("P1"));
      f->store->addUser("home1", Role::Home, kHomePassword, "P1");
      f->store->addProtocol(makeProtocol("reach", "shoulder_flexion", 10, 110, 8));
    }
    ProgrammeItem item;
    item.protocolName = "reach";
    item.sets = 3;
    clinic.store->setProgrammeExercise("P1", item);
    certA = makeCertificate(certs, "a");
    certB = makeCertificate(certs, "b");
    QTcpServer probe;
    probe.listen(QHostAddress::LocalHost, 0);
    port = probe.serverPort();
  }
  bool start(const std::pair<QString, QString>& cert) {
    api = std::make_unique<SyncApi>(*clinic.db, SyncApi::Options{});
    api->log = [this](const QString& line) { serverLog << line; };
    server =
        std::make_unique<HttpsServer>(serverTls(cert.first, cert.second), HttpsServer::Limits{},
                                      [this](const HttpRequest& r) { return api->handle(r); });
    return server->listen(QHostAddress::LocalHost, port);
  }
  void stop() {
    server.reset();
    api.reset();
  }
  QString url() const { return "https://localhost:" + QString::number(port); }

  std::unique_ptr<HomeSyncClient> client() {
    HomeSyncClient::Options o;
    o.chunkBytes = 16 << 10;  // several chunks per session
    o.timeoutMs = 10000;
    return std::make_unique<HomeSyncClient>(DatabaseUrl::parse(home.path), stateDir.path(), o);
  }
  bool enrol(HomeSyncClient& c) {
    const QString code = clinic.store->createEnrolmentCode("home1", 600).code;
    QSignalSpy done(&c, &HomeSyncClient::enrolFinished);
    c.enrol(url(), code, "test tablet");
    if (!done.wait(30000)) return false;
    return done.at(0).at(0).toBool();
  }
  SyncStatus sync(HomeSyncClient& c) {
    QSignalSpy done(&c, &HomeSyncClient::synced);
    c.sync();
    EXPECT_TRUE(done.wait(60000));
    return c.status();
  }
  /// A home session recorded by the home account in the local records, with its outcome.
  qint64 recordAtHome(int n) {
    const std::filesystem::path csv = home.file(("home" + std::to_string(n) + ".csv").c_str());
    simulateTo(csv, 6.0 + n, 100.0);
    ClinicalStore patient(*home.db);
    patient.signIn("home1", kHomePassword);
    const qint64 id = patient.importRecording(csv, "P1", "reach");
    patient.saveHomeOutcome(id, n, "session " + QString::number(n), "{\"sets\": 3}");
    return id;
  }
  /// The CSV SHA-256 of a session as its records export it.
  QString exportSha(ClinicalStore& store, qint64 id, const QString& name) {
    const QString path = certs.filePath(name + ".csv");
    store.exportRecording(id, path.toStdString());
    return fileSha256(path);
  }
  int count(Fixture& f, const QString& sql) { return rawQuery(f.path, sql)[0][0].toInt(); }
};

}  // namespace

TEST(HomeSync, SessionsRecordedOfflineAreSentOnceEachWhenTheServerComesUp) {
  HomeSyncFixture f;
  ASSERT_FALSE(f.certA.first.isEmpty()) << "openssl could not make a certificate";
  ASSERT_TRUE(f.start(f.certA));
  auto c = f.client();
  ASSERT_TRUE(f.enrol(*c));
  EXPECT_TRUE(c->status().enrolled);
  // The device state is private: owner-only, and holds the token and the pinned certificate.
  SyncState stateFile(f.stateDir.path());
  namespace fs = std::filesystem;
  EXPECT_EQ(fs::status(stateFile.filePath().toStdString()).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(stateFile.device().token.size(), 43);
  EXPECT_EQ(QSslCertificate(stateFile.device().certificate),
            QSslCertificate::fromPath(f.certA.first).value(0));
  f.stop();

  // Two sessions at home with the server down: kept, counted, nothing at the clinic.
  const std::vector<qint64> local{f.recordAtHome(1), f.recordAtHome(2)};
  const SyncStatus offline = f.sync(*c);
  EXPECT_EQ(offline.problem, SyncProblem::Offline) << offline.detail.toStdString();
  EXPECT_EQ(offline.waiting, 2);
  EXPECT_TRUE(f.clinic.store->listSessions("P1").empty());

  ASSERT_TRUE(f.start(f.certA));
  QList<qint64> sent;
  QObject::connect(c.get(), &HomeSyncClient::sessionSent, [&](qint64 id, qint64) { sent << id; });
  const SyncStatus done = f.sync(*c);
  EXPECT_EQ(done.problem, SyncProblem::None) << done.detail.toStdString();
  EXPECT_EQ(done.waiting, 0);
  EXPECT_TRUE(done.lastSent.isValid());
  EXPECT_EQ(sent, (QList<qint64>{local[0], local[1]}));
  // At the clinic: each session once, a home session with the patient's outcome, analysed, and
  // with the CSV SHA-256 of the local copy, compared end to end.
  const std::vector<SessionInfo> stored = f.clinic.store->listSessions("P1");
  ASSERT_EQ(stored.size(), 2u);
  QStringList localShas, clinicShas;
  for (qint64 id : local)
    localShas << f.exportSha(*f.home.store, id, "local" + QString::number(id));
  for (const SessionInfo& s : stored) {
    EXPECT_EQ(s.setting, kSettingHome);
    EXPECT_EQ(s.protocolName, "reach");
    EXPECT_EQ(s.analysis, kAnalysisDone);
    EXPECT_TRUE(s.painScore == 1 || s.painScore == 2);
    clinicShas << f.exportSha(*f.clinic.store, s.id, "clinic" + QString::number(s.id));
  }
  localShas.sort();
  clinicShas.sort();
  EXPECT_EQ(localShas, clinicShas);
  EXPECT_EQ(f.count(f.clinic, "SELECT count(*) FROM sync_uploads"), 2);
  EXPECT_EQ(f.count(f.clinic, "SELECT count(*) FROM sync_upload_chunks"), 0);
  for (qint64 id : local) {
    const std::optional<UploadRecord> u = stateFile.upload(id);
    ASSERT_TRUE(u && u->sent());
    EXPECT_TRUE(localShas.contains(u->sha256));
  }
  // The local sessions stay for the home window's history; a second sync sends nothing again.
  EXPECT_EQ(f.home.store->listSessions("P1").size(), 2u);
  EXPECT_EQ(f.sync(*c).waiting, 0);
  EXPECT_EQ(f.clinic.store->listSessions("P1").size(), 2u);
  // The server's log names no patient.
  for (const QString& line : f.serverLog) EXPECT_FALSE(line.contains("P1")) << line.toStdString();
}

TEST(HomeSync, AConnectionCutBetweenChunksResumesWithoutDuplicates) {
  HomeSyncFixture f;
  ASSERT_TRUE(f.start(f.certA));
  auto c = f.client();
  ASSERT_TRUE(f.enrol(*c));
  const qint64 id = f.recordAtHome(3);
  // The server goes away after the second chunk: the session stays waiting, not sent.
  int chunks = 0;
  const auto cut = QObject::connect(c.get(), &HomeSyncClient::chunkSent, [&](qint64, int) {
    if (++chunks == 2) f.stop();
  });
  const SyncStatus cutOff = f.sync(*c);
  QObject::disconnect(cut);
  EXPECT_EQ(chunks, 2);
  EXPECT_EQ(cutOff.problem, SyncProblem::Offline) << cutOff.detail.toStdString();
  EXPECT_EQ(cutOff.waiting, 1);
  SyncState stateFile(f.stateDir.path());
  ASSERT_TRUE(stateFile.upload(id).has_value());
  EXPECT_FALSE(stateFile.upload(id)->sent());
  EXPECT_GT(stateFile.upload(id)->chunks, 3);
  EXPECT_EQ(f.count(f.clinic, "SELECT count(*) FROM sync_upload_chunks"), 2);
  EXPECT_TRUE(f.clinic.store->listSessions("P1").empty());

  // Back up: the client asks what is missing and sends only that. Until complete's 200 the
  // session is still counted as waiting.
  ASSERT_TRUE(f.start(f.certA));
  int resent = 0, waitingAtLastChunk = -1;
  QObject::connect(c.get(), &HomeSyncClient::chunkSent, [&](qint64, int) {
    ++resent;
    waitingAtLastChunk = c->status().waiting;
  });
  const SyncStatus done = f.sync(*c);
  EXPECT_EQ(done.problem, SyncProblem::None) << done.detail.toStdString();
  EXPECT_EQ(resent, stateFile.upload(id)->chunks - 2);
  EXPECT_EQ(waitingAtLastChunk, 1);
  EXPECT_EQ(done.waiting, 0);
  ASSERT_EQ(f.clinic.store->listSessions("P1").size(), 1u);
  EXPECT_EQ(f.count(f.clinic, "SELECT count(*) FROM sync_uploads"), 1);
  const qint64 stored = f.clinic.store->listSessions("P1")[0].id;
  EXPECT_EQ(f.exportSha(*f.clinic.store, stored, "clinic"),
            f.exportSha(*f.home.store, id, "local"));
  EXPECT_EQ(stateFile.upload(id)->serverSession, stored);
}

TEST(HomeSync, AnotherCertificateAfterEnrolmentIsRefused) {
  HomeSyncFixture f;
  ASSERT_FALSE(f.certB.first.isEmpty());
  ASSERT_TRUE(f.start(f.certA));
  auto c = f.client();
  ASSERT_TRUE(f.enrol(*c));
  f.stop();
  f.recordAtHome(1);
  // Same address, another certificate (as a server put in its place would show).
  ASSERT_TRUE(f.start(f.certB));
  f.serverLog.clear();
  const SyncStatus refused = f.sync(*c);
  EXPECT_EQ(refused.problem, SyncProblem::CertificateChanged) << refused.detail.toStdString();
  EXPECT_EQ(refused.waiting, 1);
  EXPECT_TRUE(f.serverLog.isEmpty()) << f.serverLog.join('\n').toStdString();  // nothing sent
  EXPECT_TRUE(f.clinic.store->listSessions("P1").empty());
  // A new client (the program started again) refuses it too: the pin is kept in the state file.
  auto again = f.client();
  EXPECT_EQ(f.sync(*again).problem, SyncProblem::CertificateChanged);
  // The pinned certificate again: sent.
  f.stop();
  ASSERT_TRUE(f.start(f.certA));
  EXPECT_EQ(f.sync(*again).problem, SyncProblem::None);
  EXPECT_EQ(f.clinic.store->listSessions("P1").size(), 1u);
}

TEST(HomeSync, AProgrammeChangedAtTheClinicReachesTheLocalRecordsAtTheNextSync) {
  HomeSyncFixture f;
  ASSERT_TRUE(f.start(f.certA));
  auto c = f.client();
  ASSERT_TRUE(f.enrol(*c));
  ASSERT_EQ(f.sync(*c).problem, SyncProblem::None);
  std::vector<ProgrammeItem> local = f.home.store->programme("P1");
  ASSERT_EQ(local.size(), 1u);
  EXPECT_EQ(local[0].sets, 3);
  // The therapist changes it: 5 sets of 12, and a second exercise with a new protocol.
  f.clinic.store->addProtocol(makeProtocol("lift", "elbow_flexion", 20, 120, 6));
  ProgrammeItem reach;
  reach.protocolName = "reach";
  reach.sets = 5;
  reach.repetitions = 12;
  reach.position = 1;
  f.clinic.store->setProgrammeExercise("P1", reach);
  ProgrammeItem lift;
  lift.protocolName = "lift";
  lift.restS = 30;
  f.clinic.store->setProgrammeExercise("P1", lift);
  // Offline it stays as it was.
  f.stop();
  EXPECT_EQ(f.sync(*c).problem, SyncProblem::Offline);
  EXPECT_EQ(f.home.store->programme("P1")[0].sets, 3);
  ASSERT_TRUE(f.start(f.certA));
  ASSERT_EQ(f.sync(*c).problem, SyncProblem::None);
  local = f.home.store->programme("P1");
  ASSERT_EQ(local.size(), 2u);
  EXPECT_EQ(local[0].protocolName, "reach");
  EXPECT_EQ(local[0].sets, 5);
  EXPECT_EQ(effectiveRepetitions(local[0], f.home.store->protocol("reach")), 12);
  EXPECT_EQ(local[1].protocolName, "lift");
  EXPECT_EQ(local[1].restS, 30);
  EXPECT_EQ(f.home.store->protocol("lift").angleKey, "elbow_flexion");
  EXPECT_EQ(effectiveTarget(local[1], f.home.store->protocol("lift")),
            (std::pair<double, double>{20, 120}));
}

TEST(HomeSync, EnrolmentWithAWrongCodeOrNoServerKeepsTheInstallUnenrolled) {
  HomeSyncFixture f;
  auto c = f.client();
  QSignalSpy done(c.get(), &HomeSyncClient::enrolFinished);
  c->enrol(f.url(), "AAAA-BBBB-CCCC", {});  // nobody listens
  ASSERT_TRUE(done.wait(30000));
  EXPECT_FALSE(done.at(0).at(0).toBool());
  EXPECT_EQ(done.at(0).at(1).value<SyncProblem>(), SyncProblem::Offline);
  ASSERT_TRUE(f.start(f.certA));
  c->enrol(f.url(), "AAAA-BBBB-CCCC", {});
  ASSERT_TRUE(done.wait(30000));
  EXPECT_EQ(done.at(1).at(1).value<SyncProblem>(), SyncProblem::Refused);
  c->enrol("not a url at all ::", "x", {});
  ASSERT_TRUE(done.wait(30000));
  EXPECT_FALSE(done.at(2).at(0).toBool());
  EXPECT_FALSE(c->status().enrolled);
  EXPECT_EQ(f.sync(*c).problem, SyncProblem::NotEnrolled);
  // The address as a patient types it, without https://: enrolled.
  c->enrol("localhost:" + QString::number(f.port),
           f.clinic.store->createEnrolmentCode("home1", 600).code, {});
  ASSERT_TRUE(done.wait(30000));
  EXPECT_TRUE(done.at(3).at(0).toBool()) << done.at(3).at(2).toString().toStdString();
  EXPECT_TRUE(c->status().enrolled);
  EXPECT_EQ(c->status().server, f.url());
}
