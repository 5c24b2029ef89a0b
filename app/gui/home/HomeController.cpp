#include "app/gui/home/HomeController.h"

#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QThreadPool>

#include "app/gui/home/ExerciseScreen.h"
#include "app/gui/home/FeedbackSound.h"
#include "app/gui/home/HomeCalibrationScreen.h"
#include "app/gui/home/HomeConnectScreen.h"
#include "app/gui/home/HomeMessageScreen.h"
#include "app/gui/home/HomeStartScreen.h"
#include "app/gui/home/HomeSummaryScreen.h"
#include "app/gui/home/HomeWindow.h"
#include "app/gui/home/SensorCheckScreen.h"
#include "app/gui/home/SwitchAccess.h"
#include "app/gui/services/RecordsService.h"
#include "app/sync/HomeSyncService.h"

namespace armtrack::gui::home {

namespace {
constexpr auto kAccessKey = "home/access";
}

HomeController::HomeController(RecordsService& records, const app::PluginRegistry& registry,
                               HomeSetup setup, QString patientCode, QObject* parent)
    : QObject(parent),
      m_records(records),
      m_registry(registry),
      m_setup(std::move(setup)),
      m_patient(std::move(patientCode)),
      m_window(std::make_unique<HomeWindow>()),
      m_sound(new FeedbackSound(this)) {
  m_window->access()->setMode(
      parseAccessMode(QSettings().value(QLatin1String(kAccessKey)).toString()));
  connect(m_window.get(), &HomeWindow::closeRequested, this, &HomeController::onCloseRequested);
  if (!m_setup.syncFolder.isEmpty()) {
    // The sync runs on a thread of its own; its state is a line under every screen, so an
    // exercise is never held up by it.
    m_sync = std::make_unique<sync::HomeSyncService>(m_records.url(), m_setup.syncFolder);
    connect(m_sync.get(), &sync::HomeSyncService::statusChanged, this,
            [this](const sync::SyncStatus& s) {
              m_window->setSyncText(HomeConnectScreen::stateText(s, QDateTime::currentDateTime()));
              // A programme changed at the clinic is shown at once when nothing is under way.
              if (s.programmeChanged && !s.busy &&
                  qobject_cast<HomeStartScreen*>(m_window->currentScreen()))
                loadPlan();
            });
    m_window->setSyncText(
        HomeConnectScreen::stateText(m_sync->status(), QDateTime::currentDateTime()));
  }
}

HomeController::~HomeController() {
  m_sync.reset();    // its thread ends; an upload under way resumes next time
  m_window.reset();  // the screens first: their pending answers are dropped
  // The recordings in the temporary folder are removed on a pool thread (the application waits
  // for the pool when it ends).
  if (m_work)
    QThreadPool::globalInstance()->start([work = std::move(m_work)]() mutable { work.reset(); });
}

template <class Screen>
Screen* HomeController::show(Screen* screen) {
  m_window->showScreen(screen);
  return screen;
}

void HomeController::start() {
  m_window->show();
  m_window->raise();
  m_window->activateWindow();
  loadPlan();
}

void HomeController::setStep(std::function<QString()> step) {
  m_window->setHeading(m_plan.patient.name, std::move(step));
}

void HomeController::loadPlan() {
  setStep({});
  show(new HomeMessageScreen([] { return tr("One moment"); },
                             [] { return tr("Loading today's exercises\u2026"); }));
  // The temporary folder, when one is needed, is made on the records' thread with the plan.
  const bool makeWork = m_setup.workFolder.isEmpty() && !m_work;
  m_records.call(
      m_window.get(),
      [code = m_patient, makeWork](storage::ClinicalStore& s) {
        std::shared_ptr<QTemporaryDir> work;
        if (makeWork) {
          work = std::make_shared<QTemporaryDir>();
          if (!work->isValid())
            throw storage::StorageError(
                storage::StorageError::Kind::Io,
                tr("cannot create a temporary folder for the sensor check (%1): free some disk "
                   "space")
                    .arg(work->errorString())
                    .toStdString());
        }
        QString patient = code;
        if (patient.isEmpty()) {
          // A home account sees its own patient only.
          const std::vector<storage::Patient> own = s.listPatients();
          if (own.size() != 1)
            throw storage::StorageError(storage::StorageError::Kind::NotFound,
                                        "this account is not linked to one patient");
          patient = own.front().code;
        }
        return std::make_pair(loadHomePlan(s, patient), work);
      },
      [this](const std::pair<HomePlan, std::shared_ptr<QTemporaryDir>>& loaded) {
        const auto& [plan, work] = loaded;
        if (work) {
          m_work = work;
          m_setup.workFolder = work->path();
        }
        m_plan = plan;
        m_patient = plan.patient.code;
        emit planLoaded();
        showStart();
      },
      [this](const RecordsFailure& f) { showProblem(f.message); });
}

void HomeController::showStart() {
  setStep([] { return tr("Today"); });
  auto* screen = show(new HomeStartScreen(m_plan, m_setup.opticalConfigured(),
                                          m_window->access()->mode(), nullptr, m_sync != nullptr));
  connect(screen, &HomeStartScreen::clinicRequested, this, &HomeController::showConnect);
  connect(screen, &HomeStartScreen::startRequested, this, &HomeController::showCheck);
  connect(screen, &HomeStartScreen::signOutRequested, this, &HomeController::signOutRequested);
  connect(screen, &HomeStartScreen::accessModeChosen, this, [this](AccessMode mode) {
    m_window->access()->setMode(mode);
    QSettings().setValue(QLatin1String(kAccessKey), accessModeName(mode));
  });
}

void HomeController::showConnect() {
  if (!m_sync) return;
  setStep([] { return tr("Clinic"); });
  auto* screen = show(new HomeConnectScreen(m_sync->status().server));
  screen->serverField()->setFocus(Qt::OtherFocusReason);
  // Back through the plan: a programme fetched at enrolment shows at once.
  connect(screen, &HomeConnectScreen::backRequested, this, &HomeController::loadPlan);
  connect(screen, &HomeConnectScreen::connectRequested, m_sync.get(),
          [this](const QString& server, const QString& code) {
            m_sync->enrol(server, code, tr("home computer"));
          });
  connect(m_sync.get(), &sync::HomeSyncService::enrolFinished, screen,
          [screen](bool ok, sync::SyncProblem problem, const QString& detail) {
            screen->showResult(ok, HomeConnectScreen::enrolText(ok, problem, detail));
          });
}

app::gui::LiveSessionConfig HomeController::config(
    const QStringList& devices, const std::optional<storage::Protocol>& protocol) const {
  SessionPlan plan;
  plan.patient = m_plan.patient;
  plan.protocol = protocol;
  plan.side = defaultSide(plan.patient, protocol);
  app::gui::LiveSessionConfig c = m_setup.configure
                                      ? m_setup.configure(plan, devices, m_calibration)
                                      : app::gui::LiveSessionConfig{};
  c.devices = devices;
  return c;
}

void HomeController::showCheck() {
  setStep([] { return tr("Sensor check"); });
  auto* screen = show(new SensorCheckScreen(m_registry, config(m_setup.checkDevices(), {}),
                                            m_setup.workFolder.toStdString()));
  connect(screen, &SensorCheckScreen::done, this, [this](bool) { showCalibration(); });
}

void HomeController::showCalibration() {
  setStep([] { return tr("Calibration"); });
  auto* screen = show(new HomeCalibrationScreen(
      m_registry, config(m_setup.calibrationDevices(), {}), m_setup.workFolder));
  connect(screen, &HomeCalibrationScreen::done, this, [this](const std::optional<Calibration>& c) {
    m_calibration = c;
    showExercise(0);
  });
}

void HomeController::showExercise(std::size_t index) {
  if (index >= m_plan.exercises.size()) return showSummary();
  const HomeExercise& e = m_plan.exercises[index];
  const int count = static_cast<int>(m_plan.exercises.size());
  setStep([index, count] { return tr("Exercise %L1 of %L2").arg(index + 1).arg(count); });
  auto* screen = show(new ExerciseScreen(
      m_registry, m_records, e, static_cast<int>(index) + 1, count, m_patient,
      config(m_setup.exerciseDevices(e), e.protocol), m_setup.opticalConfigured(), m_sound));
  connect(screen, &ExerciseScreen::finished, this,
          [this, index](const HomeExerciseResult& r, bool stopForToday) {
            m_results.push_back(r);
            if (m_closing) return onCloseRequested();
            if (stopForToday)
              showSummary();
            else
              showExercise(index + 1);
          });
}

void HomeController::showSummary() {
  setStep([] { return tr("Summary"); });
  auto* screen = show(new HomeSummaryScreen(m_plan, m_results));
  QPointer<HomeSummaryScreen> guard(screen);
  connect(screen, &HomeSummaryScreen::saveRequested, this,
          [this, guard](std::optional<int> pain, const QString& comment) {
            saveAll(pain, comment, [guard](bool ok, const QString& message) {
              if (guard) guard->showSaved(ok, message);
            });
          });
  connect(screen, &HomeSummaryScreen::closeRequested, this, &HomeController::closeNow);
}

void HomeController::saveAll(std::optional<int> pain, const QString& comment,
                             const std::function<void(bool, const QString&)>& done) {
  m_records.call(
      this,
      [results = m_results, pain, comment](storage::ClinicalStore& s) {
        saveHomeOutcomes(s, results, pain, comment);
        return true;
      },
      [this, done](bool) {
        m_saved = true;
        if (m_sync) m_sync->sessionStored();  // counted as waiting, and sent when it can be
        done(true, {});
        emit outcomeSaved(true, {});
      },
      [this, done](const RecordsFailure& f) {
        done(false, f.message);
        emit outcomeSaved(false, f.message);
      });
}

void HomeController::showProblem(const QString& text) {
  setStep({});
  auto* screen = show(new HomeMessageScreen(
      [] { return tr("Something went wrong"); },
      [text] {
        return tr("%1\nPlease try again. If this happens again, call your therapist.").arg(text);
      }));
  screen->addChoice([] { return tr("&Try again"); }, [this] { loadPlan(); });
  screen->addChoice([] { return tr("Sign &out"); }, [this] { emit signOutRequested(); });
}

void HomeController::onCloseRequested() {
  // An exercise under way is ended first. When the patient closes the window, they are asked:
  // stopping saves the exercise as done so far (complete, analysed at the therapist's next
  // start); when the application ends (quit()), it is kept as interrupted.
  if (auto* exercise = qobject_cast<ExerciseScreen*>(m_window->currentScreen());
      exercise && exercise->phase() != ExerciseScreen::Phase::Done) {
    if (m_closing || exercise->phase() == ExerciseScreen::Phase::Finishing) {
      m_closing = true;
      return;  // finished() comes back here
    }
    return askToStop();
  }
  m_closing = true;
  // What was counted reaches the therapist even when the summary was not saved.
  const bool recorded = std::any_of(m_results.begin(), m_results.end(),
                                    [](const HomeExerciseResult& r) { return r.sessionId != 0; });
  if (recorded && !m_saved)
    return saveAll(std::nullopt, {}, [this](bool, const QString&) { closeNow(); });
  closeNow();
}

void HomeController::askToStop() {
  if (m_question) {
    m_question->raise();
    return;
  }
  auto* box =
      new QMessageBox(QMessageBox::Question, tr("Stop this exercise?"),
                      tr("Do you want to stop for today?"), QMessageBox::NoButton, m_window.get());
  box->setInformativeText(
      tr("What you have done so far is saved for your therapist. You can also keep "
         "exercising."));
  QPushButton* stop = box->addButton(tr("&Stop and save"), QMessageBox::AcceptRole);
  QPushButton* keep = box->addButton(tr("&Keep exercising"), QMessageBox::RejectRole);
  box->setDefaultButton(keep);  // one stray key press does not end the exercise
  box->setEscapeButton(keep);
  box->setAttribute(Qt::WA_DeleteOnClose);
  m_question = box;
  connect(stop, &QPushButton::clicked, this, [this] {
    auto* exercise = qobject_cast<ExerciseScreen*>(m_window->currentScreen());
    if (!exercise || exercise->phase() == ExerciseScreen::Phase::Done) return onCloseRequested();
    m_closing = true;
    exercise->stopAndSave();  // finished() comes back to onCloseRequested()
  });
  box->open();
}

void HomeController::quit() {
  if (m_question) m_question->close();
  if (auto* exercise = qobject_cast<ExerciseScreen*>(m_window->currentScreen());
      exercise && exercise->phase() != ExerciseScreen::Phase::Done) {
    if (!m_closing) {
      m_closing = true;
      exercise->cutShort();
    }
    return;  // finished() comes back to onCloseRequested()
  }
  onCloseRequested();
}

void HomeController::closeNow() {
  m_window->allowClose();
  m_window->close();
  emit closed();
}

}  // namespace armtrack::gui::home
