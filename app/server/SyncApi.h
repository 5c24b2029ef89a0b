// The sync API of armtrack-server (docs/sync.md): requests from home devices turned into calls
// on the clinical records, with tokens, rate limits and status codes. No network here: it takes
// an HttpRequest and gives an HttpResponse, so it is tested without sockets too.
#pragma once

#include <QElapsedTimer>
#include <QHash>
#include <functional>

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
  };
  /// db: the clinic's records, opened on this thread.
  SyncApi(storage::Database& db, Options options);
  HttpResponse handle(const HttpRequest& request);
  /// Called with one line per request (method, route, status, device id): never a patient's
  /// name or code, never a token.
  std::function<void(const QString&)> log;

 private:
  HttpResponse route(const HttpRequest& request, qint64& device);

  storage::Database& m_db;
  RateLimiter m_perToken;
  RateLimiter m_perAddress;
  RateLimiter m_refusedTokens;
};

}  // namespace armtrack::server
