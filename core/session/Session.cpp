#include "core/session/Session.h"

#include <fcntl.h>
#include <pthread.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QCoreApplication>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <ctime>
#include <system_error>
#include <utility>

#include "core/sync/SensorPayload.h"

namespace armtrack::session {

namespace {

/// Creates path empty, failing if it exists (O_EXCL): a recording that appears between a check
/// and the writer's open is never replaced. Returns an empty string or why not.
std::string claimName(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd >= 0) {
    ::close(fd);
    return {};
  }
  if (errno == EEXIST)
    return path.string() +
           ": exists; allow overwriting (--overwrite) to replace it, or choose "
           "another file name";
  return path.string() + ": cannot create the file: " + std::generic_category().message(errno);
}

/// Removes the empty file claimName() made, unless a writer has it (locked) or wrote into it.
void removeUnusedClaim(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  struct stat st {};
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0 && ::fstat(fd, &st) == 0 && st.st_size == 0)
    ::unlink(path.c_str());
  ::close(fd);
}

}  // namespace

// ---------------------------------------------------------------------------------------------

void LatencyHistogram::add(double seconds) {
  const double s = std::max(0.0, seconds);
  const auto bin = static_cast<std::size_t>(std::min(s / kBin, static_cast<double>(kBins)));
  ++m_bins[bin];
  ++m_count;
  m_max = std::max(m_max, s);
}

double LatencyHistogram::quantile(double q) const {
  if (m_count == 0) return 0.0;
  const auto want = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(m_count)));
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < m_bins.size(); ++i) {
    seen += m_bins[i];
    if (seen >= std::max<std::uint64_t>(want, 1))
      return i == kBins ? m_max : std::min(m_max, static_cast<double>(i + 1) * kBin);
  }
  return m_max;
}

std::uint64_t SessionStats::lost() const {
  std::uint64_t n = inputOverflow;
  for (const StreamStats& s : streams) n += s.rejected;
  return n;
}

// ---------------------------------------------------------------------------------------------

Session::Session(SessionParams params, QObject* parent)
    : QObject(parent), m_params(std::move(params)) {}

Session::~Session() {
  stop();
}

/// One device's way into the session: samples to the worker's queue, states and problems to the
/// session's messages and signals. Called in the device's thread.
class Session::DeviceInput final : public SampleInput {
 public:
  DeviceInput(Session& session, int index, std::string label)
      : m_session(session), m_index(index), m_label(std::move(label)) {}

  void samplesArrived(const SampleBatch& batch) override { m_session.onSamples(m_index, batch); }
  void stateChanged(DeviceState state, const std::string& reason) override {
    m_session.logEvent(m_label + ": " + toString(state) +
                       (reason.empty() ? std::string() : " (" + reason + ")"));
    emit m_session.deviceStateChanged(m_index, state, QString::fromStdString(reason));
  }
  void problemReported(const std::string& message) override {
    m_session.logEvent(m_label + ": " + message);
    emit m_session.problem(QString::fromStdString(m_label + ": " + message));
  }

 private:
  Session& m_session;
  const int m_index;
  const std::string m_label;
};

int Session::addDevice(std::unique_ptr<SampleSource> device, const QString& label) {
  DeviceEntry e;
  e.firstStream = static_cast<int>(m_streams.size());
  const int index = static_cast<int>(m_devices.size());
  for (std::size_t k = 0; k < device->streams().size(); ++k)
    m_streams.push_back({index, static_cast<int>(k), device->streams()[k]});
  e.device = std::move(device);
  e.label = label;
  m_devices.push_back(std::move(e));
  return index;
}

void Session::logEvent(const std::string& text) {
  {
    std::lock_guard lock(m_statsMutex);
    if (m_events.size() >= m_params.maxEvents) m_events.erase(m_events.begin());
    m_events.push_back(text);
  }
}

