#include "app/gui/signin/FirstRunScreen.h"

#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "app/gui/common/Forms.h"
#include "core/storage/TextRules.h"

namespace armtrack::gui {

namespace {
// The records refuse shorter ones (core/storage/TextRules.h), counted in code points.
constexpr int kMinPasswordLength = storage::kMinPasswordLength;
}  // namespace

FirstRunScreen::FirstRunScreen(const QString& defaultFolder, const QString& fixedDatabase,
                               QWidget* parent)
    : QWidget(parent),
      m_fixed(!fixedDatabase.isEmpty()),
      m_fixedDatabase(fixedDatabase),
      m_folder(new QLineEdit(defaultFolder, this)),
      m_browse(new QPushButton(this)),
      m_databaseNote(new QLabel(this)),
      m_admin(new QLineEdit(this)),
      m_password(new QLineEdit(this)),
      m_repeat(new QLineEdit(this)),
      m_message(new MessageLine(this)),
      m_create(new QPushButton(this)) {
  QWidget* column = nullptr;
  auto* layout = centredColumn(this, 600, &column);
  m_heading = heading(QString(), column);
  layout->addWidget(m_heading);
  m_intro = new QLabel(column);
  m_intro->setWordWrap(true);
  layout->addWidget(m_intro);

  m_where = new QGroupBox(column);
  auto* whereLayout = new QVBoxLayout(m_where);
  if (m_fixed) {
    m_folder->hide();
    m_browse->hide();
  } else {
    auto* row = new QHBoxLayout;
    row->addWidget(m_folder, 1);
    row->addWidget(m_browse);
    whereLayout->addLayout(row);
    connect(m_browse, &QPushButton::clicked, this, &FirstRunScreen::chooseFolder);
    connect(m_folder, &QLineEdit::textChanged, this, &FirstRunScreen::updateDatabaseNote);
  }
  m_databaseNote->setWordWrap(true);
  whereLayout->addWidget(m_databaseNote);
  layout->addWidget(m_where);

  m_account = new QGroupBox(column);
  auto* form = new QFormLayout(m_account);
  m_password->setEchoMode(QLineEdit::Password);
  m_repeat->setEchoMode(QLineEdit::Password);
  m_adminLabel = new QLabel(m_account);
  m_adminLabel->setBuddy(m_admin);
  m_passwordLabel = new QLabel(m_account);
  m_passwordLabel->setBuddy(m_password);
  m_repeatLabel = new QLabel(m_account);
  m_repeatLabel->setBuddy(m_repeat);
  form->addRow(m_adminLabel, m_admin);
  form->addRow(m_passwordLabel, m_password);
  form->addRow(m_repeatLabel, m_repeat);
  layout->addWidget(m_account);
  layout->addWidget(m_message);

  m_create->setDefault(true);
  m_create->setAutoDefault(true);
  auto* buttons = new QHBoxLayout;
  buttons->addStretch();
  buttons->addWidget(m_create);
  layout->addLayout(buttons);
  layout->addStretch();

  connect(m_create, &QPushButton::clicked, this, &FirstRunScreen::submit);
  for (QLineEdit* e : {m_folder, m_admin, m_password, m_repeat})
    connect(e, &QLineEdit::returnPressed, this, &FirstRunScreen::submit);
  setTabOrder(m_folder, m_browse);
  setTabOrder(m_browse, m_admin);
  setTabOrder(m_admin, m_password);
  setTabOrder(m_password, m_repeat);
  setTabOrder(m_repeat, m_create);
  setFocusProxy(m_fixed ? m_admin : m_folder);
  retranslateUi();
}

void FirstRunScreen::retranslateUi() {
  setWindowTitle(tr("First start"));
  setHeading(m_heading, tr("Welcome to ArmTrack"));
  m_intro->setText(
      tr("ArmTrack keeps its patients, sessions and recordings in one database. Choose where it "
         "lives and create the administrator account; the administrator then adds the "
         "therapists' accounts, the protocols and the home programmes under ArmTrack > "
         "Administration."));
  m_where->setTitle(tr("Where the data lives"));
  m_browse->setText(tr("&Browse..."));
  m_folder->setAccessibleName(tr("Data folder"));
  m_browse->setAccessibleName(tr("Choose the data folder"));
  m_account->setTitle(tr("Administrator account"));
  m_admin->setAccessibleName(tr("Administrator name"));
  m_password->setAccessibleName(tr("Password"));
  m_password->setPlaceholderText(tr("at least %n characters", nullptr, kMinPasswordLength));
  m_repeat->setAccessibleName(tr("Password again"));
  m_adminLabel->setText(tr("&Name:"));
  m_passwordLabel->setText(tr("&Password:"));
  m_repeatLabel->setText(tr("Password &again:"));
  m_create->setText(tr("&Create and sign in"));
  updateDatabaseNote();
}

void FirstRunScreen::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

QString FirstRunScreen::folder() const {
  return m_folder->text().trimmed();
}

void FirstRunScreen::updateDatabaseNote() {
  if (m_fixed) {
    m_databaseNote->setText(tr("The database given on the command line: %1").arg(m_fixedDatabase));
    return;
  }
  const QString f = folder();
  m_databaseNote->setText(f.isEmpty() ? tr("Choose a folder.")
                                      : tr("The records will be kept in %1.")
                                            .arg(QDir(f).filePath(QStringLiteral("armtrack.db"))));
}

void FirstRunScreen::chooseFolder() {
  const QString chosen =
      QFileDialog::getExistingDirectory(this, tr("Where ArmTrack keeps its data"), folder());
  if (!chosen.isEmpty()) m_folder->setText(chosen);
}

void FirstRunScreen::submit() {
  if (!m_create->isEnabled()) return;
  const auto refuse = [this](TextFn text, QLineEdit* field) {
    m_message->showMessage(std::move(text));
    field->setFocus();
    field->selectAll();
  };
  if (!m_fixed && folder().isEmpty())
    return refuse([] { return tr("Choose the folder where ArmTrack keeps its data."); }, m_folder);
  if (!m_fixed && QDir::isRelativePath(folder()))
    return refuse(
        [] { return tr("Give the data folder as a full path, e.g. %1.").arg(QDir::homePath()); },
        m_folder);
  const QString admin = m_admin->text().trimmed();
  if (admin.isEmpty()) return refuse([] { return tr("Give the administrator a name."); }, m_admin);
  if (storage::codePoints(m_password->text()) < kMinPasswordLength)
    return refuse(
        [] {
          return tr("The password needs at least %n characters.", nullptr, kMinPasswordLength);
        },
        m_password);
  if (m_password->text() != m_repeat->text())
    return refuse([] { return tr("The two passwords differ. Type the same password twice."); },
                  m_repeat);
  m_message->clear();
  emit createRequested(folder(), admin, m_password->text());
}

void FirstRunScreen::setBusy(bool busy) {
  for (QWidget* w :
       std::initializer_list<QWidget*>{m_folder, m_browse, m_admin, m_password, m_repeat, m_create})
    w->setEnabled(!busy);
  if (busy)
    m_message->showMessage([] { return tr("Creating the records..."); }, MessageLine::Kind::Notice);
}

void FirstRunScreen::showError(const QString& message) {
  setBusy(false);
  m_message->showMessage(message);
}

}  // namespace armtrack::gui
