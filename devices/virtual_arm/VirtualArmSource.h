// The virtual arm's sensors with injected faults, stepped in simulated time. Plain C++ (no Qt),
// so the fault schedule is tested exactly; VirtualArmDevice paces it in real time.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/sync/ArmSampleAssembler.h"

namespace armtrack::devices::virtualarm {

/// A span of simulated time [start, start + duration) (s).
struct Window {
  double start = 0.0;
  double duration = 0.0;
  bool contains(double t) const { return t >= start && t < start + duration; }
  double end() const { return start + duration; }
};

/// One stream goes silent for a while (a marker occluded, a sensor's radio fading).
struct Dropout {
  std::string stream;  ///< "upper", "forearm", "kinect" or "webcam"
  Window window;
};

/// The device clock steps by delta (s) at simulated time at (a reset, a resync gone wrong).
struct ClockJump {
  double at = 0.0;
  double delta = 0.0;
};

struct Faults {
  std::vector<Dropout> dropouts;
  std::vector<Window> disappear;  ///< the whole device goes away and comes back
  bool restartClock = false;      ///< after coming back, the IMU clock restarts from 0
  std::vector<Window> stalls;     ///< the link holds everything, then delivers it in one burst
  std::vector<ClockJump> jumps;   ///< steps of the IMU clock
  double corruptProbability = 0.0;  ///< chance that an IMU sample carries NaN
  double driftPpm = 0.0;            ///< IMU clock rate error (ppm; positive runs fast)

  bool any() const;
};

/// "10+2|30+1" -> windows; throws std::invalid_argument with a message naming the bad part.
std::vector<Window> parseWindows(const std::string& text);
/// "kinect@10+2|upper@30+1" -> dropouts.
std::vector<Dropout> parseDropouts(const std::string& text);
/// "25:-0.5|40:2" -> clock jumps.
std::vector<ClockJump> parseJumps(const std::string& text);

struct VirtualArmParams {
  SimulationParams sim;  ///< sensors, rates, noise; duration may be +infinity
  std::string trajectory = "multi-joint";
  TrajectoryOptions trajectoryOptions;
  bool truth = true;  ///< a Truth stream beside the IMUs
  Faults faults;
};

/// One stream of the virtual arm.
struct VirtualStream {
  std::string name;  ///< "upper", "forearm", "kinect", "webcam", "truth"
  ArmSlot slot = ArmSlot::UpperArmImu;
  double rateHz = 0.0;
};

struct VirtualSample {
  int stream = 0;
  double deviceTime = 0.0;  ///< s on the stream's (faulty) clock
  SensorPayload payload;
};

enum class SourceEventKind { DropoutStart, DropoutEnd, LinkLost, LinkBack, StallStart, StallEnd,
                             ClockJump, Finished };

struct SourceEvent {
  SourceEventKind kind = SourceEventKind::LinkLost;
  double t = 0.0;      ///< simulated time (s)
  int stream = -1;     ///< for dropouts
  std::string text;    ///< what to tell the user
};

/// Steps the simulation. Not thread-safe.
class VirtualArmSource {
 public:
  /// Throws std::invalid_argument on bad parameters (unknown trajectory or dropout stream, bad
  /// rates).
  explicit VirtualArmSource(const VirtualArmParams& params);
  ~VirtualArmSource();

  const std::vector<VirtualStream>& streams() const { return m_streams; }
  const RecordingMeta& meta() const { return m_stream->meta(); }

  /// Starts at simulated time t (s) instead of 0 (devices sharing one time base).
  void skipTo(double t);
  /// Everything due up to simulated time t (s): the samples delivered now (held ones first, at
  /// the end of a stall), and the fault events.
  void advance(double t, std::vector<VirtualSample>& out, std::vector<SourceEvent>& events);

  bool linkUp() const { return m_linkUp; }
  bool finished() const { return m_finished; }
  std::uint64_t dropped(int stream) const { return m_dropped.at(static_cast<std::size_t>(stream)); }
  std::uint64_t corrupted(int stream) const {
    return m_corrupted.at(static_cast<std::size_t>(stream));
  }

 private:
  int streamIndex(ArmSlot slot) const;
  double imuClock(double t) const;
  void emitRow(const ArmSample& row, std::vector<VirtualSample>& out,
               std::vector<SourceEvent>& events);

  VirtualArmParams m_p;
  std::unique_ptr<Trajectory> m_trajectory;
  std::unique_ptr<SensorStream> m_stream;
  std::vector<VirtualStream> m_streams;
  std::vector<std::uint64_t> m_dropped, m_corrupted;
  std::vector<bool> m_inDropout;
  std::vector<VirtualSample> m_held;  // samples held by a stall
  bool m_linkUp = true, m_stalled = false, m_finished = false;
  double m_clockBase = 0.0;    // simulated time at which the IMU clock reads 0
  double m_jumpOffset = 0.0;   // s added by the clock jumps so far
  std::size_t m_nextJump = 0;
  std::mt19937_64 m_rng;
};

}  // namespace armtrack::devices::virtualarm
