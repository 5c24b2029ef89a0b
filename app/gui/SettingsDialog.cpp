#include "app/gui/SettingsDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QUrl>
#include <QVBoxLayout>

#include "app/gui/common/Forms.h"
#include "app/i18n/Language.h"
#include "core/storage/StorageError.h"

namespace armtrack::gui {

namespace {

void select(QComboBox* box, const QVariant& value) {
  const int i = box->findData(value);
  box->setCurrentIndex(i >= 0 ? i : 0);
}

}  // namespace

SettingsDialog::SettingsDialog(const AppSettings& s, Theme theme, QWidget* parent)
    : QDialog(parent),
      m_original(s),
      m_units(new QComboBox(this)),
      m_dataFolder(new QLineEdit(s.dataFolder, this)),
      m_database(new QLineEdit(s.databaseUrl, this)),
      m_syncServer(new QLineEdit(s.syncServerAddress, this)),
      m_plugins(new QListWidget(this)),
      m_addPlugin(new QPushButton(tr("&Add folder..."), this)),
      m_removePlugin(new QPushButton(tr("&Remove"), this)),
      m_filter(new QComboBox(this)),
      m_method(new QComboBox(this)),
      m_language(new QComboBox(this)),
      m_theme(new QComboBox(this)),
      m_message(new MessageLine(this)) {
  setWindowTitle(tr("Settings"));
  auto* layout = new QVBoxLayout(this);

  auto* display = new QGroupBox(tr("Display"), this);
  auto* displayForm = new QFormLayout(display);
  m_units->addItem(tr("degrees"), QStringLiteral("deg"));
  m_units->addItem(tr("radians"), QStringLiteral("rad"));
  select(m_units, s.units == AppSettings::AngleUnit::Radians ? QStringLiteral("rad")
                                                             : QStringLiteral("deg"));
  m_units->setAccessibleName(tr("Angle units"));
  displayForm->addRow(tr("Angle &units:"), m_units);
  m_language->addItem(tr("as the system"), QString());
  // Each language by its own name, as its speakers look for it.
  for (const i18n::Language& l : i18n::shippedLanguages())
    m_language->addItem(l.nativeName, l.code);
  select(m_language, s.language);
  m_language->setAccessibleName(tr("Language"));
  displayForm->addRow(tr("&Language:"), m_language);
  m_theme->addItem(tr("as the system"), themeName(Theme::System));
  m_theme->addItem(tr("light"), themeName(Theme::Light));
  m_theme->addItem(tr("dark"), themeName(Theme::Dark));
  select(m_theme, themeName(theme));
  m_theme->setAccessibleName(tr("Appearance"));
  displayForm->addRow(tr("A&ppearance:"), m_theme);
  layout->addWidget(display);

  auto* data = new QGroupBox(tr("Data"), this);
  auto* dataForm = new QFormLayout(data);
  auto* folderRow = new QHBoxLayout;
  m_dataFolder->setPlaceholderText(QDir::toNativeSeparators(AppSettings{}.effectiveDataFolder()));
  m_dataFolder->setAccessibleName(tr("Data folder"));
  auto* browse = new QPushButton(tr("&Browse..."), this);
  folderRow->addWidget(m_dataFolder, 1);
  folderRow->addWidget(browse);
  // A label given as text to addRow() with a layout as its field has no buddy, so its
  // mnemonic would show as a literal "&": name the line edit as the buddy.
  auto* folderLabel = new QLabel(tr("Data &folder:"), this);
  folderLabel->setBuddy(m_dataFolder);
  dataForm->addRow(folderLabel, folderRow);
  m_database->setPlaceholderText(tr("armtrack.db in the data folder"));
  m_database->setToolTip(tr("A file path, sqlite:PATH, or postgresql://user@host:port/dbname"));
  m_database->setAccessibleName(tr("Database"));
  dataForm->addRow(tr("&Database:"), m_database);
  m_syncServer->setPlaceholderText(tr("https://NAME:PORT (optional)"));
  m_syncServer->setToolTip(
      tr("The clinic's sync server as patients type it on their home computer; shown with each "
         "enrolment code"));
  m_syncServer->setAccessibleName(tr("Sync server address"));
  dataForm->addRow(tr("S&ync server address:"), m_syncServer);
  layout->addWidget(data);

  auto* devices =
      new QGroupBox(tr("Device plugin folders (searched before the built-in ones)"), this);
  auto* devicesLayout = new QHBoxLayout(devices);
  m_plugins->addItems(s.pluginFolders);
  m_plugins->setAccessibleName(tr("Plugin folders"));
  devicesLayout->addWidget(m_plugins, 1);
  auto* pluginButtons = new QVBoxLayout;
  pluginButtons->addWidget(m_addPlugin);
  pluginButtons->addWidget(m_removePlugin);
  pluginButtons->addStretch();
  devicesLayout->addLayout(pluginButtons);
  layout->addWidget(devices);

  auto* analysis = new QGroupBox(tr("Estimation of new sessions"), this);
  auto* analysisForm = new QFormLayout(analysis);
  m_filter->addItem(tr("EKF (extended Kalman filter)"), QStringLiteral("ekf"));
  m_filter->addItem(tr("UKF (unscented Kalman filter)"), QStringLiteral("ukf"));
  select(m_filter, s.filter);
  m_filter->setAccessibleName(tr("Default filter"));
  analysisForm->addRow(tr("F&ilter:"), m_filter);
  m_method->addItem(tr("A: body acceleration modelled"), QStringLiteral("A"));
  m_method->addItem(tr("B: body acceleration as states"), QStringLiteral("B"));
  m_method->addItem(tr("C: no compensation"), QStringLiteral("C"));
  select(m_method, s.method);
  m_method->setAccessibleName(tr("Default method"));
  analysisForm->addRow(tr("&Method:"), m_method);
  layout->addWidget(analysis);

  layout->addWidget(m_message);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  layout->addWidget(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &SettingsDialog::submit);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString f =
        QFileDialog::getExistingDirectory(this, tr("Data folder"), m_dataFolder->text());
    if (!f.isEmpty()) m_dataFolder->setText(f);
  });
  connect(m_addPlugin, &QPushButton::clicked, this, &SettingsDialog::addPluginFolder);
  connect(m_removePlugin, &QPushButton::clicked, this,
          [this] { delete m_plugins->takeItem(m_plugins->currentRow()); });
}

