// The replay device: plays a recording in the open format (docs/recording-format.md) at real
// time or faster, one stream per sensor the recording holds.
#pragma once

#include <QTimer>

#include "core/io/Recording.h"
#include "devices/api/Device.h"

namespace armtrack::devices::replay {

class ReplayDevice final : public Device {
  Q_OBJECT
 public:
  /// speed: recording seconds per second (>= 0.1). loop: start again at the end.
  ReplayDevice(Recording recording, double speed, bool loop);

  double timeScale() const override { return m_speed; }
  const Recording& recording() const { return m_rec; }

 public slots:
  void start() override;
  void stop() override;

 private:
  void tick();
  static std::vector<StreamInfo> describe(const Recording& rec);

  Recording m_rec;
  double m_speed;
  bool m_loop;
  std::vector<int> m_streamOf;  // ArmSlot -> stream index, -1 when absent
  QTimer* m_timer = nullptr;
  double m_startHost = 0.0;   // hostNow() when the current pass started
  double m_timeOffset = 0.0;  // added to recording times (loops keep device time increasing)
  std::size_t m_next = 0;
};

}  // namespace armtrack::devices::replay
