#include "app/gui/SignInScreen.h"

#include <QFormLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

#include "app/gui/Forms.h"

namespace armtrack::gui {

SignInScreen::SignInScreen(const QString& database, const QString& lastUser, QWidget* parent)
    : QWidget(parent),
      m_name(new QLineEdit(lastUser, this)),
      m_password(new QLineEdit(this)),
      m_message(new MessageLine(this)),
      m_signIn(new QPushButton(tr("&Sign in"), this)) {
  setWindowTitle(tr("Sign in"));
  QWidget* column = nullptr;
  auto* layout = centredColumn(this, 480, &column);
  layout->addWidget(heading(tr("Sign in to ArmTrack"), column));
  auto* where = new QLabel(tr("Records: %1").arg(database), column);
  where->setWordWrap(true);
  where->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(where);
  auto* form = new QFormLayout;
  m_name->setAccessibleName(tr("Account name"));
  m_password->setEchoMode(QLineEdit::Password);
  m_password->setAccessibleName(tr("Password"));
  form->addRow(tr("&Name:"), m_name);
  form->addRow(tr("&Password:"), m_password);
  layout->addLayout(form);
  layout->addWidget(m_message);
  m_signIn->setDefault(true);
  auto* buttons = new QHBoxLayout;
  buttons->addStretch();
  buttons->addWidget(m_signIn);
  layout->addLayout(buttons);
  layout->addStretch();

  connect(m_signIn, &QPushButton::clicked, this, &SignInScreen::submit);
  connect(m_name, &QLineEdit::returnPressed, this, &SignInScreen::submit);
  connect(m_password, &QLineEdit::returnPressed, this, &SignInScreen::submit);
  m_wait.setInterval(1000);
  connect(&m_wait, &QTimer::timeout, this, &SignInScreen::tick);
  setTabOrder(m_name, m_password);
  setTabOrder(m_password, m_signIn);
  setFocusProxy(lastUser.isEmpty() ? m_name : m_password);
}

QString SignInScreen::userName() const {
  return m_name->text().trimmed();
}

void SignInScreen::submit() {
  if (!m_signIn->isEnabled()) return;
  if (userName().isEmpty()) {
    m_message->showMessage(tr("Type your account name."));
    m_name->setFocus();
    return;
  }
  if (m_password->text().isEmpty()) {
    m_message->showMessage(tr("Type your password."));
    m_password->setFocus();
    return;
  }
  emit signInRequested(userName(), m_password->text());
}

void SignInScreen::setBusy(bool busy) {
  m_name->setEnabled(!busy);
  m_password->setEnabled(!busy);
  m_signIn->setEnabled(!busy && m_waitLeft == 0);
  if (busy) m_message->showMessage(tr("Signing in..."), MessageLine::Kind::Notice);
}

void SignInScreen::showError(const QString& message) {
  // The store's words ("wrong user name or password", "try again in N s"), with what to do.
  static const QRegularExpression waitRe(QStringLiteral("try again in (\\d+) s"));
  const auto wait = waitRe.match(message);
  m_waitLeft = wait.hasMatch() ? wait.captured(1).toInt() : 0;
  setBusy(false);
  QString text = message;
  if (m_waitLeft == 0)
    text += u'\n' + tr("Check the name and the password (is Caps Lock on?) and try again. If "
                       "you have forgotten it, an administrator can set a new one.");
  m_message->showMessage(text);
  m_password->setFocus();
  m_password->selectAll();
  if (m_waitLeft > 0) {
    m_signIn->setEnabled(false);
    m_signIn->setText(tr("Wait %n s", nullptr, m_waitLeft));
    m_wait.start();
  }
}

void SignInScreen::tick() {
  if (--m_waitLeft > 0) {
    m_signIn->setText(tr("Wait %n s", nullptr, m_waitLeft));
    return;
  }
  m_wait.stop();
  m_waitLeft = 0;
  m_signIn->setText(tr("&Sign in"));
  m_signIn->setEnabled(m_name->isEnabled());
}

}  // namespace armtrack::gui
