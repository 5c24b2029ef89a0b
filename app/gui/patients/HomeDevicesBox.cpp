#include "app/gui/patients/HomeDevicesBox.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

#include "app/gui/common/Forms.h"
#include "app/gui/common/SessionTableModel.h"
#include "app/gui/patients/DeviceTableModel.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/services/RecordsService.h"
#include "ui/Retranslate.h"

namespace armtrack::gui {

namespace {

constexpr qint64 kHour = 3600;
constexpr qint64 kDay = 24 * kHour;
constexpr qint64 kDefaultValidity = 7 * kDay;

struct HomeAccounts {
  std::vector<storage::User> accounts;
};

}  // namespace

HomeDevicesBox::HomeDevicesBox(RecordsService& records, const AppSettings& settings,
                               const QString& patientCode, QWidget* parent)
    : QGroupBox(parent),
      m_records(records),
      m_settings(settings),
      m_patient(patientCode),
      m_accountLabel(new QLabel(this)),
      m_account(new QComboBox(this)),
      m_validityLabel(new QLabel(this)),
      m_validity(new QComboBox(this)),
      m_noAccount(new QLabel(this)),
      m_make(new QPushButton(this)),
      m_codeArea(new QWidget(this)),
      m_codeText(new QLabel(m_codeArea)),
      m_codeInfo(new QLabel(m_codeArea)),
      m_copy(new QPushButton(m_codeArea)),
      m_devicesLabel(new QLabel(this)),
      m_table(new QTableView(this)),
      m_devices(new DeviceTableModel(this)),
      m_refresh(new QPushButton(this)),
      m_revoke(new QPushButton(this)),
      m_message(new MessageLine(this)) {
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  form->setRowWrapPolicy(QFormLayout::WrapLongRows);
  m_accountLabel->setBuddy(m_account);
  m_validityLabel->setBuddy(m_validity);
  form->addRow(m_accountLabel, m_account);
  form->addRow(m_validityLabel, m_validity);
  layout->addLayout(form);
  m_noAccount->setWordWrap(true);
  m_noAccount->hide();
  layout->addWidget(m_noAccount);
  layout->addWidget(m_make);

  // The code as the patient types it: large, fixed-width so that 0 and O, 1 and I stand apart.
  auto* codeLayout = new QVBoxLayout(m_codeArea);
  codeLayout->setContentsMargins(0, 0, 0, 0);
  QFont big = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  // Half as large again as the text: still within the side pane's 300 pixels at 1024x600.
  big.setPointSizeF(font().pointSizeF() * 1.5);
  big.setBold(true);
  m_codeText->setFont(big);
  m_codeText->setAlignment(Qt::AlignCenter);
  m_codeText->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  m_codeText->setFocusPolicy(Qt::StrongFocus);
  m_codeText->setFrameShape(QFrame::StyledPanel);
  codeLayout->addWidget(m_codeText);
  m_codeInfo->setWordWrap(true);
  m_codeInfo->setTextFormat(Qt::PlainText);  // names an account
  m_codeInfo->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  codeLayout->addWidget(m_codeInfo);
  codeLayout->addWidget(m_copy);
  m_codeArea->hide();
  layout->addWidget(m_codeArea);

  layout->addWidget(m_devicesLabel);
  m_devicesLabel->setBuddy(m_table);
  m_table->setModel(m_devices);
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setSelectionMode(QAbstractItemView::SingleSelection);
  m_table->setTabKeyNavigation(false);  // Tab leaves the table; arrows move inside
  m_table->verticalHeader()->hide();
  m_table->horizontalHeader()->setStretchLastSection(true);
  m_table->setMinimumHeight(110);
  layout->addWidget(m_table);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_refresh);
  buttons->addStretch();
  buttons->addWidget(m_revoke);
  layout->addLayout(buttons);
  layout->addWidget(m_message);
  // A device names itself when it enrols: its label is shown as typed, never as markup.
  for (auto* l : m_message->findChildren<QLabel*>()) l->setTextFormat(Qt::PlainText);

