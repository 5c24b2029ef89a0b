#include "app/server/SyncApi.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QThread>

#include "core/storage/ClinicalStore.h"
#include "core/storage/SessionAnalysis.h"
#include "core/storage/SyncUploads.h"

#ifndef ARMTRACK_VERSION
#define ARMTRACK_VERSION "unknown"
#endif

namespace armtrack::server {

namespace {

using storage::StorageError;
using Kind = StorageError::Kind;

HttpResponse json(int status, const QJsonObject& body) {
  return {status, QJsonDocument(body).toJson(QJsonDocument::Compact), "application/json", {}};
}

HttpResponse error(int status, const QString& message) {
  return json(status, {{"error", message}});
}

int statusOf(const StorageError& e) {
  switch (e.kind()) {
    case Kind::NotFound:
      return 404;
    case Kind::AccessDenied:
      return 404;  // a home account's refusal looks like absence
    case Kind::Exists:
      return 409;
    case Kind::Usage:
      return 400;
    case Kind::Corrupt:
      return 422;
    case Kind::Authentication:
      return 401;
    case Kind::Io:
      return 503;
    default:
      return 500;
  }
}

QJsonObject stateJson(const QString& uuid, const storage::UploadState& s) {
  QJsonArray missing;
  for (int m : s.missing) missing.append(m);
  return {{"uuid", uuid.toLower()},
          {"missing", missing},
          {"session", s.sessionId ? QJsonValue(s.sessionId) : QJsonValue()}};
}

QJsonObject exerciseJson(const storage::ProgrammeItem& item, const storage::Protocol& p) {
  const auto [lo, hi] = storage::effectiveTarget(item, p);
  const auto trunk = storage::effectiveTrunkLimit(item, p);
  return {{"position", item.position},
          {"protocol", item.protocolName},
          {"angle", p.angleKey},
          {"side", p.side},
          {"sets", item.sets},
          {"repetitions", storage::effectiveRepetitions(item, p)},
          {"target_min_deg", lo},
          {"target_max_deg", hi},
          {"rest_s", item.restS},
          {"sessions_per_week", item.sessionsPerWeek},
          {"trunk_limit_deg", trunk ? QJsonValue(*trunk) : QJsonValue()},
          {"notes", item.notes}};
}

/// "/api/v1/sessions/<uuid>[/chunks/<n>|/complete]" split; empty parts when it is not that.
struct SessionRoute {
  QString uuid, tail;
  int chunk = -1;
};
std::optional<SessionRoute> sessionRoute(const QString& path) {
  static const QRegularExpression re(
      "^/api/v1/sessions/([0-9a-fA-F-]{36})(?:/(chunks)/([0-9]{1,6})|/(complete))?$");
  const QRegularExpressionMatch m = re.match(path);
  if (!m.hasMatch()) return std::nullopt;
  SessionRoute r{m.captured(1), m.captured(2) + m.captured(4), -1};
  if (!m.captured(3).isEmpty()) r.chunk = m.captured(3).toInt();
  return r;
}

}  // namespace

bool RateLimiter::allow(const QByteArray& key) {
  const qint64 now = m_clock.elapsed();
  if (m_buckets.size() > 10000 && !m_buckets.contains(key)) m_buckets.clear();
  auto it = m_buckets.find(key);
  if (it == m_buckets.end()) it = m_buckets.insert(key, {m_burst, now});
  it->tokens = std::min(m_burst, it->tokens + (now - it->at) * m_rate / 1000.0);
  it->at = now;
  if (it->tokens < 1) return false;
  it->tokens -= 1;
  return true;
}

bool RateLimiter::hasLeft(const QByteArray& key) {
  const auto it = m_buckets.constFind(key);
  if (it == m_buckets.constEnd()) return true;
  return std::min(m_burst, it->tokens + (m_clock.elapsed() - it->at) * m_rate / 1000.0) >= 1;
}

namespace {

/// Lines for the server's log that come with an answer (from a worker, which does not log
/// itself): logLine writes them and takes them off before the answer is sent.
const QByteArray kLogHeader = "X-Armtrack-Log";

/// This worker thread's connection to url, opened on first use and kept while the thread lives
/// (a pool's thread ends after 30 s idle, closing it). A connection that failed is opened again.
storage::Database& workerDatabase(const storage::DatabaseUrl& url, bool reopen) {
  thread_local std::unique_ptr<storage::Database> db;
  thread_local QString opened;
  if (reopen || !db || opened != url.display()) {
    db.reset();
    db = std::make_unique<storage::Database>(url, storage::Database::Options{});
    opened = url.display();
  }
  return *db;
}

}  // namespace

SyncApi::SyncApi(storage::Database& db, Options options)
    : m_db(db),
      m_home(std::make_unique<QObject>()),
      m_perToken(options.ratePerSecond, options.burst),
      m_perAddress(options.enrolPerMinute / 60.0, options.enrolPerMinute),
      m_refusedTokens(options.refusedTokensPerMinute / 60.0, options.refusedTokensPerMinute) {
  m_workers.setMaxThreadCount(options.workers > 0 ? options.workers
                                                  : std::max(2, QThread::idealThreadCount()));
  m_writers.setMaxThreadCount(std::max(1, options.writers));
}

SyncApi::~SyncApi() {
  m_workers.waitForDone();
  m_writers.waitForDone();
}

HttpResponse SyncApi::guarded(const std::function<HttpResponse()>& f) {
  try {
    return f();
  } catch (const StorageError& e) {
    return error(statusOf(e), QString::fromStdString(e.what()));
  } catch (const std::exception& e) {
    HttpResponse r = error(500, "internal error; the server's log says more");
    r.headers.append(qMakePair(kLogHeader, "internal error: " + QByteArray(e.what())));
    return r;
  }
}

void SyncApi::logLine(const HttpRequest& request, const HttpResponse& response, qint64 device) {
  if (!log) return;
  for (const auto& [name, value] : response.headers)
    if (name == kLogHeader) log(QString::fromLocal8Bit(value));
  // The route with the UUID (random, names no one) and the device's number only.
  log(QString::fromLatin1(request.method) + ' ' + request.path.left(120) + ' ' +
      QString::number(response.status) + (device ? " device " + QString::number(device) : ""));
}

HttpResponse SyncApi::handle(const HttpRequest& request) {
  qint64 device = 0;
  Job later;
  HttpResponse response = guarded([&] { return route(request, device, &later); });
  if (later) response = guarded([&] { return later(m_db); });
  logLine(request, response, device);
  response.headers.removeIf([](const auto& h) { return h.first == kLogHeader; });
  return response;
}

void SyncApi::handle(const HttpRequest& request, const HttpsServer::Responder& done) {
  qint64 device = 0;
  Job later;
  HttpResponse response = guarded([&] { return route(request, device, &later); });
  const auto answer = [this, done](const HttpRequest& r, HttpResponse response, qint64 device) {
    logLine(r, response, device);
    response.headers.removeIf([](const auto& h) { return h.first == kLogHeader; });
    done(response);
  };
  if (!later) return answer(request, response, device);
  HttpRequest head = request;  // what the log needs; the body stays behind
  head.body.clear();
  const storage::DatabaseUrl url = m_db.url();
  QObject* home = m_home.get();
  // Completions (long: an analysis) and chunk writes (short) have pools of their own, so chunks
  // are not queued behind analyses.
  QThreadPool& pool = request.path.endsWith("/complete") ? m_workers : m_writers;
  pool.start([this, later, head, device, url, home, answer] {
    HttpResponse response = guarded([&] { return later(workerDatabase(url, false)); });
    if (response.status == 503) {  // the connection may have died since: once more, afresh
      response = guarded([&] { return later(workerDatabase(url, true)); });
    }
    QMetaObject::invokeMethod(
        home, [answer, head, response, device] { answer(head, response, device); },
        Qt::QueuedConnection);
  });
}

HttpResponse SyncApi::route(const HttpRequest& r, qint64& device, Job* later) {
  const QString& path = r.path;
  if (path == "/api/v1/health") {
    if (r.method != "GET") return error(405, "use GET");
    m_db.exec("SELECT count(*) FROM schema_version");  // throws Io when the database is gone
    return json(200, {{"status", "ok"}, {"version", ARMTRACK_VERSION}, {"api", 1}});
  }
  if (path == "/api/v1/enrol") {
    if (r.method != "POST") return error(405, "use POST");
    if (!m_perAddress.allow("enrol " + r.peer.toString().toLatin1()))
      return error(429, "too many enrolment attempts from this address: wait a minute");
    const QJsonObject body = QJsonDocument::fromJson(r.body).object();
    if (!body.value("code").isString()) return error(400, "send {\"code\": \"...\"}");
    storage::ClinicalStore store(m_db);
    const storage::DeviceEnrolment e =
        store.enrolDevice(body.value("code").toString(), body.value("label").toString());
    device = e.deviceId;
    return json(201, {{"token", e.token}, {"device", e.deviceId}, {"patient", e.patientCode}});
  }
  if (!path.startsWith("/api/v1/")) return error(404, "no such resource");

  // Everything else is a device's: its token first, then its rate.
  const QByteArray auth = r.header("authorization");
  if (!auth.startsWith("Bearer "))
    return error(401, "send the device token: Authorization: Bearer <token>");
  const QByteArray token = auth.mid(7).trimmed();
  if (!m_perToken.allow(token)) {
    HttpResponse slow = error(429, "too many requests: slow down");
    slow.headers.append(qMakePair(QByteArray("Retry-After"), QByteArray("1")));
    return slow;
  }
  const QByteArray address = r.peer.toString().toLatin1();
  if (!m_refusedTokens.hasLeft(address))
    return error(429, "too many refused tokens from this address: wait a minute");
  storage::ClinicalStore store(m_db);
  try {
    store.signInWithDeviceToken(QString::fromLatin1(token));
  } catch (const StorageError& e) {
    if (e.kind() == Kind::Authentication) m_refusedTokens.allow(address);
    throw;
  }
  device = store.deviceId();
  const QString patientCode = [&] {
    QSqlQuery q = m_db.exec("SELECT code FROM patients WHERE id = ?", {*store.user().patientId});
    return q.next() ? q.value(0).toString() : QString();
  }();

  if (path == "/api/v1/programme") {
    if (r.method != "GET") return error(405, "use GET");
    QJsonArray exercises;
    for (const storage::ProgrammeItem& item : store.programme(patientCode))
      exercises.append(exerciseJson(item, store.protocol(item.protocolName)));
    return json(200, {{"patient", patientCode}, {"exercises", exercises}});
  }
  const std::optional<SessionRoute> s = sessionRoute(path);
  if (!s) return error(404, "no such resource");
  storage::SyncUploads uploads(store);
  if (s->tail.isEmpty()) {
    if (r.method == "GET") return json(200, stateJson(s->uuid, uploads.state(s->uuid)));
    if (r.method != "PUT") return error(405, "use PUT or GET");
    QJsonParseError parse;
    const QJsonDocument doc = QJsonDocument::fromJson(r.body, &parse);
    if (!doc.isObject()) return error(400, "the session's metadata must be a JSON object");
    const QJsonObject o = doc.object();
    storage::UploadMeta meta;
    meta.sha256 = o.value("sha256").toString();
    meta.sizeBytes = static_cast<qint64>(o.value("size_bytes").toDouble(-1));
    meta.chunkCount = o.value("chunks").toInt(-1);
    if (o.contains("sidecar") && !o.value("sidecar").isObject())
      return error(400, "sidecar must be a JSON object");
    meta.metaJson = QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact));
    const storage::UploadState st = uploads.declare(s->uuid, meta);
    return json(st.created ? 201 : 200, stateJson(s->uuid, st));
  }
  if (s->tail == "chunks") {
    if (r.method != "PUT") return error(405, "use PUT");
    // Written on a writer thread with its own connection: a durable write of up to 8 MiB would
    // hold the event loop, and with it every other device's TLS handshake and request.
    *later = [uuid = s->uuid, chunk = s->chunk, body = r.body, token,
              sha = QString::fromLatin1(r.header("x-chunk-sha256"))](storage::Database& db) {
      storage::ClinicalStore store(db);
      store.signInWithDeviceToken(QString::fromLatin1(token));
      storage::SyncUploads(store).putChunk(uuid, chunk, body, sha);
      return json(200, {{"uuid", uuid.toLower()}, {"chunk", chunk}});
    };
    return {};
  }
  if (r.method != "POST") return error(405, "use POST");
  // The join, the import and the analysis: on a worker with its own connection, signed in
  // again there with the token checked above.
  const QString uuid = s->uuid;
  *later = [this, uuid, token](storage::Database& db) {
    if (beforeCompletion) beforeCompletion();
    storage::ClinicalStore store(db);
    store.signInWithDeviceToken(QString::fromLatin1(token));
    storage::SyncUploads uploads(store);
    QString analysis = "pending";
    QString failure;
    const qint64 id = uploads.complete(uuid, [&](qint64 sessionId) {
      // Analysed on arrival by the server itself; a failure leaves it pending for the clinic.
      try {
        storage::ClinicalStore service(db);
        service.signInAsService("armtrack-server");
        storage::analyseSession(service, sessionId);
        analysis = "done";
      } catch (const StorageError& e) {
        analysis = e.kind() == Kind::Usage || e.kind() == Kind::Corrupt ? "failed" : "pending";
        failure = "session " + QString::number(sessionId) + " stored, analysis " + analysis;
      }
    });
    if (analysis == "pending") {
      QSqlQuery q = db.exec("SELECT analysis FROM sessions WHERE id = ?", {id});
      if (q.next()) analysis = q.value(0).toString();
    }
    HttpResponse done =
        json(200, {{"uuid", uuid.toLower()}, {"session", id}, {"analysis", analysis}});
    if (!failure.isEmpty()) done.headers.append(qMakePair(kLogHeader, failure.toLatin1()));
    return done;
  };
  return {};
}

}  // namespace armtrack::server
