// AppController's demo mode (--demo: demo records made, signed in, a live session at once) and
// the command line's quit hooks (--quit-after, --quit-when-live, --screenshot), apart from the
// navigation in AppController.cpp.
#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QScreen>
#include <QStandardPaths>
#include <QTimer>
#include <cstdio>

#include "app/gui/AppController.h"
#include "app/gui/CloseWhileRecording.h"
#include "app/gui/MainWindow.h"
#include "app/gui/common/MessageScreen.h"
#include "app/gui/home/HomeController.h"
#include "app/gui/home/HomeWindow.h"
#include "app/gui/live/LiveSessionScreen.h"
#include "app/gui/newsession/LiveConfig.h"
#include "app/gui/services/DemoData.h"
#include "core/storage/DatabaseFiles.h"

namespace armtrack::gui {

void AppController::quitAfterLimit() {
  if (!m_options.screenshot.isEmpty()) saveWindowImage(m_options.screenshot);
  if (!m_options.quitWhenLive) return quitApplication(0);
  std::fprintf(stderr, "armtrack: no live session showed estimates within %g s\n",
               m_options.quitAfterSeconds);
  quitApplication(1);
}

void AppController::quitApplication(int code) {
  m_closeGuard->quitting();
  if (m_home) {
    m_quitCode = code;
    m_home->quit();  // closeHome() ends the application once the window has closed
    return;
  }
  code == 0 ? QApplication::quit() : QApplication::exit(code);
}

void AppController::quitOnceLive(QWidget* screen) {
  auto* live = qobject_cast<app::gui::LiveSessionScreen*>(screen);
  if (!live) return;
  connect(live, &app::gui::LiveSessionScreen::sessionFailed, this, [](const QString& why) {
    std::fprintf(stderr, "armtrack: the live session failed: %s\n", qPrintable(why));
    QApplication::exit(1);
  });
  auto* poll = new QTimer(live);
  connect(poll, &QTimer::timeout, this, [this, live, poll] {
    if (live->sessionTime() < 2.0 || live->estimatesDrained() == 0) return;
    poll->stop();
    std::fprintf(stderr, "armtrack: the live session is running: %llu estimates in %.1f s\n",
                 static_cast<unsigned long long>(live->estimatesDrained()), live->sessionTime());
    if (!m_options.screenshot.isEmpty() && !saveWindowImage(m_options.screenshot))
      return QApplication::exit(1);
    m_closeGuard->quitting();
    QApplication::quit();
  });
  poll->start(100);
}

void AppController::startDemoSession() {
  // The demo patient with the demo protocol, live with the virtual arm at once.
  m_records->call(
      m_window.get(),
      [](storage::ClinicalStore& s) {
        SessionPlan plan;
        plan.patient = s.patient(QString::fromLatin1(DemoAccounts::kLivePatient));
        plan.protocol = s.protocol(QString::fromLatin1(DemoAccounts::kLiveProtocol));
        plan.side = defaultSide(plan.patient, plan.protocol);
        return plan;
      },
      [this](const SessionPlan& plan) {
        NewSessionChoices demo;
        // The virtual arm makes the protocol's exercise, so the counter counts.
        demo.devices = demoDevicesFor(plan);
        showLiveSession(plan, demo);
        emit demoReady();
      },
      [this](const RecordsFailure& f) { showDatabaseProblem(f); });
}

bool AppController::saveWindowImage(const QString& path) const {
  QApplication::processEvents();
  // From the screen, so the OpenGL views are included.
  const QWidget* window = m_home ? static_cast<QWidget*>(m_home->window()) : m_window.get();
  const QPixmap shot = window->screen()->grabWindow(window->winId());
  const bool ok = shot.save(path);
  if (!ok) qWarning("armtrack: cannot write the screenshot %s", qPrintable(path));
  return ok;
}

storage::DatabaseUrl AppController::demoDatabaseUrl() const {
  if (!m_options.database.isEmpty()) return storage::DatabaseUrl::parse(m_options.database);
  storage::DatabaseUrl url;
  url.path = QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                 .filePath(QStringLiteral("demo/armtrack-demo.db"));
  return url;
}

void AppController::startDemo() {
  storage::DatabaseUrl url;
  try {
    url = demoDatabaseUrl();
  } catch (const storage::StorageError& e) {
    return showDatabaseProblem({e.kind(), QString::fromStdString(e.what())});
  }
  m_demoUrl = url;
  if (url.engine == storage::DatabaseUrl::Engine::Sqlite)
    storage::makePrivateFolders(QFileInfo(url.path).absolutePath());  // 0700
  auto* wait = new MessageScreen(
      [] { return tr("Preparing the demo"); },
      [where = url.display()] {
        return tr("Making demo records in %1: three patients, two protocols and six weeks of "
                  "sessions, simulated and analysed the way real ones are. This takes a few "
                  "seconds.")
            .arg(where);
      });
  wait->setProgress(0);
  m_window->showScreen(wait);
  RecordsJob* job = m_records->startJob(
      wait,
      [url](JobContext& c) {
        return buildDemoDatabase(
            url, [&c](int p) { c.progress(p); }, c.cancelFlag());
      },
      [this, wait, url](bool built) {
        if (!built) return QApplication::quit();
        if (m_options.home) {
          wait->setText([] { return tr("Signing in as the demo patient at home..."); });
          m_records->signIn(
              url, QString::fromLatin1(DemoAccounts::kHome),
              QString::fromLatin1(DemoAccounts::kPassword), wait,
              [this](const storage::User& user) {
                emit signedIn(user.name);
                showHome();
                emit demoReady();
              },
              [this](const RecordsFailure& f) { showDatabaseProblem(f); });
          return;
        }
        wait->setText([] { return tr("Signing in as the demo therapist..."); });
        m_records->signIn(
            url, QString::fromLatin1(DemoAccounts::kTherapist),
            QString::fromLatin1(DemoAccounts::kPassword), wait,
            [this](const storage::User& user) {
              m_window->setSignedIn([name = user.name, role = user.role] {
                return tr("%1 (%2, demo)").arg(name, roleText(role));
              });
              m_window->showStatus(
                  [] {
                    return tr("Demo records: accounts \"%1\" and \"%2\", password \"%3\".")
                        .arg(QString::fromLatin1(DemoAccounts::kTherapist),
                             QString::fromLatin1(DemoAccounts::kAdmin),
                             QString::fromLatin1(DemoAccounts::kPassword));
                  },
                  0);
              emit signedIn(user.name);
              startDemoSession();
            },
            [this](const RecordsFailure& f) { showDatabaseProblem(f); });
      },
      [this](const RecordsFailure& f) { showDatabaseProblem(f); });
  connect(job, &RecordsJob::progress, wait, &MessageScreen::setProgress);
  wait->addAction([] { return tr("&Cancel"); }, [job] { job->cancel(); });
}

}  // namespace armtrack::gui
