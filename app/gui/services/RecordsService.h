// The clinical records as the GUI reaches them: every call runs on a thread of its own and
// answers on the caller's thread, so the GUI never waits for the disk or the database.
#pragma once

#include <QObject>
#include <QPointer>
#include <QRegularExpression>
#include <QString>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

#include "core/storage/ClinicalStore.h"
#include "core/storage/DatabaseUrl.h"

namespace armtrack::gui {

/// A message of the core without its references to the project's documentation files
/// ("... (docs/storage.md, \"Files and permissions\")"): the command line's readers have the
/// sources, the application's users do not.
inline QString withoutSourceReferences(QString text) {
  static const QRegularExpression cited(QStringLiteral("\\s*\\((?:see )?docs/[^)]*\\)"));
  static const QRegularExpression bare(QStringLiteral("\\s*\\bdocs/[\\w./-]+\\.md\\b"));
  return text.remove(cited).remove(bare);
}

/// Why a records call failed, in words for the user.
struct RecordsFailure {
  std::optional<storage::StorageError::Kind> kind;  ///< empty: not a storage error
  QString message;                                  ///< what went wrong and what to do
};
using FailedFn = std::function<void(const RecordsFailure&)>;

/// What a database location holds, before anyone signs in.
enum class DatabaseState {
  Missing,     ///< no database there yet: the first-run assistant creates one
  NoAccounts,  ///< a database without accounts (e.g. a new PostgreSQL one): likewise
  Ready,       ///< accounts exist: sign in
};

/// What a long job sees on its thread: the signed-in store (if any), the cancel flag and a
/// progress callback that may be called as often as wanted.
class JobContext {
 public:
  JobContext(storage::ClinicalStore* store, std::shared_ptr<std::atomic<bool>> cancel,
             std::function<void(int)> progress)
      : m_store(store), m_cancel(std::move(cancel)), m_progress(std::move(progress)) {}
  /// The job thread's own connection, signed in as the GUI's user. Throws StorageError when no
  /// one is signed in.
  storage::ClinicalStore& store() const;
  bool cancelled() const { return m_cancel->load(); }
  const std::atomic<bool>* cancelFlag() const { return m_cancel.get(); }
  /// percent 0-100; repeated values are not passed on.
  void progress(int percent);

 private:
  storage::ClinicalStore* m_store;
  std::shared_ptr<std::atomic<bool>> m_cancel;
  std::function<void(int)> m_progress;
  int m_last = -1;
};

/// A long job as the GUI sees it. Deletes itself once its answer has been delivered. Deleting
/// it earlier (or cancel()) asks the job to stop.
class RecordsJob : public QObject {
  Q_OBJECT
 public:
  explicit RecordsJob(QObject* parent = nullptr);
  ~RecordsJob() override;
  /// Asks the job to stop; it answers (usually as cancelled) when it has.
  void cancel() { m_cancel->store(true); }
  bool cancelRequested() const { return m_cancel->load(); }
  std::shared_ptr<std::atomic<bool>> flag() const { return m_cancel; }

 signals:
  void progress(int percent);  ///< 0-100
  void finished();             ///< after done or failed has run

 private:
  std::shared_ptr<std::atomic<bool>> m_cancel = std::make_shared<std::atomic<bool>>(false);
};

/// Owns two connections to the records, each in its own thread: one for short calls (lists,
/// a patient, a sign-in), one for long jobs (analyses, imports, reports, exports) so that a long
/// job never holds up the screens. Qt Sql connections belong to the thread that opened them
/// (core/storage/SessionAnalysis.h). Construct and call from the GUI thread.
class RecordsService : public QObject {
  Q_OBJECT
 public:
  explicit RecordsService(QObject* parent = nullptr);
  ~RecordsService() override;  ///< cancels running jobs, closes the connections, joins

  /// Whether url holds a database with accounts.
  void probe(const storage::DatabaseUrl& url, QObject* receiver,
             std::function<void(DatabaseState)> done, FailedFn failed);
  /// Creates url's database (its folder too) and its first administrator, then signs in.
  void create(const storage::DatabaseUrl& url, const QString& admin, const QString& password,
              QObject* receiver, std::function<void(const storage::User&)> done, FailedFn failed);
  /// Opens url and signs in (the store's throttling applies after wrong passwords).
  void signIn(const storage::DatabaseUrl& url, const QString& name, const QString& password,
              QObject* receiver, std::function<void(const storage::User&)> done, FailedFn failed);
  /// Closes both connections; later calls fail with "not signed in".
  void signOut();
  bool signedIn() const { return m_user.has_value(); }
  /// The signed-in account (signedIn() must be true).
  const storage::User& user() const { return *m_user; }
  const storage::DatabaseUrl& url() const { return m_url; }

