// The sync API of armtrack-server (docs/sync.md): requests from home devices turned into calls
// on the clinical records, with tokens, rate limits and status codes. No network here: it takes
// an HttpRequest and gives an HttpResponse, so it is tested without sockets too.
#pragma once

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QThreadPool>
#include <functional>
#include <memory>

#include "app/server/HttpsServer.h"
#include "core/storage/Database.h"

namespace armtrack::server {

/// A token bucket per key (a device token, an address): rate requests a second, burst at once.
class RateLimiter {
 public:
  RateLimiter(double rate, double burst) : m_rate(rate), m_burst(burst) { m_clock.start(); }
  /// Takes one request for key; false when its bucket is empty. Keeps at most 10000 keys.
  bool allow(const QByteArray& key);
  /// Whether key's bucket has a request left, without taking it.
  bool hasLeft(const QByteArray& key);

 private:
  struct Bucket {
    double tokens = 0;
    qint64 at = 0;  // ms on m_clock
  };
  double m_rate, m_burst;
  QElapsedTimer m_clock;
  QHash<QByteArray, Bucket> m_buckets;
};

class SyncApi {
 public:
  struct Options {
    double ratePerSecond = 20;  ///< per device token
    double burst = 200;
    double enrolPerMinute = 10;  ///< enrolment attempts per address
    /// Requests with an unknown or revoked token per address (each is audited: without a limit
    /// made-up tokens would flood the audit log).
    double refusedTokensPerMinute = 10;
    /// Completions (join, import, analysis) run at once on workers; 0: one per processor.
    int workers = 0;
    /// Chunks written at once, each writer with its own connection.
    int writers = 4;
  };
  /// db: the clinic's records, opened on this thread. The workers open their own connections
  /// to db.url() (a Qt Sql connection belongs to the thread that opened it).
  SyncApi(storage::Database& db, Options options);
  ~SyncApi();  ///< waits for the completions running
  /// Answers at once, completions too (on this thread, holding it meanwhile).
  HttpResponse handle(const HttpRequest& request);
  /// Answers through done, on this thread: a completion (`POST .../complete`: the join, the
  /// import and the analysis) and a chunk (its durable write) later, from a worker, so other
  /// requests are answered meanwhile; everything else at once. armtrack-server's way.
  void handle(const HttpRequest& request, const HttpsServer::Responder& done);
  /// Called with one line per request (method, route, status, device id): never a patient's
  /// name or code, never a token. Called on this thread only.
  std::function<void(const QString&)> log;
  /// Called on the worker at the start of each completion, before anything is read (tests
  /// hold a completion there).
  std::function<void()> beforeCompletion;

 private:
  /// The part of a request that runs on a worker, with the worker's connection.
  using Job = std::function<HttpResponse(storage::Database&)>;
  /// The answer, or an empty one with *later set to what is left to run on a worker.
  HttpResponse route(const HttpRequest& request, qint64& device, Job* later);
  HttpResponse guarded(const std::function<HttpResponse()>& f);
  void logLine(const HttpRequest& request, const HttpResponse& response, qint64 device);

  storage::Database& m_db;
  std::unique_ptr<QObject> m_home;  ///< on this thread: the workers' answers come back through it
  QThreadPool m_workers;            ///< completions; destroyed before m_home: waits for them
  QThreadPool m_writers;            ///< chunk writes
  RateLimiter m_perToken;
  RateLimiter m_perAddress;
  RateLimiter m_refusedTokens;
};

}  // namespace armtrack::server
