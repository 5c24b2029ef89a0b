#include "app/gui/services/RecordsService.h"

#include <QDir>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QSqlQuery>
#include <QThread>

#include "core/io/Recording.h"
#include "core/storage/DatabaseFiles.h"

Q_LOGGING_CATEGORY(lcRecords, "armtrack.gui.records")

namespace armtrack::gui {

namespace {

using storage::StorageError;

/// Carries a call's answer from its worker thread to the receiver's thread. It lives in the
/// worker thread; Qt drops the queued answer when the receiver is deleted first.
class Relay : public QObject {
  Q_OBJECT
 signals:
  void delivered(const std::function<void()>& deliver);
  void progressed(int percent);
};

// The services' messages start in lower case, as the command line prints them after a colon;
// on a screen they stand alone.
QString sentence(const std::string& text) {
  QString s = withoutSourceReferences(QString::fromStdString(text));
  if (!s.isEmpty()) s[0] = s[0].toUpper();
  return s;
}

RecordsFailure failureOf(std::exception_ptr e) {
  try {
    std::rethrow_exception(e);
  } catch (const StorageError& s) {
    return {s.kind(), sentence(s.what())};
  } catch (const RecordingError& r) {
    return {std::nullopt, sentence(r.message())};
  } catch (const std::exception& x) {
    return {std::nullopt, sentence(x.what())};
  } catch (...) {
    return {std::nullopt, RecordsService::tr("an unexpected error")};
  }
}

}  // namespace

storage::ClinicalStore& JobContext::store() const {
  if (!m_store) throw StorageError(StorageError::Kind::Authentication, "not signed in");
  return *m_store;
}

void JobContext::progress(int percent) {
  percent = std::clamp(percent, 0, 100);
  if (percent == m_last || !m_progress) return;
  m_last = percent;
  m_progress(percent);
}

RecordsJob::RecordsJob(QObject* parent) : QObject(parent) {}

RecordsJob::~RecordsJob() {
  m_cancel->store(true);  // nobody waits for the answer any more
}

void RecordsService::Connection::close() {
  store.reset();
  db.reset();
}

/// A thread with an event loop and the connection that belongs to it.
class RecordsService::Worker {
 public:
  explicit Worker(const QString& name) : m_thread(new QThread) {
    m_thread->setObjectName(name);
    m_context = new QObject;
    m_context->moveToThread(m_thread);
    m_thread->start();
  }
  ~Worker() {
    QMetaObject::invokeMethod(
        m_context,
        [this] {
          connection.close();
          m_context->deleteLater();
          QThread::currentThread()->quit();
        },
        Qt::QueuedConnection);
    // Jobs were asked to stop; an analysis checks its flag every few hundred rows.
    if (m_thread->wait(QDeadlineTimer(30000))) {
      delete m_thread;
    } else {
      // Deleting a running QThread aborts the program: leave it to the process's end.
      qCWarning(lcRecords) << "the records thread" << m_thread->objectName()
                           << "did not stop within 30 s";
    }
  }
  void post(std::function<void()> fn) {
    QMetaObject::invokeMethod(m_context, std::move(fn), Qt::QueuedConnection);
  }
  void runBlocking(const std::function<void()>& fn) {
    QMetaObject::invokeMethod(m_context, fn, Qt::BlockingQueuedConnection);
  }
  QThread* thread() const { return m_thread; }

  Connection connection;  // worker thread only

