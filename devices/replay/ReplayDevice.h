// The replay device: plays a recording in the open format (docs/recording-format.md) at real
// time or faster, one stream per sensor the recording holds. The file is read row by row as it
// plays, so an hour-long recording needs no more memory than a minute's.
#pragma once

#include <QTimer>
#include <filesystem>
#include <memory>

#include "core/io/Recording.h"
#include "devices/api/Device.h"

namespace armtrack::devices::replay {

class ReplayDevice final : public Device {
  Q_OBJECT
 public:
  /// Opens the file and reads its first rows (the streams and their rates). speed: recording
  /// seconds per second (>= 0.1). loop: start again at the end. Throws RecordingError for a
  /// file that cannot be read or holds no rows.
  ReplayDevice(const std::filesystem::path& file, double speed, bool loop);
  ~ReplayDevice() override;

  double timeScale() const override { return m_speed; }

 public slots:
  void start() override;
  void stop() override;

 private:
  struct Opened;  // the reader with its first row
  static Opened open(const std::filesystem::path& file);
  static std::vector<StreamInfo> describe(const std::filesystem::path& file);
  ReplayDevice(const std::filesystem::path& file, double speed, bool loop,
               std::vector<StreamInfo> streams);
  bool rewind();  // opens the file again for a pass; false (state Error) when it fails
  void tick();
  void fail(const QString& reason);
  void reportNewWarnings();  // the reader's warnings not reported yet

  std::filesystem::path m_file;
  double m_speed;
  bool m_loop;
  std::vector<int> m_streamOf;  // StreamRole -> stream index, -1 when absent
  QTimer* m_timer = nullptr;
  std::unique_ptr<RecordingReader> m_reader;
  ArmSample m_pending;  // the next row to publish
  bool m_hasPending = false;
  double m_firstT = 0.0;  // recording time of the first row
  double m_lastT = 0.0;   // of the last row published in this pass
  std::uint64_t m_passRows = 0;
  std::size_t m_warningsShown = 0;
  double m_startHost = 0.0;   // hostNow() when the current pass started
  double m_timeOffset = 0.0;  // added to recording times (loops keep device time increasing)
};

}  // namespace armtrack::devices::replay
