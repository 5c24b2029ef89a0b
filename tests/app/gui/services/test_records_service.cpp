// RecordsService: the records on their own threads, answering on the caller's thread; first
// run, sign-in with the store's throttling, calls after sign-out, long jobs with progress and
// cancel, and answers dropped when the asking screen is gone.
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include "app/gui/services/RecordsService.h"

using namespace armtrack;
using gui::DatabaseState;
using gui::RecordsFailure;
using gui::RecordsService;

class TestRecordsService : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  storage::DatabaseUrl url(const char* name) const {
    storage::DatabaseUrl u;
    u.path = m_dir.filePath(QString::fromUtf8(name));
    return u;
  }
  // Creates a database with boss/boss-pass-1 and signs in.
  bool createAndSignIn(RecordsService& r, const storage::DatabaseUrl& u, QObject* receiver) {
    bool done = false;
    QString error;
    r.create(
        u, QStringLiteral("boss"), QStringLiteral("boss-pass-1"), receiver,
        [&](const storage::User&) { done = true; },
        [&](const RecordsFailure& f) { error = f.message; });
    if (!QTest::qWaitFor([&] { return done || !error.isEmpty(); }, 20000)) return false;
    if (!error.isEmpty()) qWarning() << error;
    return done;
  }

 private slots:
  void initTestCase() { QVERIFY(m_dir.isValid()); }

  void probeCreateSignIn() {
    RecordsService r;
    QObject receiver;
    const auto u = url("a/b/first.db");  // folders that do not exist yet
    std::optional<DatabaseState> state;
    r.probe(u, &receiver, [&](DatabaseState s) { state = s; }, {});
    QTRY_VERIFY(state.has_value());
    QCOMPARE(*state, DatabaseState::Missing);
    QVERIFY(createAndSignIn(r, u, &receiver));
    QVERIFY(r.signedIn());
    QCOMPARE(r.user().name, QStringLiteral("boss"));
    QCOMPARE(r.user().role, storage::Role::Admin);
    state.reset();
    r.probe(u, &receiver, [&](DatabaseState s) { state = s; }, {});
    QTRY_VERIFY(state.has_value());
    QCOMPARE(*state, DatabaseState::Ready);

    // A short call and a long job both reach the records as boss, each on its own thread.
    Qt::HANDLE mainThread = QThread::currentThreadId(), callThread = nullptr, jobThread = nullptr;
    std::optional<qint64> added;
    r.call(
        &receiver,
        [&](storage::ClinicalStore& s) {
          callThread = QThread::currentThreadId();
          storage::Patient p;
          p.code = QStringLiteral("P01");
          p.name = QStringLiteral("Ada Example");
          return s.addPatient(p);
        },
        [&](qint64 id) {
          QCOMPARE(QThread::currentThreadId(), mainThread);
          added = id;
        },
        {});
    QTRY_VERIFY(added.has_value());
    std::optional<int> seen;
    r.startJob(
        &receiver,
        [&](gui::JobContext& c) {
          jobThread = QThread::currentThreadId();
          return static_cast<int>(c.store().listPatients().size());
        },
        [&](int n) { seen = n; }, {});
    QTRY_VERIFY(seen.has_value());
    QCOMPARE(*seen, 1);
    QVERIFY(callThread != mainThread && jobThread != mainThread && callThread != jobThread);

    // Creating again is refused: the records already have accounts.
    QString error;
    r.create(
        u, QStringLiteral("other"), QStringLiteral("other-pass"), &receiver,
        [](const storage::User&) {}, [&](const RecordsFailure& f) { error = f.message; });
    QTRY_VERIFY(!error.isEmpty());
    QVERIFY2(error.contains(QStringLiteral("already has accounts")), qPrintable(error));
  }

  void wrongPasswordsAreThrottled() {
    RecordsService r;
    QObject receiver;
    const auto u = url("throttle.db");
    QVERIFY(createAndSignIn(r, u, &receiver));
    r.signOut();
    QVERIFY(!r.signedIn());
    std::vector<RecordsFailure> failures;
    for (int i = 0; i < 4; ++i) {
      const std::size_t before = failures.size();
      r.signIn(
          u, QStringLiteral("boss"), QStringLiteral("wrong"), &receiver,
          [](const storage::User&) { QFAIL("signed in with a wrong password"); },
          [&](const RecordsFailure& f) { failures.push_back(f); });
      QTRY_COMPARE(failures.size(), before + 1);
    }
    for (const RecordsFailure& f : failures)
      QCOMPARE(f.kind, std::optional(storage::StorageError::Kind::Authentication));
    QVERIFY2(failures[0].message.contains(QStringLiteral("Wrong user name or password")),
             qPrintable(failures[0].message));
    // The fourth came too soon after the third: refused without looking at the password.
    QVERIFY2(failures[3].message.contains(QStringLiteral("try again in")),
             qPrintable(failures[3].message));
    QVERIFY(!r.signedIn());
    // After the wait the right password works again.
    bool in = false;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
          if (in) return true;
          bool answered = false;
          r.signIn(
              u, QStringLiteral("boss"), QStringLiteral("boss-pass-1"), &receiver,
              [&](const storage::User&) { in = answered = true; },
              [&](const RecordsFailure&) { answered = true; });
          // Unanswered within the wait: try again while the outer timeout lasts.
          if (!QTest::qWaitFor([&] { return answered; }, 10000)) return false;
          return in;
        }(),
        10000);
    QVERIFY(r.signedIn());
  }

  void callsAfterSignOutFailInWords() {
    RecordsService r;
    QObject receiver;
    QVERIFY(createAndSignIn(r, url("signout.db"), &receiver));
    r.signOut();
    QString error;
    r.call(
        &receiver, [](storage::ClinicalStore& s) { return s.listPatients().size(); },
        [](std::size_t) { QFAIL("answered after sign-out"); },
        [&](const RecordsFailure& f) { error = f.message; });
    QTRY_VERIFY(!error.isEmpty());
    QCOMPARE(error, QStringLiteral("Not signed in"));
  }

  void jobsReportProgressAndStopWhenCancelled() {
    RecordsService r;
    QObject receiver;
    QVERIFY(createAndSignIn(r, url("jobs.db"), &receiver));
    std::atomic<bool> started = false;
    std::optional<bool> result;
    gui::RecordsJob* job = r.startJob(
        &receiver,
        [&](gui::JobContext& c) {
          started = true;
          for (int i = 0; i <= 100; ++i) {
            c.progress(i);
            if (c.cancelled()) return false;
            QThread::msleep(20);  // a slow job, not a wait in the test
          }
          return true;
        },
        [&](bool finished) { result = finished; }, {});
    QSignalSpy progress(job, &gui::RecordsJob::progress);
    QSignalSpy finished(job, &gui::RecordsJob::finished);
    QTRY_VERIFY(progress.count() >= 3);
    job->cancel();
    QTRY_VERIFY(result.has_value());
    QCOMPARE(*result, false);  // it stopped early
    QTRY_COMPARE(finished.count(), 1);
    // Percentages rise and stay within 0-100.
    int last = -1;
    for (const auto& args : progress) {
      const int p = args.at(0).toInt();
      QVERIFY(p > last && p <= 100);
      last = p;
    }
  }

  void answersForAGoneReceiverAreDropped() {
    RecordsService r;
    QObject keeper;
    QVERIFY(createAndSignIn(r, url("gone.db"), &keeper));
    bool called = false;
    std::atomic<bool> ran = false;
    auto* receiver = new QObject;
    r.call(
        receiver,
        [&](storage::ClinicalStore& s) {
          QThread::msleep(100);
          ran = true;
          return s.listPatients().size();
        },
        [&](std::size_t) { called = true; }, [&](const RecordsFailure&) { called = true; });
    delete receiver;  // the screen went away before the answer
    QTRY_VERIFY(ran.load());
    // A later call on the same thread answers, so the earlier answer had its chance.
    bool later = false;
    r.call(
        &keeper, [](storage::ClinicalStore&) { return 1; }, [&](int) { later = true; }, {});
    QTRY_VERIFY(later);
    QVERIFY(!called);
  }

  void brokenDatabaseIsReportedNotCrashed() {
    RecordsService r;
    QObject receiver;
    const auto u = url("garbage.db");
    QFile f(u.path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(4096, 'x'));
    f.close();
    std::optional<RecordsFailure> failure;
    r.probe(
        u, &receiver, [](DatabaseState) { QFAIL("a garbage file opened"); },
        [&](const RecordsFailure& e) { failure = e; });
    QTRY_VERIFY(failure.has_value());
    QCOMPARE(failure->kind, std::optional(storage::StorageError::Kind::Corrupt));
    QVERIFY2(failure->message.contains(u.path), qPrintable(failure->message));
  }
};

QTEST_GUILESS_MAIN(TestRecordsService)
#include "test_records_service.moc"
