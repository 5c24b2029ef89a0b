#include "app/gui/CloseWhileRecording.h"

#include <QMessageBox>
#include <QPushButton>

#include "app/gui/MainWindow.h"
#include "app/gui/live/LiveSessionScreen.h"

namespace armtrack::gui {

using app::gui::LiveSessionScreen;

CloseWhileRecording::CloseWhileRecording(MainWindow& window) : QObject(&window), m_window(window) {}

bool CloseWhileRecording::mayClose() {
  if (m_quitting) return true;
  auto* live = qobject_cast<LiveSessionScreen*>(m_window.currentScreen());
  if (!live) return true;
  const LiveSessionScreen::State s = live->state();
  if (s == LiveSessionScreen::State::Stopping) {
    m_closing = true;  // the window closes once the session has stopped
    return false;
  }
  if (s != LiveSessionScreen::State::Recording && s != LiveSessionScreen::State::Paused)
    return true;
  if (m_question) {
    m_question->raise();
    m_question->activateWindow();
    return false;
  }
  auto* box = new QMessageBox(QMessageBox::Question, tr("A recording is under way"),
                              tr("Stop the recording and save the session before closing?"),
                              QMessageBox::NoButton, &m_window);
  box->setInformativeText(
      tr("Stop and save ends the session as the Stop button does and closes ArmTrack; the "
         "session is analysed when ArmTrack next starts. Keep recording goes back to the "
         "session."));
  QPushButton* stop = box->addButton(tr("&Stop and save"), QMessageBox::AcceptRole);
  QPushButton* keep = box->addButton(tr("&Keep recording"), QMessageBox::RejectRole);
  box->setDefaultButton(keep);
  box->setEscapeButton(keep);
  box->setAttribute(Qt::WA_DeleteOnClose);
  m_question = box;
  connect(stop, &QPushButton::clicked, this, [this, live = QPointer<LiveSessionScreen>(live)] {
    if (!live) return;
    m_closing = true;
    live->stop();  // AppController closes the window when sessionStopped() comes
  });
  box->open();
  return false;
}

}  // namespace armtrack::gui
