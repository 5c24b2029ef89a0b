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

/// Saves what the X server shows of window (so an OpenGL view is included) as <name>.png in
/// $ARMTRACK_SCREENSHOT_DIR, when that is set. Returns the file written, or "".
inline QString saveScreenshot(QWidget* window, const QString& name) {
  const QString dir = qEnvironmentVariable("ARMTRACK_SCREENSHOT_DIR");
  if (dir.isEmpty() || !window) return {};
  QDir().mkpath(dir);
  QApplication::processEvents();
  const QPixmap shot = window->screen()->grabWindow(window->winId());
  const QString path = QDir(dir).filePath(name + QStringLiteral(".png"));
  return shot.save(path) ? path : QString();
}

}  // namespace armtrack::gui::test
