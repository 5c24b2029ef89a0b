#include "ui/DeviceOptionsForm.h"

#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QRegularExpression>
#include <QSerialPortInfo>
#include <QToolButton>

namespace armtrack::ui {

std::vector<OptionField> parseOptionsHelp(const QString& help) {
  static const QRegularExpression line(QStringLiteral("^([A-Za-z0-9_-]+)=(\\S*)\\s*(.*)$"));
  static const QRegularExpression pattern(QStringLiteral("[A-Z]{2,}|[@|]"));
  std::vector<OptionField> out;
  QString section;
  for (const QString& raw : help.split(u'\n')) {
    if (raw.trimmed().isEmpty()) continue;
    if (raw.front().isSpace()) {  // continues the previous meaning
      if (!out.empty()) out.back().meaning += QLatin1Char(' ') + raw.trimmed();
      continue;
    }
    const QRegularExpressionMatch m = line.match(raw);
    if (!m.hasMatch()) {
      section = raw.trimmed();
      if (section.endsWith(u':')) section.chop(1);
      continue;
    }
    OptionField f;
    f.key = m.captured(1);
    const QString value = m.captured(2);
    if (pattern.match(value).hasMatch())
      f.placeholder = value;
    else
      f.defaultValue = value;
    f.meaning = m.captured(3).trimmed();
    f.section = section;
    out.push_back(f);
  }
  return out;
}

bool isSerialPortOption(const OptionField& f) {
  return f.meaning.startsWith(QLatin1String("serial port"), Qt::CaseInsensitive);
}

std::vector<SerialPortChoice> availableSerialPorts() {
  std::vector<SerialPortChoice> out;
  for (const QSerialPortInfo& p : QSerialPortInfo::availablePorts()) {
    QStringList what;
    for (const QString& w : {p.description(), p.manufacturer()})
      if (!w.isEmpty() && !what.contains(w)) what << w;
    out.push_back({p.systemLocation(), what.join(QStringLiteral(", "))});
  }
  return out;
}

DeviceOptionsForm::DeviceOptionsForm(QWidget* parent) : QWidget(parent) {
  m_form = new QFormLayout(this);
  m_form->setContentsMargins(0, 0, 0, 0);
  setAccessibleName(tr("Device options"));
}

void DeviceOptionsForm::setOptionsHelp(const QString& help) {
  while (m_form->rowCount() > 0) m_form->removeRow(0);
  m_edits.clear();
  m_portButtons.clear();
  m_fields = parseOptionsHelp(help);
  QString section;
  for (const OptionField& f : m_fields) {
    if (f.section != section) {
      section = f.section;
      auto* heading = new QLabel(QStringLiteral("<b>%1</b>").arg(section.toHtmlEscaped()), this);
      heading->setWordWrap(true);
      m_form->addRow(heading);
    }
    auto* edit = new QLineEdit(f.defaultValue, this);
    edit->setPlaceholderText(f.placeholder.isEmpty() ? tr("(not set)") : f.placeholder);
    edit->setToolTip(f.meaning);
    edit->setAccessibleName(f.key);
    edit->setAccessibleDescription(f.meaning);
    connect(edit, &QLineEdit::textChanged, this, &DeviceOptionsForm::changed);
    auto* label = new QLabel(f.key, this);
    label->setBuddy(edit);
    label->setToolTip(f.meaning);
    QToolButton* ports = nullptr;
    if (isSerialPortOption(f)) {
      // The ports found, listed afresh at each press (a receiver plugged in after the page
      // opened shows up): typing /dev/rfcomm0 from memory is not what a therapist should need.
      auto* row = new QWidget(this);
      auto* h = new QHBoxLayout(row);
      h->setContentsMargins(0, 0, 0, 0);
      edit->setParent(row);
      h->addWidget(edit, 1);
      ports = new QToolButton(row);
      namePortsButton(ports);
      ports->setFocusPolicy(Qt::StrongFocus);
      h->addWidget(ports);
      const std::size_t index = m_edits.size();
      connect(ports, &QToolButton::clicked, this, [this, index] { showPorts(index); });
      m_form->addRow(label, row);
    } else {
      m_form->addRow(label, edit);
    }
    m_portButtons.push_back(ports);
    // What the option means, in the plugin's words, under its field: the key alone ("wrist-hsv")
    // says nothing to a therapist.
    if (!f.meaning.isEmpty()) {
      auto* meaning = new QLabel(f.meaning, this);
      meaning->setTextFormat(Qt::PlainText);
      meaning->setWordWrap(true);
      meaning->setObjectName(QStringLiteral("optionMeaning"));
      meaning->setAccessibleName(f.key);
      QFont small = meaning->font();
      small.setPointSizeF(small.pointSizeF() * 0.9);
      meaning->setFont(small);
      m_form->addRow(meaning);
    }
    m_edits.push_back(edit);
  }
}

void DeviceOptionsForm::namePortsButton(QToolButton* b) {
  b->setText(tr("Ports found..."));
  b->setAccessibleName(tr("Serial ports found on this computer"));
}

void DeviceOptionsForm::setPortLister(std::function<std::vector<SerialPortChoice>()> lister) {
  m_ports = std::move(lister);
}

QToolButton* DeviceOptionsForm::portsButton(const QString& key) const {
  for (std::size_t i = 0; i < m_fields.size() && i < m_portButtons.size(); ++i)
    if (m_fields[i].key == key) return m_portButtons[i];
  return nullptr;
}

void DeviceOptionsForm::showPorts(std::size_t field) {
  if (field >= m_edits.size() || !m_portButtons[field]) return;
  auto* menu = new QMenu(this);
  menu->setAttribute(Qt::WA_DeleteOnClose);
  menu->setObjectName(QStringLiteral("serialPorts"));
  const std::vector<SerialPortChoice> ports = m_ports ? m_ports() : std::vector<SerialPortChoice>{};
  if (ports.empty()) {
    QAction* none = menu->addAction(
        tr("No serial port found: plug the sensor's receiver in (or pair the Bluetooth sensor), "
           "then look again"));
    none->setEnabled(false);
  }
  for (const SerialPortChoice& p : ports) {
    QAction* a =
        menu->addAction(p.what.isEmpty() ? p.path : QStringLiteral("%1  (%2)").arg(p.path, p.what));
    a->setData(p.path);
    QLineEdit* edit = m_edits[field];
    connect(a, &QAction::triggered, edit, [edit, path = p.path] { edit->setText(path); });
  }
  QToolButton* b = m_portButtons[field];
  menu->popup(b->mapToGlobal(QPoint(0, b->height())));
}

void DeviceOptionsForm::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    setAccessibleName(tr("Device options"));
    for (QToolButton* b : m_portButtons)
      if (b) namePortsButton(b);
    for (std::size_t i = 0; i < m_fields.size() && i < m_edits.size(); ++i)
      if (m_fields[i].placeholder.isEmpty()) m_edits[i]->setPlaceholderText(tr("(not set)"));
  }
  QWidget::changeEvent(event);
}

void DeviceOptionsForm::setValues(const QVariantMap& options) {
  for (std::size_t i = 0; i < m_fields.size(); ++i)
    if (options.contains(m_fields[i].key))
      m_edits[i]->setText(options.value(m_fields[i].key).toString());
}

QString DeviceOptionsForm::optionsText() const {
  QStringList parts;
  for (std::size_t i = 0; i < m_fields.size(); ++i) {
    const QString v = m_edits[i]->text().trimmed();
    if (v.isEmpty() || v == m_fields[i].defaultValue) continue;
    parts << m_fields[i].key + QLatin1Char('=') + v;
  }
  return parts.join(u',');
}

QLineEdit* DeviceOptionsForm::edit(const QString& key) const {
  for (std::size_t i = 0; i < m_fields.size(); ++i)
    if (m_fields[i].key == key) return m_edits[i];
  return nullptr;
}

}  // namespace armtrack::ui
