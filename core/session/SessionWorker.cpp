// The session's worker thread (Session::workerLoop, docs/session.md): device samples through the
// time synchroniser and the row assembler into the estimator, then to the recorder's queue and to
// the results the GUI drains, with the statistics published every 0.1 s.
#include <pthread.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/estimation/TrunkMotionDetector.h"
#include "core/session/EstimatorMessages.h"
#include "core/session/Session.h"
#include "core/session/TrunkMessages.h"
#include "core/sync/ArmSampleAssembler.h"
#include "core/sync/SensorPayload.h"
#include "core/sync/TimeSync.h"

namespace armtrack::session {

namespace {

/// The stream each sensor block of a row comes from.
StreamRole roleOf(SensorBlock b) {
  switch (b) {
    case SensorBlock::UpperArm:
      return StreamRole::UpperArmImu;
    case SensorBlock::Forearm:
      return StreamRole::ForearmImu;
    case SensorBlock::Elbow:
    case SensorBlock::Wrist:
      return StreamRole::Optical;
    case SensorBlock::CamWrist:
    case SensorBlock::CamElbow:
      return StreamRole::Camera;
  }
  return StreamRole::UpperArmImu;
}

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

/// What the worker thread holds while it runs, and its steps.
class Session::Worker {
  /// The synchroniser's sink: onEvent().
  struct Sink {
    Worker* worker;
    void operator()(const SensorEvent& ev) const { worker->onEvent(ev); }
  };

 public:
  explicit Worker(Session& s)
      : m_s(s),
        m_scale(s.m_scale),
        m_window(s.m_params.latencyWindow * s.m_scale),
        m_sync(syncParams(m_window), clocksOf(s.m_streams)),
        m_assembler(rolesOf(s.m_streams), s.m_params.mergeWindow),
        m_received(s.m_streams.size()),
        m_rejected(s.m_streams.size()),
        m_messages(blockStreams(s), s.m_params.refusalQuietSeconds,
                   s.m_params.refusalSummarySeconds),
        m_trunkMessages(s.m_params.trunkMessageSeconds) {
    if (s.m_params.estimate) m_filter = makeEstimator(s.m_params.estimator);
    // A sensor calibration turns every row's readings from the first on, as a fitted one does.
    m_fitted = s.m_params.calibration;
    m_calibration = s.m_liveCalibration.get();
    // Without a trunk IMU, an optical shoulder tells whether the trunk moved (as `estimate` does,
    // core/estimation/RecordingEstimator.cpp).
    const bool trunkImu = std::any_of(s.m_streams.begin(), s.m_streams.end(), [](const Stream& st) {
      return st.info.role == StreamRole::TrunkImu;
    });
    if (!trunkImu && s.m_columns.elbow) m_trunkDetector.emplace();
    m_local.reserve(4096);
  }

  /// Until the input is closed; then everything received is processed and the recorder told.
  void run() {
    for (;;) {
      const bool closed = takeInput();
      if (closed) break;
      const double now = hostNow() * m_scale;
      m_sync.poll(now, Sink{this});
      // The open row cannot grow any more once the synchroniser has released everything up to a
      // merge window past it: complete it now rather than when the next sample arrives.
      if (auto t = m_assembler.openTime(); t && *t + m_s.m_params.mergeWindow < now - m_window) {
        if (auto done = m_assembler.flush()) processRow(std::move(*done), m_rowOldestArrival);
        m_rowOldestArrival = std::numeric_limits<double>::infinity();
      }
      publish(false);
    }
    // Shutdown: everything received is processed.
    m_sync.flush(Sink{this});
    if (auto done = m_assembler.flush()) processRow(std::move(*done), m_rowOldestArrival);
    if (m_calibration) m_calibration->finish();
    m_messages.finish(m_notes);
    m_trunkMessages.finish(m_notes);
    publish(true);
    {
      std::lock_guard lock(m_s.m_recMutex);
      m_s.m_recClosed = true;
    }
    m_s.m_recCv.notify_one();
  }

 private:
  static std::vector<ClockParams> clocksOf(const std::vector<Stream>& streams) {
    std::vector<ClockParams> clocks;
    for (const Stream& s : streams) {
      ClockParams c;
      c.wrapPeriod = s.info.wrapPeriod;
      clocks.push_back(c);
    }
    return clocks;
  }

