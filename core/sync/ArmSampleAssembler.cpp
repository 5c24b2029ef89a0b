#include "core/sync/ArmSampleAssembler.h"

#include <utility>

namespace armtrack {

ArmSampleAssembler::ArmSampleAssembler(std::vector<StreamRole> roleOfDevice, double mergeWindow)
    : m_roles(std::move(roleOfDevice)), m_window(mergeWindow) {}

bool ArmSampleAssembler::slotFilled(StreamRole slot) const {
  const ArmSample& r = *m_row;
  switch (slot) {
    case StreamRole::UpperArmImu:
      return r.upperArm.has_value();
    case StreamRole::ForearmImu:
      return r.forearm.has_value();
    case StreamRole::Optical:
      return r.elbow.has_value() || r.wrist.has_value() || r.shoulder.has_value();
    case StreamRole::Camera:
      return r.camWrist.has_value() || r.camElbow.has_value();
    case StreamRole::Truth:
      return r.trueAngles.has_value();
    case StreamRole::TrunkImu:
      return r.trunk.has_value();
  }
  return false;
}

void ArmSampleAssembler::fill(StreamRole slot, const SensorPayload& payload) {
  ArmSample& r = *m_row;
  switch (slot) {
    case StreamRole::UpperArmImu:
      r.upperArm = std::get<ImuReading>(payload);
      break;
    case StreamRole::ForearmImu:
      r.forearm = std::get<ImuReading>(payload);
      break;
    case StreamRole::Optical: {
      const auto& o = std::get<OpticalPositions>(payload);
      r.elbow = o.elbow;
      r.wrist = o.wrist;
      r.shoulder = o.shoulder;
      break;
    }
    case StreamRole::Camera: {
      const auto& m = std::get<MarkerPixels>(payload);
      r.camWrist = m.wrist;
      r.camElbow = m.elbow;
      break;
    }
    case StreamRole::Truth: {
      const auto& truth = std::get<TruthAngles>(payload);
      r.trueAngles = truth.th;
      r.trueTrunk = truth.trunk;
      break;
    }
    case StreamRole::TrunkImu:
      r.trunk = std::get<ImuReading>(payload);
      break;
  }
}

std::optional<ArmSample> ArmSampleAssembler::add(const SensorEvent& event) {
  if (event.device < 0 || static_cast<std::size_t>(event.device) >= m_roles.size()) {
    ++m_mismatched;
    return std::nullopt;
  }
  const StreamRole slot = m_roles[static_cast<std::size_t>(event.device)];
  const bool imu = slot == StreamRole::UpperArmImu || slot == StreamRole::ForearmImu ||
                   slot == StreamRole::TrunkImu;
  const bool ok = imu ? std::holds_alternative<ImuReading>(event.payload)
                  : slot == StreamRole::Optical
                      ? std::holds_alternative<OpticalPositions>(event.payload)
                  : slot == StreamRole::Camera ? std::holds_alternative<MarkerPixels>(event.payload)
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
