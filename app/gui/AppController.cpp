#include "app/gui/AppController.h"

#include <QLabel>
#include <QSettings>
#include <QVBoxLayout>

#include "app/gui/Appearance.h"
#include "app/gui/MainWindow.h"

namespace armtrack::gui {

AppController::AppController(AppOptions options, QObject* parent)
    : QObject(parent),
      m_options(std::move(options)),
      m_records(std::make_unique<RecordsService>()),
      m_window(std::make_unique<MainWindow>()) {}

AppController::~AppController() {
  m_window.reset();  // screens first: they hold pending calls to the records
  m_records.reset();
}

void AppController::start() {
  QSettings settings;
  m_settings = AppSettings::load(settings);
  installTranslators(m_options.language.isEmpty() ? m_settings.language : m_options.language);
  loadPlugins();
  m_window->show();
  showMessage(tr("Welcome"), tr("%n device plugin(s) found.", nullptr,
                                static_cast<int>(m_plugins.names().size())));
}

void AppController::loadPlugins() {
  QStringList folders = m_options.pluginFolders;
  folders << m_settings.pluginFolders << app::PluginRegistry::defaultFolders();
  m_plugins.load(folders);
}

void AppController::showMessage(const QString& title, const QString& text) {
  auto* screen = new QWidget;
  screen->setWindowTitle(title);
  auto* layout = new QVBoxLayout(screen);
  auto* label = new QLabel(text, screen);
  label->setWordWrap(true);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  layout->addWidget(label);
  m_window->showScreen(screen);
}

}  // namespace armtrack::gui
