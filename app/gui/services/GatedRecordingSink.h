// The session's recording sink in the live screen: rows pass to the real sink (opened on the
// first row recorded, in the recorder thread) only while recording is on, so Record, Pause and
// Record again make one recording with a gap, and a session that is only watched writes nothing.
#pragma once

#include <QString>
#include <atomic>
#include <limits>
#include <memory>
#include <mutex>

#include "app/gui/services/RecordingTarget.h"
#include "core/io/Recording.h"

namespace armtrack::app::gui {

/// Shared by the screen (GUI thread: setRecording) and the sink (recorder thread).
class RecordingGate {
 public:
  explicit RecordingGate(std::shared_ptr<RecordingTarget> target) : m_target(std::move(target)) {}
  void setRecording(bool on) { m_recording = on; }
  bool recording() const { return m_recording; }
  RecordingTarget* target() const { return m_target.get(); }
  /// Rows the session produced while not recording (paused or not started).
  std::uint64_t skipped() const { return m_skipped; }
  /// Why the sink could not be opened, if it could not (recording is then turned off).
  QString openError() const;
  /// The first recorded row's time (s, session clock), where recording time begins
  /// (core/metrics/SessionTime.h); NaN until a row was recorded.
  double firstRecordedS() const { return m_firstRecordedS; }

 private:
  friend class GatedRecordingSink;
  std::shared_ptr<RecordingTarget> m_target;
  std::atomic<bool> m_recording{false};
  std::atomic<std::uint64_t> m_skipped{0};
  std::atomic<double> m_firstRecordedS{std::numeric_limits<double>::quiet_NaN()};
  mutable std::mutex m_mutex;
  QString m_openError;
};

class GatedRecordingSink final : public RecordingSink {
 public:
  GatedRecordingSink(std::shared_ptr<RecordingGate> gate, RecordingMeta meta,
                     RecordingColumns columns);
  void append(const ArmSample& sample) override;
  void flush() override;
  void sync() override;
  void close() override;
  std::uint64_t rows() const override { return m_inner ? m_inner->rows() : 0; }
  std::uint64_t rowsWritten() const override { return m_inner ? m_inner->rowsWritten() : 0; }

 private:
  std::shared_ptr<RecordingGate> m_gate;
  RecordingMeta m_meta;
  RecordingColumns m_columns;
  std::unique_ptr<RecordingSink> m_inner;
  bool m_closed = false;
};

}  // namespace armtrack::app::gui
