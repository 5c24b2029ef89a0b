// The main window hosts one screen at a time: the old one is deleted, the title and keyboard
// focus follow the new one, and a screen with unsaved work can refuse the window's closing.
#include <QCloseEvent>
#include <QLineEdit>
#include <QPointer>
#include <QTest>
#include <QVBoxLayout>

#include "app/gui/MainWindow.h"
#include "tests/app/gui/support/GuiTestSupport.h"

namespace {

class Refusing : public QWidget {
 public:
  bool refuse = true;

 protected:
  void closeEvent(QCloseEvent* e) override { refuse ? e->ignore() : e->accept(); }
};

}  // namespace

class TestMainWindow : public QObject {
  Q_OBJECT
 private slots:
  void hostsOneScreenAtATime() {
    armtrack::gui::MainWindow w;
    w.show();
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    auto* first = new QWidget;
    first->setWindowTitle(QStringLiteral("First"));
    auto* edit = new QLineEdit(first);
    (new QVBoxLayout(first))->addWidget(edit);
    w.showScreen(first);
    QCOMPARE(w.currentScreen(), first);
    QCOMPARE(w.windowTitle(), QStringLiteral("First - ArmTrack"));
    QTRY_VERIFY(edit->hasFocus());
    QPointer<QWidget> gone(first);
    auto* second = new QWidget;
    second->setWindowTitle(QStringLiteral("Second"));
    w.showScreen(second);
    QTRY_VERIFY(gone.isNull());
    QCOMPARE(w.windowTitle(), QStringLiteral("Second - ArmTrack"));
    second->setWindowTitle(QStringLiteral("Renamed"));
    QCOMPARE(w.windowTitle(), QStringLiteral("Renamed - ArmTrack"));
  }

  void aScreenMayRefuseTheClose() {
    armtrack::gui::MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* screen = new Refusing;
    w.showScreen(screen);
    QVERIFY(!w.close());
    QVERIFY(w.isVisible());
    screen->refuse = false;
    QVERIFY(w.close());
  }
};

ARMTRACK_APP_TEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
