#include "app/gui/newsession/NewSessionScreen.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QRadioButton>
#include <QVBoxLayout>
#include <QWizard>

#include "app/gui/common/AngleNames.h"
#include "app/gui/common/Forms.h"
#include "app/gui/common/SensorCalibrationPage.h"
#include "app/gui/newsession/CameraCalibrationPage.h"
#include "app/gui/newsession/DevicesPage.h"
#include "app/gui/newsession/LiveConfig.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/services/RecordsService.h"

namespace armtrack::gui {

namespace {

struct SetupData {
  storage::Patient patient;
  std::vector<storage::Protocol> protocols;
};

}  // namespace

SessionSetupPage::SessionSetupPage(RecordsService& records, const QString& patientCode,
                                   QWidget* parent)
    : QWizardPage(parent),
      m_patient(new QLabel(patientCode, this)),
      m_patientLabel(new QLabel(this)),
      m_protocolLabel(new QLabel(this)),
      m_armLabel(new QLabel(this)),
      m_protocol(new QComboBox(this)),
      m_protocolDetails(new QLabel(this)),
      m_left(new QRadioButton(this)),
      m_right(new QRadioButton(this)),
      m_message(new MessageLine(this)) {
  auto* form = new QFormLayout(this);
  m_patient->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  form->addRow(m_patientLabel, m_patient);
  m_protocol->addItem(QString(), QString());  // none: free movement
  m_protocolLabel->setBuddy(m_protocol);
  form->addRow(m_protocolLabel, m_protocol);
  m_protocolDetails->setWordWrap(true);
  form->addRow(QString(), m_protocolDetails);
  auto* sides = new QHBoxLayout;
  auto* group = new QButtonGroup(this);
  for (QRadioButton* b : {m_left, m_right}) {
    group->addButton(b);
    sides->addWidget(b);
  }
  sides->addStretch();
  form->addRow(m_armLabel, sides);
  form->addRow(m_message);
  retranslateUi();
  connect(m_protocol, &QComboBox::currentIndexChanged, this, &SessionSetupPage::protocolChanged);
  connect(m_left, &QRadioButton::toggled, this, &SessionSetupPage::protocolChanged);
  m_message->showMessage([] { return tr("Reading the patient and the protocols..."); },
                         MessageLine::Kind::Notice);
  records.call(
      this,
      [patientCode](storage::ClinicalStore& s) {
        return SetupData{s.patient(patientCode), s.listProtocols()};
      },
      [this](const SetupData& d) {
        m_plan.patient = d.patient;
        m_protocols = d.protocols;
        m_patient->setText(tr("%1 (%2)").arg(d.patient.name, d.patient.code));
        for (const storage::Protocol& p : m_protocols) m_protocol->addItem(p.name, p.name);
        m_loaded = true;
        m_message->clear();
        selectSide(defaultSide(d.patient, std::nullopt));
        protocolChanged();
        emit completeChanged();
        emit loaded();
      },
      [this](const RecordsFailure& f) {
        m_message->showMessage([why = f.message] {
          return tr("The patient or the protocols could not be read: %1. Go back and try again.")
              .arg(why);
        });
      });
}

void SessionSetupPage::retranslateUi() {
  setTitle(tr("Patient, protocol and arm"));
  setSubTitle(tr("Choose what this session trains and which arm wears the sensors."));
  m_patientLabel->setText(tr("Patient:"));
  m_protocolLabel->setText(tr("&Protocol:"));
  m_protocol->setAccessibleName(tr("Protocol"));
  m_protocol->setItemText(0, tr("(no protocol: free movement)"));
  m_armLabel->setText(tr("Arm:"));
  m_left->setText(tr("&Left arm"));
  m_right->setText(tr("&Right arm"));
  m_left->setAccessibleName(tr("Left arm"));
  m_right->setAccessibleName(tr("Right arm"));
  if (m_loaded) {
    m_patient->setText(tr("%1 (%2)").arg(m_plan.patient.name, m_plan.patient.code));
    protocolChanged();
  }
}

void SessionSetupPage::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWizardPage::changeEvent(event);
}

