// The demo records: made through the records' own import and analysis, with a range of motion
// per session close to what was simulated (the truth), dates over six weeks, working accounts,
// and a cancel that leaves no half-made file.
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "app/clinical/Outputs.h"
#include "app/gui/services/DemoData.h"
#include "core/storage/SessionAnalysis.h"

using namespace armtrack;

class TestDemoData : public QObject {
  Q_OBJECT
  QTemporaryDir m_dir;

 private slots:
  void buildsAnalysedHistoryCloseToTheTruth() {
    storage::DatabaseUrl url;
    url.path = m_dir.filePath(QStringLiteral("demo.db"));
    std::vector<int> progress;
    QElapsedTimer timer;
    timer.start();
    QVERIFY(gui::buildDemoDatabase(url, [&](int p) { progress.push_back(p); }));
    qInfo("demo database built in %.2f s", timer.elapsed() / 1000.0);
    QVERIFY(!progress.empty());
    QCOMPARE(progress.back(), 100);
    QVERIFY(std::is_sorted(progress.begin(), progress.end()));

    storage::Database db(url, {});
    storage::ClinicalStore store(db);
    const storage::User& u = store.signIn(QString::fromLatin1(gui::DemoAccounts::kTherapist),
                                          gui::DemoAccounts::kPassword);
    QCOMPARE(u.role, storage::Role::Therapist);
    QCOMPARE(store.listPatients().size(), std::size_t{3});
    QVERIFY(store.protocol(QString::fromLatin1(gui::DemoAccounts::kLiveProtocol)).id > 0);

    // Ada's six sessions: weekly, flexion simulated as 70 + 11 * week deg.
    const auto d = clinical::progressReportData(store, QStringLiteral("P001"));
    QCOMPARE(d.sessions.size(), std::size_t{6});
    std::vector<reports::ProgressSession> s = d.sessions;
    std::sort(s.begin(), s.end(), [](auto& a, auto& b) { return a.startedAt < b.startedAt; });
    const QDateTime first = QDateTime::fromString(s.front().startedAt, Qt::ISODateWithMs);
    const QDateTime last = QDateTime::fromString(s.back().startedAt, Qt::ISODateWithMs);
    QVERIFY(first.daysTo(last) >= 34 && first.daysTo(last) <= 36);
    QVERIFY(last < QDateTime::currentDateTimeUtc());
    for (std::size_t week = 0; week < s.size(); ++week) {
      QVERIFY(s[week].romRad[0].has_value());
      const double romDeg = *s[week].romRad[0] * 180 / M_PI;
      const double truth = 70 + 11 * static_cast<double>(week);
      qInfo("week %zu: ROM %.1f deg, simulated %.1f deg", week, romDeg, truth);
      QVERIFY2(std::abs(romDeg - truth) < 2,
               qPrintable(QStringLiteral("week %1: ROM %2 deg, simulated %3 deg")
                              .arg(week)
                              .arg(romDeg)
                              .arg(truth)));
      QVERIFY(s[week].repetitions.has_value() && *s[week].repetitions >= 3);
    }
    // The home account sees Ada alone, and her programme: two exercises in order.
    storage::ClinicalStore home(db);
    QCOMPARE(
        home.signIn(QString::fromLatin1(gui::DemoAccounts::kHome), gui::DemoAccounts::kPassword)
            .role,
        storage::Role::Home);
    QCOMPARE(home.listPatients().size(), std::size_t{1});
    QCOMPARE(home.listPatients()[0].code, QStringLiteral("P001"));
    const auto programme = home.programme(QStringLiteral("P001"));
    QCOMPARE(programme.size(), std::size_t{2});
    QCOMPARE(programme[0].protocolName, QStringLiteral("Elbow flexion"));
    QCOMPARE(programme[1].protocolName, QString::fromLatin1(gui::DemoAccounts::kLiveProtocol));
    for (const storage::ProgrammeItem& item : programme) {
      QCOMPARE(item.sets, 2);
      QCOMPARE(item.repetitions.value_or(0), 5);
      QVERIFY(item.targetMinDeg && item.targetMaxDeg && *item.targetMinDeg < *item.targetMaxDeg);
    }
    // Bruno's are of the left arm.
    const auto bruno = store.listSessions(QStringLiteral("P002"));
    QCOMPARE(bruno.size(), std::size_t{4});
    QCOMPARE(store.recordingMeta(bruno.front().id).side, Side::Left);
  }

  void cancelLeavesNothing() {
    storage::DatabaseUrl url;
    url.path = m_dir.filePath(QStringLiteral("cancelled.db"));
    std::atomic<bool> cancel = false;
    const bool done = gui::buildDemoDatabase(
        url, [&](int p) { cancel = p >= 10; }, &cancel);
    QVERIFY(!done);
    QVERIFY(!QFileInfo::exists(url.path));
  }

  void replacesAnOldDemo() {
    storage::DatabaseUrl url;
    url.path = m_dir.filePath(QStringLiteral("demo.db"));  // made by the first test
    QVERIFY(QFileInfo::exists(url.path));
    QVERIFY(gui::buildDemoDatabase(url, {}));
    storage::Database db(url, {});
    storage::ClinicalStore store(db);
    store.signIn(QString::fromLatin1(gui::DemoAccounts::kTherapist), gui::DemoAccounts::kPassword);
    QCOMPARE(store.listSessions(QStringLiteral("P001")).size(), std::size_t{6});  // not 12
  }
};

QTEST_GUILESS_MAIN(TestDemoData)
#include "test_demo_data.moc"
