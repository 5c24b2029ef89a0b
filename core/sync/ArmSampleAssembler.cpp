#include "core/sync/ArmSampleAssembler.h"

#include <utility>

namespace armtrack {

ArmSampleAssembler::ArmSampleAssembler(std::vector<ArmSlot> slotOfDevice, double mergeWindow)
    : m_slots(std::move(slotOfDevice)), m_window(mergeWindow) {}

bool ArmSampleAssembler::slotFilled(ArmSlot slot) const {
  const ArmSample& r = *m_row;
  switch (slot) {
    case ArmSlot::UpperArmImu:
      return r.upperArm.has_value();
    case ArmSlot::ForearmImu:
      return r.forearm.has_value();
    case ArmSlot::Optical:
      return r.elbow.has_value() || r.wrist.has_value();
    case ArmSlot::Camera:
      return r.camWrist.has_value() || r.camElbow.has_value();
    case ArmSlot::Truth:
      return r.trueAngles.has_value();
  }
  return false;
}

void ArmSampleAssembler::fill(ArmSlot slot, const SensorPayload& payload) {
  ArmSample& r = *m_row;
  switch (slot) {
    case ArmSlot::UpperArmImu:
      r.upperArm = std::get<ImuReading>(payload);
      break;
    case ArmSlot::ForearmImu:
      r.forearm = std::get<ImuReading>(payload);
      break;
    case ArmSlot::Optical: {
      const auto& o = std::get<OpticalPositions>(payload);
      r.elbow = o.elbow;
      r.wrist = o.wrist;
      break;
    }
    case ArmSlot::Camera: {
      const auto& m = std::get<MarkerPixels>(payload);
      r.camWrist = m.wrist;
      r.camElbow = m.elbow;
      break;
    }
    case ArmSlot::Truth:
      r.trueAngles = std::get<TruthAngles>(payload).th;
      break;
  }
}

std::optional<ArmSample> ArmSampleAssembler::add(const SensorEvent& event) {
  if (event.device < 0 || static_cast<std::size_t>(event.device) >= m_slots.size()) {
    ++m_mismatched;
    return std::nullopt;
  }
  const ArmSlot slot = m_slots[static_cast<std::size_t>(event.device)];
  const bool imu = slot == ArmSlot::UpperArmImu || slot == ArmSlot::ForearmImu;
  const bool ok = imu                       ? std::holds_alternative<ImuReading>(event.payload)
                  : slot == ArmSlot::Optical ? std::holds_alternative<OpticalPositions>(event.payload)
                  : slot == ArmSlot::Camera  ? std::holds_alternative<MarkerPixels>(event.payload)
                                             : std::holds_alternative<TruthAngles>(event.payload);
  if (!ok) {
    ++m_mismatched;
    return std::nullopt;
  }
  std::optional<ArmSample> done;
  if (m_row && (event.t - m_row->t > m_window || slotFilled(slot))) done = std::exchange(m_row, {});
  if (!m_row) {
    m_row.emplace();
    m_row->t = event.t;
  }
  fill(slot, event.payload);
  return done;
}

std::optional<ArmSample> ArmSampleAssembler::flush() {
  return std::exchange(m_row, {});
}

}  // namespace armtrack