QString Session::columnsOfStreams(RecordingColumns& columns, bool& imu) {
  imu = false;
  columns = RecordingColumns{};
  columns.estimate = m_params.estimate;
  for (const Stream& s : m_streams) {
    switch (s.info.role) {
      case StreamRole::UpperArmImu:
        imu = columns.upperArm = true;
        break;
      case StreamRole::ForearmImu:
        imu = columns.forearm = true;
        break;
      case StreamRole::Optical:
        columns.elbow = columns.wrist = true;
        columns.shoulder = columns.shoulder || s.info.shoulder;
        break;
      case StreamRole::Camera:
        columns.camWrist = columns.camElbow = true;
        if (s.info.camera) m_params.meta.camera = s.info.camera;
        if (!m_params.meta.camera)
          return QStringLiteral(
                     "the camera of %1 has no calibration; calibrate it "
                     "(armtrack-cli camera-calibrate, camera-register) and pass the "
                     "file to the device")
              .arg(m_devices[static_cast<std::size_t>(s.device)].label);
        break;
      case StreamRole::Truth:
        columns.truth = true;
        columns.trueTrunk = columns.trueTrunk || s.info.trueTrunk;
        break;
      case StreamRole::TrunkImu:
        columns.trunk = true;
        // The sidecar's trunk block: the device's mounting (a simulation, a recording), else the
        // one the session was given, else the sensor flat on the middle of the sternum.
        if (s.info.trunkMount) m_params.meta.trunk = s.info.trunkMount;
        if (!m_params.meta.trunk) {
          m_params.meta.trunk = defaultTrunkMount(m_params.meta.side);
          logEvent(m_devices[static_cast<std::size_t>(s.device)].label.toStdString() + " " +
                   s.info.name +
                   ": the sternum sensor's mounting is not known; assuming it flat on the middle "
                   "of the sternum, 10 cm below the shoulder. The trunk angles are only as good "
                   "as that guess: calibrate the sternum sensor from the upright start pose");
        }
        break;
    }
  }
  return {};
}

QString Session::openRecording(const RecordingColumns& columns) {
  if (m_params.openSink && !m_params.recordingPath.empty())
    return QStringLiteral("record into a file or a database, not both");
  if (m_params.openSink) {
    try {
      m_writer = m_params.openSink(m_params.meta, columns);
    } catch (const RecordingError& e) {
      return QStringLiteral("cannot record: %1").arg(QString::fromStdString(e.what()));
    }
  } else if (!m_params.recordingPath.empty()) {
    // RecordingWriter replaces an existing file; without overwrite the session never lets it.
    // A directory is left to the writer, which refuses it with its own message.
    const std::filesystem::path& csv = m_params.recordingPath;
    bool claimed = false;
    if (!m_params.overwrite && !std::filesystem::is_directory(csv)) {
      std::error_code ec;
      if (std::filesystem::exists(sidecarPath(csv), ec))
        return QStringLiteral(
                   "cannot record: %1: exists; allow overwriting (--overwrite) to "
                   "replace the recording, or choose another file name")
            .arg(QString::fromStdString(sidecarPath(csv).string()));
      if (const std::string why = claimName(csv); !why.empty())
        return QStringLiteral("cannot record: %1").arg(QString::fromStdString(why));
      claimed = true;
    }
    try {
      m_writer = std::make_unique<RecordingWriter>(csv, m_params.meta, columns);
    } catch (const RecordingError& e) {
      if (claimed) removeUnusedClaim(csv);
      return QStringLiteral("cannot record: %1").arg(QString::fromStdString(e.what()));
    }
  }

  return {};
}

