#include "core/session/LiveCalibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace armtrack::session {

std::filesystem::path movementCalibrationPath(const std::filesystem::path& csv) {
  std::filesystem::path p = csv;
  p.replace_extension(".movement-calibration.json");
  return p;
}

LiveCalibration::LiveCalibration(const LiveCalibrationParams& params, RecordingMeta meta,
                                 FilterParamsFor paramsFor)
    : m_params(params), m_meta(std::move(meta)), m_paramsFor(std::move(paramsFor)) {
  m_status.state = LiveCalibrationStatus::State::Collecting;
}

LiveCalibration::~LiveCalibration() {
  finish();
}

void LiveCalibration::finish() {
  m_cancel = true;
  if (m_thread.joinable()) m_thread.join();
}

void LiveCalibration::add(const ArmSample& row) {
  // Every reading (not only those kept for the fit) tells whether the arm rests.
  if (row.upperArm) m_upperStill.add(row.t, *row.upperArm, m_params.rest.windowSeconds);
  if (row.forearm) m_forearmStill.add(row.t, *row.forearm, m_params.rest.windowSeconds);
  // Whether the arm rests, looked at every kRestCheckSeconds of session time: each look goes
  // over a second of readings of both IMUs, too much for every row at 1 kHz. (A clock that
  // went back looks again at once.)
  if (!(row.t >= m_restCheckedT && row.t - m_restCheckedT < kRestCheckSeconds)) {
    m_rest = m_upperStill.still(m_params.rest) && m_forearmStill.still(m_params.rest);
    m_restCheckedT = row.t;
  }
  if (std::isnan(m_firstT)) {
    m_firstT = row.t;
    m_nextFitT = row.t + m_params.firstSeconds;
  }
  // Rows without IMU readings (optical) are all kept; a row with readings when one is due.
  const bool upper = row.upperArm && row.t >= m_nextUpperT;
  const bool forearm = row.forearm && row.t >= m_nextForearmT;
  if (row.hasImu() && !upper && !forearm) return;
  // (a microsecond short, so that a clock exactly at a multiple of the step keeps its rate)
  const double step = m_params.maxRateHz > 0.0 ? 1.0 / m_params.maxRateHz - 1e-6 : 0.0;
  if (upper) m_nextUpperT = row.t + step;
  if (forearm) m_nextForearmT = row.t + step;
  m_window.push_back(row);
  m_windowRest.push_back(atRest());
  while (!m_window.empty() && row.t - m_window.front().t > m_params.windowSeconds) {
    m_window.pop_front();
    m_windowRest.pop_front();
    m_windowCut = true;
  }
}

std::size_t LiveCalibration::windowStart() const {
  if (!m_windowCut || m_window.empty()) return 0;
  for (std::size_t i = 0; i < m_window.size(); ++i) {
    if (!m_windowRest[i]) continue;
    return m_window.back().t - m_window[i].t >= 0.5 * m_params.windowSeconds ? i : 0;
  }
  return 0;
}

void LiveCalibration::startFit(double t) {
  m_fitStartT = t;
  Recording rec;
  rec.meta = m_meta;
  rec.samples.assign(m_window.begin() + static_cast<std::ptrdiff_t>(windowStart()),
                     m_window.end());
  m_done = false;
  {
    // A refit keeps the finding in use (or "as fitted") on show until it is done.
    std::lock_guard lock(m_statusMutex);
    m_status.fitting = true;
    if (!m_madeOne) m_status.state = LiveCalibrationStatus::State::Fitting;
  }
  AutoCalibrationParams ap;
  ap.windowSeconds = m_params.windowSeconds;
  ap.betterFraction = m_params.betterFraction;
  ap.cancel = &m_cancel;
  ap.currentRollSeen = m_currentRollSeen;
  m_thread = std::thread([this, rec = std::move(rec), ap, current = m_current] {
    m_result = autoCalibrate(rec, m_paramsFor, ap, current ? &*current : nullptr);
    m_done = true;
  });
}

std::optional<AutoCalibrationResult> LiveCalibration::poll(double t) {
  if (m_pending) {
    if (m_cancel) {
      m_pending.reset();
      std::lock_guard lock(m_statusMutex);
      m_status.waitingForRest = false;
      return std::nullopt;
    }
    if (atRest()) return release(t);
    if (!m_toldWaiting && t - m_pendingSince >= m_params.restWaitTellSeconds) {
      m_toldWaiting = true;
      m_notes.push_back("calibration from movement: the fitted straps wait for the arm to rest (" +
                        std::to_string(static_cast<long>(t - m_pendingSince)) +
                        " s without a rest so far): hold the arm still for a moment to use them");
    }
    return std::nullopt;
  }
  if (m_thread.joinable()) {
    if (!m_done && !m_params.waitForFit) return std::nullopt;
    return finishFit(t);
  }
  if (!m_cancel && !std::isnan(m_firstT) && t >= m_nextFitT && !m_window.empty()) {
    startFit(t);
    if (m_params.waitForFit) return poll(t);  // the fit's result at this very row
  }
  return std::nullopt;
}

