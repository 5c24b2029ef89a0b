// The protocols page of the administrator's screen (the CLI's `protocol add`, `protocol list`;
// the store's updateProtocol).
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>

#include "app/gui/admin/AdminDialogs.h"
#include "app/gui/admin/AdminScreen.h"
#include "app/gui/common/AngleNames.h"
#include "app/gui/services/RecordsService.h"

namespace armtrack::gui::admin {

namespace {

QString sideText(const QString& side) {
  if (side == QLatin1String("left")) return ProtocolsPage::tr("left arm");
  if (side == QLatin1String("right")) return ProtocolsPage::tr("right arm");
  return ProtocolsPage::tr("either arm");
}

}  // namespace

ProtocolsPage::ProtocolsPage(RecordsService& records, QWidget* parent)
    : AdminPage(records, parent), m_add(addButton()), m_edit(addButton()) {
  connect(m_add, &QPushButton::clicked, this, &ProtocolsPage::addProtocol);
  connect(m_edit, &QPushButton::clicked, this, &ProtocolsPage::editProtocol);
  connect(m_table, &QTableWidget::cellActivated, this, &ProtocolsPage::editProtocol);
  retranslateUi();
  reload();
}

void ProtocolsPage::retranslateUi() {
  m_table->setAccessibleName(tr("Protocols"));
  m_add->setText(tr("&Add protocol..."));
  m_edit->setText(tr("&Edit protocol..."));
}

void ProtocolsPage::reload() {
  m_records.call(
      this, [](storage::ClinicalStore& s) { return s.listProtocols(); },
      [this](const std::vector<storage::Protocol>& protocols) {
        m_protocols = protocols;
        std::vector<QStringList> rows;
        const QLocale locale;
        for (const storage::Protocol& p : protocols) {
          const int angle = angleIndex(p.angleKey);
          rows.push_back({p.name, angle >= 0 ? angleName(angle) : p.angleKey,
                          tr("%1 to %2 deg")
                              .arg(locale.toString(p.targetMinDeg, 'f', 0),
                                   locale.toString(p.targetMaxDeg, 'f', 0)),
                          locale.toString(p.repetitions), sideText(p.side),
                          p.trunkLimitDeg
                              ? tr("%1 deg").arg(locale.toString(*p.trunkLimitDeg, 'f', 0))
                              : tr("off")});
        }
        fill({tr("Name"), tr("Angle"), tr("Target"), tr("Repetitions"), tr("Side"),
              tr("Trunk limit")},
             rows, {});
        emit loaded();
      },
      [this](const RecordsFailure& f) { failed(f.message); });
}

void ProtocolsPage::addProtocol() {
  storage::Protocol fresh;
  fresh.angleKey = angleKey(0);
  fresh.targetMaxDeg = 90;
  fresh.repetitions = 10;
  openDialog(fresh);
}

void ProtocolsPage::editProtocol() {
  const QString name = selectedKey();
  for (const storage::Protocol& p : m_protocols)
    if (p.name == name) return openDialog(p);
  failed(tr("Choose the protocol to edit."));
}

void ProtocolsPage::openDialog(const storage::Protocol& protocol) {
  const bool adding = protocol.name.isEmpty();
  auto* dialog = new ProtocolDialog(protocol, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &FormDialog::submitted, this, [this, dialog, adding] {
    const storage::Protocol p = dialog->protocol();
    m_records.call(
        dialog,
        [p, adding](storage::ClinicalStore& s) {
          adding ? static_cast<void>(s.addProtocol(p)) : s.updateProtocol(p);
        },
        [this, dialog, p, adding] {
          dialog->accept();
          done(adding ? tr("Protocol %1 added: it is offered in new sessions and programmes.")
                            .arg(p.name)
                      : tr("Protocol %1 saved.").arg(p.name));
          reload();
        },
        [dialog](const RecordsFailure& f) { dialog->showError(f.message); });
  });
  dialog->open();
}

}  // namespace armtrack::gui::admin