  static std::vector<StreamRole> rolesOf(const std::vector<Stream>& streams) {
    std::vector<StreamRole> roles;
    for (const Stream& s : streams) roles.push_back(s.info.role);
    return roles;
  }

  static SyncParams syncParams(double window) {
    SyncParams sp;
    sp.latencyWindow = window;
    return sp;
  }

  /// The stream each sensor block's readings come from, named for the estimator's messages.
  static std::array<std::string, kNumSensorBlocks> blockStreams(const Session& s) {
    std::array<std::string, kNumSensorBlocks> names;
    for (int b = 0; b < kNumSensorBlocks; ++b)
      for (const Stream& st : s.m_streams)
        if (st.info.role == roleOf(static_cast<SensorBlock>(b)))
          names[static_cast<std::size_t>(b)] =
              s.m_devices[static_cast<std::size_t>(st.device)].label.toStdString() + " " +
              st.info.name;
    return names;
  }

  /// Waits for samples (at most a worker period) and pushes them into the synchroniser; true
  /// once the input is closed.
  bool takeInput() {
    bool closed = false;
    {
      std::unique_lock lock(m_s.m_inputMutex);
      m_s.m_inputCv.wait_for(lock, std::chrono::duration<double>(m_s.m_params.workerPeriod),
                             [&] { return !m_s.m_input.empty() || m_s.m_inputClosed; });
      m_maxQueued = std::max(m_maxQueued, m_s.m_input.size());
      m_local.swap(m_s.m_input);
      closed = m_s.m_inputClosed;
    }
    for (DeviceSample& s : m_local) {
      if (s.stream < 0) continue;  // a stream index the device does not have
      const auto k = static_cast<std::size_t>(s.stream);
      ++m_received[k];
      if (!validPayload(m_s.m_streams[k].info.role, s.payload)) {
        ++m_rejected[k];
        continue;
      }
      if (m_sync.push(s.stream, s.deviceTime, s.arrivalTime * m_scale, std::move(s.payload),
                      Sink{this}) == PushResult::Rejected)
        ++m_rejected[k];
    }
    m_local.clear();
    return closed;
  }

  /// Where the synchroniser's events go: into the row being assembled, each finished row on.
  void onEvent(const SensorEvent& ev) {
    if (auto done = m_assembler.add(ev)) {
      processRow(std::move(*done), m_rowOldestArrival);
      m_rowOldestArrival = ev.arrivalTime;
    } else {
      m_rowOldestArrival = std::min(m_rowOldestArrival, ev.arrivalTime);
    }
  }

  /// One assembled row: estimated, kept for the GUI, queued for the recorder (never dropped).
  void processRow(ArmSample row, double oldestArrival) {
    ++m_rows;
    row.t -= m_s.m_startTime * m_scale;  // session time: 0 at start()
    if (row.elbow) m_pendingOptical.opticalElbow = row.elbow;
    if (row.wrist) m_pendingOptical.opticalWrist = row.wrist;
    if (row.camElbow) m_pendingOptical.camElbow = row.camElbow;
    if (row.camWrist) m_pendingOptical.camWrist = row.camWrist;
    if (row.shoulder) m_pendingOptical.opticalShoulder = row.shoulder;
    bool trunkMoved = false;
    if (m_trunkDetector) {
      TrunkMotionInput in;
      in.t = row.t;
      in.shoulder = row.shoulder;
      const TrunkMotionStatus st = m_trunkDetector->update(in);
      trunkMoved = st.moving;
      m_trunkMessages.update(st, row.t, m_notes);
    }
    if (m_filter && m_calibration) calibrateFromMovement(row);
    if (m_filter) {
      // The readings in the fitted sensor frames once a calibration from movement is in use;
      // the recording keeps them as the devices gave them.
      ArmSample corrected;
      if (m_fitted) {
        corrected = row;
        applyCalibration(*m_fitted, corrected);
      }
      const UpdateResult r = m_filter->update(m_fitted ? corrected : row);
      m_messages.update(m_filter->counters(), row.t, m_notes);
      // Rows predicted through refused readings and recovered rows are estimates too: the GUI
      // shows them with their status and (grown) uncertainty.
      if (hasEstimate(r) && row.hasImu()) {
        const JointEstimate e = m_filter->estimate();
        row.estimate = e.th;
        ++m_estimates;
        const double lat = hostNow() - oldestArrival / m_scale;
        m_latency.add(lat);
        EstimateRow out;
        out.t = row.t;
        out.th = e.th;
        out.truth = row.trueAngles;
        out.latency = lat;
        out.thStd = e.thStd;
        out.status = r;
        out.headingFromStartPoseOnly = m_filter->headingFromStartPoseOnly();
        out.opticalElbow = std::exchange(m_pendingOptical.opticalElbow, std::nullopt);
        out.opticalWrist = std::exchange(m_pendingOptical.opticalWrist, std::nullopt);
        out.camElbow = std::exchange(m_pendingOptical.camElbow, std::nullopt);
        out.camWrist = std::exchange(m_pendingOptical.camWrist, std::nullopt);
        out.opticalShoulder = std::exchange(m_pendingOptical.opticalShoulder, std::nullopt);
        if (const std::optional<TrunkEstimate> trunk = m_filter->trunk();
            trunk && trunk->measured) {
          out.trunk = trunk->angles;
          out.trunkStd = trunk->angleStd;
        }
        out.trueTrunk = row.trueTrunk;
        out.trunkMoved = trunkMoved;
        m_fresh.push_back(std::move(out));
      }
    }
    if (m_s.m_writer) {
      keepRecordedGroups(row);
      std::unique_lock lock(m_s.m_recMutex);
      if (m_s.m_recQueue.size() >= m_s.m_params.recorderCapacity) {
        ++m_recorderWaits;  // never drop a row: wait for the recorder
        m_s.m_recSpaceCv.wait(
            lock, [&] { return m_s.m_recQueue.size() < m_s.m_params.recorderCapacity; });
      }
      const bool wake = m_s.m_recQueue.empty();
      m_s.m_recQueue.push_back(std::move(row));
      lock.unlock();
      if (wake) m_s.m_recCv.notify_one();
    }
  }