  connect(m_account, &QComboBox::currentIndexChanged, this, [this] {
    m_code.clear();  // a code shown belongs to the account it was made for
    showCode();
    loadDevices();
  });
  connect(m_make, &QPushButton::clicked, this, &HomeDevicesBox::makeCode);
  connect(m_copy, &QPushButton::clicked, this, [this] {
    if (m_code.isEmpty()) return;
    QApplication::clipboard()->setText(m_code);
    m_message->showMessage([] { return tr("The code is copied."); }, MessageLine::Kind::Notice);
  });
  connect(m_refresh, &QPushButton::clicked, this, &HomeDevicesBox::reload);
  connect(m_revoke, &QPushButton::clicked, this, &HomeDevicesBox::revokeSelected);
  connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this,
          &HomeDevicesBox::updateButtons);
  connect(m_devices, &QAbstractItemModel::modelReset, this, &HomeDevicesBox::updateButtons);
  retranslateUi();
  updateButtons();
}

void HomeDevicesBox::retranslateUi() {
  setTitle(tr("Home devices"));
  m_accountLabel->setText(tr("Home &account:"));
  m_account->setAccessibleName(tr("Home account"));
  m_validityLabel->setText(tr("Code va&lid for:"));
  m_validity->setAccessibleName(tr("Code valid for"));
  const qint64 chosen = m_validity->count() > 0 ? validity() : kDefaultValidity;
  const QSignalBlocker block(m_validity);
  m_validity->clear();
  m_validity->addItem(tr("1 hour"), kHour);
  m_validity->addItem(tr("1 day"), kDay);
  m_validity->addItem(tr("7 days"), 7 * kDay);
  m_validity->addItem(tr("30 days"), 30 * kDay);
  m_validity->setCurrentIndex(std::max(0, m_validity->findData(chosen)));
  m_noAccount->setText(
      tr("This patient has no home account yet. An administrator adds one (Administration, "
         "Accounts); then make an enrolment code here."));
  m_make->setText(tr("Make enrolment &code"));
  m_make->setToolTip(
      tr("A one-time code the patient types on their home computer to connect it to the clinic"));
  m_codeText->setAccessibleName(tr("Enrolment code"));
  m_copy->setText(tr("Cop&y code"));
  m_devicesLabel->setText(tr("Enrolled &devices:"));
  m_table->setAccessibleName(tr("Enrolled devices"));
  m_refresh->setText(tr("Re&fresh"));
  m_refresh->setToolTip(tr("Read the devices again (a patient may have enrolled meanwhile)"));
  m_revoke->setText(tr("Re&voke device..."));
  showCode();
}

void HomeDevicesBox::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) {
    retranslateUi();
    ui::refreshModelTexts(m_devices);
  }
  QGroupBox::changeEvent(event);
}

QString HomeDevicesBox::account() const {
  return m_account->currentData().toString();
}

qint64 HomeDevicesBox::validity() const {
  return m_validity->currentData().toLongLong();
}

qint64 HomeDevicesBox::selectedDevice() const {
  const QModelIndexList rows = m_table->selectionModel()->selectedRows();
  return rows.isEmpty() ? 0 : rows.first().data(DeviceTableModel::IdRole).toLongLong();
}

void HomeDevicesBox::fail(const QString& message, bool denied) {
  const QString text =
      denied ? tr("Only therapists and administrators may make enrolment codes and see or revoke "
                  "home devices. Ask one of them.")
             : message;
  m_message->showMessage(text);
  emit failed(text);
}

void HomeDevicesBox::reload() {
  m_records.call(
      this,
      [code = m_patient](storage::ClinicalStore& s) {
        return HomeAccounts{s.listHomeAccounts(code)};
      },
      [this](const HomeAccounts& a) {
        m_accounts = a.accounts;
        const QString keep = account();
        {
          const QSignalBlocker block(m_account);
          m_account->clear();
          for (const storage::User& u : m_accounts)
            m_account->addItem(u.disabled ? tr("%1 (disabled)").arg(u.name) : u.name, u.name);
          const int i = m_account->findData(keep);
          m_account->setCurrentIndex(i >= 0 ? i : 0);
        }
        m_noAccount->setVisible(m_accounts.empty());
        updateButtons();
        if (account() != keep) {
          m_code.clear();
          showCode();
        }
        loadDevices();
      },
      [this](const RecordsFailure& f) {
        m_accounts.clear();
        m_account->clear();
        updateButtons();
        fail(f.message, f.kind == storage::StorageError::Kind::AccessDenied);
      });
}

