// The patients through the real window, on the demo records: search, add with validation
// messages (nothing typed lost), a duplicate code refused in words, the patient page with its
// sessions and a progress chart whose values match what was simulated, the normal range shaded,
// a progress report PDF naming the patient, and editing.
#include <QAreaSeries>
#include <QChart>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineSeries>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTableView>
#include <QWizard>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/common/Forms.h"
#include "app/gui/newsession/NewSessionScreen.h"
#include "app/gui/patients/PatientDialog.h"
#include "app/gui/patients/PatientListScreen.h"
#include "app/gui/patients/PatientScreen.h"
#include "app/gui/patients/ProgressChart.h"
#include "app/gui/services/DemoData.h"
#include "app/gui/signin/SignInScreen.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack::gui;
using armtrack::gui::test::findControl;
using armtrack::gui::test::typeInto;

class TestPatients : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  std::unique_ptr<AppController> m_app;

  static void activate(QWidget* w) { QVERIFY(test::activate(w)); }
  QWidget* screen() const { return m_app->window()->currentScreen(); }
  template <class T>
  T* current() const {
    return qobject_cast<T*>(screen());
  }
  QTableView* patientTable() const {
    return findControl<QTableView>(screen(), QStringLiteral("Patient list"));
  }
  PatientDialog* openNewPatientDialog() {
    activate(m_app->window());
    QTest::keySequence(screen(), QKeySequence::New);
    PatientDialog* d = nullptr;
    if (!QTest::qWaitFor([&] { return (d = screen()->findChild<PatientDialog*>()) != nullptr; }))
      return nullptr;
    activate(d);  // Xvfb has no window manager to do it
    return d;
  }

 private slots:
  void initTestCase() {
    m_app = test::demoApp(m_dir);
    QVERIFY(m_app);
    QTRY_VERIFY(current<PatientListScreen>());
    QTRY_COMPARE(patientTable()->model()->rowCount(), 3);
  }

  void searchFilters() {
    auto* search = findControl<QLineEdit>(screen(), QStringLiteral("Search patients"));
    QVERIFY(search);
    typeInto(search, QStringLiteral("ejemplo"));
    QCOMPARE(patientTable()->model()->rowCount(), 1);
    QCOMPARE(current<PatientListScreen>()->selectedCode(), QStringLiteral("P003"));
    typeInto(search, QStringLiteral("stroke"));  // the diagnosis column
    QCOMPARE(patientTable()->model()->rowCount(), 1);
    QCOMPARE(current<PatientListScreen>()->selectedCode(), QStringLiteral("P001"));
    typeInto(search, QStringLiteral("nobody-is-called-this"));
    QCOMPARE(patientTable()->model()->rowCount(), 0);
    typeInto(search, QString());
    QCOMPARE(patientTable()->model()->rowCount(), 3);
  }

  void addAPatientWithValidation() {
    PatientDialog* d = openNewPatientDialog();
    QVERIFY(d);
    auto* code = findControl<QLineEdit>(d, QStringLiteral("Patient code"));
    auto* name = findControl<QLineEdit>(d, QStringLiteral("Patient name"));
    auto* forearm = findControl<QDoubleSpinBox>(d, QStringLiteral("Forearm length"));
    auto* upper = findControl<QDoubleSpinBox>(d, QStringLiteral("Upper arm length"));
    auto* side = findControl<QComboBox>(d, QStringLiteral("Affected side"));
    auto* save = findControl<QPushButton>(d, QStringLiteral("Save"));
    QVERIFY(code && name && forearm && upper && side && save);

    typeInto(code, QStringLiteral("bad code!"));
    typeInto(name, QStringLiteral("Dora Test"));
    QTest::mouseClick(save, Qt::LeftButton);
    QVERIFY2(armtrack::gui::test::visibleMessage(d).contains(QStringLiteral("letters, digits")),
             qPrintable(armtrack::gui::test::visibleMessage(d)));
    QCOMPARE(d->focusWidget(), code);  // the field to mend has the dialog's focus
    QCOMPARE(name->text(), QStringLiteral("Dora Test"));
    typeInto(code, QStringLiteral("P010"));
    upper->setValue(30);
    forearm->setValue(3);  // a typing slip: 3 cm
    QTest::mouseClick(save, Qt::LeftButton);
    QVERIFY2(armtrack::gui::test::visibleMessage(d).contains(QStringLiteral("forearm length")),
             qPrintable(armtrack::gui::test::visibleMessage(d)));
    QCOMPARE(d->focusWidget(), forearm);
    forearm->setValue(25);
    side->setCurrentIndex(side->findData(QStringLiteral("left")));
    QTest::mouseClick(save, Qt::LeftButton);
    QTRY_VERIFY(!screen()->findChild<PatientDialog*>());
    QTRY_COMPARE(patientTable()->model()->rowCount(), 4);
    QCOMPARE(current<PatientListScreen>()->selectedCode(), QStringLiteral("P010"));
  }

  void aDuplicateCodeIsRefusedAndNothingIsLost() {
    PatientDialog* d = openNewPatientDialog();
    QVERIFY(d);
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Patient code")), QStringLiteral("P001"));
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Patient name")), QStringLiteral("Twin"));
    auto* notes = findControl<QPlainTextEdit>(d, QStringLiteral("Notes"));
    notes->setPlainText(QStringLiteral("long notes typed with care"));
    QTest::mouseClick(findControl<QPushButton>(d, QStringLiteral("Save")), Qt::LeftButton);
    QTRY_VERIFY(!armtrack::gui::test::visibleMessage(d).startsWith(QStringLiteral("Saving")));
    QVERIFY2(armtrack::gui::test::visibleMessage(d).contains(QStringLiteral("P001")),
             qPrintable(armtrack::gui::test::visibleMessage(d)));
    QVERIFY(d->isVisible());
    QCOMPARE(notes->toPlainText(), QStringLiteral("long notes typed with care"));
    QVERIFY(findControl<QPushButton>(d, QStringLiteral("Save"))->isEnabled());
    d->reject();
    QTRY_VERIFY(!screen()->findChild<PatientDialog*>());
    QCOMPARE(patientTable()->model()->rowCount(), 4);
  }

  void thePatientPageShowsSessionsAndProgress() {
    auto* list = current<PatientListScreen>();
    typeInto(findControl<QLineEdit>(screen(), QStringLiteral("Search patients")),
             QStringLiteral("Ada"));
    QTest::keyClick(findControl<QLineEdit>(screen(), QStringLiteral("Search patients")),
                    Qt::Key_Return);
    QTRY_VERIFY(current<PatientScreen>());
    Q_UNUSED(list);
    auto* page = current<PatientScreen>();
    QSignalSpy loaded(page, &PatientScreen::loaded);
    QTRY_COMPARE(page->overview().patient.code, QStringLiteral("P001"));
    auto* sessions = findControl<QTableView>(screen(), QStringLiteral("Sessions"));
    QCOMPARE(sessions->model()->rowCount(), 6);
    QVERIFY(page->selectedSession() != 0);

    ProgressChart* chart = page->progressChart();
    QCOMPARE(chart->angle(), 0);  // the protocol's angle: shoulder flexion
    QCOMPARE(chart->points(), 6);
    // The values drawn are what was simulated: flexion from 0 to 70 + 11 * week deg (0.2 deg
    // measured error).
    const QStandardItemModel* table = chart->table();
    QCOMPARE(table->rowCount(), 6);
    for (int week = 0; week < 6; ++week) {
      const double rom = table->item(week, 1)->text().toDouble();
      QVERIFY2(std::abs(rom - (70 + 11 * week)) < 2, qPrintable(table->item(week, 1)->text()));
    }
    // Each angle's largest value against the normal range of the same motion from the neutral
    // position (AAOS via Norkin & White, Table A.1): flexion 0-180 deg, not the 240 deg arc of
    // flexion and extension; and the table's "of normal" against the same (test_progress_chart
    // checks the sides of neutral).
    const double namedNormalDeg[] = {180, 180, 70, 150, 80};
    for (int a = 0; a < 5; ++a) {
      chart->setAngle(a);
      QAreaSeries* area = nullptr;
      for (QAbstractSeries* s : chart->chart()->series())
        if (auto* found = qobject_cast<QAreaSeries*>(s)) area = found;
      QVERIFY(area);
      QCOMPARE(area->upperSeries()->at(0).y(), namedNormalDeg[a]);
      QCOMPARE(area->lowerSeries()->at(0).y(), 0.0);
      for (int row = 0; row < chart->table()->rowCount(); ++row) {
        const double largest = chart->table()->item(row, 1)->text().toDouble();
        const double percent = chart->table()->item(row, 2)->text().remove(u'%').toDouble();
        QVERIFY2(std::abs(percent - std::max(0.0, 100 * largest / namedNormalDeg[a])) <= 1.0,
                 qPrintable(chart->table()->item(row, 2)->text()));
      }
    }
    // Another angle redraws with its own values.
    chart->setAngle(3);
    QCOMPARE(chart->points(), 6);
    // The elbow swings from 20 deg to 20 + 50 + 6 * week deg.
    QVERIFY(std::abs(chart->table()->item(5, 1)->text().toDouble() - 100) < 3);
    chart->setAngle(0);
    // The details are on screen, not only in the model.
    for (const QString& shown :
         {QStringLiteral("Ischaemic stroke, left hemisphere; right hemiparesis"),
          QStringLiteral("29.0 cm")}) {
      const auto labels = page->findChildren<QLabel*>();
      QVERIFY2(std::any_of(labels.begin(), labels.end(),
                           [&](QLabel* l) { return l->text() == shown && l->isVisible(); }),
               qPrintable(shown));
    }
    test::saveScreenshot(m_app->window(), QStringLiteral("demo-patient"));
  }

  void aProgressReportNamesThePatient() {
    auto* page = current<PatientScreen>();
    QVERIFY(page);
    QSignalSpy written(page, &PatientScreen::reportWritten);
    const QString pdf = m_dir.filePath(QStringLiteral("progress.pdf"));
    page->writeProgressReport(pdf);
    QTRY_COMPARE_WITH_TIMEOUT(written.count(), 1, 30000);
    QCOMPARE(written.at(0).at(1).toString(), QString());
    const QString text = test::pdfText(pdf);
    QVERIFY2(text.contains(QStringLiteral("Ada Example")), qPrintable(text.left(400)));
    // The page asks for all sessions: the period is their first to last day, in the running
    // head and the details, never "progress - to -" or "From - To -" (issue 25, item 7).
    QStringList days;
    for (const auto& s : page->overview().sessions) days << s.startedAt.left(10);
    QVERIFY(!days.isEmpty());
    std::sort(days.begin(), days.end());
    const QString period = QStringLiteral("%1 to %2").arg(days.front(), days.back());
    const QString flat = text.simplified();
    QVERIFY2(flat.contains(QStringLiteral("progress ") + period), qPrintable(flat.left(600)));
    QVERIFY2(flat.contains(QStringLiteral("Period ") + period), qPrintable(flat.left(1200)));
    QVERIFY(!flat.contains(QStringLiteral("- to -")));
    QVERIFY(!flat.contains(QStringLiteral("From -")));
    // A folder that cannot be written: the page says so and stays usable.
    page->writeProgressReport(QStringLiteral("/proc/no-such-dir/x.pdf"));
    QTRY_COMPARE_WITH_TIMEOUT(written.count(), 2, 30000);
    QVERIFY2(written.at(1).at(1).toString().contains(QStringLiteral("could not be written")),
             qPrintable(written.at(1).at(1).toString()));
  }

  void editingUpdatesThePage() {
    auto* page = current<PatientScreen>();
    QTest::mouseClick(findControl<QPushButton>(screen(), QStringLiteral("Edit patient...")),
                      Qt::LeftButton);
    PatientDialog* d = nullptr;
    QTRY_VERIFY((d = screen()->findChild<PatientDialog*>()) != nullptr);
    QVERIFY(findControl<QLineEdit>(d, QStringLiteral("Patient code"))->isReadOnly());
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Diagnosis")), QStringLiteral("Updated"));
    QSignalSpy loaded(page, &PatientScreen::loaded);
    QTest::mouseClick(findControl<QPushButton>(d, QStringLiteral("Save")), Qt::LeftButton);
    QTRY_COMPARE(loaded.count(), 1);
    QCOMPARE(page->overview().patient.diagnosis, QStringLiteral("Updated"));
    QCOMPARE(page->overview().patient.name, QStringLiteral("Ada Example"));  // the rest kept
  }

  void aNewSessionStartsWithProtocolAndSide() {
    activate(m_app->window());
    QVERIFY(current<PatientScreen>());
    QTest::keySequence(screen(), QKeySequence(QStringLiteral("Ctrl+R")));
    QTRY_VERIFY(current<NewSessionScreen>());
    auto* setup = current<NewSessionScreen>()->setupPage();
    QTRY_VERIFY(setup->isComplete());
    SessionPlan plan = setup->plan();
    QCOMPARE(plan.patient.code, QStringLiteral("P001"));
    QVERIFY(!plan.protocol);
    QCOMPARE(plan.side, armtrack::Side::Right);  // Ada's affected side
    QVERIFY(setup->selectProtocol(QStringLiteral("Elbow flexion")));
    QVERIFY(!setup->selectProtocol(QStringLiteral("No such protocol")));
    QVERIFY(findControl<QRadioButton>(screen(), QStringLiteral("Left arm")));
    QTest::mouseClick(findControl<QRadioButton>(screen(), QStringLiteral("Left arm")),
                      Qt::LeftButton);
    plan = setup->plan();
    QVERIFY(plan.protocol && plan.protocol->angleKey == QStringLiteral("elbow_flexion"));
    QCOMPARE(plan.side, armtrack::Side::Left);
    test::saveScreenshot(m_app->window(), QStringLiteral("demo-new-session"));
    // Cancel goes back to the patient, nothing recorded.
    current<NewSessionScreen>()->wizard()->reject();
    QTRY_VERIFY(current<PatientScreen>());
    QTRY_COMPARE(current<PatientScreen>()->overview().sessions.size(), std::size_t{6});
  }

  void backReturnsToTheListWithThePatientSelected() {
    activate(m_app->window());
    QTest::keySequence(screen(), QKeySequence::Back);
    QTRY_VERIFY(current<PatientListScreen>());
    QTRY_COMPARE(current<PatientListScreen>()->selectedCode(), QStringLiteral("P001"));
    test::saveScreenshot(m_app->window(), QStringLiteral("demo-patients"));
  }

  void cleanupTestCase() { m_app.reset(); }
};

ARMTRACK_APP_TEST_MAIN(TestPatients)
#include "test_patients.moc"
