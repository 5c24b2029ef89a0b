// Review of a stored session through the real window, on the demo records: the replayed arm
// shows the stored estimate at the cursor, playback advances, repetitions are listed, another
// session is overlaid, a re-estimation with another filter and method makes a new version (a
// calibration of the wrong file is refused in words), notes typed and left unsaved come back,
// and the report and every export are written; a session without an analysis says why.
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QLineSeries>
#include <QPlainTextEdit>
#include <QProcess>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QSignalSpy>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTableView>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/common/Forms.h"
#include "app/gui/live/LiveSessionScreen.h"
#include "app/gui/review/ReviewScreen.h"
#include "app/gui/review/TrunkPanel.h"
#include "app/gui/services/DemoData.h"
#include "app/gui/signin/SignInScreen.h"
#include "core/io/Recording.h"
#include "core/storage/SessionAnalysis.h"
#include "tests/app/gui/support/GuiTestSupport.h"
#include "tests/support/LeaningPatient.h"
#include "ui/AnglePlotPanel.h"
#include "ui/ArmView.h"

using namespace armtrack::gui;
using armtrack::clinical::ExportFormat;

class TestReview : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  std::unique_ptr<AppController> m_app;
  std::vector<qint64> m_sessions;  // Ada's, oldest first

  ReviewScreen* review() const {
    return qobject_cast<ReviewScreen*>(m_app->window()->currentScreen());
  }
  ReviewScreen* open(qint64 id) {
    m_app->showReview(id);
    ReviewScreen* r = review();
    if (!r) return nullptr;
    QSignalSpy loaded(r, &ReviewScreen::loaded);
    if (!loaded.wait(20000)) return nullptr;
    return r;
  }

 private slots:
  void initTestCase() {
    m_app = test::demoApp(m_dir);
    QVERIFY(m_app);
    bool read = false;
    m_app->records().call(
        m_app->window(),
        [](armtrack::storage::ClinicalStore& s) { return s.listSessions(QStringLiteral("P001")); },
        [&](std::vector<armtrack::storage::SessionInfo> list) {
          std::sort(list.begin(), list.end(),
                    [](auto& a, auto& b) { return a.startedAt < b.startedAt; });
          for (const auto& s : list) m_sessions.push_back(s.id);
          read = true;
        },
        {});
    QTRY_VERIFY(read);
    QCOMPARE(m_sessions.size(), std::size_t{6});
  }

  void replaysTheStoredEstimates() {
    ReviewScreen* r = open(m_sessions.back());
    QVERIFY(r);
    const auto& a = r->data().analysis;
    QVERIFY(a && a->t.size() > 1000);
    // It opens on the first estimate after the filter's start-up second (issue 25, item 4), not
    // on the unconverged first one: the cursor there and the arm in that estimate's pose.
    std::size_t settled = 0;
    while (a->t[settled] < a->t.front() + 1.0) ++settled;
    const double origin = r->timeOrigin();
    QVERIFY(origin <= a->t.front());
    QCOMPARE(r->cursor(), a->t[settled] - origin);
    QVERIFY((r->armView()->pose() - a->joints[settled]).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY((r->armView()->pose() - a->joints[0]).cwiseAbs().maxCoeff() > 1e-9);
    // One time base: the slider and the plots both span recording time, from the first
    // recorded row (not the session clock for one and time since the first estimate for the
    // other).
    QVERIFY(std::abs(r->timeRange().first - (a->t.front() - origin)) < 1e-9);
    QVERIFY(std::abs(r->timeRange().second - (a->t.back() - origin)) < 1e-9);
    QVERIFY(std::abs(r->plots()->trace().samples().front().t - r->timeRange().first) < 1e-6);
    QVERIFY(std::abs(r->plots()->trace().samples().back().t - r->timeRange().second) < 1e-6);
    // The arm at a cursor shows the stored estimate of that instant.
    const std::size_t i = a->t.size() / 2;
    r->setCursor(a->t[i] - origin);
    QVERIFY((r->armView()->pose() - a->joints[i]).cwiseAbs().maxCoeff() < 1e-12);
    QCOMPARE(r->plots()->trace().samples().size(), a->t.size());
    // Playback moves on by itself, then stops where asked.
    r->setCursor(0);
    r->play();
    QTRY_VERIFY_WITH_TIMEOUT(r->cursor() > 1.0, 10000);
    r->pause();
    const double at = r->cursor();
    QTest::qWait(200);  // paused: the cursor stays
    QCOMPARE(r->cursor(), at);
    // The repetitions of the metrics are listed (4 swings of 5 s in 20 s).
    QVERIFY(r->repetitionTable()->model()->rowCount() >= 3);
    test::saveScreenshot(m_app->window(), QStringLiteral("demo-review"));
  }

  void overlaysAnotherSession() {
    ReviewScreen* r = review();
    QSignalSpy shown(r, &ReviewScreen::overlayShown);
    r->compareWith(m_sessions.front());
    QVERIFY(shown.wait(10000));
    QCOMPARE(shown.at(0).at(0).toLongLong(), m_sessions.front());
    r->compareWith(0);
    QCOMPARE(shown.count(), 2);
  }

  void reestimatesWithAnotherFilterAndMethod() {
    ReviewScreen* r = review();
    QCOMPARE(r->data().versions, 1);
    QSignalSpy done(r, &ReviewScreen::reestimated);
    ReestimateChoice c;
    c.filter = armtrack::FilterKind::Ukf;
    c.model = armtrack::MeasurementModel::InclinometerGyro;
    c.optical = false;
    r->reestimate(c);
    QVERIFY(done.wait(60000));
    QCOMPARE(done.at(0).at(0).toInt(), 2);
    QCOMPARE(r->data().versions, 2);
    const QJsonObject p = QJsonDocument::fromJson(r->data().analysis->paramsJson.toUtf8()).object();
    QCOMPARE(p["filter"].toString(), QStringLiteral("ukf"));
    QCOMPARE(p["method"].toString(), QStringLiteral("C"));
    QCOMPARE(p["optical"].toBool(), false);
    // A calibration file that is not one: refused in words, nothing stored.
    const QString bogus = m_dir.filePath(QStringLiteral("not-a-calibration.json"));
    QFile f(bogus);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{\"side\": \"right\", \"geometry\": 12}");
    f.close();
    c.calibrationFile = bogus;
    r->reestimate(c);
    QVERIFY(done.wait(60000));
    QCOMPARE(done.at(1).at(0).toInt(), 0);
    QVERIFY2(done.at(1).at(1).toString().contains(QStringLiteral("not-a-calibration.json")),
             qPrintable(done.at(1).at(1).toString()));
    QCOMPARE(r->data().versions, 2);
  }

  void unsavedNotesComeBack() {
    ReviewScreen* r = review();
    QTest::keyClicks(r->notesEditor(), QStringLiteral("Shoulder pain at 110 deg."));
    // Leave without saving (another screen replaces this one), then come back.
    const qint64 id = r->sessionId();
    m_app->showPatient(QStringLiteral("P001"));
    QTRY_VERIFY(!review());
    r = open(id);
    QVERIFY(r);
    QCOMPARE(r->notesEditor()->toPlainText(), QStringLiteral("Shoulder pain at 110 deg."));
    QSignalSpy saved(r, &ReviewScreen::notesSaved);
    r->saveNotes();
    QVERIFY(saved.wait(10000));
    QCOMPARE(saved.at(0).at(0).toString(), QString());
    // Stored, and no draft left over.
    r = open(id);
    QCOMPARE(r->data().info.notes, QStringLiteral("Shoulder pain at 110 deg."));
    QCOMPARE(r->notesEditor()->toPlainText(), QStringLiteral("Shoulder pain at 110 deg."));
  }

  // The review and the PDF report of the same session agree on times (issue 25, item 3): the
  // first repetition starts at the same time in the table and in the report, and an event
  // marked 5.0 s into the recording is drawn and printed at 5.0 s.
  void theReviewAndTheReportShareOneTimeBase() {
    ReviewScreen* r = review();
    const qint64 id = r->sessionId();
    // The live screen's older notes line, on the session clock.
    const double markedAt = r->timeOrigin() + 5.0;
    bool stored = false;
    m_app->records().call(
        m_app->window(),
        [id, markedAt](armtrack::storage::ClinicalStore& s) {
          s.updateSessionNotes(id, QStringLiteral("Events: %1 s: Pain").arg(markedAt, 0, 'f', 1));
        },
        [&] { stored = true; }, {});
    QTRY_VERIFY(stored);
    r = open(id);
    QVERIFY(r);
    QCOMPARE(r->events().size(), std::size_t{1});
    QVERIFY(std::abs(r->events()[0].recordingS - 5.0) < 0.051);
    QCOMPARE(r->events()[0].label, std::string("Pain"));
    const QModelIndex first = r->repetitionTable()->model()->index(0, 0);
    QVERIFY(first.isValid());
    const double reviewStart = first.data(RepetitionTableModel::StartRole).toDouble();

    QSignalSpy written(r, &ReviewScreen::outputWritten);
    const QString pdf = m_dir.filePath(QStringLiteral("times.pdf"));
    r->writeReport(pdf);
    QVERIFY(written.wait(60000));
    const QString text = test::pdfText(pdf);
    // The repetitions' table: "1  <start>  <end>  ...".
    const QRegularExpressionMatch row =
        QRegularExpression(QStringLiteral("\\n\\s*1\\s+(\\d+\\.\\d\\d)\\s+(\\d+\\.\\d\\d)\\s"))
            .match(text);
    QVERIFY2(row.hasMatch(), qPrintable(text.left(3000)));
    QVERIFY2(
        std::abs(row.captured(1).toDouble() - reviewStart) <= 0.0051,
        qPrintable(QStringLiteral("report %1, review %2").arg(row.captured(1)).arg(reviewStart)));
    QVERIFY2(text.simplified().contains(QStringLiteral("0:05.0 Pain")), qPrintable(text));
  }

  void writesTheReportAndEveryExport() {
    ReviewScreen* r = review();
    QSignalSpy written(r, &ReviewScreen::outputWritten);
    const QString pdf = m_dir.filePath(QStringLiteral("session.pdf"));
    r->writeReport(pdf);
    QVERIFY(written.wait(60000));
    QCOMPARE(written.at(0).at(1).toString(), QString());
    QVERIFY(test::pdfText(pdf).contains(QStringLiteral("Ada Example")));

    const QString csv = m_dir.filePath(QStringLiteral("angles.csv"));
    const QString mot = m_dir.filePath(QStringLiteral("angles.mot"));
    const QString bids = m_dir.filePath(QStringLiteral("bids"));
    const QString rec = m_dir.filePath(QStringLiteral("rec.csv"));
    r->exportTo(ExportFormat::Csv, csv);
    QVERIFY(written.wait(60000));
    r->exportTo(ExportFormat::Mot, mot);
    QVERIFY(written.wait(60000));
    r->exportTo(ExportFormat::Bids, bids);
    QVERIFY(written.wait(60000));
    r->exportTo(ExportFormat::Recording, rec);
    QVERIFY(written.wait(60000));
    for (int i = 1; i < written.count(); ++i)
      QVERIFY2(written.at(i).at(1).toString().isEmpty(),
               qPrintable(written.at(i).at(1).toString()));
    QVERIFY(QFileInfo(csv).size() > 1000);
    QVERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("angles_metrics.csv"))));
    QVERIFY(QFileInfo(mot).size() > 1000);
    QVERIFY(QFileInfo::exists(bids + QStringLiteral("/dataset_description.json")));
    QVERIFY(QFileInfo(rec).size() > 1000);
    // A place that cannot be written: said in words, the screen stays usable.
    r->exportTo(ExportFormat::Csv, QStringLiteral("/proc/armtrack-no-such/angles.csv"));
    QVERIFY(written.wait(60000));
    QVERIFY2(written.last().at(1).toString().contains(QStringLiteral("could not be written")),
             qPrintable(written.last().at(1).toString()));
  }

  // Issue 25, item 2: a session waiting for its analysis (a home session before a therapist
  // signed in) said "no analysis yet (it may have been cut short or failed)". The review now
  // says why from the session's analysis state: pending, failed (with the stored reason), or cut
  // short. The states are set in the file, as another program would leave them.
  // A session whose patient leaned with each reach (sternum IMU, Kinect with the shoulder),
  // analysed with a 10-degree trunk limit: the Trunk block shows the session's four values and
  // the repetition table each repetition's, with the compensated ones marked; an arm-only
  // session says "not measured" and hides the trunk's columns (issue 26).
  void showsTheTrunk() {
    const armtrack::Recording rec = armtrack::test::leaningReaches(20, 831);
    const double trueLean = armtrack::test::trueLeanDeg(rec);
    const std::string csv = m_dir.filePath(QStringLiteral("lean.csv")).toStdString();
    armtrack::writeRecording(csv, rec);
    qint64 id = 0;
    QString failure;
    m_app->records().call(
        m_app->window(),
        [csv](armtrack::storage::ClinicalStore& s) {
          const qint64 id = s.importRecording(csv, QStringLiteral("P001"), QString());
          armtrack::storage::AnalysisOptions o;
          o.trunkFlexionLimitDeg = 10.0;
          armtrack::storage::analyseSession(s, id, o);
          return id;
        },
        [&](qint64 done) { id = done; }, [&](const RecordsFailure& e) { failure = e.message; });
    QTRY_VERIFY_WITH_TIMEOUT(id != 0 || !failure.isEmpty(), 60000);
    QVERIFY2(failure.isEmpty(), qPrintable(failure));

    ReviewScreen* r = open(id);
    QVERIFY(r);
    const TrunkPanel* trunk = r->trunkPanel();
    // Largest trunk flexion: the true lean's to a degree and a half, in the locale's numbers.
    const QString flexion = trunk->valueText(0);
    QVERIFY2(flexion.endsWith(QChar(0x00b0)), qPrintable(flexion));
    bool ok = false;
    const double shown = QLocale().toDouble(flexion.chopped(1), &ok);
    QVERIFY2(ok, qPrintable(flexion));
    QVERIFY2(std::abs(shown - trueLean) < 1.5, qPrintable(flexion));
    for (int i = 1; i < 4; ++i) QVERIFY(!trunk->valueText(i).contains(QStringLiteral("not")));
    QVERIFY2(trunk->valueText(3).endsWith(QStringLiteral(" cm")), qPrintable(trunk->valueText(3)));
    // 10-degree limit, every repetition leaning about 18 deg: all of them.
    QCOMPARE(trunk->compensationText(), QStringLiteral("%1 of %1 (flexion over 10.0\u00b0)")
                                            .arg(r->repetitionTable()->model()->rowCount()));
    QTableView* table = r->repetitionTable();
    const QAbstractItemModel* m = table->model();
    QVERIFY(m->rowCount() >= 3);
    for (int c = RepetitionTableModel::TrunkFlexion; c < RepetitionTableModel::ColumnCount; ++c)
      QVERIFY(!table->isColumnHidden(c));
    for (int row = 0; row < m->rowCount(); ++row) {
      const double rep =
          QLocale().toDouble(m->index(row, RepetitionTableModel::TrunkFlexion).data().toString());
      QVERIFY2(std::abs(rep - trueLean) < 1.5, qPrintable(QString::number(rep)));
      QCOMPARE(m->index(row, RepetitionTableModel::Compensation).data().toString(),
               QStringLiteral("yes"));
    }
    // The trunk's curves, from the estimates stored with the session: every row of the analysis,
    // the largest flexion the true lean's to a degree and a half.
    const armtrack::ui::AnglePlotPanel* plots = r->plots();
    QVERIFY(!plots->trunkChart()->isHidden());
    const std::deque<armtrack::ui::AngleSample>& curve = plots->trunkTrace().samples();
    QCOMPARE(curve.size(), plots->trace().samples().size());
    double largest = 0;
    for (const armtrack::ui::AngleSample& a : curve) largest = std::max(largest, a.deg[0]);
    QVERIFY2(std::abs(largest - trueLean) < 1.5, qPrintable(QString::number(largest)));
    QVERIFY(plots->trunkChart()->series(0)->count() > 10);
    // At the deepest lean the 3D figure leans with the stored estimate; the trunk plot in view.
    const auto deepest =
        std::max_element(curve.begin(), curve.end(),
                         [](const auto& a, const auto& b) { return a.deg[0] < b.deg[0]; });
    r->setCursor(deepest->t);
    QVERIFY(r->armView()->trunk().has_value());
    QVERIFY2(std::abs((*r->armView()->trunk())(0) * 180 / M_PI - deepest->deg[0]) < 1e-6,
             qPrintable(QString::number((*r->armView()->trunk())(0) * 180 / M_PI)));
    for (QWidget* w = plots->trunkChart(); w; w = w->parentWidget())
      if (auto* scroll = qobject_cast<QScrollArea*>(w)) {
        scroll->ensureWidgetVisible(plots->trunkChart());
        break;
      }
    test::saveScreenshot(m_app->window(), QStringLiteral("review-trunk-plot"));
    test::saveScreenshot(m_app->window(), QStringLiteral("review-trunk"));

    r = open(m_sessions.back());
    QVERIFY(r);
    QVERIFY(r->plots()->trunkChart()->isHidden());
    QVERIFY(r->plots()->trunkTrace().empty());
    for (int i = 0; i < 4; ++i)
      QCOMPARE(r->trunkPanel()->valueText(i), QStringLiteral("not measured"));
    QCOMPARE(r->trunkPanel()->compensationText(), QString());
    for (int c = RepetitionTableModel::TrunkFlexion; c < RepetitionTableModel::ColumnCount; ++c)
      QVERIFY(r->repetitionTable()->isColumnHidden(c));
  }

  void saysWhyASessionHasNoAnalysis() {
    const qint64 id = m_sessions.front();
    {
      QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), "edit");
      db.setDatabaseName(m_dir.filePath(QStringLiteral("demo.db")));
      db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=10000"));
      QVERIFY(db.open());
      QSqlQuery q(db);
      QVERIFY(q.exec(QStringLiteral("PRAGMA foreign_keys = ON")));
      for (const char* sql : {"DELETE FROM metrics WHERE session_id = %1",
                              "DELETE FROM estimates WHERE session_id = %1",
                              "UPDATE sessions SET analysis = 'pending' WHERE id = %1"})
        QVERIFY2(q.exec(QString::fromLatin1(sql).arg(id)), qPrintable(q.lastError().text()));
      db.close();
    }
    QSqlDatabase::removeDatabase(QStringLiteral("edit"));
    const auto said = [&](const QString& what) {
      for (const MessageLine* m : review()->findChildren<MessageLine*>())
        if (m->isVisible() && m->text().contains(what)) return true;
      return false;
    };
    const auto setState = [&](const QString& state, const QString& note) {
      QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), "edit");
      db.setDatabaseName(m_dir.filePath(QStringLiteral("demo.db")));
      db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=10000"));
      bool ok = db.open();
      QSqlQuery q(db);
      q.prepare(QStringLiteral("UPDATE sessions SET analysis = ?, analysis_note = ? WHERE id = ?"));
      q.addBindValue(state);
      q.addBindValue(note);
      q.addBindValue(id);
      ok = ok && q.exec();
      if (!ok) qWarning("%s", qPrintable(q.lastError().text()));
      q.finish();
      db.close();
      return ok;
    };
    QVERIFY(open(id));
    QVERIFY(said(QStringLiteral("waiting for its analysis")));
    QVERIFY(!said(QStringLiteral("cut short")));
    QVERIFY(setState(QStringLiteral("failed"), QStringLiteral("the recording holds no arm rows")));
    QSqlDatabase::removeDatabase(QStringLiteral("edit"));
    QVERIFY(open(id));
    QVERIFY(said(QStringLiteral("could not be analysed: the recording holds no arm rows")));
    QVERIFY(setState(QStringLiteral("none"), QStringLiteral("")));
    QSqlDatabase::removeDatabase(QStringLiteral("edit"));
    QVERIFY(open(id));
    QVERIFY(said(QStringLiteral("was cut short, so it was not analysed")));
  }

  void cleanupTestCase() { m_app.reset(); }
};

ARMTRACK_APP_TEST_MAIN(TestReview)
#include "test_review.moc"