void HomeDevicesBox::loadDevices() {
  const QString name = account();
  if (name.isEmpty()) {
    m_devices->setDevices({});
    emit loaded();
    return;
  }
  m_records.call(
      this, [name](storage::ClinicalStore& s) { return s.listDevices(name); },
      [this, name](const std::vector<storage::DeviceInfo>& devices) {
        if (name != account()) return;  // another account was chosen meanwhile
        const qint64 keep = selectedDevice();
        m_devices->setDevices(devices);
        m_table->resizeColumnsToContents();
        for (int r = 0; r < m_devices->rowCount(); ++r)
          if (m_devices->deviceAt(r)->id == keep) m_table->selectRow(r);
        emit loaded();
      },
      [this](const RecordsFailure& f) {
        fail(f.message, f.kind == storage::StorageError::Kind::AccessDenied);
      });
}

void HomeDevicesBox::makeCode() {
  const QString name = account();
  if (name.isEmpty() || m_busy) return;
  m_busy = true;
  updateButtons();
  m_message->showMessage([] { return tr("Making the code..."); }, MessageLine::Kind::Notice);
  m_records.call(
      this,
      [name, seconds = validity()](storage::ClinicalStore& s) {
        return s.createEnrolmentCode(name, seconds);
      },
      [this, name](const storage::EnrolmentCode& c) {
        m_busy = false;
        if (name == account()) {
          m_code = c.code;
          m_expiresAt = c.expiresAt;
        }
        m_message->clear();
        showCode();
        updateButtons();
        m_codeText->setFocus();
        emit codeMade(c.code);
      },
      [this](const RecordsFailure& f) {
        m_busy = false;
        updateButtons();
        fail(f.message, f.kind == storage::StorageError::Kind::AccessDenied);
      });
}

void HomeDevicesBox::showCode() {
  m_codeArea->setVisible(!m_code.isEmpty());
  m_codeText->setText(m_code);
  if (m_code.isEmpty()) return;
  const QString until = SessionTableModel::localTime(m_expiresAt);
  const QString server = m_settings.syncServerAddress;
  m_codeInfo->setText(
      server.isEmpty()
          ? tr("For %1, once, until %2. The patient types it when their home computer asks to "
               "connect to the clinic.")
                .arg(account(), until)
          : tr("For %1, once, until %2. The patient types it, with the server address %3, when "
               "their home computer asks to connect to the clinic.")
                .arg(account(), until, server));
}

void HomeDevicesBox::updateButtons() {
  const bool any = !account().isEmpty();
  m_account->setEnabled(any);
  m_validity->setEnabled(any);
  m_make->setEnabled(any && !m_busy);
  m_refresh->setEnabled(true);
  const int row = m_table->selectionModel()->hasSelection()
                      ? m_table->selectionModel()->selectedRows().value(0).row()
                      : -1;
  const storage::DeviceInfo* d = m_devices->deviceAt(row);
  m_revoke->setEnabled(d && d->revokedAt.isEmpty());
}

void HomeDevicesBox::revokeSelected() {
  const int row = m_table->selectionModel()->selectedRows().value(0).row();
  const storage::DeviceInfo* d = m_devices->deviceAt(row);
  if (!d || !d->revokedAt.isEmpty()) return;
  const qint64 id = d->id;
  const QString label = m_devices->data(m_devices->index(row, DeviceTableModel::Label)).toString();
  auto* box = new QMessageBox(
      QMessageBox::Warning, tr("Revoke device"),
      tr("Revoke the device \"%1\" of %2? It can no longer send sessions or fetch the programme; "
         "to use it again the patient enrols it with a new code. Sessions it sent stay.")
          .arg(label, account()),
      QMessageBox::Cancel, this);
  box->setTextFormat(Qt::PlainText);
  box->addButton(tr("Re&voke"), QMessageBox::DestructiveRole);
  box->setDefaultButton(QMessageBox::Cancel);  // Enter alone revokes nothing
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::buttonClicked, this, [this, box, id, label](QAbstractButton* b) {
    if (box->buttonRole(b) != QMessageBox::DestructiveRole) return;
    m_records.call(
        this, [id](storage::ClinicalStore& s) { s.revokeDevice(id); },
        [this, label] {
          m_message->showMessage([label] { return tr("The device \"%1\" is revoked.").arg(label); },
                                 MessageLine::Kind::Notice);
          loadDevices();
        },
        [this](const RecordsFailure& f) {
          fail(f.message, f.kind == storage::StorageError::Kind::AccessDenied);
        });
  });
  box->open();
}

}  // namespace armtrack::gui
