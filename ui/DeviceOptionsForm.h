// A form for a device plugin's options, built from the plugin's own help text
// (DevicePlugin::optionsHelp(): one "key=default  meaning" per line), so a plugin needs no user
// interface of its own (docs/architecture.md).
#pragma once

#include <QString>
#include <QVariantMap>
#include <QWidget>
#include <vector>

class QFormLayout;
class QLineEdit;

namespace armtrack::ui {

struct OptionField {
  QString key;
  QString defaultValue;  ///< empty when none (a required option, or a fault that is off)
  QString placeholder;   ///< a pattern to follow, e.g. "STREAM@START+SECONDS"
  QString meaning;
  QString section;  ///< the heading the option comes under, if any
};

/// Reads a plugin's help text: "key=value  meaning" lines, continuation lines (indented) added
/// to the meaning, other lines taken as section headings. A value written in capitals (with
/// '@', '+', ':' or '|') is a pattern, not a default.
std::vector<OptionField> parseOptionsHelp(const QString& help);

class DeviceOptionsForm : public QWidget {
  Q_OBJECT
 public:
  explicit DeviceOptionsForm(QWidget* parent = nullptr);

  /// Shows the options of one plugin, all at their defaults.
  void setOptionsHelp(const QString& help);
  /// Fills the fields from options (keys the form does not have are ignored).
  void setValues(const QVariantMap& options);
  /// The options the user changed from their defaults, as "key=value,..." (the text after
  /// "plugin:" in a device spec; values must not contain ',').
  QString optionsText() const;
  const std::vector<OptionField>& fields() const { return m_fields; }
  QLineEdit* edit(const QString& key) const;

 signals:
  void changed();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  QFormLayout* m_form;
  std::vector<OptionField> m_fields;
  std::vector<QLineEdit*> m_edits;
};

}  // namespace armtrack::ui
