// The live session screen under load (not a ctest test; figures for the README). Runs a virtual
// arm session (1 kHz IMUs, 30 Hz Kinect and webcam, EKF) in the real screen and prints, every
// report interval: frames per second of the 3D view and of the plots, the longest stall of the
// GUI thread (a 2 ms watchdog timer: the longest time the event loop did not get round to it)
// with how much of it the thread ran, waited for a core or was blocked (the kernel's schedstat),
// the whole process's CPU use and its resident memory; at the end, each thread's CPU and time
// waiting for a core, and whether the estimator kept up.
//
//   tests/support/run-gui-test.sh build/tests/benchmarks/bench_live_screen [--seconds 600]
//       [--interval 30] [--size 1280x800] [--worker-nice N]
#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <QApplication>
#include <QChartView>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QTimer>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "app/gui/live/LiveSessionScreen.h"
#include "app/gui/services/SessionController.h"
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

/// One thread of this process as the scheduler counts it (ms on a CPU and waiting for one).
struct ThreadTimes {
  std::string name;
  double cpuMs = 0, queueMs = 0;
};

/// Every thread of this process by id.
std::map<int, ThreadTimes> threadTimes() {
  std::map<int, ThreadTimes> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    ThreadTimes t;
    std::ifstream comm(e.path() / "comm");
    std::getline(comm, t.name);
    std::ifstream stat(e.path() / "schedstat");
    double cpuNs = 0, waitNs = 0;
    if (!(stat >> cpuNs >> waitNs)) continue;  // ended meanwhile
    t.cpuMs = cpuNs * 1e-6;
    t.queueMs = waitNs * 1e-6;
    out[std::stoi(e.path().filename().string())] = t;
  }
  return out;
}

/// A thread's kind: its name without a trailing number ("llvmpipe-1" -> "llvmpipe-"); the main
/// thread is the GUI thread.
std::string threadKind(int tid, const std::string& name) {
  if (tid == getpid()) return "GUI thread";
  std::string kind = name;
  while (!kind.empty() && std::isdigit(static_cast<unsigned char>(kind.back()))) kind.pop_back();
  return kind;
}

