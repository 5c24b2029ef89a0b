#include "app/gui/patients/PatientListScreen.h"

#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QShortcut>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

#include "app/gui/common/Forms.h"
#include "app/gui/patients/PatientDialog.h"
#include "app/gui/patients/PatientTableModel.h"
#include "app/gui/services/RecordsService.h"
#include "ui/Retranslate.h"

namespace armtrack::gui {

namespace {

/// text without accents and case: "Müller" -> "muller", "Straße" -> "strasse". With
/// umlautsSpelled, ä, ö and ü become ae, oe and ue first, as German spells them without the
/// dots ("Mueller").
QString searchFold(QString text, bool umlautsSpelled) {
  if (umlautsSpelled)
    for (const auto& [from, to] : {std::pair{u"ä", u"ae"},
                                   {u"ö", u"oe"},
                                   {u"ü", u"ue"},
                                   {u"Ä", u"Ae"},
                                   {u"Ö", u"Oe"},
                                   {u"Ü", u"Ue"}})
      text.replace(QString::fromUtf16(from), QString::fromUtf16(to));
  const QString decomposed = text.normalized(QString::NormalizationForm_KD);
  QString out;
  out.reserve(decomposed.size());
  for (const QChar c : decomposed)
    if (c.category() != QChar::Mark_NonSpacing) out += c;
  out = out.toCaseFolded();
  for (const auto& [from, to] : {std::pair{u"ß", u"ss"},
                                 {u"ø", u"o"},
                                 {u"ł", u"l"},
                                 {u"đ", u"d"},
                                 {u"æ", u"ae"},
                                 {u"œ", u"oe"},
                                 {u"ı", u"i"}})
    out.replace(QString::fromUtf16(from), QString::fromUtf16(to));
  return out;
}

/// Keeps the rows where any column holds the search text, regardless of case and accents:
/// "muller" and "MULLER" find Müller.
class PatientSearch : public QSortFilterProxyModel {
 public:
  using QSortFilterProxyModel::QSortFilterProxyModel;
  void setSearch(const QString& text) {
    m_query = searchFold(text.trimmed(), false);
    invalidateFilter();
  }

 protected:
  bool filterAcceptsRow(int row, const QModelIndex& parent) const override {
    if (m_query.isEmpty()) return true;
    const QAbstractItemModel* m = sourceModel();
    for (int c = 0; c < m->columnCount(parent); ++c) {
      const QString text = m->index(row, c, parent).data(Qt::DisplayRole).toString();
      if (searchFold(text, false).contains(m_query) || searchFold(text, true).contains(m_query))
        return true;
    }
    return false;
  }

 private:
  QString m_query;
};

}  // namespace

PatientListScreen::PatientListScreen(RecordsService& records, const QString& select,
                                     QWidget* parent)
    : QWidget(parent),
      m_records(records),
      m_model(new PatientTableModel(this)),
      m_proxy(new PatientSearch(this)),
      m_search(new QLineEdit(this)),
      m_table(new QTableView(this)),
      m_open(new QPushButton(this)),
      m_add(new QPushButton(this)),
      m_edit(new QPushButton(this)),
      m_message(new MessageLine(this)) {
  m_canWrite = records.signedIn() && records.user().role != storage::Role::Home;
  m_proxy->setSourceModel(m_model);
  m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
  m_proxy->setFilterKeyColumn(-1);  // every column
  m_proxy->setSortCaseSensitivity(Qt::CaseInsensitive);
  m_proxy->setSortRole(Qt::EditRole);

  auto* layout = new QVBoxLayout(this);
  m_heading = heading(QString(), this);
  layout->addWidget(m_heading);
  auto* searchRow = new QHBoxLayout;
  m_searchLabel = new QLabel(this);
  m_searchLabel->setBuddy(m_search);
  m_search->setClearButtonEnabled(true);
  searchRow->addWidget(m_searchLabel);
  searchRow->addWidget(m_search, 1);
  layout->addLayout(searchRow);

  m_table->setModel(m_proxy);
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setSelectionMode(QAbstractItemView::SingleSelection);
  m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_table->setSortingEnabled(true);
  m_table->sortByColumn(PatientTableModel::Code, Qt::AscendingOrder);
  m_table->setTabKeyNavigation(false);  // Tab leaves the table; arrows move inside
  m_table->verticalHeader()->hide();
  m_table->horizontalHeader()->setStretchLastSection(true);
  m_table->setAlternatingRowColors(true);
  layout->addWidget(m_table, 1);
  layout->addWidget(m_message);

  auto* buttons = new QHBoxLayout;
  m_add->setShortcut(QKeySequence::New);
  buttons->addWidget(m_add);
  buttons->addWidget(m_edit);
  buttons->addStretch();
  m_open->setDefault(true);
  buttons->addWidget(m_open);
  layout->addLayout(buttons);
  m_add->setVisible(m_canWrite);
  m_edit->setVisible(m_canWrite);

  connect(m_search, &QLineEdit::textChanged, this,
          [this](const QString& text) { static_cast<PatientSearch*>(m_proxy)->setSearch(text); });
  connect(m_search, &QLineEdit::textChanged, this, [this] {
    // Keep a selection while searching so Enter opens the first match.
    if (!m_table->selectionModel()->hasSelection() && m_proxy->rowCount() > 0)
      m_table->selectRow(0);
    updateButtons();
  });
  connect(m_search, &QLineEdit::returnPressed, this, &PatientListScreen::openSelected);
  connect(m_table, &QTableView::activated, this, &PatientListScreen::openSelected);
  connect(m_open, &QPushButton::clicked, this, &PatientListScreen::openSelected);
  connect(m_add, &QPushButton::clicked, this, &PatientListScreen::addPatient);
  connect(m_edit, &QPushButton::clicked, this, &PatientListScreen::editPatient);
  connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this,
          &PatientListScreen::updateButtons);
  // Down from the search field goes into the list.
  auto* toList =
      new QShortcut(QKeySequence(Qt::Key_Down), m_search, nullptr, nullptr, Qt::WidgetShortcut);
  connect(toList, &QShortcut::activated, this, [this] {
    m_table->setFocus();
    if (!m_table->selectionModel()->hasSelection()) m_table->selectRow(0);
  });
  setTabOrder(m_search, m_table);
  setTabOrder(m_table, m_add);
  setTabOrder(m_add, m_edit);
  setTabOrder(m_edit, m_open);
  setFocusProxy(m_search);
  retranslateUi();
  updateButtons();
  reload(select);
}

