#include "core/session/LiveCalibration.h"

#include <cmath>
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
  while (!m_window.empty() && row.t - m_window.front().t > m_params.windowSeconds)
    m_window.pop_front();
}

void LiveCalibration::startFit(double t) {
  m_fitStartT = t;
  Recording rec;
  rec.meta = m_meta;
  rec.samples.assign(m_window.begin(), m_window.end());
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
  std::optional<AutoCalibrationResult> out;
  if (m_thread.joinable()) {
    if (!m_done && !m_params.waitForFit) return out;
    m_thread.join();
    out = std::move(m_result);
    m_result = {};
    using Outcome = AutoCalibrationResult::Outcome;
    m_madeOne = m_madeOne || out->outcome != Outcome::NotTried;
    m_nextFitT = t + (m_madeOne ? m_params.refineSeconds : m_params.retrySeconds);
    if (m_cancel) out->calibration.reset();  // stopped meanwhile: nothing more to use it on
    if (out->calibration) {
      m_current = out->calibration;
      m_currentRollSeen = out->forearmRollSeen;
    }
    std::lock_guard lock(m_statusMutex);
    ++m_status.fits;
    m_status.fitting = false;
    m_status.line = out->line;
    if (out->calibration) {
      ++m_status.applied;
      m_status.calibration = out->calibration;
      m_status.summary = out->summary;
      m_status.appliedAt = t;
      if (std::isnan(m_status.firstAppliedAt)) m_status.firstAppliedAt = t;
      m_status.fittedAt = m_fitStartT;
    }
    m_status.state = m_current   ? LiveCalibrationStatus::State::Applied
                     : m_madeOne ? LiveCalibrationStatus::State::AsFitted
                                 : LiveCalibrationStatus::State::Collecting;
    return out;
  }
  if (!m_cancel && !std::isnan(m_firstT) && t >= m_nextFitT && !m_window.empty()) {
    startFit(t);
    if (m_params.waitForFit) return poll(t);  // the fit's result at this very row
  }
  return out;
}

LiveCalibrationStatus LiveCalibration::status() const {
  std::lock_guard lock(m_statusMutex);
  return m_status;
}

}  // namespace armtrack::session
