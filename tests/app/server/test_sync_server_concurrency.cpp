// armtrack-server under concurrent requests (issue 28; docs/sync.md): a completion (join, import,
// analysis) runs on a worker while other requests are answered; two home devices of two patients
// upload at once to the server process on PostgreSQL, and both sessions are stored once and whole;
// the program reads its configuration file (the package's /etc/armtrack/server.conf).
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QSemaphore>
#include <QThread>
#include <QTimer>

#include "tests/app/server/SyncServerFixture.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;
using namespace armtrack::server;
using namespace armtrack::server::test;

namespace {

/// A request sent without waiting for its answer, which arrives as the event loop runs.
class PendingRequest {
 public:
  PendingRequest(quint16 port, const QSslCertificate& ca, const QByteArray& request,
                 std::function<void()> onAnswer)
      : m_onAnswer(std::move(onAnswer)) {
    QSslConfiguration tls = QSslConfiguration::defaultConfiguration();
    tls.setCaCertificates({ca});
    m_socket.setSslConfiguration(tls);
    QObject::connect(&m_socket, &QSslSocket::encrypted,
                     [this, request] { m_socket.write(request); });
    QObject::connect(&m_socket, &QSslSocket::readyRead, [this] {
      m_in += m_socket.readAll();
      if (!answered() || m_told) return;
      m_told = true;
      m_onAnswer();
    });
    m_socket.connectToHostEncrypted("localhost", port);
  }
  /// Whether the whole answer (headers and Content-Length bytes of body) has come.
  bool answered() const {
    const qsizetype end = m_in.indexOf("\r\n\r\n");
    if (end < 0) return false;
    const qsizetype at = m_in.toLower().indexOf("content-length:");
    const qsizetype eol = m_in.indexOf("\r\n", at);
    return m_in.size() - end - 4 >= m_in.mid(at + 15, eol - at - 15).trimmed().toLongLong();
  }
  QByteArray raw() const { return m_in; }
  Reply reply() const {
    const qsizetype end = m_in.indexOf("\r\n\r\n");
    return {answered() ? m_in.mid(9, 3).toInt() : 0, m_in.mid(end + 4)};
  }

 private:
  QSslSocket m_socket;
  QByteArray m_in;
  bool m_told = false;
  std::function<void()> m_onAnswer;
};

/// Runs the event loop until done() or about limitMs have passed; the test then checks done().
template <typename F>
void runUntil(F done, int limitMs = 60000) {
  for (int waited = 0; !done() && waited < limitMs; waited += 20) {
    QEventLoop loop;
    QTimer::singleShot(20, &loop, &QEventLoop::quit);
    loop.exec();
  }
}

std::vector<int> missingOf(const Reply& r) {
  std::vector<int> out;
  for (const QJsonValue& v : r.json().value("missing").toArray()) out.push_back(v.toInt());
  return out;
}

}  // namespace

// The completion is held on its worker (beforeCompletion) until the test lets it go; meanwhile a
// health and a programme request are answered. Only the order of events is checked. A server that
// completed on its event loop would block there (at most 10 s, the hook's own limit, so the test
// fails rather than hangs) and answer the completion first.
TEST(SyncServer, ACompletionRunsOffTheEventLoopAndOtherRequestsAreAnsweredMeanwhile) {
  ServerFixture f;
  SyncTestClient c = f.device("home1");
  const TestRecording t = makeRecording(f);
  const QList<QByteArray> chunks = t.chunks(2);
  const QByteArray uuid = newUuid();
  ASSERT_EQ(c.send("PUT", "/api/v1/sessions/" + uuid, t.meta(chunks.size())).status, 201);
  sendChunks(c, uuid, chunks);

  QSemaphore started, go;
  f.api->beforeCompletion = [&] {
    started.release();
    go.tryAcquire(1, 10000);
  };
  QStringList events;
  const QByteArray request = "POST /api/v1/sessions/" + uuid +
                             "/complete HTTP/1.1\r\nHost: localhost\r\nAuthorization: Bearer " +
                             c.token + "\r\nContent-Length: 0\r\n\r\n";
  PendingRequest completion(f.server->port(), QSslCertificate::fromPath(f.certPath).value(0),
                            request, [&] { events << "completion answered"; });
  runUntil([&] { return started.available() > 0; });
  ASSERT_TRUE(started.tryAcquire()) << "the completion never started";
  events << "completion started";

  const Reply health = f.client().send("GET", "/api/v1/health");
  events << "health answered " + QString::number(health.status);
  const Reply programme = c.send("GET", "/api/v1/programme");
  events << "programme answered " + QString::number(programme.status);
  go.release();
  runUntil([&] { return completion.answered(); });
  f.api->beforeCompletion = nullptr;

  EXPECT_EQ(events, (QStringList{"completion started", "health answered 200",
                                 "programme answered 200", "completion answered"}));
  const Reply done = completion.reply();
  ASSERT_EQ(done.status, 200) << completion.raw().toStdString();
  EXPECT_EQ(done.json().value("analysis").toString(), "done");
  ASSERT_EQ(f.store->listSessions("P1").size(), 1u);
  const qint64 id = done.json().value("session").toInteger();
  EXPECT_EQ(f.store->session(id).analysis, kAnalysisDone);
  expectSameRows(*f.store, id, t.rec);
  EXPECT_TRUE(f.logLines.contains("POST /api/v1/sessions/" + uuid + "/complete 200 device 1"))
      << f.logLines.join('\n').toStdString();
}

