// The first-run assistant and sign-in, driven through the real window: the records are made in
// the folder chosen, validation messages keep what was typed, a wrong password keeps the name
// and the password, and a home account gets its own home window (test_home_mode goes through
// it), from which signing out comes back here.
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QSettings>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/common/Forms.h"
#include "app/gui/common/MessageScreen.h"
#include "app/gui/home/HomeController.h"
#include "app/gui/home/HomeStartScreen.h"
#include "app/gui/home/HomeWindow.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/signin/FirstRunScreen.h"
#include "app/gui/signin/SignInScreen.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack::gui;
using armtrack::gui::test::findControl;
using armtrack::gui::test::typeInto;

class TestSignIn : public QObject {
  Q_OBJECT

  QString dataFolder() const { return test::isolatedHome().filePath(QStringLiteral("clinic")); }

  static QString message(QWidget* screen) {
    auto* m = screen->findChild<MessageLine*>();
    return m && m->isVisible() ? m->text() : QString();
  }

 private slots:
  void firstRunCreatesTheRecordsWhereChosen() {
    AppController app({});
    app.start();
    QTRY_VERIFY(qobject_cast<FirstRunScreen*>(app.window()->currentScreen()));
    auto* screen = app.window()->currentScreen();
    auto* folder = findControl<QLineEdit>(screen, QStringLiteral("Data folder"));
    auto* admin = findControl<QLineEdit>(screen, QStringLiteral("Administrator name"));
    auto* password = findControl<QLineEdit>(screen, QStringLiteral("Password"));
    auto* again = findControl<QLineEdit>(screen, QStringLiteral("Password again"));
    auto* create = findControl<QPushButton>(screen, QStringLiteral("Create and sign in"));
    QVERIFY(folder && admin && password && again && create);
    QVERIFY(create->isDefault());

    typeInto(folder, dataFolder());
    typeInto(admin, QStringLiteral("boss"));
    typeInto(password, QStringLiteral("short"));
    typeInto(again, QStringLiteral("short"));
    QTest::keyClick(again, Qt::Key_Return);
    QVERIFY2(message(screen).contains(QStringLiteral("at least 10 characters")),
             qPrintable(message(screen)));
    QCOMPARE(admin->text(), QStringLiteral("boss"));  // nothing typed is lost
    typeInto(password, QStringLiteral("boss-pass-1"));
    typeInto(again, QStringLiteral("boss-pass-2"));
    QTest::mouseClick(create, Qt::LeftButton);
    QVERIFY2(message(screen).contains(QStringLiteral("differ")), qPrintable(message(screen)));
    QVERIFY(!QFileInfo::exists(dataFolder()));  // nothing made from an invalid form
    typeInto(again, QStringLiteral("boss-pass-1"));
    QTest::keyClick(again, Qt::Key_Return);

    QTRY_COMPARE(app.window()->currentScreen()->windowTitle(), QStringLiteral("Patients"));
    QVERIFY(QFileInfo::exists(QDir(dataFolder()).filePath(QStringLiteral("armtrack.db"))));
    QVERIFY(app.records().signedIn());
    QCOMPARE(AppSettings::load(*std::make_unique<QSettings>()).dataFolder, dataFolder());
  }

  void signInKeepsWhatWasTyped() {
    AppController app({});
    app.start();
    QTRY_VERIFY(qobject_cast<SignInScreen*>(app.window()->currentScreen()));
    auto* screen = app.window()->currentScreen();
    auto* name = findControl<QLineEdit>(screen, QStringLiteral("Account name"));
    auto* password = findControl<QLineEdit>(screen, QStringLiteral("Password"));
    QVERIFY(name && password);
    QCOMPARE(name->text(), QStringLiteral("boss"));  // remembered from the last sign-in
    typeInto(password, QStringLiteral("not-the-password"));
    QTest::keyClick(password, Qt::Key_Return);
    QTRY_VERIFY(message(screen).contains(QStringLiteral("Wrong user name or password")));
    QVERIFY(message(screen).contains(QStringLiteral("Caps Lock")));
    test::saveScreenshot(app.window(), QStringLiteral("sign-in-wrong-password"));
    QCOMPARE(app.window()->currentScreen(), screen);
    QCOMPARE(name->text(), QStringLiteral("boss"));
    QCOMPARE(password->text(), QStringLiteral("not-the-password"));
    QVERIFY(password->hasSelectedText());  // typing replaces it
    QTest::keyClicks(password, QStringLiteral("boss-pass-1"));
    QTest::keyClick(password, Qt::Key_Return);
    QTRY_COMPARE(app.window()->currentScreen()->windowTitle(), QStringLiteral("Patients"));
  }

  void aHomeAccountGetsTheHomeWindowAlone() {
    AppController app({});
    app.start();
    QTRY_VERIFY(qobject_cast<SignInScreen*>(app.window()->currentScreen()));
    emit qobject_cast<SignInScreen*>(app.window()->currentScreen())
        ->signInRequested(QStringLiteral("boss"), QStringLiteral("boss-pass-1"));
    QTRY_VERIFY(app.records().signedIn());
    bool added = false;
    app.records().call(
        app.window(),
        [](armtrack::storage::ClinicalStore& s) {
          armtrack::storage::Patient p;
          p.code = QStringLiteral("H01");
          p.name = QStringLiteral("Home Patient");
          s.addPatient(p);
          s.addUser(QStringLiteral("home1"), armtrack::storage::Role::Home, "home-pass-1",
                    QStringLiteral("H01"));
        },
        [&] { added = true; }, {});
    QTRY_VERIFY(added);
    app.signOut();
    QTRY_VERIFY(qobject_cast<SignInScreen*>(app.window()->currentScreen()));
    emit qobject_cast<SignInScreen*>(app.window()->currentScreen())
        ->signInRequested(QStringLiteral("home1"), QStringLiteral("home-pass-1"));
    // The home window, in place of the main one: a patient without a programme yet.
    QTRY_VERIFY(app.home() && app.home()->window()->isVisible());
    QVERIFY(!app.window()->isVisible());
    armtrack::gui::home::HomeStartScreen* start = nullptr;
    QTRY_VERIFY((start = qobject_cast<armtrack::gui::home::HomeStartScreen*>(
                     app.home()->window()->currentScreen())) != nullptr);
    QVERIFY(start->exerciseLines().isEmpty());
    QVERIFY(!findControl<QPushButton>(start, QStringLiteral("Start"))->isEnabled());
    findControl<QPushButton>(start, QStringLiteral("Sign out"))->click();
    QTRY_VERIFY(qobject_cast<SignInScreen*>(app.window()->currentScreen()));
    QTRY_VERIFY(app.home() == nullptr);
    QVERIFY(app.window()->isVisible());
    QVERIFY(!app.records().signedIn());
  }
};

ARMTRACK_APP_TEST_MAIN(TestSignIn)
#include "test_sign_in.moc"
