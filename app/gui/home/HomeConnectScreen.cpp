#include "app/gui/home/HomeConnectScreen.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include "app/gui/home/HomeStyle.h"
#include "ui/Retranslate.h"

namespace armtrack::gui::home {

HomeConnectScreen::HomeConnectScreen(const QString& server, QWidget* parent)
    : HomeScreen(parent),
      m_title(heading({}, this)),
      m_intro(bodyText({}, this)),
      m_serverLabel(bodyText({}, this)),
      m_server(new QLineEdit(server, this)),
      m_codeLabel(bodyText({}, this)),
      m_code(new QLineEdit(this)),
      m_result(bodyText({}, this)),
      m_connect(bigButton({}, this, true)),
      m_back(bigButton({}, this)) {
  auto* root = new QVBoxLayout(this);
  root->addWidget(m_title);
  root->addWidget(m_intro);
  for (QLineEdit* field : {m_server, m_code}) setHomeFont(field, 1.0, false);
  m_serverLabel->setBuddy(m_server);
  m_codeLabel->setBuddy(m_code);
  m_code->setMaxLength(40);
  m_server->setMaxLength(300);
  root->addWidget(m_serverLabel);
  root->addWidget(m_server);
  root->addWidget(m_codeLabel);
  root->addWidget(m_code);
  root->addWidget(m_result);
  m_result->hide();
  root->addStretch(1);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_connect, 2);
  buttons->addWidget(m_back, 1);
  root->addLayout(buttons);
  setTabOrder(m_server, m_code);
  setTabOrder(m_code, m_connect);
  setTabOrder(m_connect, m_back);
  connect(m_connect, &QPushButton::clicked, this, &HomeConnectScreen::submit);
  connect(m_code, &QLineEdit::returnPressed, this, &HomeConnectScreen::submit);
  connect(m_server, &QLineEdit::returnPressed, m_code, qOverload<>(&QWidget::setFocus));
  connect(m_back, &QPushButton::clicked, this, &HomeConnectScreen::backRequested);
  retranslate();
}

void HomeConnectScreen::retranslate() {
  setAccessibleName(tr("Connect to the clinic"));
  m_title->setText(tr("Connect to the clinic"));
  m_intro->setText(
      tr("Your therapist gives you the clinic's address and a code. Once connected, your "
         "sessions are sent to your therapist and your exercises come from the clinic. You can "
         "always exercise without a connection: sessions are kept and sent later."));
  m_serverLabel->setText(tr("Clinic's &address (for example sync.clinic.example:8443)"));
  m_codeLabel->setText(tr("&Code from your therapist"));
  m_server->setAccessibleName(tr("Clinic's address"));
  m_code->setAccessibleName(tr("Code from your therapist"));
  m_code->setPlaceholderText(QStringLiteral("7KQ2-M9XD-4TRA"));
  ui::setButtonText(m_connect, tr("&Connect"));
  ui::setButtonText(m_back, tr("&Back"));
  for (QPushButton* b : {m_connect, m_back}) b->setAccessibleName(QString(b->text()).remove(u'&'));
}

void HomeConnectScreen::submit() {
  if (!m_connect->isEnabled()) return;
  if (m_server->text().trimmed().isEmpty() || m_code->text().trimmed().isEmpty()) {
    showResult(false, tr("Type the clinic's address and the code, then press Connect."));
    (m_server->text().trimmed().isEmpty() ? m_server : m_code)->setFocus();
    return;
  }
  m_connect->setEnabled(false);
  m_result->show();
  setBanner(m_result, tr("Connecting\u2026"), Tone::Neutral);
  emit connectRequested(m_server->text().trimmed(), m_code->text().trimmed());
}

void HomeConnectScreen::showResult(bool ok, const QString& text) {
  m_connect->setEnabled(true);
  m_result->show();
  setBanner(m_result, text, ok ? Tone::Good : Tone::Problem);
  if (ok) m_back->setFocus();
  emit choicesChanged();
}

QString HomeConnectScreen::stateText(const sync::SyncStatus& s, const QDateTime& now) {
  using sync::SyncProblem;
  QStringList parts;
  if (!s.enrolled || s.problem == SyncProblem::NotEnrolled)
    parts << tr("Not connected to a clinic: sessions are kept on this computer");
  else if (s.busy)
    parts << tr("Sending to the clinic\u2026");
  else if (s.problem == SyncProblem::CertificateChanged)
    parts << tr(
        "The clinic's server is not the one connected before: nothing was sent. Sessions "
        "are kept; call your therapist.");
  else if (s.problem == SyncProblem::Refused)
    parts << tr(
        "The clinic no longer accepts this computer: sessions are kept. Call your "
        "therapist.");
  else if (s.problem != SyncProblem::None)
    parts << tr("Not connected: sessions are kept and sent later");
  if (s.waiting > 0)
    parts << tr("%n session(s) waiting to be sent", nullptr, s.waiting);
  else if (s.enrolled && s.problem == SyncProblem::None && !s.busy)
    parts << tr("Everything is sent");
  if (s.lastSent.isValid()) {
    const QDateTime at = s.lastSent.toLocalTime();
    parts << (at.date() == now.date()
                  ? tr("Sent today %1").arg(at.toString(QStringLiteral("HH:mm")))
                  : tr("Last sent %1").arg(QLocale().toString(at, QLocale::ShortFormat)));
  }
  return parts.join(QStringLiteral(" \u00b7 "));
}

QString HomeConnectScreen::enrolText(bool ok, sync::SyncProblem problem, const QString& detail) {
  using sync::SyncProblem;
  if (ok) return tr("Connected to the clinic. Your sessions will be sent there.");
  switch (problem) {
    case SyncProblem::Offline:
      return tr(
          "The clinic's server cannot be reached: check the address and the internet "
          "connection, then try again.");
    case SyncProblem::Refused:
      return tr("The code is wrong, used or expired: ask your therapist for a new one.");
    case SyncProblem::LocalError:
      return tr("This computer cannot keep the connection (%1): call your therapist.").arg(detail);
    default:
      return tr("The clinic's server did not accept it (%1): try again, or call your therapist.")
          .arg(detail);
  }
}

QString HomeConnectScreen::resultText() const {
  return m_result->isHidden() ? QString() : m_result->text();
}

QList<QAbstractButton*> HomeConnectScreen::choices() const {
  return {m_connect, m_back};
}

QAbstractButton* HomeConnectScreen::defaultChoice() const {
  return m_connect;
}

}  // namespace armtrack::gui::home
