// The virtual-arm device: the simulated IMUs, Kinect and webcam of VirtualArmSource, delivered in
// real time from a timer in the device thread. Demo mode and the integration tests use it.
#pragma once

#include <QTimer>
#include <memory>

#include "devices/api/Device.h"
#include "devices/virtual_arm/VirtualArmSource.h"

namespace armtrack::devices::virtualarm {

/// Virtual arms running at the same time share one simulated time base, so that two of them (say
/// the IMUs in one, the Kinect in another) describe the same arm at the same instant: simulated
/// time 0 is when the first of them started. acquireEpoch() returns that host time (hostNow());
/// each acquire is matched by a releaseEpoch(). Any thread.
double acquireEpoch();
void releaseEpoch();

class VirtualArmDevice final : public Device {
  Q_OBJECT
 public:
  /// tickSeconds: how often the timer delivers what is due (s).
  VirtualArmDevice(const VirtualArmParams& params, double tickSeconds);
  ~VirtualArmDevice() override;

  /// The simulated arm's set-up (geometry, up, camera). Any thread (immutable).
  const RecordingMeta& meta() const { return m_meta; }

 public slots:
  void start() override;
  void stop() override;

 private:
  void tick();
  static std::vector<StreamInfo> describe(const VirtualArmSource& source);
  // The source is built once here for the stream list and the metadata; start() builds its own.
  VirtualArmDevice(const VirtualArmSource& source, const VirtualArmParams& params,
                   double tickSeconds);

  VirtualArmParams m_params;
  double m_tick;
  RecordingMeta m_meta;
  std::unique_ptr<VirtualArmSource> m_source;
  QTimer* m_timer = nullptr;
  double m_epoch = 0.0;
  double m_started = 0.0, m_batteryShown = -1e9;  // hostNow() at start, at the last report
  std::vector<std::uint64_t> m_reportedDrops;
};

}  // namespace armtrack::devices::virtualarm