void SettingsDialog::addPluginFolder() {
  const QString f = QFileDialog::getExistingDirectory(this, tr("Plugin folder"));
  if (!f.isEmpty() && m_plugins->findItems(f, Qt::MatchExactly).isEmpty()) m_plugins->addItem(f);
}

AppSettings SettingsDialog::settings() const {
  AppSettings s = m_original;
  s.units = m_units->currentData().toString() == QLatin1String("rad")
                ? AppSettings::AngleUnit::Radians
                : AppSettings::AngleUnit::Degrees;
  s.dataFolder = m_dataFolder->text().trimmed();
  s.databaseUrl = m_database->text().trimmed();
  s.syncServerAddress = m_syncServer->text().trimmed();
  s.pluginFolders.clear();
  for (int i = 0; i < m_plugins->count(); ++i) s.pluginFolders << m_plugins->item(i)->text();
  s.filter = m_filter->currentData().toString();
  s.method = m_method->currentData().toString();
  s.language = m_language->currentData().toString();
  return s;
}

Theme SettingsDialog::theme() const {
  return parseTheme(m_theme->currentData().toString());
}

void SettingsDialog::submit() {
  const AppSettings s = settings();
  if (!s.dataFolder.isEmpty() && QDir::isRelativePath(s.dataFolder)) {
    m_message->showMessage(
        tr("Give the data folder as a full path, e.g. %1.").arg(QDir::homePath()));
    m_dataFolder->setFocus();
    return;
  }
  try {
    s.effectiveDatabase();
  } catch (const storage::StorageError& e) {
    m_message->showMessage(tr("The database location is not one ArmTrack understands: %1")
                               .arg(QString::fromStdString(e.what())));
    m_database->setFocus();
    return;
  }
  if (!s.syncServerAddress.isEmpty()) {
    const QUrl url(s.syncServerAddress, QUrl::StrictMode);
    if (!url.isValid() || url.scheme() != QLatin1String("https") || url.host().isEmpty()) {
      m_message->showMessage(
          tr("Give the sync server address as https://NAME:PORT, e.g. "
             "https://sync.clinic.example:8443, or leave it empty."));
      m_syncServer->setFocus();
      return;
    }
  }
  for (const QString& f : s.pluginFolders)
    if (!QDir(f).exists()) {
      m_message->showMessage(tr("The plugin folder %1 does not exist.").arg(f));
      return;
    }
  accept();
}

}  // namespace armtrack::gui
