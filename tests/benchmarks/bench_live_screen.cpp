// The live session screen under load (not a ctest test; figures for the README). Runs a virtual
// arm session (1 kHz IMUs, 30 Hz Kinect and webcam, EKF) in the real screen and prints, every
// report interval: frames per second of the 3D view and of the plots, the longest stall of the
// GUI thread (a 2 ms watchdog timer: the longest time the event loop did not get round to it)
// and the same less the time the thread waited for a core (the kernel's schedstat),
// the whole process's CPU use and its resident memory.
//
//   tests/support/run-gui-test.sh build/tests/benchmarks/bench_live_screen [--seconds 600]
//       [--interval 30] [--size 1280x800]
#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <QApplication>
#include <QChartView>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>

#include "app/gui/live/LiveSessionScreen.h"
#include "app/plugins/PluginRegistry.h"
#include "ui/AnglePlotPanel.h"
#include "ui/OpenGlSetup.h"

namespace {

double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double residentMb() {
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

/// Bytes the allocator has handed out and not had back (all arenas): beside the resident size,
/// it tells a leak (both grow) from memory the allocator keeps (only the resident size grows).
double heapInUseMb() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd) / (1024.0 * 1024.0);
}

/// The calling thread's time on a CPU and waiting in a run queue for one (ms), from the
/// scheduler's statistics: a stall spent waiting for a core is the machine's, not the program's.
std::pair<double, double> threadCpuAndWaitMs() {
  std::ifstream f("/proc/thread-self/schedstat");
  double cpuNs = 0, waitNs = 0;
  f >> cpuNs >> waitNs;
  return {cpuNs * 1e-6, waitNs * 1e-6};
}

double loadAverage() {
  std::ifstream f("/proc/loadavg");
  double one = 0;
  f >> one;
  return one;
}

/// Counts the paints of the charts' viewports (what the user sees refresh).
class PaintCounter : public QObject {
 public:
  std::uint64_t paints = 0;
  bool eventFilter(QObject*, QEvent* e) override {
    if (e->type() == QEvent::Paint) ++paints;
    return false;
  }
};

/// Times every event the GUI thread delivers (outermost deliveries only) and keeps, per kind of
/// receiver and event, the longest and the total: which work makes the GUI thread stall.
class ProfilingApplication : public QApplication {
 public:
  using QApplication::QApplication;
  bool profiling = false;
  struct Figure {
    double maxMs = 0, totalMs = 0;
    std::uint64_t count = 0;
  };
  std::map<std::string, Figure> figures;

  bool notify(QObject* receiver, QEvent* e) override {
    if (!profiling || m_depth > 0) return QApplication::notify(receiver, e);
    // Named before delivery: a DeferredDelete leaves the receiver gone.
    const char* cls = receiver->metaObject()->className();
    const char* parent = receiver->parent() ? receiver->parent()->metaObject()->className() : "";
    const int type = static_cast<int>(e->type());
    ++m_depth;
    QElapsedTimer t;
    t.start();
    const bool r = QApplication::notify(receiver, e);
    const double ms = t.nsecsElapsed() * 1e-6;
    --m_depth;
    if (ms >= 0.05) {
      Figure& f = figures[std::string(cls) + "<" + parent + " " + std::to_string(type)];
      f.maxMs = std::max(f.maxMs, ms);
      f.totalMs += ms;
      ++f.count;
    }
    return r;
  }

  /// The slowest kinds of work since the last call, longest first.
  void print(double seconds) {
    std::vector<std::pair<std::string, Figure>> v(figures.begin(), figures.end());
    std::sort(v.begin(), v.end(),
              [](const auto& a, const auto& b) { return a.second.maxMs > b.second.maxMs; });
    for (std::size_t i = 0; i < std::min<std::size_t>(6, v.size()); ++i)
      std::printf("    %-58s max %6.1f ms, %6.1f ms/s, %5.1f /s\n", v[i].first.c_str(),
                  v[i].second.maxMs, v[i].second.totalMs / seconds,
                  static_cast<double>(v[i].second.count) / seconds);
    figures.clear();
  }

