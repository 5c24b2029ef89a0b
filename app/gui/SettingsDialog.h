// The settings: units, where the data lives, plugin folders, the default filter and method,
// language and appearance. Kept in QSettings (services/AppSettings.h).
#pragma once

#include <QDialog>

#include "app/gui/Appearance.h"
#include "app/gui/services/AppSettings.h"

class QComboBox;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace armtrack::gui {

class MessageLine;

class SettingsDialog : public QDialog {
  Q_OBJECT
 public:
  SettingsDialog(const AppSettings& settings, Theme theme, QWidget* parent = nullptr);
  /// The settings as the form holds them.
  AppSettings settings() const;
  Theme theme() const;

 private:
  void submit();
  void addPluginFolder();

  AppSettings m_original;
  QComboBox* m_units;
  QLineEdit* m_dataFolder;
  QLineEdit* m_database;
  QLineEdit* m_syncServer;
  QListWidget* m_plugins;
  QPushButton* m_addPlugin;
  QPushButton* m_removePlugin;
  QComboBox* m_filter;
  QComboBox* m_method;
  QComboBox* m_language;
  QComboBox* m_theme;
  MessageLine* m_message;
};

}  // namespace armtrack::gui