// Requests on one connection are answered in order even when the first is a completion answered
// later: the second is read only once the first is answered.
TEST(SyncServer, RequestsOnOneConnectionAreAnsweredInOrderAroundACompletion) {
  ServerFixture f;
  SyncTestClient c = f.device("home1");
  const TestRecording t = makeRecording(f);
  const QByteArray uuid = newUuid();
  ASSERT_EQ(c.send("PUT", "/api/v1/sessions/" + uuid, t.meta(1)).status, 201);
  sendChunks(c, uuid, {t.csv});
  const QByteArray auth = "Authorization: Bearer " + c.token + "\r\n";
  const QByteArray both = "POST /api/v1/sessions/" + uuid + "/complete HTTP/1.1\r\nHost: x\r\n" +
                          auth + "Content-Length: 0\r\n\r\nGET /api/v1/sessions/" + uuid +
                          " HTTP/1.1\r\nHost: x\r\n" + auth + "Content-Length: 0\r\n\r\n";
  PendingRequest pipelined(f.server->port(), QSslCertificate::fromPath(f.certPath).value(0), both,
                           [] {});
  const auto secondBody = [&] {  // the second answer follows the first's body
    const QByteArray rest = pipelined.reply().body.mid(pipelined.reply().body.indexOf("HTTP/1.1"));
    return QJsonDocument::fromJson(rest.mid(rest.indexOf("\r\n\r\n") + 4)).object();
  };
  runUntil([&] { return secondBody().contains("session"); });
  const Reply r = pipelined.reply();
  ASSERT_EQ(r.status, 200);
  const qsizetype second = r.body.indexOf("HTTP/1.1 200");
  ASSERT_GT(second, 0) << r.body.toStdString();
  const QJsonObject first = QJsonDocument::fromJson(r.body.left(second)).object();
  EXPECT_EQ(first.value("analysis").toString(), "done") << r.body.toStdString();
  EXPECT_EQ(secondBody().value("session").toInteger(), first.value("session").toInteger());
}

// Two home devices of two patients upload at once, each from its own thread, to the server
// process on PostgreSQL: each session is stored once, its rows bit for bit and its checksum the
// declared one, and nothing of either is left over or mixed up.
TEST(SyncServerProgram, TwoDevicesUploadAtOnceOnPostgres) {
  ServerFixture f({}, Engine::Postgres);
  ServerProcess server;
  ASSERT_TRUE(server.start(f, 0)) << server.process.readAllStandardError().toStdString();
  const QSslCertificate ca = QSslCertificate::fromPath(f.certPath).value(0);
  struct Device {
    QString account, patient;
    TestRecording t;
    QByteArray token, uuid;
    Reply done;
    std::vector<int> statuses;
  };
  Device devices[2] = {{"home1", "P1", makeRecording(f), {}, newUuid(), {}, {}},
                       {"home2", "P2", {}, {}, newUuid(), {}, {}}};
  {  // the second patient's recording: another length, so the two cannot be taken for each other
    TestRecording& t = devices[1].t;
    t.rec = simulateTo(f.file("home2.csv"), 7.0, 100.0);
    t.csv = QByteArray::fromStdString(fileBytes(f.file("home2.csv")));
    t.sidecar = QByteArray::fromStdString(fileBytes(f.file("home2.json")));
    t.sha = sha256Hex(t.csv).toLatin1();
  }
  for (Device& d : devices) {
    SyncTestClient c(server.port, ca);
    const QByteArray code = f.store->createEnrolmentCode(d.account, 600).code.toUtf8();
    const Reply r = c.send("POST", "/api/v1/enrol", "{\"code\":\"" + code + "\"}");
    ASSERT_EQ(r.status, 201) << r.body.toStdString();
    d.token = r.json().value("token").toString().toLatin1();
  }
  // Each device: declare, send its chunks, complete, on its own thread and connections.
  std::vector<std::unique_ptr<QThread>> threads;
  for (Device& d : devices) {
    threads.emplace_back(QThread::create([&d, &server, ca] {
      SyncTestClient c(server.port, ca);
      c.token = d.token;
      const QList<QByteArray> chunks = d.t.chunks(8);
      const QByteArray at = "/api/v1/sessions/" + d.uuid;
      d.statuses.push_back(c.send("PUT", at, d.t.meta(chunks.size())).status);
      for (int i = 0; i < chunks.size(); ++i) {
        d.statuses.push_back(c.send("PUT", at + "/chunks/" + QByteArray::number(i), chunks[i],
                                    {{"X-Chunk-Sha256", sha256Hex(chunks[i]).toLatin1()}})
                                 .status);
      }
      d.done = c.send("POST", at + "/complete");
    }));
  }
  for (auto& t : threads) t->start();
  for (auto& t : threads) ASSERT_TRUE(t->wait(120000));

  for (const Device& d : devices) {
    SCOPED_TRACE(d.account.toStdString());
    EXPECT_EQ(d.statuses.front(), 201);
    EXPECT_EQ(std::count(d.statuses.begin(), d.statuses.end(), 200), 8);
    ASSERT_EQ(d.done.status, 200) << d.done.body.toStdString();
    EXPECT_EQ(d.done.json().value("analysis").toString(), "done");
    const qint64 id = d.done.json().value("session").toInteger();
    const std::vector<SessionInfo> sessions = f.store->listSessions(d.patient);
    ASSERT_EQ(sessions.size(), 1u);
    EXPECT_EQ(sessions[0].id, id);
    EXPECT_EQ(f.store->session(id).patientCode, d.patient);
    expectSameRows(*f.store, id, d.t.rec);
    const auto stored =
        rawQuery(f.path, "SELECT sha256, session_id FROM sync_uploads WHERE uuid = '" +
                             QString::fromLatin1(d.uuid).toLower() + "'");
    ASSERT_EQ(stored.size(), 1u);
    EXPECT_EQ(stored[0][0].toString().toLatin1(), d.t.sha);
    EXPECT_EQ(stored[0][1].toLongLong(), id);
    // Asked again afterwards: the same session, nothing missing.
    SyncTestClient c(server.port, ca);
    c.token = d.token;
    const Reply state = c.send("GET", "/api/v1/sessions/" + d.uuid);
    EXPECT_EQ(state.json().value("session").toInteger(), id);
    EXPECT_TRUE(missingOf(state).empty());
  }
  EXPECT_EQ(f.count("SELECT count(*) FROM sessions"), 2);
  EXPECT_EQ(f.count("SELECT count(*) FROM sync_uploads"), 2);
  EXPECT_EQ(f.count("SELECT count(*) FROM sync_upload_chunks"), 0);
  EXPECT_EQ(f.count("SELECT count(*) FROM audit_log WHERE action = 'sync-upload'"), 2);
  server.process.terminate();
  server.process.waitForFinished(10000);
}

