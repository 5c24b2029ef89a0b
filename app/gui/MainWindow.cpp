#include "app/gui/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

#include "app/gui/HelpWindow.h"
#include "app/gui/common/Forms.h"
#include "ui/ScreenStack.h"

namespace armtrack::gui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_stack(new ui::ScreenStack(this)), m_who(new QLabel(this)) {
  setCentralWidget(m_stack);
  setMinimumSize(640, 480);  // the screens scroll and split down to a 1024x600 netbook
  resize(1200, 760);         // fits a 1280x800 screen; a window manager may maximise it
  statusBar()->addPermanentWidget(m_who);

  m_file = menuBar()->addMenu(QString());
  m_patients = m_file->addAction(QString(), this, &MainWindow::patientsRequested);
  m_admin = m_file->addAction(QString(), this, &MainWindow::adminRequested);
  m_settings = m_file->addAction(QString(), this, &MainWindow::settingsRequested);
  m_signOut = m_file->addAction(QString(), this, &MainWindow::signOutRequested);
  m_file->addSeparator();
  m_quit = m_file->addAction(QString(), this, &QWidget::close);
  m_quit->setShortcut(QKeySequence::Quit);

  m_help = menuBar()->addMenu(QString());
  m_guide = m_help->addAction(QString(), this, &MainWindow::showUserGuide);
  m_guide->setShortcut(QKeySequence::HelpContents);
  m_about = m_help->addAction(QString(), this, [this] {
    QMessageBox::about(this, tr("About ArmTrack"),
                       tr("<p><b>ArmTrack %1</b></p><p>Measures the shoulder's and elbow's joint "
                          "angles from two wearable IMUs and a Kinect or webcam, for upper-limb "
                          "rehabilitation.</p>")
                           .arg(QApplication::applicationVersion()));
  });
  retranslateUi();
  setSignedIn({});
}

void MainWindow::retranslateUi() {
  m_who->setAccessibleName(tr("Signed-in account"));
  const QString who = m_whoText ? m_whoText() : QString();
  m_who->setText(who.isEmpty() ? QString() : tr("Signed in as %1").arg(who));
  // The status message too, while it is still shown.
  if (m_statusText && !m_statusShown.isEmpty() && statusBar()->currentMessage() == m_statusShown) {
    m_statusShown = m_statusText();
    statusBar()->showMessage(m_statusShown);
  }
  m_file->setTitle(tr("&ArmTrack"));
  m_patients->setText(tr("&Patients"));
  m_patients->setShortcut(QKeySequence(tr("Ctrl+Shift+P")));
  m_admin->setText(tr("A&dministration..."));
  m_admin->setShortcut(QKeySequence(tr("Ctrl+Shift+D")));
  m_settings->setText(tr("&Settings..."));
  m_settings->setShortcut(QKeySequence::Preferences);
  if (m_settings->shortcut().isEmpty()) m_settings->setShortcut(QKeySequence(tr("Ctrl+,")));
  m_signOut->setText(tr("Sign &out"));
  m_quit->setText(tr("&Quit"));
  m_help->setTitle(tr("&Help"));
  m_guide->setText(tr("&User guide"));
  m_about->setText(tr("&About ArmTrack"));
  updateTitle();
}

void MainWindow::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QMainWindow::changeEvent(event);
}

void MainWindow::showScreen(QWidget* screen) {
  m_stack->showScreen(screen);
  connect(screen, &QWidget::windowTitleChanged, this, &MainWindow::updateTitle);
  updateTitle();
  QWidget* focus = screen->focusProxy();
  for (QWidget* w = screen->nextInFocusChain(); !focus && w && screen->isAncestorOf(w);
       w = w->nextInFocusChain())
    if ((w->focusPolicy() & Qt::TabFocus) && w->isEnabled()) focus = w;
  if (focus) focus->setFocus(Qt::OtherFocusReason);
}

void MainWindow::showUserGuide() {
  if (!m_helpWindow) {
    m_helpWindow = new HelpWindow(this);
    m_helpWindow->setAttribute(Qt::WA_DeleteOnClose);
  }
  const ScreenHelp help = screenHelp(m_stack->screen());
  m_helpWindow->showFor(help.hint, help.headings);
  m_helpWindow->show();
  m_helpWindow->raise();
  m_helpWindow->activateWindow();
  emit userGuideRequested();
}

HelpWindow* MainWindow::helpWindow() const {
  return m_helpWindow.data();
}

QWidget* MainWindow::currentScreen() const {
  return m_stack->screen();
}

void MainWindow::setSignedIn(TextFn who) {
  m_whoText = std::move(who);
  const QString name = m_whoText ? m_whoText() : QString();
  m_who->setText(name.isEmpty() ? QString() : tr("Signed in as %1").arg(name));
  m_patients->setEnabled(!name.isEmpty());
  m_signOut->setEnabled(!name.isEmpty());
  if (name.isEmpty()) setAdministrator(false);
}

void MainWindow::setAdministrator(bool administrator) {
  m_admin->setVisible(administrator);
  m_admin->setEnabled(administrator);
}

void MainWindow::showStatus(TextFn text, int ms) {
  m_statusText = std::move(text);
  m_statusShown = m_statusText ? m_statusText() : QString();
  statusBar()->showMessage(m_statusShown, ms);
}

void MainWindow::showStatus(const QString& text, int ms) {
  showStatus([text] { return text; }, ms);
}

void MainWindow::updateTitle() {
  const QWidget* current = m_stack->screen();
  const QString screen = current ? current->windowTitle() : QString();
  setWindowTitle(screen.isEmpty() ? tr("ArmTrack") : tr("%1 - ArmTrack").arg(screen));
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (m_mayClose && !m_mayClose()) {
    event->ignore();
    return;
  }
  // A screen with unsaved work (a recording, typed notes) may refuse to be closed.
  if (QWidget* current = m_stack->screen(); current && !current->close()) {
    event->ignore();
    return;
  }
  event->accept();
}

}  // namespace armtrack::gui