  /// Feeds the calibration from movement the row as the devices gave it; when a fit has
  /// finished, tells its line, and when its calibration is to be used, restarts the estimator
  /// with it (the new mounting changes the model; a fresh start is the one consistent state).
  /// LiveCalibration hands a fit to be used over only at a row at which the arm rests.
  void calibrateFromMovement(const ArmSample& row) {
    m_calibration->add(row);
    std::optional<AutoCalibrationResult> r = m_calibration->poll(row.t);
    for (std::string& n : m_calibration->takeNotes()) m_news.push_back(std::move(n));
    if (!r) return;
    const bool firstTry = !m_toldCalibration;
    m_toldCalibration = true;
    // Every fit that was made is told; "not tried" only the first time (it repeats until the
    // patient rests once and moves enough).
    if (r->outcome != AutoCalibrationResult::Outcome::NotTried || firstTry)
      m_news.push_back(r->line + " (at " + std::to_string(static_cast<long>(row.t)) + " s)");
    if (!r->calibration) return;
    RecordingMeta meta = m_s.m_params.meta;
    applyCalibration(*r->calibration, meta);
    m_filter = makeEstimator(sessionFilterParams(m_s.m_params.estimator, meta));
    m_fitted = std::move(r->calibration);
    // The new estimator's counters start from zero: the old one's untold refusals are summed
    // up now and the messages start afresh with it.
    m_messages.finish(m_notes);
    m_messages = EstimatorMessages(blockStreams(m_s), m_s.m_params.refusalQuietSeconds,
                                   m_s.m_params.refusalSummarySeconds);
    m_news.push_back(
        "the estimator restarted with the straps fitted from the movement: the "
        "angles may jump once here");
  }

  /// Leaves out of a row what the recording has no columns for (a device that sent a shoulder or
  /// true trunk angles it did not declare in its StreamInfo): the rest of the row is recorded,
  /// and the user told once.
  void keepRecordedGroups(ArmSample& row) {
    const RecordingColumns& c = m_s.m_columns;
    const bool shoulder = row.shoulder && !c.shoulder, trueTrunk = row.trueTrunk && !c.trueTrunk;
    if (!shoulder && !trueTrunk) return;
    if (shoulder) row.shoulder.reset();
    if (trueTrunk) row.trueTrunk.reset();
    if (!m_toldUndeclared) {
      m_toldUndeclared = true;
      m_notes.push_back(std::string("recording: a device sent ") +
                        (shoulder ? "shoulder positions" : "true trunk angles") +
                        " its stream does not declare; they are used but not recorded");
    }
  }