// The program reads its options from --config (the package's /etc/armtrack/server.conf), the
// command line's winning; a line it does not understand stops it, naming the file and line.
TEST(SyncServerProgram, ReadsItsConfigurationFileAndTheCommandLineWins) {
  ServerFixture f;
  QFile conf(f.dir.filePath("server.conf"));
  ASSERT_TRUE(conf.open(QIODevice::WriteOnly));
  conf.write(
      "# a comment\n\ndb = " + f.path.toUtf8() + "\nport = 1\ncert = " + f.certPath.toUtf8() +
      "   # trailing comment\nkey = " + f.keyPath.toUtf8() + "\nlisten = 127.0.0.1\nrate = 5\n");
  conf.close();
  QTcpServer probe;
  ASSERT_TRUE(probe.listen(QHostAddress::LocalHost, 0));
  const quint16 port = probe.serverPort();
  probe.close();
  QProcess p;
  p.start(ARMTRACK_SERVER, {"--config", conf.fileName(), "--port", QString::number(port)});
  QByteArray out;
  for (int i = 0; i < 100 && !out.contains("listening"); ++i) {
    p.waitForReadyRead(100);
    out += p.readAllStandardOutput();
  }
  EXPECT_TRUE(out.contains("listening on https://127.0.0.1:" + QByteArray::number(port)))
      << out.toStdString() << p.readAllStandardError().toStdString();
  SyncTestClient c(port, QSslCertificate::fromPath(f.certPath).value(0));
  const Reply health = c.send("GET", "/api/v1/health");
  EXPECT_EQ(health.status, 200);
  EXPECT_EQ(health.json().value("status").toString(), "ok");
  p.terminate();
  ASSERT_TRUE(p.waitForFinished(10000));

  ASSERT_TRUE(conf.open(QIODevice::Append));
  conf.write("porte = 8443\n");
  conf.close();
  p.start(ARMTRACK_SERVER, {"--config", conf.fileName()});
  ASSERT_TRUE(p.waitForFinished(10000));
  EXPECT_EQ(p.exitCode(), 2);
  EXPECT_TRUE(p.readAllStandardError().contains("server.conf:9: expected 'name = value'"));
  p.start(ARMTRACK_SERVER, {"--config", f.dir.filePath("absent.conf")});
  ASSERT_TRUE(p.waitForFinished(10000));
  EXPECT_EQ(p.exitCode(), 2);
  EXPECT_TRUE(p.readAllStandardError().contains("cannot read the configuration"));
  p.start(ARMTRACK_SERVER, {"--version"});
  ASSERT_TRUE(p.waitForFinished(10000));
  EXPECT_TRUE(p.readAllStandardOutput().startsWith("armtrack-server "));
}
