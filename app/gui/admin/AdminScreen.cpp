#include "app/gui/admin/AdminScreen.h"

#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include "app/gui/common/Forms.h"
#include "app/gui/services/RecordsService.h"

namespace armtrack::gui::admin {

AdminPage::AdminPage(RecordsService& records, QWidget* parent)
    : QWidget(parent),
      m_records(records),
      m_table(new QTableWidget(this)),
      m_message(new MessageLine(this)) {
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setSelectionMode(QAbstractItemView::SingleSelection);
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_table->setTabKeyNavigation(false);  // Tab leaves the table; arrows move inside
  m_table->verticalHeader()->hide();
  m_table->horizontalHeader()->setStretchLastSection(true);
  m_table->setAlternatingRowColors(true);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_table, 1);
  layout->addWidget(m_message);
  auto* buttons = new QHBoxLayout;
  buttons->addStretch();
  layout->addLayout(buttons);
}

QPushButton* AdminPage::addButton(QWidget*) {
  auto* button = new QPushButton(this);
  auto* row = static_cast<QHBoxLayout*>(layout()->itemAt(layout()->count() - 1)->layout());
  row->insertWidget(static_cast<int>(m_buttons.size()), button);
  m_buttons << button;
  return button;
}

QString AdminPage::selectedKey() const {
  const QList<QTableWidgetItem*> items = m_table->selectedItems();
  if (items.isEmpty()) return {};
  const QTableWidgetItem* first = m_table->item(items.first()->row(), 0);
  return first ? first->data(Qt::UserRole).toString() : QString();
}

void AdminPage::fill(const QStringList& headers, const std::vector<QStringList>& rows,
                     const QString& select) {
  const QString keep = select.isEmpty() ? selectedKey() : select;
  m_table->clear();
  m_table->setColumnCount(static_cast<int>(headers.size()));
  m_table->setHorizontalHeaderLabels(headers);
  m_table->setRowCount(static_cast<int>(rows.size()));
  int selectRow = rows.empty() ? -1 : 0;
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    // The first cell's text is the row's key unless it says otherwise after a tab.
    const QStringList& cells = rows[r];
    for (int c = 0; c < cells.size() && c < headers.size(); ++c) {
      auto* item = new QTableWidgetItem(cells[c].section(u'\t', 0, 0));
      if (c == 0) {
        const QString key = cells[c].contains(u'\t') ? cells[c].section(u'\t', 1) : cells[c];
        item->setData(Qt::UserRole, key);
        if (key == keep) selectRow = r;
      }
      item->setToolTip(item->text());
      m_table->setItem(r, c, item);
    }
  }
  m_table->resizeColumnsToContents();
  m_table->horizontalHeader()->setStretchLastSection(false);  // set again: the last column fills
  m_table->horizontalHeader()->setStretchLastSection(true);
  if (selectRow >= 0) m_table->selectRow(selectRow);
}

void AdminPage::failed(const QString& message) {
  m_message->showMessage(message);
}

void AdminPage::done(const QString& message) {
  m_message->showMessage(message, MessageLine::Kind::Notice);
}

void AdminPage::confirm(const QString& title, const QString& question, std::function<void()> yes) {
  auto* box = new QMessageBox(QMessageBox::Question, title, question,
                              QMessageBox::Yes | QMessageBox::Cancel, this);
  box->setDefaultButton(QMessageBox::Cancel);  // Enter alone does not remove anything
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::finished, this, [yes = std::move(yes)](int result) {
    if (result == QMessageBox::Yes) yes();
  });
  box->open();
}

void AdminPage::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) {
    retranslateUi();
    reload();
  }
  QWidget::changeEvent(event);
}

AdminScreen::AdminScreen(RecordsService& records, QWidget* parent)
    : QWidget(parent),
      m_heading(heading(QString(), this)),
      m_tabs(new QTabWidget(this)),
      m_accounts(new AccountsPage(records, this)),
      m_protocols(new ProtocolsPage(records, this)),
      m_programmes(new ProgrammePage(records, this)),
      m_back(new QPushButton(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_heading);
  m_tabs->addTab(m_accounts, QString());
  m_tabs->addTab(m_protocols, QString());
  m_tabs->addTab(m_programmes, QString());
  layout->addWidget(m_tabs, 1);
  auto* row = new QHBoxLayout;
  row->addWidget(m_back);
  row->addStretch();
  layout->addLayout(row);
  m_back->setShortcut(QKeySequence::Back);
  connect(m_back, &QPushButton::clicked, this, &AdminScreen::backRequested);
  // A protocol added on its page is offered at once in the programmes.
  connect(m_tabs, &QTabWidget::currentChanged, this, [this](int index) {
    if (auto* page = qobject_cast<AdminPage*>(m_tabs->widget(index))) page->reload();
  });
  retranslateUi();
  setFocusProxy(m_tabs);
}

void AdminScreen::retranslateUi() {
  setWindowTitle(tr("Administration"));
  setHeading(m_heading, tr("Administration"));
  m_tabs->setTabText(0, tr("&Accounts"));
  m_tabs->setTabText(1, tr("P&rotocols"));
  m_tabs->setTabText(2, tr("&Home programmes"));
  m_tabs->setAccessibleName(tr("Administration"));
  const QKeySequence back = m_back->shortcut();
  m_back->setText(tr("Back to the patients"));
  m_back->setShortcut(back);
}

void AdminScreen::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

}  // namespace armtrack::gui::admin
