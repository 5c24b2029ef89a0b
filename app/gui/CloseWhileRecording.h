// The main window's question when it is closed during a recording: "Stop and save" ends the
// session as the Stop button does (complete, its analysis pending until the next start) and then
// closes the window; "Keep recording" (the default) leaves everything as it was.
#pragma once

#include <QMessageBox>
#include <QObject>
#include <QPointer>

class QMessageBox;

namespace armtrack::gui {

class MainWindow;

class CloseWhileRecording : public QObject {
  Q_OBJECT
 public:
  explicit CloseWhileRecording(MainWindow& window);

  /// MainWindow's close guard: true when nothing is being recorded (or quitting() was called).
  bool mayClose();
  /// The window closes once the session under way has stopped ("Stop and save" was chosen).
  bool closing() const { return m_closing; }
  /// The application ends on its own (--quit-after, a test): close without asking.
  void quitting() { m_quitting = true; }
  /// The question while it is open (for tests).
  QMessageBox* question() const { return m_question; }

 private:
  MainWindow& m_window;
  QPointer<QMessageBox> m_question;
  bool m_closing = false;
  bool m_quitting = false;
};

}  // namespace armtrack::gui