bool SessionSetupPage::isComplete() const {
  return m_loaded;
}

bool SessionSetupPage::selectProtocol(const QString& name) {
  const int i = m_protocol->findData(name);
  if (i < 0) return false;
  m_protocol->setCurrentIndex(i);
  return true;
}

void SessionSetupPage::selectSide(Side side) {
  (side == Side::Left ? m_left : m_right)->setChecked(true);
}

void SessionSetupPage::protocolChanged() {
  const QString name = m_protocol->currentData().toString();
  const auto it = std::find_if(m_protocols.begin(), m_protocols.end(),
                               [&](const auto& p) { return p.name == name; });
  const std::optional<storage::Protocol> chosen =
      it == m_protocols.end() ? std::nullopt : std::optional(*it);
  // A new protocol brings its own side (when it has one).
  const QString before = m_plan.protocol ? m_plan.protocol->name : QString();
  if (chosen && chosen->name != before && chosen->side != QLatin1String("either"))
    selectSide(defaultSide(m_plan.patient, chosen));
  m_plan.protocol = chosen;
  m_plan.side = m_left->isChecked() ? Side::Left : Side::Right;
  QString text;
  if (chosen) {
    text =
        tr("Trains %1, target %L2\u2013%L3\u00b0, %n repetition(s).", nullptr, chosen->repetitions)
            .arg(angleName(angleIndex(chosen->angleKey)))
            .arg(chosen->targetMinDeg, 0, 'f', 0)
            .arg(chosen->targetMaxDeg, 0, 'f', 0);
    const QString mine =
        m_plan.side == Side::Left ? QStringLiteral("left") : QStringLiteral("right");
    if (chosen->side != QLatin1String("either") && chosen->side != mine)
      text += u' ' + tr("Note: this protocol is meant for the %1 arm.")
                         .arg(chosen->side == QLatin1String("left") ? tr("left") : tr("right"));
  } else if (m_protocols.empty() && m_protocol->count() == 1) {
    text =
        tr("No protocols are stored yet: an administrator adds them under ArmTrack > "
           "Administration > Protocols. Without one the session records free movement.");
  }
  m_protocolDetails->setText(text);
}

SessionPlan SessionSetupPage::plan() const {
  return m_plan;
}

NewSessionScreen::NewSessionScreen(RecordsService& records, const app::PluginRegistry& plugins,
                                   const AppSettings& settings, const QString& patientCode,
                                   const QStringList& devices, QWidget* parent)
    : QWidget(parent), m_wizard(new QWizard(this)) {
  m_choices.devices = devices;
  m_wizard->setWindowFlags(Qt::Widget);  // a step of the main window, not a dialog of its own
  m_wizard->setWizardStyle(QWizard::ClassicStyle);
  m_wizard->setOption(QWizard::NoBackButtonOnStartPage);
  retranslateUi();
  m_setup = new SessionSetupPage(records, patientCode, m_wizard);
  m_wizard->addPage(m_setup);
  addDeviceSteps(plugins, settings);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(m_wizard);
  connect(m_wizard, &QWizard::accepted, this, [this] { emit accepted(plan(), m_choices); });
  connect(m_wizard, &QWizard::rejected, this, &NewSessionScreen::cancelled);
  setFocusProxy(m_wizard);
}

void NewSessionScreen::retranslateUi() {
  setWindowTitle(tr("New session"));
  m_wizard->setButtonText(QWizard::FinishButton, tr("&Start the live session"));
}

void NewSessionScreen::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

