// The home window's side of the sync (issue 28): the line under every screen says where the
// sessions stand ("3 sessions waiting to be sent", "Sent today 10:42", "Not connected: sessions
// are kept and sent later"), and the clinic screen takes the address and the code from the
// keyboard alone: Space typed in a field is text (it never presses Connect), Enter connects,
// empty fields are refused with what to do.
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include "app/gui/home/HomeConnectScreen.h"
#include "app/gui/home/HomeWindow.h"
#include "app/gui/home/SwitchAccess.h"
#include "app/i18n/Language.h"

using namespace armtrack::gui::home;
using armtrack::sync::SyncProblem;
using armtrack::sync::SyncStatus;

class TestHomeConnect : public QObject {
  Q_OBJECT

  HomeWindow* m_window = nullptr;
  HomeConnectScreen* m_screen = nullptr;

  void key(Qt::Key k, const QString& text = {}) {
    QWidget* to = QApplication::focusWidget() ? QApplication::focusWidget() : m_window;
    QKeyEvent press(QEvent::KeyPress, k, Qt::NoModifier, text);
    QApplication::sendEvent(to, &press);
  }
  void type(const QString& text) {
    for (QChar c : text) key(c == u' ' ? Qt::Key_Space : Qt::Key_A, QString(c));
  }

 private slots:
  void initTestCase() {
    armtrack::i18n::setLanguage("en");  // the English plurals ("3 sessions")
  }
  void init() {
    m_window = new HomeWindow;
    m_screen = new HomeConnectScreen(QString());
    m_window->showScreen(m_screen);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window));
    m_window->activateWindow();
    m_screen->serverField()->setFocus();
  }
  void cleanup() {
    m_window->allowClose();
    delete m_window;
  }

  void theSyncLineSaysWhereTheSessionsStand() {
    const QDateTime now(QDate(2026, 11, 28), QTime(15, 0));
    SyncStatus s;
    s.enrolled = true;
    s.waiting = 3;
    s.lastSent = QDateTime(QDate(2026, 11, 28), QTime(10, 42)).toUTC();
    QString text = HomeConnectScreen::stateText(s, now);
    QVERIFY2(text.contains("3 sessions waiting to be sent"), qPrintable(text));
    QVERIFY2(text.contains("Sent today 10:42"), qPrintable(text));
    s.problem = SyncProblem::Offline;
    text = HomeConnectScreen::stateText(s, now);
    QVERIFY2(text.contains("Not connected: sessions are kept and sent later"), qPrintable(text));
    s.problem = SyncProblem::CertificateChanged;
    QVERIFY(HomeConnectScreen::stateText(s, now).contains("not the one connected before"));
    s = {};
    QVERIFY(HomeConnectScreen::stateText(s, now).contains("Not connected to a clinic"));
    m_window->setSyncText("1 session waiting to be sent");
    QCOMPARE(m_window->syncText(), QString("1 session waiting to be sent"));
    m_window->setSyncText({});
    QCOMPARE(m_window->syncText(), QString());
  }

  void theAddressAndCodeAreTypedWithTheKeyboardAlone() {
    QSignalSpy asked(m_screen, &HomeConnectScreen::connectRequested);
    // Enter with nothing typed: refused with what to do, nothing sent.
    key(Qt::Key_Return);
    QCOMPARE(asked.size(), 0);
    QVERIFY(m_screen->resultText().contains("Type the clinic's address"));
    m_screen->serverField()->setFocus();
    type("sync.clinic.example");
    QCOMPARE(m_screen->serverField()->text(), QString("sync.clinic.example"));
    key(Qt::Key_Return);  // on to the code
    QCOMPARE(QApplication::focusWidget(), m_screen->codeField());
    type("7KQ2 M9XD");  // a space is text here, not "go on"
    QCOMPARE(asked.size(), 0);
    QCOMPARE(m_screen->codeField()->text(), QString("7KQ2 M9XD"));
    key(Qt::Key_Return);
    QCOMPARE(asked.size(), 1);
    QCOMPARE(asked.at(0).at(0).toString(), QString("sync.clinic.example"));
    QCOMPARE(asked.at(0).at(1).toString(), QString("7KQ2 M9XD"));
    m_screen->showResult(false, HomeConnectScreen::enrolText(false, SyncProblem::Refused, {}));
    QVERIFY(m_screen->resultText().contains("ask your therapist for a new one"));
    QVERIFY(m_screen->choices().first()->isEnabled());  // may try again
  }
};

QTEST_MAIN(TestHomeConnect)
#include "test_home_connect.moc"
