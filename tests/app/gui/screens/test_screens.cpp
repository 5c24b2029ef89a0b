// The therapist's screens at the size of the screen the test runs on (ctest runs it at 1024x600
// and 1920x1080, in English and in German: tests/app/gui/screens/CMakeLists.txt), in one
// application on demo records: the demo's live session, the patient page, a session's review,
// signing in again, the patient list with the new-patient dialog, the new-session steps, and the
// home window (its start and an exercise under way).
// On each screen: no text is cut (LayoutCheck.h), no plot is lower than 120 px, the live angle
// table shows all its columns; in German no text the screen shows is an English source string of
// translations/armtrack_de.ts, nor one of Qt's own English buttons. F1 opens the user guide at
// the screen's section. Each screen is saved as screens-<screen>-<width>x<height>-<lang>.png in
// the screenshot folder (the build's screenshots/ by default).
#include <QApplication>
#include <QDialog>
#include <QFile>
#include <QLibraryInfo>
#include <QListWidget>
#include <QRegularExpression>
#include <QScreen>
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QTextBlock>
#include <QTextBrowser>
#include <QWizard>
#include <QXmlStreamReader>

#include "app/gui/HelpWindow.h"
#include "app/gui/SettingsDialog.h"
#include "app/gui/home/ExerciseScreen.h"
#include "app/gui/home/HomeCalibrationScreen.h"
#include "app/gui/home/HomeController.h"
#include "app/gui/home/HomeStartScreen.h"
#include "app/gui/home/HomeWindow.h"
#include "app/gui/home/SensorCheckScreen.h"
#include "app/gui/live/LiveSessionScreen.h"
#include "app/gui/newsession/DevicesPage.h"
#include "app/gui/newsession/NewSessionScreen.h"
#include "app/gui/patients/PatientListScreen.h"
#include "app/gui/patients/PatientScreen.h"
#include "app/gui/review/ReviewScreen.h"
#include "app/gui/signin/SignInScreen.h"
#include "app/i18n/Language.h"
#include "core/storage/ClinicalStore.h"
#include "tests/app/gui/screens/LayoutCheck.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack::gui;
using armtrack::app::gui::LiveSessionScreen;

namespace {

/// The English source texts of the German translation whose German differs ('&' removed).
QSet<QString> englishSources() {
  QSet<QString> out;
  QFile f(QStringLiteral(ARMTRACK_SOURCE_DIR "/translations/armtrack_de.ts"));
  if (!f.open(QIODevice::ReadOnly)) return out;
  QXmlStreamReader xml(&f);
  QString source;
  while (!xml.atEnd()) {
    if (!xml.readNextStartElement()) continue;
    if (xml.name() == QLatin1String("source")) {
      source = xml.readElementText();
    } else if (xml.name() == QLatin1String("translation")) {
      QString german = xml.readElementText(QXmlStreamReader::IncludeChildElements);
      QString english = source;
      english.remove(u'&');
      german.remove(u'&');
      if (!german.isEmpty() && german != english && !english.contains(u'%'))
        out.insert(english.trimmed());
    }
  }
  return out;
}

}  // namespace

