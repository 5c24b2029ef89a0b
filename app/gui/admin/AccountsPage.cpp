// The accounts page of the administrator's screen (the CLI's `user add`, `user list`,
// `user disable`, `user enable`; the store's setPassword and removeUser).
#include <QPushButton>
#include <QTableWidget>

#include "app/gui/admin/AdminDialogs.h"
#include "app/gui/admin/AdminScreen.h"
#include "app/gui/services/RecordsService.h"

namespace armtrack::gui::admin {

namespace {
struct Accounts {
  std::vector<storage::User> users;
  std::vector<storage::Patient> patients;
};
}  // namespace

AccountsPage::AccountsPage(RecordsService& records, QWidget* parent)
    : AdminPage(records, parent),
      m_add(addButton()),
      m_password(addButton()),
      m_disable(addButton()),
      m_remove(addButton()) {
  connect(m_add, &QPushButton::clicked, this, &AccountsPage::addAccount);
  connect(m_password, &QPushButton::clicked, this, &AccountsPage::resetPassword);
  connect(m_disable, &QPushButton::clicked, this, &AccountsPage::toggleDisabled);
  connect(m_remove, &QPushButton::clicked, this, &AccountsPage::removeAccount);
  connect(m_table, &QTableWidget::itemSelectionChanged, this, &AccountsPage::updateDisableButton);
  retranslateUi();
  reload();
}

void AccountsPage::retranslateUi() {
  m_table->setAccessibleName(tr("Accounts"));
  m_add->setText(tr("&Add account..."));
  m_password->setText(tr("Reset &password..."));
  m_remove->setText(tr("Re&move account..."));
  updateDisableButton();
}

const storage::User* AccountsPage::selectedUser() const {
  const QString name = selectedKey();
  for (const storage::User& u : m_users)
    if (!name.isEmpty() && u.name == name) return &u;
  return nullptr;
}

void AccountsPage::updateDisableButton() {
  const storage::User* u = selectedUser();
  m_disable->setText(u && u->disabled ? tr("&Enable account") : tr("D&isable account..."));
}

void AccountsPage::reload() {
  m_records.call(
      this,
      [](storage::ClinicalStore& s) {
        return Accounts{s.listUsers(), s.listPatients()};
      },
      [this](const Accounts& a) {
        m_users = a.users;
        m_patients = a.patients;
        std::vector<QStringList> rows;
        for (const storage::User& u : m_users) {
          QString patient;
          for (const storage::Patient& p : m_patients)
            if (u.patientId && p.id == *u.patientId) patient = tr("%1 - %2").arg(p.code, p.name);
          rows.push_back(
              {u.name, roleText(u.role), patient, u.disabled ? tr("Disabled") : tr("Active")});
        }
        fill({tr("Name"), tr("Role"), tr("Patient (home accounts)"), tr("Status")}, rows, {});
        updateDisableButton();
        emit loaded();
      },
      [this](const RecordsFailure& f) { failed(f.message); });
}

void AccountsPage::addAccount() {
  auto* dialog = new AccountDialog(m_patients, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &FormDialog::submitted, this, [this, dialog] {
    const QString name = dialog->name(), patient = dialog->patientCode();
    const storage::Role role = dialog->role();
    const std::string password = dialog->password().toStdString();
    m_records.call(
        dialog,
        [name, role, password, patient](storage::ClinicalStore& s) {
          s.addUser(name, role, password, patient);
        },
        [this, dialog, name, role] {
          dialog->accept();
          done(tr("Account %1 (%2) added: they can sign in now.").arg(name, roleText(role)));
          reload();
        },
        [dialog](const RecordsFailure& f) { dialog->showError(f.message); });
  });
  dialog->open();
}

void AccountsPage::resetPassword() {
  const QString name = selectedKey();
  if (name.isEmpty()) return failed(tr("Choose the account whose password to reset."));
  auto* dialog = new PasswordDialog(name, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &FormDialog::submitted, this, [this, dialog, name] {
    const std::string password = dialog->password().toStdString();
    m_records.call(
        dialog, [name, password](storage::ClinicalStore& s) { s.setPassword(name, password); },
        [this, dialog, name] {
          dialog->accept();
          done(tr("The password of %1 is reset. Tell them the new one in person.").arg(name));
        },
        [dialog](const RecordsFailure& f) { dialog->showError(f.message); });
  });
  dialog->open();
}

void AccountsPage::toggleDisabled() {
  const storage::User* u = selectedUser();
  if (!u) return failed(tr("Choose the account to disable or enable."));
  const QString name = u->name;
  const bool disable = !u->disabled;
  auto apply = [this, name, disable] {
    m_records.call(
        this, [name, disable](storage::ClinicalStore& s) { s.setUserDisabled(name, disable); },
        [this, name, disable] {
          done(disable ? tr("Account %1 disabled: it can no longer sign in. Its sessions and "
                            "history keep its name.")
                             .arg(name)
                       : tr("Account %1 enabled: it can sign in again.").arg(name));
          reload();
        },
        [this](const RecordsFailure& f) { failed(f.message); });
  };
  if (!disable) return apply();
  confirm(tr("Disable account"),
          tr("Disable the account %1? It can no longer sign in until an administrator enables "
             "it again. Its sessions and history stay, under its name.")
              .arg(name),
          apply);
}

void AccountsPage::removeAccount() {
  const QString name = selectedKey();
  if (name.isEmpty()) return failed(tr("Choose the account to remove."));
  confirm(tr("Remove account"),
          tr("Remove the account %1? They can no longer sign in. The sessions they recorded "
             "stay.")
              .arg(name),
          [this, name] {
            m_records.call(
                this, [name](storage::ClinicalStore& s) { s.removeUser(name); },
                [this, name] {
                  done(tr("Account %1 removed.").arg(name));
                  reload();
                },
                [this](const RecordsFailure& f) { failed(f.message); });
          });
}

}  // namespace armtrack::gui::admin