std::optional<AutoCalibrationResult> LiveCalibration::finishFit(double t) {
  m_thread.join();
  std::optional<AutoCalibrationResult> out = std::move(m_result);
  m_result = {};
  using Outcome = AutoCalibrationResult::Outcome;
  m_madeOne = m_madeOne || out->outcome != Outcome::NotTried;
  m_nextFitT = t + (m_madeOne ? m_params.refineSeconds : m_params.retrySeconds);
  if (m_cancel) out->calibration.reset();  // stopped meanwhile: nothing more to use it on
  {
    std::lock_guard lock(m_statusMutex);
    ++m_status.fits;
    m_status.fitting = false;
    m_status.line = out->line;
  }
  if (out->calibration) {
    if (m_params.applyAtRest && !atRest()) {
      // Mid-movement: kept until the arm rests (LiveCalibrationParams::applyAtRest).
      m_pending = std::move(out);
      m_pendingSince = t;
      m_toldWaiting = false;
      std::lock_guard lock(m_statusMutex);
      m_status.waitingForRest = true;
      m_status.readyAt = t;
      return std::nullopt;
    }
    m_pendingSince = t;
    m_pending = std::move(out);
    return release(t);
  }
  std::lock_guard lock(m_statusMutex);
  m_status.state = m_current   ? LiveCalibrationStatus::State::Applied
                   : m_madeOne ? LiveCalibrationStatus::State::AsFitted
                               : LiveCalibrationStatus::State::Collecting;
  return out;
}

std::optional<AutoCalibrationResult> LiveCalibration::release(double t) {
  std::optional<AutoCalibrationResult> out = std::move(m_pending);
  m_pending.reset();
  if (t > m_pendingSince) {
    char waited[96];
    std::snprintf(waited, sizeof waited, "; used at the arm's first rest, %.1f s after the fit",
                  t - m_pendingSince);
    out->line += waited;
  }
  // Refits count from the application: the next window then holds the movement since.
  m_nextFitT = std::max(m_nextFitT, t + m_params.refineSeconds);
  m_current = out->calibration;
  m_currentRollSeen = out->forearmRollSeen;
  std::lock_guard lock(m_statusMutex);
  m_status.line = out->line;
  m_status.waitingForRest = false;
  ++m_status.applied;
  m_status.calibration = out->calibration;
  m_status.summary = out->summary;
  m_status.appliedAt = t;
  if (std::isnan(m_status.firstAppliedAt)) m_status.firstAppliedAt = t;
  m_status.fittedAt = m_fitStartT;
  m_status.readyAt = m_pendingSince;
  m_status.state = LiveCalibrationStatus::State::Applied;
  return out;
}

std::vector<std::string> LiveCalibration::takeNotes() {
  return std::exchange(m_notes, {});
}

bool LiveCalibration::atRest() const {
  return m_rest;
}

void ImuStillness::add(double t, const ImuReading& r, double seconds) {
  m_readings.push_back({t, r.gyr, r.acc});
  while (t - m_readings.front().t > seconds) m_readings.pop_front();
}

bool ImuStillness::still(const RestBiasParams& p) const {
  // A window nearly full (a gap in the readings is no rest) of enough readings.
  if (m_readings.size() < static_cast<std::size_t>(std::max(p.minSamples, 2)) ||
      m_readings.back().t - m_readings.front().t < 0.9 * p.windowSeconds)
    return false;
  const double n = static_cast<double>(m_readings.size());
  const double mid = m_readings.front().t + 0.5 * (m_readings.back().t - m_readings.front().t);
  Eigen::Vector3d gMean = Eigen::Vector3d::Zero(),
                  aSum[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  double aN[2] = {0.0, 0.0};
  for (const Reading& r : m_readings) {
    gMean += r.gyr;
    const int half = r.t < mid ? 0 : 1;
    aSum[half] += r.acc;
    aN[half] += 1.0;
  }
  gMean /= n;
  // (comparisons written so that NaN readings are no rest)
  if (!(gMean.cwiseAbs().maxCoeff() <= p.maxBias) || aN[0] == 0.0 || aN[1] == 0.0) return false;
  Eigen::Vector3d gVar = Eigen::Vector3d::Zero();
  for (const Reading& r : m_readings) gVar += (r.gyr - gMean).cwiseAbs2();
  gVar /= n;
  return gVar.maxCoeff() <= p.maxGyroStd * p.maxGyroStd &&
         (aSum[1] / aN[1] - aSum[0] / aN[0]).norm() <= p.maxAccelChange;
}

LiveCalibrationStatus LiveCalibration::status() const {
  std::lock_guard lock(m_statusMutex);
  return m_status;
}

}  // namespace armtrack::session