 private:
  int m_depth = 0;
};

}  // namespace

int main(int argc, char** argv) {
  armtrack::ui::setDefaultSurfaceFormat();
  ProfilingApplication app(argc, argv);
  QCommandLineParser cli;
  cli.addHelpOption();
  cli.addOption({QStringLiteral("seconds"), QStringLiteral("Length of the run (s)."),
                 QStringLiteral("s"), QStringLiteral("60")});
  cli.addOption({QStringLiteral("interval"), QStringLiteral("Seconds between reports."),
                 QStringLiteral("s"), QStringLiteral("10")});
  cli.addOption({QStringLiteral("size"), QStringLiteral("Window size."), QStringLiteral("WxH"),
                 QStringLiteral("1280x800")});
  cli.addOption({QStringLiteral("plugins"), QStringLiteral("Plugin folder."), QStringLiteral("dir"),
                 QStringLiteral(ARMTRACK_PLUGIN_DIR)});
  cli.addOption({QStringLiteral("hide"),
                 QStringLiteral("Hide a part to see what it costs: 3d, plots, table."),
                 QStringLiteral("part")});
  cli.addOption({QStringLiteral("profile"),
                 QStringLiteral("Print, each interval, the GUI thread's slowest kinds of work "
                                "(receiver class < parent class, event type).")});
  cli.process(app);
  app.profiling = cli.isSet(QStringLiteral("profile"));
  const double seconds = cli.value(QStringLiteral("seconds")).toDouble();
  const double interval = cli.value(QStringLiteral("interval")).toDouble();
  const QStringList wh = cli.value(QStringLiteral("size")).split(u'x');

  armtrack::app::PluginRegistry registry;
  registry.load({cli.value(QStringLiteral("plugins"))});
  armtrack::app::gui::LiveSessionConfig config;
  config.devices = armtrack::app::gui::demoDevices();
  config.patientLabel = QStringLiteral("Benchmark");
  config.targetDeg = std::make_pair(20.0, 90.0);
  config.targetRepetitions = 10;
  armtrack::app::gui::LiveSessionScreen screen(registry, config);
  screen.resize(wh.value(0).toInt(), wh.value(1).toInt());
  screen.show();
  for (const QString& part : cli.values(QStringLiteral("hide"))) {
    if (part == u"3d") screen.armView()->hide();
    if (part == u"plots") screen.plots()->hide();
    if (part == u"table") screen.plots()->setTableVisible(false);
  }
  PaintCounter plotPaints;
  const auto charts = screen.plots()->findChildren<QChartView*>();
  for (QChartView* c : charts) c->viewport()->installEventFilter(&plotPaints);

  // The watchdog: a 2 ms timer on the GUI thread; a late tick is a stall.
  QElapsedTimer clock;
  clock.start();
  // Beside each stall, the part of it the GUI thread spent waiting for a core (other processes
  // had them): "own" is the stall less that wait.
  double lastTick = 0, maxStallMs = 0, maxStallAllMs = 0, maxOwnMs = 0, maxOwnAllMs = 0;
  double lastWait = 0;
  QTimer watchdog;
  watchdog.setTimerType(Qt::PreciseTimer);
  QObject::connect(&watchdog, &QTimer::timeout, [&] {
    const double now = clock.nsecsElapsed() * 1e-6;
    const double wait = threadCpuAndWaitMs().second;
    if (lastTick > 0) {
      const double stall = now - lastTick - 2.0;
      maxStallMs = std::max(maxStallMs, stall);
      maxOwnMs = std::max(maxOwnMs, stall - (wait - lastWait));
    }
    lastTick = now;
    lastWait = wait;
  });

  struct Mark {
    double t, cpu;
    std::uint64_t frames, redraws, paints, drains, estimates;
  };
  auto mark = [&] {
    return Mark{clock.nsecsElapsed() * 1e-9, cpuSeconds(),      screen.armView()->framesRendered(),
                screen.plots()->redraws(),   plotPaints.paints, screen.drains(),
                screen.estimatesDrained()};
  };
  Mark start{}, prev{};
  bool failed = false;
  QObject::connect(&screen, &armtrack::app::gui::LiveSessionScreen::sessionFailed,
                   [&](const QString& why) {
                     std::fprintf(stderr, "bench_live_screen: %s\n", qPrintable(why));
                     failed = true;
                     app.exit(1);
                   });
  QObject::connect(&screen, &armtrack::app::gui::LiveSessionScreen::sessionStarted, [&] {
    // Skip the first second (start-up), then measure.
    QTimer::singleShot(1000, [&] {
      start = prev = mark();
      lastTick = 0;
      maxStallMs = maxOwnMs = 0;
      watchdog.start(2);
      std::printf(
          "Live session screen, %dx%d, virtual arm (1 kHz IMUs, 30 Hz Kinect and "
          "webcam), EKF, drained at %.0f Hz\n",
          screen.width(), screen.height(), screen.drainRate());
      std::printf("%8s %9s %11s %12s %10s %13s %9s %9s %10s %10s %6s\n", "time s", "3D fps",
                  "plot fps", "plot paint/s", "drains/s", "max stall ms", "own ms", "CPU %",
                  "RSS MB", "heap MB", "load");
      std::fflush(stdout);
    });
  });
  QTimer report;
  QObject::connect(&report, &QTimer::timeout, [&] {
    if (start.t == 0) return;
    const Mark m = mark();
    const double dt = m.t - prev.t;
    std::printf("%8.0f %9.1f %11.1f %12.1f %10.1f %13.1f %9.1f %9.1f %10.1f %10.1f %6.2f\n",
                m.t - start.t, (m.frames - prev.frames) / dt, (m.redraws - prev.redraws) / dt,
                (m.paints - prev.paints) / dt / std::max<qsizetype>(1, charts.size()),
                (m.drains - prev.drains) / dt, maxStallMs, maxOwnMs,
                100.0 * (m.cpu - prev.cpu) / dt, residentMb(), heapInUseMb(), loadAverage());
    std::fflush(stdout);
    if (app.profiling) {
      const auto& d = screen.drainTimes();
      std::printf(
          "    drain, longest parts: take %.1f, feed %.1f, plots %.1f, 3D %.1f, device figures "
          "%.1f, whole %.1f ms; largest batch %zu estimates\n",
          d.takeMs, d.feedMs, d.plotsMs, d.armMs, d.statsMs, d.wholeMs, d.mostRows);
      screen.resetDrainTimes();
      app.print(dt);
    }
    maxStallAllMs = std::max(maxStallAllMs, maxStallMs);
    maxOwnAllMs = std::max(maxOwnAllMs, maxOwnMs);
    maxStallMs = maxOwnMs = 0;
    prev = m;
    if (m.t - start.t >= seconds - 1e-3) {
      const double total = m.t - start.t;
      std::printf(
          "whole run: 3D %.1f fps, plots %.1f fps, longest GUI stall %.1f ms (%.1f ms not "
          "counting waits for a core), CPU %.0f %% of one core, %llu estimates drained\n",
          (m.frames - start.frames) / total, (m.redraws - start.redraws) / total, maxStallAllMs,
          maxOwnAllMs, 100.0 * (m.cpu - start.cpu) / total,
          static_cast<unsigned long long>(m.estimates - start.estimates));
      std::fflush(stdout);
      screen.stop();
    }
  });
  QObject::connect(&screen, &armtrack::app::gui::LiveSessionScreen::sessionStopped,
                   [&] { app.exit(failed ? 1 : 0); });
  report.start(static_cast<int>(interval * 1000));
  screen.start();
  return app.exec();
}
