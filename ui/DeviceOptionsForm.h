// A form for a device plugin's options, built from the plugin's own help text
// (DevicePlugin::optionsHelp(): one "key=default  meaning" per line), so a plugin needs no user
// interface of its own (docs/architecture.md).
#pragma once

#include <QString>
#include <QVariantMap>
#include <QWidget>
#include <vector>

#include <functional>

class QFormLayout;
class QLineEdit;
class QToolButton;

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

/// Whether an option names a serial port: its meaning begins "serial port" (the plugins' help
/// says so, e.g. "serial port of the Shimmer, required (e.g. /dev/rfcomm0)").
bool isSerialPortOption(const OptionField& f);

/// The serial ports on this computer as a user picks one: the device's path (/dev/ttyUSB0) and
/// what it is, where the system says ("CP2102 USB to UART"). Qt's list of ports, read afresh at
/// each call.
struct SerialPortChoice {
  QString path, what;
};
std::vector<SerialPortChoice> availableSerialPorts();

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
  /// The button beside a serial port option that lists the ports found (null for other keys).
  QToolButton* portsButton(const QString& key) const;
  /// Where the ports come from (availableSerialPorts() by default): tests give a list.
  void setPortLister(std::function<std::vector<SerialPortChoice>()> lister);

 signals:
  void changed();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  QFormLayout* m_form;
  std::vector<OptionField> m_fields;
  std::vector<QLineEdit*> m_edits;
  std::vector<QToolButton*> m_portButtons;  // per field; null where not a serial port
  std::function<std::vector<SerialPortChoice>()> m_ports = availableSerialPorts;

  void showPorts(std::size_t field);
  /// Its words, in the language of the moment (built and on a language change).
  void namePortsButton(QToolButton* b);
};

}  // namespace armtrack::ui
