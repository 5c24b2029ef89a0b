#include "ui/DeviceOptionsForm.h"

#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>

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

DeviceOptionsForm::DeviceOptionsForm(QWidget* parent) : QWidget(parent) {
  m_form = new QFormLayout(this);
  m_form->setContentsMargins(0, 0, 0, 0);
  setAccessibleName(tr("Device options"));
}

void DeviceOptionsForm::setOptionsHelp(const QString& help) {
  while (m_form->rowCount() > 0) m_form->removeRow(0);
  m_edits.clear();
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
    m_form->addRow(label, edit);
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

void DeviceOptionsForm::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    setAccessibleName(tr("Device options"));
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