 private:
  QThread* m_thread;
  QObject* m_context;
};

RecordsService::RecordsService(QObject* parent)
    : QObject(parent),
      m_short(std::make_unique<Worker>(QStringLiteral("records"))),
      m_long(std::make_unique<Worker>(QStringLiteral("records-jobs"))) {}

RecordsService::~RecordsService() {
  for (const auto& flag : m_cancelFlags)
    if (auto f = flag.lock()) f->store(true);
  m_long.reset();
  m_short.reset();
}

void RecordsService::post(Lane lane, QObject* receiver,
                          std::function<Deliver(Connection&, JobContext&)> work, FailedFn failed,
                          RecordsJob* job) {
  Q_ASSERT(receiver);
  Worker& worker = lane == Lane::Short ? *m_short : *m_long;
  auto* relay = new Relay;
  connect(relay, &Relay::delivered, receiver,
          [](const std::function<void()>& deliver) { deliver(); });
  std::shared_ptr<std::atomic<bool>> cancel =
      job ? job->flag() : std::make_shared<std::atomic<bool>>(false);
  if (job) {
    connect(relay, &Relay::progressed, job, &RecordsJob::progress);
    connect(relay, &Relay::delivered, job, [job] {
      emit job->finished();
      job->deleteLater();
    });
    m_cancelFlags.erase(std::remove_if(m_cancelFlags.begin(), m_cancelFlags.end(),
                                       [](const auto& w) { return w.expired(); }),
                        m_cancelFlags.end());
    m_cancelFlags.push_back(cancel);
  }
  relay->moveToThread(worker.thread());
  worker.post([&worker, relay, cancel, work = std::move(work), failed = std::move(failed)] {
    JobContext context(worker.connection.store.get(), cancel,
                       [relay](int p) { emit relay->progressed(p); });
    Deliver deliver;
    try {
      deliver = work(worker.connection, context);
    } catch (...) {
      deliver = [failed, f = failureOf(std::current_exception())] {
        if (failed) failed(f);
      };
    }
    if (deliver) emit relay->delivered(deliver);
    relay->deleteLater();
  });
}

storage::User RecordsService::openAndSignIn(Connection& c, const storage::DatabaseUrl& url,
                                            const QString& name, const QString& password) {
  c.close();
  c.db = std::make_unique<storage::Database>(url, storage::Database::Options{});
  auto store = std::make_unique<storage::ClinicalStore>(*c.db);
  const storage::User user = store->signIn(name, password.toStdString());
  c.store = std::move(store);
  return user;
}

void RecordsService::probe(const storage::DatabaseUrl& url, QObject* receiver,
                           std::function<void(DatabaseState)> done, FailedFn failed) {
  post(
      Lane::Short, receiver,
      [url, done = std::move(done)](Connection&, JobContext&) -> Deliver {
        DatabaseState state = DatabaseState::Ready;
        try {
          storage::Database db(url, {});
          QSqlQuery q = db.exec(QStringLiteral("SELECT count(*) FROM users"));
          if (!q.next() || q.value(0).toLongLong() == 0) state = DatabaseState::NoAccounts;
        } catch (const StorageError& e) {
          // A missing SQLite file; a PostgreSQL database that does not exist is the
          // administrator's to create, so it stays an error.
          if (e.kind() != StorageError::Kind::NotFound ||
              url.engine != storage::DatabaseUrl::Engine::Sqlite)
            throw;
          state = DatabaseState::Missing;
        }
        return [done, state] { done(state); };
      },
      std::move(failed), nullptr);
}

void RecordsService::create(const storage::DatabaseUrl& url, const QString& admin,
                            const QString& password, QObject* receiver,
                            std::function<void(const storage::User&)> done, FailedFn failed) {
  post(
      Lane::Short, receiver,
      [this, guard = QPointer<RecordsService>(this), url, admin, password, done = std::move(done)](
          Connection& c, JobContext&) -> Deliver {
        if (url.engine == storage::DatabaseUrl::Engine::Sqlite) {
          const QString folder = QFileInfo(url.path).absolutePath();
          if (!storage::makePrivateFolders(folder).isEmpty())  // 0700 where it makes one
            throw StorageError(StorageError::Kind::Io,
                               tr("cannot create the folder %1: choose a folder you may write to")
                                   .arg(folder)
                                   .toStdString());
        }
        c.close();
        {
          storage::Database db(url, {.create = true, .migrate = false});
          storage::ClinicalStore store(db);
          store.initialise(admin, password.toStdString());
        }
        const storage::User user = openAndSignIn(c, url, admin, password);
        return [this, guard, url, admin, password, user, done] {
          if (guard) signedInShort(url, admin, password, user);
          done(user);
        };
      },
      std::move(failed), nullptr);
}

void RecordsService::signIn(const storage::DatabaseUrl& url, const QString& name,
                            const QString& password, QObject* receiver,
                            std::function<void(const storage::User&)> done, FailedFn failed) {
  post(
      Lane::Short, receiver,
      [this, guard = QPointer<RecordsService>(this), url, name, password, done = std::move(done)](
          Connection& c, JobContext&) -> Deliver {
        const storage::User user = openAndSignIn(c, url, name, password);
        return [this, guard, url, name, password, user, done] {
          if (guard) signedInShort(url, name, password, user);
          done(user);
        };
      },
      std::move(failed), nullptr);
}

void RecordsService::signedInShort(const storage::DatabaseUrl& url, const QString& name,
                                   const QString& password, const storage::User& user) {
  m_user = user;
  m_url = url;
  // The job connection signs in as the same account. Jobs posted after this run after it.
  post(
      Lane::Long, this,
      [url, name, password](Connection& c, JobContext&) -> Deliver {
        openAndSignIn(c, url, name, password);
        return {};
      },
      [this](const RecordsFailure& f) {
        emit problem(tr("The background connection to the records could not sign in (%1). "
                        "Reports, exports and analyses will fail until you sign in again.")
                         .arg(f.message));
      },
      nullptr);
}

void RecordsService::runBlocking(const std::function<void(storage::ClinicalStore*)>& fn) {
  Worker& w = *m_short;
  w.runBlocking([&] { fn(w.connection.store.get()); });
}

void RecordsService::signOut() {
  m_user.reset();
  m_short->post([w = m_short.get()] { w->connection.close(); });
  m_long->post([w = m_long.get()] { w->connection.close(); });
}

}  // namespace armtrack::gui

#include "RecordsService.moc"