  /// The messages made under no lock, told through logEvent (so maxEvents holds) and problem().
  void tellNotes() {
    for (const std::string& n : m_notes) {
      m_s.logEvent(n);
      emit m_s.problem(QString::fromStdString(n));
    }
    m_notes.clear();
    // What the calibration from movement did is news, not a problem: the messages only (the
    // screens say it in their own words from Session::movementCalibration()).
    for (const std::string& n : m_news) m_s.logEvent(n);
    m_news.clear();
  }

  /// New estimates to the results the GUI drains; the statistics every 0.1 s, and at the end.
  void publish(bool final) {
    tellNotes();
    if (!m_fresh.empty()) {
      std::lock_guard lock(m_s.m_resultMutex);
      for (EstimateRow& r : m_fresh) {
        if (m_s.m_results.size() >= m_s.m_params.resultCapacity) {
          m_s.m_results.pop_front();
          std::lock_guard st(m_s.m_statsMutex);
          ++m_s.m_stats.resultsOverwritten;
        }
        m_s.m_results.push_back(std::move(r));
      }
      m_fresh.clear();
    }
    const double now = hostNow();
    if (!final && now < m_nextStats) return;
    m_nextStats = now + 0.1;
    std::uint64_t totalRejects = 0;
    std::unique_lock lock(m_s.m_statsMutex);
    SessionStats& stats = m_s.m_stats;
    for (std::size_t i = 0; i < m_s.m_streams.size(); ++i) {
      StreamStats& st = stats.streams[i];
      st.received = m_received[i];
      st.rejected = m_rejected[i];
      totalRejects += m_rejected[i];
      const DeviceSyncStats ds = m_sync.stats(static_cast<int>(i));
      st.late = ds.merge.late;
      st.driftPpm = ds.driftPpm;
      st.jitterMs = ds.jitter * 1e3;
    }
    stats.rows = m_rows;
    stats.estimates = m_estimates;
    stats.recorderWaits = m_recorderWaits;
    stats.latency = m_latency;
    stats.maxInputQueued = std::max(stats.maxInputQueued, m_maxQueued);
    if (m_filter) stats.estimator = m_filter->counters();
    stats.workerCpuSeconds = threadCpuSeconds();
    if (totalRejects > m_reportedRejects) {
      m_notes.push_back("rejected " + std::to_string(totalRejects - m_reportedRejects) +
                        " sample(s) with NaN/infinite values or the wrong kind of data");
      m_reportedRejects = totalRejects;
    }
    lock.unlock();
    tellNotes();
  }

  Session& m_s;
  // A replay at N x runs the session's clocks N times faster, so device time stays the
  // recording's time; latencies are reported in real seconds.
  const double m_scale;
  const double m_window;
  TimeSync<SensorPayload> m_sync;
  ArmSampleAssembler m_assembler;
  std::unique_ptr<JointEstimator> m_filter;
  std::vector<DeviceSample> m_local;
  std::vector<std::uint64_t> m_received, m_rejected;
  std::uint64_t m_rows = 0, m_estimates = 0, m_recorderWaits = 0;
  LatencyHistogram m_latency;
  std::vector<EstimateRow> m_fresh;
  std::size_t m_maxQueued = 0;
  double m_rowOldestArrival = std::numeric_limits<double>::infinity();
  double m_nextStats = 0.0;
  std::uint64_t m_reportedRejects = 0;
  // What the estimator refused, its recoveries and restarts, told as they happen (rate-limited).
  EstimatorMessages m_messages;
  std::vector<std::string> m_notes;  // messages made under no lock, told by publish()
  std::vector<std::string> m_news;   // the same, for the messages only (not problem())
  // Without a trunk IMU: whether the trunk left its start pose (an optical shoulder's cue).
  std::optional<TrunkMotionDetector> m_trunkDetector;
  TrunkMessages m_trunkMessages;
  bool m_toldUndeclared = false;
  // The calibration from movement (the session's, when asked for) and the one in use.
  LiveCalibration* m_calibration = nullptr;
  std::optional<Calibration> m_fitted;
  bool m_toldCalibration = false;
  // Optical measurements waiting for the next estimate (they often come in rows of their own).
  EstimateRow m_pendingOptical;
};

void Session::workerLoop() {
  pthread_setname_np(pthread_self(), "armtrack-worker");
  Worker(*this).run();
}

}  // namespace armtrack::session