void PatientListScreen::retranslateUi() {
  setWindowTitle(tr("Patients"));
  setHeading(m_heading, tr("Patients"));
  m_searchLabel->setText(tr("&Search:"));
  m_search->setPlaceholderText(tr("code, name, diagnosis..."));
  m_search->setAccessibleName(tr("Search patients"));
  m_table->setAccessibleName(tr("Patient list"));
  m_open->setText(tr("&Open"));
  ui::setButtonText(m_add, tr("&New patient..."));
  m_add->setToolTip(tr("Add a patient (%1)")
                        .arg(QKeySequence(QKeySequence::New).toString(QKeySequence::NativeText)));
  m_edit->setText(tr("&Edit..."));
}

void PatientListScreen::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

void PatientListScreen::reload(const QString& select) {
  m_message->showMessage([] { return tr("Loading the patients..."); }, MessageLine::Kind::Notice);
  m_records.call(
      this, [](storage::ClinicalStore& s) { return s.listPatients(); },
      [this, select](std::vector<storage::Patient> patients) {
        const QString keep = select.isEmpty() ? selectedCode() : select;
        const int n = static_cast<int>(patients.size());
        m_model->setPatients(std::move(patients));
        m_message->clear();
        if (n == 0)
          m_message->showMessage(
              [canWrite = m_canWrite] {
                return canWrite ? tr("No patients yet. Add the first with \"New patient\".")
                                : tr("No patients.");
              },
              MessageLine::Kind::Notice);
        const int row = m_model->rowOf(keep);
        if (row >= 0)
          m_table->selectRow(m_proxy->mapFromSource(m_model->index(row, 0)).row());
        else if (m_proxy->rowCount() > 0)
          m_table->selectRow(0);
        updateButtons();
        emit loaded(n);
      },
      [this](const RecordsFailure& f) {
        m_message->showMessage(
            [why = f.message] { return tr("The patients could not be read: %1").arg(why); });
      });
}

QString PatientListScreen::selectedCode() const {
  const QModelIndexList rows = m_table->selectionModel()->selectedRows();
  return rows.isEmpty() ? QString() : rows.first().data(PatientTableModel::CodeRole).toString();
}

void PatientListScreen::updateButtons() {
  const bool any = !selectedCode().isEmpty();
  m_open->setEnabled(any);
  m_edit->setEnabled(any);
}

void PatientListScreen::openSelected() {
  const QString code = selectedCode();
  if (!code.isEmpty()) emit openRequested(code);
}

void PatientListScreen::addPatient() {
  if (!m_canWrite) return;
  auto* dialog = new PatientDialog(storage::Patient{}, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &PatientDialog::saveRequested, this,
          [this, dialog](const storage::Patient& p) { saveFromDialog(dialog, p, true); });
  dialog->open();
}

void PatientListScreen::editPatient() {
  const int row = m_model->rowOf(selectedCode());
  if (!m_canWrite || row < 0) return;
  auto* dialog = new PatientDialog(*m_model->patientAt(row), this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &PatientDialog::saveRequested, this,
          [this, dialog](const storage::Patient& p) { saveFromDialog(dialog, p, false); });
  dialog->open();
}

void PatientListScreen::saveFromDialog(PatientDialog* dialog, const storage::Patient& p,
                                       bool adding) {
  m_records.call(
      dialog,
      [p, adding](storage::ClinicalStore& s) {
        adding ? void(s.addPatient(p)) : s.updatePatient(p);
      },
      [this, dialog, code = p.code] {
        dialog->accept();
        reload(code);
      },
      [dialog, code = p.code](const RecordsFailure& f) {
        if (f.kind == storage::StorageError::Kind::Exists)
          return dialog->showError(
              tr("A patient with the code %1 exists already. Choose another code, or cancel "
                 "and open that patient from the list.")
                  .arg(code),
              QStringLiteral("code"));
        dialog->showError(f.message);
      });
}

}  // namespace armtrack::gui
