#include "app/gui/services/SensorCheckJob.h"

#include <QCoreApplication>
#include <QPointer>
#include <QThread>

#include "core/io/Recording.h"

namespace armtrack::gui {

SensorCheckResult judgeSensorCheck(const std::filesystem::path& csv,
                                   const SensorCheckParams& params) {
  SensorCheckResult r;
  try {
    const Recording rec = readRecording(csv);
    // A check recorded with a sternum sensor judges it too, against the mounting the session
    // assumed for it (the recording's sidecar).
    SensorCheckParams p = params;
    if (!p.trunk && rec.meta.trunk) p.trunk = rec.meta.trunk;
    r = checkSensors(rec.samples, p);
  } catch (const std::exception& e) {
    r.status = SensorCheckStatus::MissingUpperArm;
    r.explanation = e.what();
  }
  return r;
}

SensorCheckJob::SensorCheckJob(QObject* parent) : QObject(parent) {}

SensorCheckJob::~SensorCheckJob() = default;

void SensorCheckJob::start(const std::filesystem::path& csv, const SensorCheckParams& params) {
  const int generation = ++m_generation;
  m_running = true;
  QPointer<SensorCheckJob> self(this);
  QThread* worker = QThread::create([csv, params, self, generation] {
    const SensorCheckResult r = judgeSensorCheck(csv, params);
    // Queued to the GUI thread; dropped when the job is gone by then or was started again.
    QMetaObject::invokeMethod(QCoreApplication::instance(), [self, generation, r] {
      if (!self || self->m_generation != generation) return;
      self->m_running = false;
      emit self->judged(r);
    });
  });
  worker->setObjectName(QStringLiteral("armtrack-sensor-check"));
  connect(worker, &QThread::finished, worker, &QObject::deleteLater);
  worker->start(QThread::LowPriority);
}

void SensorCheckJob::cancel() {
  ++m_generation;
  m_running = false;
}

}  // namespace armtrack::gui
