#include "core/estimation/RestBias.h"

#include <cmath>
#include <limits>

namespace armtrack {

void RestBias::reset() {
  m_bias.setZero();
  m_windows = 0;
  m_open = false;
  m_lastT = -std::numeric_limits<double>::infinity();
}

void RestBias::startWindow(double t) {
  m_open = true;
  m_start = t;
  m_nGyr = 0;
  m_sumGyr.setZero();
  m_sumGyr2.setZero();
  for (int h = 0; h < 2; ++h) {
    m_nAcc[h] = 0;
    m_sumAcc[h].setZero();
  }
}

// A window is still when its rates barely vary, their mean is a plausible bias and gravity kept
// its direction; its mean rate then updates the bias.
void RestBias::closeWindow() {
  m_open = false;
  if (m_nGyr < m_p.minSamples || m_nAcc[0] == 0 || m_nAcc[1] == 0) return;
  const Eigen::Vector3d mean = m_sumGyr / m_nGyr;
  const Eigen::Vector3d var = (m_sumGyr2 / m_nGyr - mean.cwiseAbs2()).cwiseMax(0.0);
  if (var.maxCoeff() > m_p.maxGyroStd * m_p.maxGyroStd) return;
  if (mean.cwiseAbs().maxCoeff() > m_p.maxBias) return;
  const Eigen::Vector3d a0 = m_sumAcc[0] / m_nAcc[0], a1 = m_sumAcc[1] / m_nAcc[1];
  if ((a1 - a0).norm() > m_p.maxAccelChange) return;
  m_bias = m_windows == 0 ? mean : Eigen::Vector3d(m_bias + m_p.gain * (mean - m_bias));
  ++m_windows;
}

void RestBias::add(double t, const ImuReading& r) {
  if (!std::isfinite(t) || !r.gyr.allFinite() || !r.acc.allFinite()) return;
  if (m_open && t < m_lastT) m_open = false;  // time went back: the window is not one stretch
  m_lastT = t;
  if (m_open && t - m_start >= m_p.windowSeconds) closeWindow();
  if (!m_open) startWindow(t);
  if (!r.gyrHeld) {
    ++m_nGyr;
    m_sumGyr += r.gyr;
    m_sumGyr2 += r.gyr.cwiseAbs2();
  }
  if (!r.accHeld) {
    const int half = t - m_start < 0.5 * m_p.windowSeconds ? 0 : 1;
    ++m_nAcc[half];
    m_sumAcc[half] += r.acc;
  }
}

}  // namespace armtrack
