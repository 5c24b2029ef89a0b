// The home window driven by one key: scanning steps the focus through the screen's usable
// choices (hidden and disabled ones skipped) starting on the main one, and the switch takes the
// one highlighted; "press to go on" always takes the main choice; the keyboard mode presses the
// focused button; Escape goes to the screen; a held switch is one press; Space in the comment
// box is text in every mode; keys of another window are left alone.
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTest>

#include "app/gui/home/HomeMessageScreen.h"
#include "app/gui/home/HomeWindow.h"
#include "app/gui/home/SwitchAccess.h"

using namespace armtrack::gui::home;

namespace {

class Screen : public HomeMessageScreen {
 public:
  Screen() : HomeMessageScreen([] { return QStringLiteral("T"); }, [] { return QString(); }) {}
  void escapePressed() override { ++escapes; }
  int escapes = 0;
};

}  // namespace

class TestSwitchAccess : public QObject {
  Q_OBJECT

  HomeWindow* m_window = nullptr;
  Screen* m_screen = nullptr;
  QStringList m_pressed;
  QList<QPushButton*> m_buttons;

  void key(Qt::Key k, bool autoRepeat = false) {
    QWidget* to = QApplication::focusWidget() ? QApplication::focusWidget() : m_window;
    QKeyEvent press(QEvent::KeyPress, k, Qt::NoModifier, QString(), autoRepeat);
    QApplication::sendEvent(to, &press);
  }

 private slots:
  void init() {
    m_window = new HomeWindow;
    m_screen = new Screen;
    m_pressed.clear();
    m_buttons.clear();
    for (const char* name : {"go", "hidden", "off", "other", "last"}) {
      const QString n = QString::fromLatin1(name);
      m_buttons << m_screen->addChoice([n] { return n; }, [this, n] { m_pressed << n; });
    }
    m_window->showScreen(m_screen);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window));
    m_window->activateWindow();
    m_buttons[1]->hide();
    m_buttons[2]->setEnabled(false);
  }
  void cleanup() {
    m_window->allowClose();
    delete m_window;
  }

  void scanningStepsThroughUsableChoicesAndTakesTheHighlighted() {
    SwitchAccess* a = m_window->access();
    a->setScanInterval(100);  // clamped to 500 ms
    QCOMPARE(a->scanInterval(), 500);
    a->setMode(AccessMode::Scanning);
    QCOMPARE(a->highlighted(), m_buttons[0]);                         // starts on the main choice
    QTRY_COMPARE_WITH_TIMEOUT(a->highlighted(), m_buttons[3], 2000);  // hidden, disabled skipped
    QCOMPARE(QApplication::focusWidget(), m_buttons[3]);
    key(Qt::Key_Space);
    QCOMPARE(m_pressed, QStringList{QStringLiteral("other")});
    key(Qt::Key_Space, true);  // the switch held down: no second press
    QCOMPARE(m_pressed.size(), 1);
    QTRY_COMPARE_WITH_TIMEOUT(a->highlighted(), m_buttons[4], 2000);
    QTRY_COMPARE_WITH_TIMEOUT(a->highlighted(), m_buttons[0], 2000);  // and round again
  }

  void stepModeAlwaysTakesTheMainChoice() {
    m_window->access()->setMode(AccessMode::Step);
    m_buttons[4]->setFocus();
    key(Qt::Key_Space);
    key(Qt::Key_Return);
    QCOMPARE(m_pressed, (QStringList{QStringLiteral("go"), QStringLiteral("go")}));
    QVERIFY(!m_window->access()->highlighted());
  }

  void keyboardPressesTheFocusedButtonAndEscapePauses() {
    m_window->access()->setMode(AccessMode::Keyboard);
    m_buttons[3]->setFocus();
    key(Qt::Key_Space);
    QCOMPARE(m_pressed, QStringList{QStringLiteral("other")});
    key(Qt::Key_Escape);
    QCOMPARE(m_screen->escapes, 1);
  }

  void spaceInTheCommentIsTextInEveryMode() {
    auto* box = new QPlainTextEdit(m_screen);
    box->show();
    for (AccessMode mode : {AccessMode::Keyboard, AccessMode::Step, AccessMode::Scanning}) {
      m_window->access()->setMode(mode);
      box->setFocus();
      QTest::keyClicks(box, QStringLiteral("a b"));
    }
    QVERIFY(m_pressed.isEmpty());
    QCOMPARE(box->toPlainText(), QStringLiteral("a ba ba b"));
  }

  void keysOfAnotherWindowAreLeftAlone() {
    m_window->access()->setMode(AccessMode::Step);
    QPushButton elsewhere(QStringLiteral("elsewhere"));
    int clicked = 0;
    connect(&elsewhere, &QPushButton::clicked, this, [&] { ++clicked; });
    elsewhere.show();
    elsewhere.setFocus();
    QKeyEvent press(QEvent::KeyPress, Qt::Key_Space, Qt::NoModifier);
    QApplication::sendEvent(&elsewhere, &press);
    QVERIFY(m_pressed.isEmpty());
  }
};

QTEST_MAIN(TestSwitchAccess)
#include "test_switch_access.moc"
