#include "app/gui/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStackedWidget>
#include <QStatusBar>

namespace armtrack::gui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_stack(new QStackedWidget(this)), m_who(new QLabel(this)) {
  setCentralWidget(m_stack);
  setMinimumSize(900, 600);
  resize(1200, 760);  // fits a 1280x800 screen; a window manager may maximise it
  statusBar()->addPermanentWidget(m_who);
  m_who->setAccessibleName(tr("Signed-in account"));

  QMenu* file = menuBar()->addMenu(tr("&ArmTrack"));
  m_patients = file->addAction(tr("&Patients"), this, &MainWindow::patientsRequested);
  m_patients->setShortcut(QKeySequence(tr("Ctrl+Shift+P")));
  m_settings = file->addAction(tr("&Settings..."), this, &MainWindow::settingsRequested);
  m_settings->setShortcut(QKeySequence::Preferences);
  if (m_settings->shortcut().isEmpty()) m_settings->setShortcut(QKeySequence(tr("Ctrl+,")));
  m_signOut = file->addAction(tr("Sign &out"), this, &MainWindow::signOutRequested);
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  QAction* guide = help->addAction(tr("&User guide"), this, &MainWindow::userGuideRequested);
  guide->setShortcut(QKeySequence::HelpContents);
  help->addAction(tr("&About ArmTrack"), this, [this] {
    QMessageBox::about(this, tr("About ArmTrack"),
                       tr("<p><b>ArmTrack %1</b></p><p>Measures the shoulder's and elbow's joint "
                          "angles from two wearable IMUs and a Kinect or webcam, for upper-limb "
                          "rehabilitation.</p>")
                           .arg(QApplication::applicationVersion()));
  });
  setSignedIn({});
  updateTitle();
}

void MainWindow::showScreen(QWidget* screen) {
  if (m_current) {
    m_stack->removeWidget(m_current);
    m_current->deleteLater();
  }
  m_current = screen;
  m_stack->addWidget(screen);
  m_stack->setCurrentWidget(screen);
  connect(screen, &QWidget::windowTitleChanged, this, &MainWindow::updateTitle);
  updateTitle();
  QWidget* focus = screen->focusProxy();
  for (QWidget* w = screen->nextInFocusChain(); !focus && w && screen->isAncestorOf(w);
       w = w->nextInFocusChain())
    if ((w->focusPolicy() & Qt::TabFocus) && w->isEnabled()) focus = w;
  if (focus) focus->setFocus(Qt::OtherFocusReason);
}

QWidget* MainWindow::currentScreen() const {
  return m_current;
}

void MainWindow::setSignedIn(const QString& who) {
  m_who->setText(who.isEmpty() ? QString() : tr("Signed in as %1").arg(who));
  m_patients->setEnabled(!who.isEmpty());
  m_signOut->setEnabled(!who.isEmpty());
}

void MainWindow::showStatus(const QString& text, int ms) {
  statusBar()->showMessage(text, ms);
}

void MainWindow::updateTitle() {
  const QString screen = m_current ? m_current->windowTitle() : QString();
  setWindowTitle(screen.isEmpty() ? tr("ArmTrack") : tr("%1 - ArmTrack").arg(screen));
}

void MainWindow::closeEvent(QCloseEvent* event) {
  // A screen with unsaved work (a recording, typed notes) may refuse to be closed.
  if (m_current && !m_current->close()) {
    event->ignore();
    return;
  }
  event->accept();
}

}  // namespace armtrack::gui
