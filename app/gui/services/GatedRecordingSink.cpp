#include "app/gui/services/GatedRecordingSink.h"

#include <cmath>

namespace armtrack::app::gui {

QString RecordingGate::openError() const {
  std::lock_guard lock(m_mutex);
  return m_openError;
}

GatedRecordingSink::GatedRecordingSink(std::shared_ptr<RecordingGate> gate, RecordingMeta meta,
                                       RecordingColumns columns)
    : m_gate(std::move(gate)), m_meta(std::move(meta)), m_columns(columns) {}

void GatedRecordingSink::append(const ArmSample& sample) {
  if (m_closed) throw RecordingError("", 0, 0, "the recording is closed");
  if (!m_gate->recording() || !m_gate->target()) {
    ++m_gate->m_skipped;
    return;
  }
  if (!m_inner) {
    try {
      m_inner = m_gate->target()->open(m_meta, m_columns);
    } catch (const RecordingError& e) {
      // Stop recording rather than fail every row; the screen shows why.
      {
        std::lock_guard lock(m_gate->m_mutex);
        m_gate->m_openError = QString::fromStdString(e.what());
      }
      m_gate->setRecording(false);
      throw;
    }
  }
  m_inner->append(sample);
  if (std::isnan(m_gate->m_firstRecordedS)) m_gate->m_firstRecordedS = sample.t;
}

void GatedRecordingSink::flush() {
  if (m_inner) m_inner->flush();
}

void GatedRecordingSink::sync() {
  if (m_inner) m_inner->sync();
}

void GatedRecordingSink::close() {
  m_closed = true;
  if (m_inner) m_inner->close();
}

}  // namespace armtrack::app::gui