class TestScreens : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  std::unique_ptr<AppController> m_app;
  QString m_lang;
  QSet<QString> m_english;
  QSet<QString> m_data;    // the records' own words (the demo's protocol names): not UI text
  QStringList m_failures;  // every screen's problems, reported at the end of each step

  QWidget* screen() const { return m_app->window()->currentScreen(); }
  template <class T>
  T* current() const {
    return qobject_cast<T*>(screen());
  }
  QString size() const {
    const QSize s = QGuiApplication::primaryScreen()->geometry().size();
    return QStringLiteral("%1x%2").arg(s.width()).arg(s.height());
  }

  /// The checks of one window's state, and its picture.
  QStringList inspect(QWidget* window, const QString& name, const QStringList& wholeTables = {}) {
    QApplication::processEvents();
    QTest::qWait(200);  // layouts settle, the plots draw
    QStringList problems = armtrack::gui::test::clippedTexts(window, wholeTables);
    if (m_lang == QLatin1String("de")) {
      // Qt's own buttons whose German differs ("OK" is German too).
      static const QStringList qtButtons = {QStringLiteral("Save"),   QStringLiteral("Cancel"),
                                            QStringLiteral("Next >"), QStringLiteral("< Back"),
                                            QStringLiteral("Yes"),    QStringLiteral("No"),
                                            QStringLiteral("Finish"), QStringLiteral("Close"),
                                            QStringLiteral("Apply"),  QStringLiteral("Help")};
      for (const QString& text : armtrack::gui::test::shownTexts(window))
        if ((m_english.contains(text) && !m_data.contains(text)) || qtButtons.contains(text))
          problems << QStringLiteral("English: \"%1\"").arg(text);
    }
    problems.removeDuplicates();
    armtrack::gui::test::saveScreenshot(
        window, QStringLiteral("screens-%1-%2-%3").arg(name, size(), m_lang));
    for (const QString& p : problems) qWarning("%s: %s", qPrintable(name), qPrintable(p));
    return problems;
  }
  void expectClean(QWidget* window, const QString& name, const QStringList& wholeTables = {}) {
    const QStringList problems = inspect(window, name, wholeTables);
    QVERIFY2(problems.isEmpty(), qPrintable(name + QStringLiteral(": ") + problems.join(u'\n')));
  }
  /// F1 on the screen shown: the guide opens at the screen's section.
  void helpOpens(const QString& heading) {
    QVERIFY(armtrack::gui::test::activate(m_app->window()));
    QTest::keyClick(m_app->window(), Qt::Key_F1);
    HelpWindow* help = nullptr;
    QTRY_VERIFY((help = m_app->window()->helpWindow()) && help->isVisible());
    const QString text = help->browser()->toPlainText();
    QVERIFY2(
        text.startsWith(m_lang == QLatin1String("de") ? QStringLiteral("ArmTrack Benutzerhandbuch")
                                                      : QStringLiteral("ArmTrack user guide")),
        qPrintable(text.left(80)));
    QVERIFY(!help->hintText().isEmpty());
    // Scrolled to the screen's section: its heading is in view.
    const QTextCursor at = help->browser()->textCursor();
    QCOMPARE(at.block().text(), heading);
    help->close();
  }

 private slots:
  void initTestCase() {
    m_lang = qEnvironmentVariable("ARMTRACK_TEST_LANG", QStringLiteral("en"));
    m_english = englishSources();
    if (m_lang != QLatin1String("en"))
      QVERIFY2(QFile::exists(QLibraryInfo::path(QLibraryInfo::TranslationsPath) +
                             QStringLiteral("/qtbase_%1.qm").arg(m_lang)),
               "Qt's own translations are missing: install qt6-translations-l10n "
               "(packaging/deps-debian12.sh)");
    QVERIFY(m_english.size() > 500);
    AppOptions o;
    o.demo = true;
    o.language = m_lang;
    o.database = m_dir.filePath(QStringLiteral("demo/armtrack-demo.db"));
    o.pluginFolders = {QStringLiteral(ARMTRACK_PLUGIN_DIR)};
    m_app = std::make_unique<AppController>(o);
    QSignalSpy ready(m_app.get(), &AppController::demoReady);
    m_app->start();
    // The window fills the screen, as maximised on a desktop.
    m_app->window()->setGeometry(QGuiApplication::primaryScreen()->availableGeometry());
    QVERIFY(ready.wait(60000));
    QCOMPARE(armtrack::i18n::currentLanguage(), m_lang);
    for (const auto& p : m_app->records().callBlocking(
             [](armtrack::storage::ClinicalStore& s) { return s.listProtocols(); }))
      m_data.insert(p.name);
  }

  void liveSession() {
    auto* live = current<LiveSessionScreen>();
    QVERIFY(live);
    QTRY_VERIFY_WITH_TIMEOUT(live->sessionTime() >= 4.0, 30000);
    // The event log's device states in the user's language (the plugins speak English).
    if (m_lang == QLatin1String("de"))
      for (QListWidget* log : live->findChildren<QListWidget*>())
        for (int i = 0; i < log->count(); ++i)
          QVERIFY2(!log->item(i)->text().contains(QRegularExpression(
                       QStringLiteral(": (streaming|connecting|disconnected|error)\\b"))),
                   qPrintable(log->item(i)->text()));
    expectClean(m_app->window(), QStringLiteral("live"),
                {QStringLiteral("Joint angles table"), QStringLiteral("Winkeltabelle")});
    helpOpens(m_lang == QLatin1String("de") ? QStringLiteral("Eine Sitzung")
                                            : QStringLiteral("A session"));
    live->stop();
    QTRY_VERIFY_WITH_TIMEOUT(current<PatientScreen>(), 20000);
  }

  void patientPage() {
    QTRY_VERIFY_WITH_TIMEOUT(current<PatientScreen>()->overview().sessions.size() >= 6, 20000);
    expectClean(m_app->window(), QStringLiteral("patient"));
    helpOpens(m_lang == QLatin1String("de") ? QStringLiteral("Die Seite eines Patienten")
                                            : QStringLiteral("The patient's page"));
  }

  void review() {
    const qint64 id = current<PatientScreen>()->overview().sessions.front().id;
    m_app->showReview(id);
    QTRY_VERIFY(current<ReviewScreen>());
    QTRY_VERIFY_WITH_TIMEOUT(current<ReviewScreen>()->data().analysis.has_value(), 30000);
    expectClean(m_app->window(), QStringLiteral("review"));
    helpOpens(m_lang == QLatin1String("de") ? QStringLiteral("Eine Sitzung auswerten")
                                            : QStringLiteral("Reviewing a session"));
  }

  void signInAndPatients() {
    m_app->signOut();
    QTRY_VERIFY(current<SignInScreen>());
    expectClean(m_app->window(), QStringLiteral("sign-in"));
    emit current<SignInScreen>()->signInRequested(QString::fromLatin1(DemoAccounts::kTherapist),
                                                  QString::fromLatin1(DemoAccounts::kPassword));
    QTRY_VERIFY_WITH_TIMEOUT(current<PatientListScreen>(), 20000);
    expectClean(m_app->window(), QStringLiteral("patients"));
    // A dialog: its buttons in the user's language too (Qt's own Save and Cancel).
    QVERIFY(armtrack::gui::test::activate(m_app->window()));
    QTest::keySequence(screen(), QKeySequence::New);
    QDialog* dialog = nullptr;
    QTRY_VERIFY((dialog = screen()->findChild<QDialog*>()) && dialog->isVisible());
    expectClean(dialog, QStringLiteral("patient-dialog"));
    dialog->reject();
  }

  void newSession() {
    m_app->startNewSession(QString::fromLatin1(DemoAccounts::kLivePatient));
    QTRY_VERIFY(current<NewSessionScreen>());
    QWizard* wizard = current<NewSessionScreen>()->wizard();
    expectClean(m_app->window(), QStringLiteral("new-session"));
    QTest::mouseClick(wizard->button(QWizard::NextButton), Qt::LeftButton);
    QTRY_COMPARE(wizard->currentPage(),
                 static_cast<QWizardPage*>(current<NewSessionScreen>()->devicesStep()));
    expectClean(m_app->window(), QStringLiteral("devices"));
    // The device check, then the sensors' calibration step (before it starts).
    auto* devices = qobject_cast<armtrack::app::gui::DevicesPage*>(
        current<NewSessionScreen>()->devicesStep()->page());
    QVERIFY(devices);
    devices->startCheck();
    QTRY_VERIFY_WITH_TIMEOUT(devices->checkPassed(), 30000);
    expectClean(m_app->window(), QStringLiteral("devices-checked"));
    QTest::mouseClick(wizard->button(QWizard::NextButton), Qt::LeftButton);
    QTRY_COMPARE(wizard->currentPage(),
                 static_cast<QWizardPage*>(current<NewSessionScreen>()->calibrationStep()));
    expectClean(m_app->window(), QStringLiteral("calibration"));
  }

  void settings() {
    m_app->showSettings();
    QDialog* dialog = nullptr;
    QTRY_VERIFY((dialog = m_app->window()->findChild<SettingsDialog*>()) && dialog->isVisible());
    expectClean(dialog, QStringLiteral("settings"));
    dialog->reject();
  }

  // The patient's home window: its start and an exercise under way.
  void homeExercise() {
    QSettings().setValue(QStringLiteral("devices/default"),
                         QStringList{QStringLiteral("virtual-arm:sensors=upper+forearm+webcam")});
    QSettings().setValue(QStringLiteral("home/access"), QStringLiteral("step"));
    m_app->signOut();
    QTRY_VERIFY(current<SignInScreen>());
    emit current<SignInScreen>()->signInRequested(QString::fromLatin1(DemoAccounts::kHome),
                                                  QString::fromLatin1(DemoAccounts::kPassword));
    const auto home = [this] { return m_app->home() ? m_app->home()->window() : nullptr; };
    QTRY_VERIFY_WITH_TIMEOUT(home() && home()->isVisible(), 20000);
    home()->setGeometry(QGuiApplication::primaryScreen()->availableGeometry());
    QVERIFY(armtrack::gui::test::activate(home()));
    const auto at = [&]<class T>(T*) { return qobject_cast<T*>(home()->currentScreen()); };
    QTRY_VERIFY(at(static_cast<home::HomeStartScreen*>(nullptr)));
    expectClean(home(), QStringLiteral("home-start"));
    const auto press = [&] {
      QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : home(),
                      Qt::Key_Space);
    };
    press();  // Start
    QTRY_VERIFY(at(static_cast<home::SensorCheckScreen*>(nullptr)));
    press();  // Start the check
    QTRY_COMPARE_WITH_TIMEOUT(at(static_cast<home::SensorCheckScreen*>(nullptr))->state(),
                              home::SensorCheckScreen::State::Passed, 60000);
    press();  // Go on
    home::HomeCalibrationScreen* calibration = nullptr;
    QTRY_VERIFY((calibration = at(static_cast<home::HomeCalibrationScreen*>(nullptr))));
    emit calibration->done(std::nullopt);  // the calibration is another test's
    home::ExerciseScreen* exercise = nullptr;
    QTRY_VERIFY((exercise = at(static_cast<home::ExerciseScreen*>(nullptr))));
    press();  // Start set 1
    QTRY_COMPARE(exercise->phase(), home::ExerciseScreen::Phase::Set);
    QTest::qWait(2000);
    expectClean(home(), QStringLiteral("home-exercise"));
  }

  void cleanupTestCase() { m_app.reset(); }
};

ARMTRACK_APP_TEST_MAIN(TestScreens)

#include "test_screens.moc"