  /// Runs job(ClinicalStore&) on the short-call thread and passes its result to done on
  /// receiver's thread; an exception goes to failed. Nothing is called back when receiver is gone.
  template <class Job, class Done>
  void call(QObject* receiver, Job job, Done done, FailedFn failed);

  /// Runs job(ClinicalStore&) on the short-call thread and waits for it: for the few short
  /// statements an interface needs at once (a session's row when recording starts). Rethrows
  /// the job's exception. Never for anything that may take long.
  template <class Job>
  auto callBlocking(Job job) -> std::invoke_result_t<Job&, storage::ClinicalStore&>;

  /// Runs job(JobContext&) on the long-job thread; done gets its result, failed its exception,
  /// both on receiver's thread. The job may call the context's progress() and should stop when
  /// cancelled() reads true. Jobs run one after another.
  template <class Job, class Done>
  RecordsJob* startJob(QObject* receiver, Job job, Done done, FailedFn failed);

 signals:
  /// Something went wrong outside any call (e.g. the job connection could not sign in).
  void problem(const QString& message);

 private:
  class Worker;
  /// One thread's connection; touched only on that thread.
  struct Connection {
    std::unique_ptr<storage::Database> db;
    std::unique_ptr<storage::ClinicalStore> store;  ///< signed in, or null
    void close();
  };
  enum class Lane { Short, Long };
  using Deliver = std::function<void()>;
  /// work runs on the lane's thread and returns what to run on receiver's thread; an exception
  /// it throws goes to failed there instead.
  void post(Lane lane, QObject* receiver, std::function<Deliver(Connection&, JobContext&)> work,
            FailedFn failed, RecordsJob* job);
  /// Runs fn on the short-call thread with its store (null before sign-in) and waits.
  void runBlocking(const std::function<void(storage::ClinicalStore*)>& fn);
  /// Signs the lane's connection in (on its thread).
  static storage::User openAndSignIn(Connection& c, const storage::DatabaseUrl& url,
                                     const QString& name, const QString& password);
  /// The short-call connection has signed in: remember the account, sign the job one in.
  void signedInShort(const storage::DatabaseUrl& url, const QString& name, const QString& password,
                     const storage::User& user);

  std::unique_ptr<Worker> m_short, m_long;
  std::optional<storage::User> m_user;
  storage::DatabaseUrl m_url;
  std::vector<std::weak_ptr<std::atomic<bool>>> m_cancelFlags;  // of running jobs
};

template <class Job, class Done>
void RecordsService::call(QObject* receiver, Job job, Done done, FailedFn failed) {
  post(
      Lane::Short, receiver,
      [job = std::move(job), done = std::move(done)](Connection&,
                                                     JobContext& context) mutable -> Deliver {
        using R = std::invoke_result_t<Job&, storage::ClinicalStore&>;
        if constexpr (std::is_void_v<R>) {
          job(context.store());
          return [done]() mutable { done(); };
        } else {
          return [done, r = job(context.store())]() mutable { done(std::move(r)); };
        }
      },
      std::move(failed), nullptr);
}

template <class Job>
auto RecordsService::callBlocking(Job job) -> std::invoke_result_t<Job&, storage::ClinicalStore&> {
  using R = std::invoke_result_t<Job&, storage::ClinicalStore&>;
  std::exception_ptr error;
  std::optional<std::conditional_t<std::is_void_v<R>, bool, R>> result;
  runBlocking([&](storage::ClinicalStore* store) {
    try {
      if (!store)
        throw storage::StorageError(storage::StorageError::Kind::Authentication, "not signed in");
      if constexpr (std::is_void_v<R>) {
        job(*store);
        result = true;
      } else {
        result = job(*store);
      }
    } catch (...) {
      error = std::current_exception();
    }
  });
  if (error) std::rethrow_exception(error);
  if constexpr (!std::is_void_v<R>) return std::move(*result);
}

template <class Job, class Done>
RecordsJob* RecordsService::startJob(QObject* receiver, Job job, Done done, FailedFn failed) {
  auto* handle = new RecordsJob(receiver);
  post(
      Lane::Long, receiver,
      [job = std::move(job), done = std::move(done)](Connection&,
                                                     JobContext& context) mutable -> Deliver {
        using R = std::invoke_result_t<Job&, JobContext&>;
        if constexpr (std::is_void_v<R>) {
          job(context);
          return [done]() mutable { done(); };
        } else {
          return [done, r = job(context)]() mutable { done(std::move(r)); };
        }
      },
      std::move(failed), handle);
  return handle;
}

}  // namespace armtrack::gui
