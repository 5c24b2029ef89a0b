#include "app/gui/signin/SignInScreen.h"

#include <QFormLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

#include "app/gui/common/Forms.h"

namespace armtrack::gui {

SignInScreen::SignInScreen(const QString& database, const QString& lastUser, QWidget* parent)
    : QWidget(parent),
      m_database(database),
      m_name(new QLineEdit(lastUser, this)),
      m_password(new QLineEdit(this)),
      m_message(new MessageLine(this)),
      m_signIn(new QPushButton(this)) {
  QWidget* column = nullptr;
  auto* layout = centredColumn(this, 480, &column);
  m_heading = heading(QString(), column);
  layout->addWidget(m_heading);
  m_where = new QLabel(column);
  m_where->setWordWrap(true);
  m_where->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_where);
  auto* form = new QFormLayout;
  m_password->setEchoMode(QLineEdit::Password);
  m_nameLabel = new QLabel(column);
  m_nameLabel->setBuddy(m_name);
  m_passwordLabel = new QLabel(column);
  m_passwordLabel->setBuddy(m_password);
  form->addRow(m_nameLabel, m_name);
  form->addRow(m_passwordLabel, m_password);
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
  retranslateUi();
}

void SignInScreen::retranslateUi() {
  setWindowTitle(tr("Sign in"));
  setHeading(m_heading, tr("Sign in to ArmTrack"));
  m_where->setText(tr("Records: %1").arg(m_database));
  m_name->setAccessibleName(tr("Account name"));
  m_password->setAccessibleName(tr("Password"));
  m_nameLabel->setText(tr("&Name:"));
  m_passwordLabel->setText(tr("&Password:"));
  updateButtonText();
}

void SignInScreen::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

void SignInScreen::updateButtonText() {
  m_signIn->setText(m_waitLeft > 0 ? tr("Wait %n s", nullptr, m_waitLeft) : tr("&Sign in"));
}

QString SignInScreen::userName() const {
  return m_name->text().trimmed();
}

void SignInScreen::submit() {
  if (!m_signIn->isEnabled()) return;
  if (userName().isEmpty()) {
    m_message->showMessage([] { return tr("Type your account name."); });
    m_name->setFocus();
    return;
  }
  if (m_password->text().isEmpty()) {
    m_message->showMessage([] { return tr("Type your password."); });
    m_password->setFocus();
    return;
  }
  emit signInRequested(userName(), m_password->text());
}

void SignInScreen::setBusy(bool busy) {
  m_name->setEnabled(!busy);
  m_password->setEnabled(!busy);
  m_signIn->setEnabled(!busy && m_waitLeft == 0);
  if (busy) m_message->showMessage([] { return tr("Signing in..."); }, MessageLine::Kind::Notice);
}

QString SignInScreen::refusalText(const QString& message) const {
  // core/storage words its refusals in English for the command line and the audit log.
  static const QRegularExpression waitRe(QStringLiteral("try again in (\\d+) s"));
  if (waitRe.match(message).hasMatch())  // counted down each second
    return m_waitLeft > 0
               ? tr("Too many wrong passwords for this account: wait %n s, then try again.",
                    nullptr, m_waitLeft)
               : tr("Too many wrong passwords for this account. You may try again now.");
  if (message.startsWith(QLatin1String("wrong user name or password"), Qt::CaseInsensitive))
    return tr("Wrong user name or password.") + u'\n' +
           tr("Check the name and the password (is Caps Lock on?) and try again. If you have "
              "forgotten it, an administrator can set a new one.");
  return message;
}

void SignInScreen::showError(const QString& message) {
  static const QRegularExpression waitRe(QStringLiteral("try again in (\\d+) s"));
  const auto wait = waitRe.match(message);
  m_waitLeft = wait.hasMatch() ? wait.captured(1).toInt() : 0;
  setBusy(false);
  m_message->showMessage([this, message] { return refusalText(message); });
  m_password->setFocus();
  m_password->selectAll();
  m_refusal = message;
  if (m_waitLeft > 0) {
    m_signIn->setEnabled(false);
    updateButtonText();
    m_wait.start();
  }
}

void SignInScreen::tick() {
  m_waitLeft = std::max(0, m_waitLeft - 1);
  // The message counts down with the button.
  m_message->showMessage([this, message = m_refusal] { return refusalText(message); },
                         m_waitLeft > 0 ? MessageLine::Kind::Error : MessageLine::Kind::Notice);
  updateButtonText();
  if (m_waitLeft > 0) return;
  m_wait.stop();
  m_signIn->setEnabled(m_name->isEnabled());
}

}  // namespace armtrack::gui