QString Session::start() {
  if (m_running) return QStringLiteral("the session is already running");
  if (m_devices.empty()) return QStringLiteral("no device: add at least one device");
  // One stream per role, and a camera model for marker pixels.
  for (std::size_t i = 0; i < m_streams.size(); ++i)
    for (std::size_t j = i + 1; j < m_streams.size(); ++j)
      if (m_streams[i].info.role == m_streams[j].info.role)
        return QStringLiteral("two streams provide the %1 (%2 and %3); keep one")
            .arg(QString::fromLatin1(toString(m_streams[i].info.role)),
                 m_devices[static_cast<std::size_t>(m_streams[i].device)].label,
                 m_devices[static_cast<std::size_t>(m_streams[j].device)].label);
  bool imu = false;
  RecordingColumns columns;
  if (QString why = columnsOfStreams(columns, imu); !why.isEmpty()) return why;
  m_columns = columns;
  m_scale = m_devices.front().device->timeScale();
  for (const DeviceEntry& d : m_devices)
    if (d.device->timeScale() != m_scale)
      return QStringLiteral(
                 "%1 runs at %2x and %3 at %4x: a replay faster than real time cannot "
                 "be mixed with live devices")
          .arg(m_devices.front().label)
          .arg(m_scale)
          .arg(d.label)
          .arg(d.device->timeScale());
  if (m_params.estimate && !imu)
    return QStringLiteral(
        "no IMU among the devices: the estimator needs the upper-arm or "
        "forearm IMU (or record without estimating)");
  if (m_params.calibration && m_params.calibration->side != m_params.meta.side)
    return QStringLiteral(
               "the sensor calibration was made for the %1 arm and the session is of the %2 "
               "arm: calibrate again for this arm")
        .arg(QString::fromStdString(sideName(m_params.calibration->side)),
             QString::fromStdString(sideName(m_params.meta.side)));
  {
    // The estimator's model: the calibrated geometry and sternum mounting when one is given.
    RecordingMeta model = m_params.meta;
    if (m_params.calibration) applyCalibration(*m_params.calibration, model);
    m_params.estimator = sessionFilterParams(m_params.estimator, model);
  }
  if (QString why = openRecording(columns); !why.isEmpty()) return why;
  m_liveCalibration.reset();
  m_movementCalibrationFile.clear();
  // The fit needs both arm IMUs (the elbow between them); without one it stays off. A sensor
  // calibration in use is not second-guessed.
  if (m_params.estimate && m_params.movementCalibration.enabled && !m_params.calibration &&
      columns.upperArm && columns.forearm)
    m_liveCalibration =
        std::make_unique<LiveCalibration>(m_params.movementCalibration, m_params.meta,
                                          [base = m_params.estimator](const RecordingMeta& meta) {
                                            return sessionFilterParams(base, meta);
                                          });

  m_stats = SessionStats{};
  for (const Stream& s : m_streams) {
    StreamStats st;
    st.device = m_devices[static_cast<std::size_t>(s.device)].label.toStdString();
    st.stream = s.info.name;
    st.role = s.info.role;
    m_stats.streams.push_back(st);
  }
  for (const DeviceEntry& d : m_devices) m_stats.deviceLabels.push_back(d.label.toStdString());
  m_inputClosed = m_recClosed = false;
  m_input.reserve(4096);
  m_startTime = hostNow();
  m_worker = std::thread([this] { workerLoop(); });
  if (m_writer) m_recorder = std::thread([this] { recorderLoop(); });

  for (std::size_t i = 0; i < m_devices.size(); ++i) {
    DeviceEntry& d = m_devices[i];
    d.input = std::make_unique<DeviceInput>(*this, static_cast<int>(i), d.label.toStdString());
    d.device->start(*d.input);
    d.started = true;
  }
  m_running = true;
  return {};
}

void Session::onSamples(int device, const SampleBatch& batch) {
  const int first = m_devices[static_cast<std::size_t>(device)].firstStream;
  const int count =
      static_cast<int>(m_devices[static_cast<std::size_t>(device)].device->streams().size());
  bool wake = false;
  std::uint64_t overflow = 0;
  {
    std::lock_guard lock(m_inputMutex);
    if (m_inputClosed) return;
    wake = m_input.empty();
    for (const DeviceSample& s : batch) {
      if (m_input.size() >= m_params.inputCapacity) {
        ++overflow;
        continue;
      }
      DeviceSample g = s;
      // A stream index the device does not have is kept (and rejected, counted, by the worker).
      g.stream = s.stream >= 0 && s.stream < count ? first + s.stream : -1 - device;
      m_input.push_back(std::move(g));
    }
  }
  if (overflow) {
    std::lock_guard lock(m_statsMutex);
    m_stats.inputOverflow += overflow;
  }
  if (wake) m_inputCv.notify_one();
}

void Session::recorderLoop() {
  pthread_setname_np(pthread_self(), "armtrack-record");
  std::deque<ArmSample> local;
  double nextFlush = hostNow() + m_params.flushInterval;
  double nextSync = hostNow() + m_params.syncInterval;
  std::string lastError;
  auto attempt = [&](auto&& step) {
    try {
      step();
      if (!lastError.empty()) {
        logEvent("recording: writing again after: " + lastError);
        lastError.clear();
      }
    } catch (const RecordingError& e) {
      if (e.what() != lastError) {
        lastError = e.what();
        logEvent("recording: " + lastError);
        emit problem(QStringLiteral("recording: ") + QString::fromStdString(lastError));
      }
      std::lock_guard lock(m_statsMutex);
      m_stats.recorderError = lastError;
    }
  };
  for (;;) {
    bool closed = false;
    {
      std::unique_lock lock(m_recMutex);
      m_recCv.wait_for(lock, std::chrono::duration<double>(m_params.flushInterval),
                       [&] { return !m_recQueue.empty() || m_recClosed; });
      local.swap(m_recQueue);
      closed = m_recClosed;
    }
    m_recSpaceCv.notify_all();
    std::uint64_t written = 0;
    for (const ArmSample& s : local) {
      try {
        m_writer->append(s);
        ++written;
      } catch (const RecordingError& e) {
        // Rows come from the synchroniser in time order with finite values; this would be a bug.
        logEvent(std::string("recording: row refused: ") + e.what());
      }
    }
    local.clear();
    const double now = hostNow();
    if (closed) {
      attempt([&] { m_writer->close(); });
    } else if (now >= nextSync) {
      attempt([&] { m_writer->sync(); });
      nextSync = now + m_params.syncInterval;
      nextFlush = now + m_params.flushInterval;
    } else if (now >= nextFlush) {
      attempt([&] { m_writer->flush(); });
      nextFlush = now + m_params.flushInterval;
    }
    {
      // What reached the file, not what was handed to the writer: rows a full disk keeps in the
      // writer's buffer are not recorded.
      std::lock_guard lock(m_statsMutex);
      m_stats.rowsToRecord += written;
      m_stats.recordedRows = m_writer->rowsWritten();
    }
    if (closed) break;
  }
}

