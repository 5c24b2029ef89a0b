// The home window's sensor check judged off the GUI thread: reads the check's recording and
// judges it (core/calibration/SensorCheck) on a thread of its own, and answers on the GUI thread.
// Qt Core, no widgets.
#pragma once

#include <QObject>
#include <filesystem>

#include "core/calibration/SensorCheck.h"

namespace armtrack::gui {

/// Reads csv and judges it; with a sternum sensor in the recording (its sidecar's trunk block)
/// and none in params, that sensor is judged against the sidecar's mounting. A recording that
/// cannot be read comes back as MissingUpperArm with the reading's error as the explanation
/// (nothing to judge on).
SensorCheckResult judgeSensorCheck(const std::filesystem::path& csv,
                                   const SensorCheckParams& params);

/// One judgement at a time: start() runs judgeSensorCheck() on a worker thread and emits judged()
/// on this object's thread. A later start() or cancel() drops the answer of an earlier one.
class SensorCheckJob : public QObject {
  Q_OBJECT
 public:
  explicit SensorCheckJob(QObject* parent = nullptr);
  ~SensorCheckJob() override;

  void start(const std::filesystem::path& csv, const SensorCheckParams& params);
  /// Forgets the judgement under way (its thread ends on its own; its answer is dropped).
  void cancel();
  bool running() const { return m_running; }

 signals:
  void judged(const armtrack::SensorCheckResult& result);

 private:
  int m_generation = 0;
  bool m_running = false;
};

}  // namespace armtrack::gui