void NewSessionScreen::addDeviceSteps(const app::PluginRegistry& plugins,
                                      const AppSettings& settings) {
  using app::gui::CameraCalibrationPage;
  using app::gui::DevicesPage;
  using app::gui::SensorCalibrationPage;
  // The arm and estimator the pages run the devices with: the plan's, with these devices.
  const auto config = [this, &settings](const QStringList& devices) {
    return liveSessionConfig(plan(), devices, settings);
  };
  m_devices =
      new WidgetStep([] { return tr("Devices"); },
                     [] {
                       return tr(
                           "Choose the sensors and their options, then check the connection: every "
                           "stream should turn green and the angles move with the arm.");
                     },
                     [this, &plugins, config] {
                       auto* page = new DevicesPage(plugins, config(m_choices.devices));
                       page->setDevices(m_choices.devices);
                       return page;
                     },
                     [](QWidget* w) { return static_cast<DevicesPage*>(w)->isComplete(); },
                     [this](QWidget* w) {
                       auto* page = static_cast<DevicesPage*>(w);
                       page->stopCheck();
                       m_choices.devices = page->devices();
                       return true;
                     });
  m_calibration = new WidgetStep(
      [] { return tr("Sensor calibration"); },
      [] {
        return tr(
            "The patient holds and makes the movements shown; ArmTrack then works out how "
            "the sensors sit on the arm. About a minute.");
      },
      [this, &plugins, &settings, config] {
        const QString folder =
            QDir(settings.effectiveDataFolder())
                .filePath(QStringLiteral("calibrations/%1_%2")
                              .arg(plan().patient.code, QDateTime::currentDateTime().toString(
                                                            QStringLiteral("yyyyMMdd-HHmmss"))));
        QDir().mkpath(folder);
        // The virtual arm plays the protocol itself; a real patient makes the movements.
        return new SensorCalibrationPage(plugins, config(calibrationDevices(m_choices.devices)),
                                         folder.toStdString());
      },
      [](QWidget* w) { return static_cast<SensorCalibrationPage*>(w)->isComplete(); },
      [this](QWidget* w) {
        m_choices.calibration.reset();
        m_choices.calibrationFile.clear();
        m_choices.calibrationVerdict.clear();
        m_choices.calibrationReason.clear();
        auto* page = static_cast<SensorCalibrationPage*>(w);
        if (!page || !page->result()) return true;  // skipped
        m_choices.calibration = page->result()->calibration;
        if (const auto v = page->verdict()) {
          m_choices.calibrationVerdict =
              *v == app::gui::CalibrationVerdict::Good     ? QStringLiteral("good")
              : *v == app::gui::CalibrationVerdict::Usable ? QStringLiteral("usable")
                                                           : QStringLiteral("poor");
          m_choices.calibrationReason = page->verdictText();
        }
        const std::filesystem::path file = page->recordingPath().parent_path() / "calibration.json";
        try {
          writeCalibration(file, *m_choices.calibration);
          m_choices.calibrationFile = QString::fromStdString(file.string());
        } catch (const std::exception&) {
          // The calibration is still used for this session; only the file is missing.
        }
        return true;
      },
      [] { return tr("Skip the calibration (the measured segment lengths are used)"); });
  m_camera = new WidgetStep(
      [] { return tr("Camera calibration"); },
      [] {
        return tr(
            "Hold the printed chessboard in front of the webcam in different places and "
            "angles until the grid is covered.");
      },
      [this, &plugins]() -> QWidget* {
        // Every device that gives webcam marker pixels counts; only a real camera's images can
        // be calibrated with the chessboard.
        const std::vector<app::gui::CameraDevice> cameras =
            app::gui::camerasAmong(plugins, m_choices.devices);
        if (!app::gui::cameraStepText(cameras).isEmpty()) {
          auto* none = new TranslatedLabel([cameras] { return app::gui::cameraStepText(cameras); });
          none->setObjectName(QStringLiteral("cameraStepText"));
          none->setProperty("complete", true);
          return none;
        }
        auto* page = new CameraCalibrationPage(app::gui::openWebcam(0), {});
        page->startCamera();
        return page;
      },
      [](QWidget* w) {
        if (auto* page = qobject_cast<CameraCalibrationPage*>(w)) return page->isComplete();
        return w->property("complete").toBool();
      },
      {}, [] { return tr("Skip the camera calibration (use the camera's stored model)"); });
  for (WidgetStep* step : {m_devices, m_calibration, m_camera}) m_wizard->addPage(step);
}

}  // namespace armtrack::gui