void Session::stopDevices() {
  for (DeviceEntry& d : m_devices) {
    if (!d.started) continue;
    if (const std::string why = d.device->stop(); !why.empty())
      logEvent(d.label.toStdString() + ": " + why);
    d.started = false;
  }
}

void Session::stop() {
  if (!m_running) return;
  stopDevices();
  {
    std::lock_guard lock(m_inputMutex);
    m_inputClosed = true;
  }
  m_inputCv.notify_one();
  if (m_worker.joinable()) m_worker.join();
  if (m_recorder.joinable()) m_recorder.join();
  m_writer.reset();
  keepMovementCalibration();
  m_running = false;
}

void Session::keepMovementCalibration() {
  if (!m_liveCalibration || m_params.recordingPath.empty()) return;
  const LiveCalibrationStatus st = m_liveCalibration->status();
  if (!st.calibration) return;
  const std::filesystem::path file = movementCalibrationPath(m_params.recordingPath);
  try {
    writeCalibration(file, *st.calibration);
    m_movementCalibrationFile = file;
    logEvent("calibration from movement: the straps used are kept in " + file.string() +
             " (armtrack-cli estimate --calibration uses them again)");
  } catch (const CalibrationError& e) {
    logEvent(std::string("calibration from movement: not kept: ") + e.what());
    emit problem(QStringLiteral("calibration from movement: not kept: ") +
                 QString::fromStdString(e.what()));
  }
}

LiveCalibrationStatus Session::movementCalibration() const {
  return m_liveCalibration ? m_liveCalibration->status() : LiveCalibrationStatus{};
}

EstimatorParams sessionFilterParams(const EstimatorParams& base, const RecordingMeta& meta) {
  const EstimatorParams e = recordingParams(meta);
  EstimatorParams p = base;
  p.geometry = e.geometry;
  p.gUp = e.gUp;
  p.camera = e.camera;
  p.side = e.side;
  p.trunk = e.trunk;  // the sternum IMU's mounting: frame 0 then moves with the thorax
  return p;
}

SessionStats Session::stats() const {
  SessionStats s;
  {
    std::lock_guard lock(m_statsMutex);
    s = m_stats;
  }
  s.elapsed = hostNow() - m_startTime;
  for (std::size_t i = 0; i < m_streams.size(); ++i) {
    const Stream& st = m_streams[i];
    const DeviceHealth h = m_devices[static_cast<std::size_t>(st.device)].device->health();
    const StreamHealth& sh = h.streams[static_cast<std::size_t>(st.index)];
    if (i < s.streams.size()) {
      s.streams[i].rateHz = sh.rateHz;
      s.streams[i].published = sh.samples;
      s.streams[i].deviceDropped = sh.dropped;
      s.streams[i].deviceCorrupt = sh.corrupt;
      s.streams[i].batteryPercent = h.batteryPercent;
    }
  }
  s.deviceStates.clear();
  for (const DeviceEntry& d : m_devices) s.deviceStates.push_back(d.device->state());
  return s;
}

std::size_t Session::takeResults(std::vector<EstimateRow>& out) {
  std::lock_guard lock(m_resultMutex);
  const std::size_t n = m_results.size();
  for (EstimateRow& r : m_results) out.push_back(std::move(r));
  m_results.clear();
  return n;
}

std::size_t Session::takeEvents(std::vector<std::string>& out) {
  std::lock_guard lock(m_statsMutex);
  const std::size_t n = m_events.size();
  for (std::string& e : m_events) out.push_back(std::move(e));
  m_events.clear();
  return n;
}

}  // namespace armtrack::session