/// The application's own worker threads (estimator, recorder, devices, session control,
/// records), by the names it gives them (15 characters at most on Linux).
bool isAppWorker(const std::string& name) {
  return name.rfind("armtrack-", 0) == 0 || name.rfind("device ", 0) == 0 ||
         name.rfind("records", 0) == 0;
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
  cli.addOption({QStringLiteral("worker-nice"),
                 QStringLiteral("Once the session runs, set the nice value of the application's "
                                "own worker threads (estimator, recorder, devices, session "
                                "control, records) to n; the GUI thread keeps 0."),
                 QStringLiteral("n")});
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
  // Of the longest stall, how long the GUI thread ran on a core, waited in the run queue for
  // one (other processes had them), and was blocked (on the OpenGL rasteriser's threads or the
  // X server, themselves waiting for cores when the machine is loaded); and the most CPU time
  // any stall took, which is the work the program does in one go.
  struct Stall {
    double ms = 0, cpuMs = 0, queueMs = 0;
  };
  Stall longest, longestAll;
  double mostCpuMs = 0, mostCpuAllMs = 0;
  // Stalls over 20 and 50 ms, in the interval and in the whole run: steadier than the longest.
  std::uint64_t over20 = 0, over50 = 0, over20All = 0, over50All = 0, ticks = 0;
  double lastTick = 0, lastCpu = 0, lastWait = 0;
  QTimer watchdog;
  watchdog.setTimerType(Qt::PreciseTimer);
  QObject::connect(&watchdog, &QTimer::timeout, [&] {
    const double now = clock.nsecsElapsed() * 1e-6;
    const auto [cpu, wait] = threadCpuAndWaitMs();
    if (lastTick > 0) {
      const Stall st{now - lastTick - 2.0, cpu - lastCpu, wait - lastWait};
      if (st.ms > longest.ms) longest = st;
      mostCpuMs = std::max(mostCpuMs, st.cpuMs);
      over20 += st.ms > 20 ? 1 : 0;
      over50 += st.ms > 50 ? 1 : 0;
      ++ticks;
    }
    lastTick = now;
    lastCpu = cpu;
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
  std::map<int, ThreadTimes> threadsAtStart;
  bool failed = false;
  const bool renice = cli.isSet(QStringLiteral("worker-nice"));
  const int workerNice = cli.value(QStringLiteral("worker-nice")).toInt();
  QObject::connect(&screen, &armtrack::app::gui::LiveSessionScreen::sessionFailed,
                   [&](const QString& why) {
                     std::fprintf(stderr, "bench_live_screen: %s\n", qPrintable(why));
                     failed = true;
                     app.exit(1);
                   });
  QObject::connect(&screen, &armtrack::app::gui::LiveSessionScreen::sessionStarted, [&] {
    // Skip the first second (start-up), then measure.
    QTimer::singleShot(1000, [&] {
      if (renice) {
        for (const auto& [tid, t] : threadTimes()) {
          if (!isAppWorker(t.name)) continue;
          const int r = setpriority(PRIO_PROCESS, static_cast<id_t>(tid), workerNice);
          std::printf("nice %d for thread %d (%s)%s\n", workerNice, tid, t.name.c_str(),
                      r == 0 ? "" : ": refused");
        }
      }
      start = prev = mark();
      threadsAtStart = threadTimes();
      lastTick = 0;
      longest = {};
      mostCpuMs = 0;
      over20 = over50 = ticks = 0;
      watchdog.start(2);
      std::printf(
          "Live session screen, %dx%d, virtual arm (1 kHz IMUs, 30 Hz Kinect and "
          "webcam), EKF, drained at %.0f Hz\n",
          screen.width(), screen.height(), screen.drainRate());
      std::printf("%6s %6s %8s %8s %8s %9s %24s %5s %5s %8s %6s %7s %7s %5s\n", "time s", "3D fps",
                  "plot fps", "paint/s", "drains/s", "stall ms", "(cpu/queue/blocked ms)", ">20ms",
                  ">50ms", "cpu max", "CPU %", "RSS MB", "heap MB", "load");
      std::fflush(stdout);
    });
  });
  QTimer report;
  QObject::connect(&report, &QTimer::timeout, [&] {
    if (start.t == 0) return;
    const Mark m = mark();
    const double dt = m.t - prev.t;
    std::printf(
        "%6.0f %6.1f %8.1f %8.1f %8.1f %9.1f %8.1f/%6.1f/%7.1f %5llu %5llu %8.1f %6.1f %7.1f "
        "%7.1f %5.2f\n",
        m.t - start.t, (m.frames - prev.frames) / dt, (m.redraws - prev.redraws) / dt,
        (m.paints - prev.paints) / dt / std::max<qsizetype>(1, charts.size()),
        (m.drains - prev.drains) / dt, longest.ms, longest.cpuMs, longest.queueMs,
        longest.ms - longest.cpuMs - longest.queueMs, static_cast<unsigned long long>(over20),
        static_cast<unsigned long long>(over50), mostCpuMs, 100.0 * (m.cpu - prev.cpu) / dt,
        residentMb(), heapInUseMb(), loadAverage());
    over20All += over20;
    over50All += over50;
    over20 = over50 = 0;
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
    if (longest.ms > longestAll.ms) longestAll = longest;
    mostCpuAllMs = std::max(mostCpuAllMs, mostCpuMs);
    longest = {};
    mostCpuMs = 0;
    prev = m;
    if (m.t - start.t >= seconds - 1e-3) {
      const double total = m.t - start.t;
      std::printf(
          "whole run: 3D %.1f fps, plots %.1f fps, longest GUI stall %.1f ms (on a core %.1f, "
          "in the run queue %.1f, blocked %.1f), most CPU in one stall %.1f ms, CPU %.0f %% of "
          "one core, %llu estimates drained\n",
          (m.frames - start.frames) / total, (m.redraws - start.redraws) / total, longestAll.ms,
          longestAll.cpuMs, longestAll.queueMs,
          longestAll.ms - longestAll.cpuMs - longestAll.queueMs, mostCpuAllMs,
          100.0 * (m.cpu - start.cpu) / total,
          static_cast<unsigned long long>(m.estimates - start.estimates));
      std::printf("stalls over 20 ms: %llu, over 50 ms: %llu (watchdog ticks %llu)\n",
                  static_cast<unsigned long long>(over20All),
                  static_cast<unsigned long long>(over50All),
                  static_cast<unsigned long long>(ticks));
      // Each kind of thread's share of a core and its time waiting for one over the run.
      std::map<std::string, ThreadTimes> kinds;
      for (const auto& [tid, t] : threadTimes()) {
        const auto before = threadsAtStart.find(tid);
        ThreadTimes& k = kinds[threadKind(tid, t.name)];
        k.cpuMs += t.cpuMs - (before != threadsAtStart.end() ? before->second.cpuMs : 0.0);
        k.queueMs += t.queueMs - (before != threadsAtStart.end() ? before->second.queueMs : 0.0);
      }
      std::printf("threads (CPU %% of one core, waiting for a core %%):\n");
      for (const auto& [kind, t] : kinds)
        if (t.cpuMs > 0.001 * total * 1000)
          std::printf("  %-18s %5.1f %% %5.1f %%%s\n", kind.c_str(), t.cpuMs / total / 10.0,
                      t.queueMs / total / 10.0, isAppWorker(kind) ? "  (worker)" : "");
      // Whether the estimator kept up: samples lost, the most waiting, rows without estimate.
      if (const auto* c = screen.findChild<armtrack::app::gui::SessionController*>();
          c && c->session()) {
        const armtrack::session::SessionStats st = c->session()->stats();
        std::printf(
            "estimator: %llu rows, %llu estimates, input overflow %llu, lost %llu, most samples "
            "queued %zu, GUI rows overwritten %llu, latency p99 %.1f ms, max %.1f ms, worker "
            "CPU %.1f %%\n",
            static_cast<unsigned long long>(st.rows), static_cast<unsigned long long>(st.estimates),
            static_cast<unsigned long long>(st.inputOverflow),
            static_cast<unsigned long long>(st.lost()), st.maxInputQueued,
            static_cast<unsigned long long>(st.resultsOverwritten), st.latency.quantile(0.99) * 1e3,
            st.latency.max() * 1e3, 100.0 * st.workerCpuSeconds / st.elapsed);
      }
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
