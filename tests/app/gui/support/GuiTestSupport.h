// Helpers for the GUI tests: a private settings/data home, finding controls the way a screen
// reader does (by accessible name), and typing into them.
#pragma once

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QLineEdit>
#include <QScreen>
#include <QTemporaryDir>
#include <QTest>
#include <QWidget>

#include <QProcess>
#include <memory>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/common/Forms.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/services/DemoData.h"
#include "app/gui/signin/SignInScreen.h"
#include "tests/support/GuiTestMain.h"

namespace armtrack::gui::test {

/// Points QSettings and QStandardPaths at a fresh temporary home. Call before QApplication.
inline QTemporaryDir& isolatedHome() {
  static QTemporaryDir home;
  qputenv("XDG_CONFIG_HOME", home.filePath(QStringLiteral("config")).toLocal8Bit());
  qputenv("XDG_DATA_HOME", home.filePath(QStringLiteral("data")).toLocal8Bit());
  qputenv("XDG_CACHE_HOME", home.filePath(QStringLiteral("cache")).toLocal8Bit());
  return home;
}

/// The visible descendant of root of type T with that accessible name (or, for buttons, that
/// text without '&'), or nullptr.
template <class T>
T* findControl(QWidget* root, const QString& name) {
  if (!root) return nullptr;
  for (T* w : root->findChildren<T*>()) {
    if (!w->isVisibleTo(root)) continue;
    if (w->accessibleName() == name) return w;
    if constexpr (std::is_base_of_v<QAbstractButton, T>)
      if (w->text().remove(u'&') == name) return w;
  }
  return nullptr;
}

/// Replaces a line edit's text by typing, as a user would.
inline void typeInto(QLineEdit* edit, const QString& text) {
  edit->setFocus();
  edit->selectAll();
  QTest::keyClick(edit, Qt::Key_Backspace);
  QTest::keyClicks(edit, text);
}

/// Makes w the active window (Xvfb has no window manager to do it), so shortcuts reach it.
inline bool activate(QWidget* w) {
  w->activateWindow();
  return QTest::qWaitForWindowActive(w);
}

/// The text of a PDF (pdftotext), or "" when it cannot be read.
/// The text of the first visible message line (common/Forms.h MessageLine) in w, or "".
inline QString visibleMessage(QWidget* w) {
  for (auto* m : w->findChildren<MessageLine*>())
    if (m->isVisible()) return m->text();
  return {};
}

inline QString pdfText(const QString& pdf) {
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
  if (!p.waitForFinished(30000)) return {};
  return QString::fromUtf8(p.readAllStandardOutput());
}

/// Signs app in as the demo account user (DemoAccounts) from the sign-in screen, waiting for
/// the screen and then for the records to be signed in (20 s each); false when either does not
/// come. Sign out first when someone is signed in.
inline bool signInAs(AppController& app, const char* user) {
  const auto screen = [&] { return qobject_cast<SignInScreen*>(app.window()->currentScreen()); };
  if (!QTest::qWaitFor([&] { return screen() != nullptr; }, 20000)) return false;
  emit screen()->signInRequested(QString::fromLatin1(user),
                                 QString::fromLatin1(DemoAccounts::kPassword));
  return QTest::qWaitFor([&] { return app.records().signedIn(); }, 20000);
}

/// The application on fresh demo records in folder dir, started and signed in as the demo
/// therapist (the patient list showing); nullptr when that fails.
inline std::unique_ptr<AppController> demoApp(const QTemporaryDir& dir, AppOptions options = {}) {
  storage::DatabaseUrl url;
  url.path = dir.filePath(QStringLiteral("demo.db"));
  if (!buildDemoDatabase(url, {})) return nullptr;
  options.database = url.path;
  auto app = std::make_unique<AppController>(options);
  app->start();
  activate(app->window());
  if (!signInAs(*app, DemoAccounts::kTherapist)) return nullptr;
  return app;
}

/// Saves what the X server shows of the window (the VTK view included) as <name>.png in the
/// screenshot folder (tests/support/GuiTestMain.h); returns the path.
inline QString saveScreenshot(QWidget* window, const QString& name) {
  // The 3D view and the plots draw from their own 30-60 Hz timers: give them a frame to show
  // the newest state. Only the picture depends on it; no test asserts on it.
  QTest::qWait(120);
  return armtrack::test::saveScreenshot(armtrack::test::grabFromScreen(window->window()), name);
}

}  // namespace armtrack::gui::test

/// main() for the application's GUI tests: a private home, the OpenGL format, the application's
/// identity (as armtrack's main() sets them).
#define ARMTRACK_APP_TEST_MAIN(TestClass)          \
  int main(int argc, char** argv) {                \
    armtrack::gui::test::isolatedHome();           \
    armtrack::ui::setDefaultSurfaceFormat();       \
    QApplication app(argc, argv);                  \
    app.setAttribute(Qt::AA_DontUseNativeDialogs); \
    armtrack::gui::setApplicationIdentity();       \
    TestClass test;                                \
    return QTest::qExec(&test, argc, argv);        \
  }
