// Builds the estimator's ArmSample rows from the synchronised, time-ordered events of several
// devices: events close together in time share one row.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/ArmSample.h"
#include "core/sync/SensorPayload.h"
#include "core/sync/TimeSync.h"

namespace armtrack {

using SensorEvent = SyncEvent<SensorPayload>;

/// Groups events into rows: an event joins the open row when it is within mergeWindow seconds of
/// the row's first event and its slot is still empty; otherwise the open row is completed and a
/// new one starts. The row time is its first event's time, so rows are non-decreasing in time when
/// the events are. Not thread-safe.
class ArmSampleAssembler {
 public:
  /// roleOfDevice[d] is the role of device d. mergeWindow in s, default 0.5 ms.
  explicit ArmSampleAssembler(std::vector<StreamRole> roleOfDevice, double mergeWindow = 0.5e-3);

  /// Adds one event; returns the row it completed, if any. An event whose payload does not fit
  /// its device's slot (e.g. pixels from an IMU device) or whose device is unknown is counted in
  /// mismatched() and ignored.
  std::optional<ArmSample> add(const SensorEvent& event);
  /// Completes the open row, if any.
  std::optional<ArmSample> flush();
  /// Time (s) of the open row, if any.
  std::optional<double> openTime() const {
    return m_row ? std::optional<double>(m_row->t) : std::nullopt;
  }

  std::uint64_t mismatched() const { return m_mismatched; }

 private:
  bool slotFilled(StreamRole slot) const;
  void fill(StreamRole slot, const SensorPayload& payload);

  std::vector<StreamRole> m_roles;
  double m_window;
  std::optional<ArmSample> m_row;
  std::uint64_t m_mismatched = 0;
};

}  // namespace armtrack
