// Rate-limits a device's problem messages so a flood of bad input reaches the user as one
// message per window, not one per packet.
#pragma once

#include <QPointer>
#include <QString>
#include <QTimer>
#include <cstdint>
#include <functional>

namespace armtrack::devices {

/// The first problem of a quiet window is reported at once; problems noted while the window is
/// open are held and summed up when it closes ("N more problems in the last second; the latest:
/// ..."), which opens the next window. A window that closes with nothing held ends the flood, and
/// the next problem is again reported at once.
///
/// Its timer is a child of the owner (normally the device), so it lives in the owner's thread;
/// use it only from that thread.
class ProblemLimiter {
 public:
  using Report = std::function<void(const QString&)>;

  ProblemLimiter(QObject* owner, Report report, int windowMs = 1000);
  ~ProblemLimiter();
  ProblemLimiter(const ProblemLimiter&) = delete;
  ProblemLimiter& operator=(const ProblemLimiter&) = delete;

  /// Notes `count` problems of which `latest` is the newest message.
  void note(std::uint64_t count, const QString& latest);
  /// Reports what is held now and ends the window (call it when the device stops).
  void flush();

  std::uint64_t held() const { return m_held; }

 private:
  void windowClosed();
  bool reportHeld();  // reports the held problems, if any; returns whether there were some

  Report m_report;
  int m_windowMs;
  QPointer<QTimer> m_timer;  // owned by the owner; deleted with the limiter if still there
  std::uint64_t m_held = 0;
  QString m_latest;
};

}  // namespace armtrack::devices
