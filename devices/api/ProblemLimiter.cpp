#include "devices/api/ProblemLimiter.h"

#include <QTimer>
#include <utility>

namespace armtrack::devices {

ProblemLimiter::ProblemLimiter(QObject* owner, Report report, int windowMs)
    : m_report(std::move(report)), m_windowMs(windowMs), m_timer(new QTimer(owner)) {
  m_timer->setSingleShot(true);
  QObject::connect(m_timer, &QTimer::timeout, m_timer, [this] { windowClosed(); });
}

ProblemLimiter::~ProblemLimiter() {
  delete m_timer.data();
}

void ProblemLimiter::note(std::uint64_t count, const QString& latest) {
  if (count == 0) return;
  if (m_timer && m_timer->isActive()) {
    m_held += count;
    m_latest = latest;
    return;
  }
  m_report(count == 1 ? latest
                      : QStringLiteral("%1 (and %2 more problems)").arg(latest).arg(count - 1));
  if (m_timer) m_timer->start(m_windowMs);
}

void ProblemLimiter::windowClosed() {
  if (reportHeld()) m_timer->start(m_windowMs);
}

void ProblemLimiter::flush() {
  if (m_timer) m_timer->stop();
  reportHeld();
}

bool ProblemLimiter::reportHeld() {
  if (m_held == 0) return false;
  const QString window =
      m_windowMs == 1000 ? QStringLiteral("second") : QStringLiteral("%1 ms").arg(m_windowMs);
  m_report(QStringLiteral("%1 more problem%2 in the last %3; the latest: %4")
               .arg(m_held)
               .arg(m_held == 1 ? QString() : QStringLiteral("s"), window, m_latest));
  m_held = 0;
  m_latest.clear();
  return true;
}

}  // namespace armtrack::devices
