// The virtual arm's sensors with injected faults, stepped in simulated time. Plain C++ (no Qt),
// so the fault schedule is tested exactly; VirtualArmDevice paces it in real time.
#pragma once

#include <cstdint>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/sync/SensorPayload.h"

namespace armtrack::devices::virtualarm {

/// A span of simulated time [start, start + duration) (s).
struct Window {
  double start = 0.0;
  double duration = 0.0;
  bool contains(double t) const { return t >= start && t < start + duration; }
  double end() const { return start + duration; }
};

/// Something happens to one stream for a while: it goes silent (a marker occluded, a sensor's
/// radio fading), saturates or reads all zeros.
struct StreamWindow {
  std::string stream;  ///< "upper", "forearm", "trunk", "kinect" or "webcam"
  Window window;
};
using Dropout = StreamWindow;

/// One sample of a stream carries absurd but finite values (a packet that passed its checksum
/// with garbage in it; NGIMU's float maximum 3.4e38).
struct Spike {
  std::string stream;  ///< "upper", "forearm", "trunk", "kinect" or "webcam"
  double at = 0.0;     ///< s: the first sample at or after this simulated time
  double value = 1e6;  ///< put in every value of the sample (rad/s, m/s^2, m or px)
};

/// Full scale of the simulated IMUs, the widest usual setting: 2000 deg/s (rad/s) and 16 g
/// (m/s^2). A saturated reading sits at +full scale on every axis.
inline constexpr double kGyroFullScale = 2000.0 * std::numbers::pi / 180.0;
inline constexpr double kAccelFullScale = 16.0 * 9.80665;

/// The device clock steps by delta (s) at simulated time at (a reset, a resync gone wrong).
struct ClockJump {
  double at = 0.0;
  double delta = 0.0;
};

struct Faults {
  std::vector<Dropout> dropouts;
  std::vector<Spike> spikes;              ///< single samples of absurd values
  std::vector<StreamWindow> saturations;  ///< IMU readings at full scale for a while
  std::vector<StreamWindow> zeros;        ///< readings of exactly zero for a while
  std::vector<Window> disappear;          ///< the whole device goes away and comes back
  bool restartClock = false;              ///< after coming back, the IMU clock restarts from 0
  std::vector<Window> stalls;       ///< the link holds everything, then delivers it in one burst
  std::vector<ClockJump> jumps;     ///< steps of the IMU clock
  double corruptProbability = 0.0;  ///< chance that an IMU sample carries NaN
  double driftPpm = 0.0;            ///< IMU clock rate error (ppm; positive runs fast)

  bool any() const;
};

/// "10+2|30+1" -> windows; throws std::invalid_argument with a message naming the bad part.
std::vector<Window> parseWindows(const std::string& text);
/// "kinect@10+2|upper@30+1" -> dropouts.
std::vector<Dropout> parseDropouts(const std::string& text);
/// "upper@10+0.2|forearm@30+1" -> stream windows (saturations, zeros); what names the fault in
/// messages ("saturation").
std::vector<StreamWindow> parseStreamWindows(const std::string& text, const std::string& what);
/// "upper@10|forearm@30:3.4e38" -> spikes (value 1e6 unless given after ':').
std::vector<Spike> parseSpikes(const std::string& text);
/// "25:-0.5|40:2" -> clock jumps.
std::vector<ClockJump> parseJumps(const std::string& text);

/// An IMU's analogue-to-digital converter: each reading becomes an integer count and is converted
/// back as a real sensor's plugin does (devices/shimmer3: count / sensitivity, the gyroscope in
/// deg/s then to rad/s), so the values lie on the lattice a real device gives. Zero counts per
/// unit: full precision (the simulator's doubles as they are).
struct ImuResolution {
  double gyroCountsPerDegS = 0.0;
  double accCountsPerMS2 = 0.0;
  double gyroMaxCount = 32767.0;  ///< counts at full scale (16 bits)
  double accMaxCount = 32767.0;

  bool quantises() const { return gyroCountsPerDegS > 0.0 || accCountsPerMS2 > 0.0; }
  /// A Shimmer3's: gyroscope 65.5 counts per deg/s (+-500 deg/s, 16 bits), low-noise
  /// accelerometer 83 counts per m/s^2 (12 bits around 2047).
  static ImuResolution shimmer3();
  /// Puts the reading on the lattice (non-finite values stay as they are).
  void apply(ImuReading& reading) const;
};

/// "full", "shimmer3" or "GYRO:ACC" (counts per deg/s and per m/s^2, 16-bit converters); throws
/// std::invalid_argument naming the bad text.
ImuResolution parseResolution(const std::string& text);

struct VirtualArmParams {
  /// Sensors, rates, noise, the trunk's motion and the sternum IMU (a "trunk" stream); duration
  /// may be +infinity.
  SimulationParams sim;
  std::string trajectory = "multi-joint";
  TrajectoryOptions trajectoryOptions;
  bool truth = true;  ///< a Truth stream beside the IMUs
  /// The two IMUs' readings exchanged, as when each sensor is strapped on the other's segment
  /// (the home window's sensor check must find it).
  bool swapImus = false;
  Faults faults;
  /// The IMUs' converter (applied after injected faults, before corrupted samples' NaN).
  ImuResolution resolution;
  /// The simulated battery: its level at the start (0-100 %; empty = not reported) and how
  /// fast it drains (% per minute of session).
  std::optional<double> batteryPercent = 80.0;
  double batteryDrainPerMinute = 1.0;
};

/// One stream of the virtual arm.
struct VirtualStream {
  std::string name;  ///< "upper", "forearm", "trunk", "kinect", "webcam", "truth"
  StreamRole role = StreamRole::UpperArmImu;
  double rateHz = 0.0;
  bool shoulder = false;   ///< kinect: its samples carry the shoulder (OpticalPositions)
  bool trueTrunk = false;  ///< truth: its samples carry the trunk's true angles (TruthAngles)
};

struct VirtualSample {
  int stream = 0;
  double deviceTime = 0.0;  ///< s on the stream's (faulty) clock
  SensorPayload payload;
};

enum class SourceEventKind {
  DropoutStart,
  DropoutEnd,
  LinkLost,
  LinkBack,
  StallStart,
  StallEnd,
  ClockJump,
  Injected,
  Finished
};

struct SourceEvent {
  SourceEventKind kind = SourceEventKind::LinkLost;
  double t = 0.0;    ///< simulated time (s)
  int stream = -1;   ///< for dropouts
  std::string text;  ///< what to tell the user
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
  /// Samples of the stream replaced by a spike, saturation or zeros.
  std::uint64_t injected(int stream) const {
    return m_injected.at(static_cast<std::size_t>(stream));
  }

 private:
  int streamIndex(StreamRole role) const;
  double imuClock(double t) const;
  void emitRow(const ArmSample& row, std::vector<VirtualSample>& out,
               std::vector<SourceEvent>& events);
  /// Applies the spikes, saturations and zeros due for stream i at time t to its payload.
  void injectValues(std::size_t i, double t, SensorPayload& payload,
                    std::vector<SourceEvent>& events);

  VirtualArmParams m_p;
  std::unique_ptr<Trajectory> m_trajectory;
  std::unique_ptr<SensorStream> m_stream;
  std::vector<VirtualStream> m_streams;
  std::vector<std::uint64_t> m_dropped, m_corrupted, m_injected;
  std::vector<bool> m_inDropout, m_inSaturation, m_inZeros;
  std::vector<bool> m_spikeDone;      // per spike
  std::vector<VirtualSample> m_held;  // samples held by a stall
  bool m_linkUp = true, m_stalled = false, m_finished = false;
  double m_clockBase = 0.0;   // simulated time at which the IMU clock reads 0
  double m_jumpOffset = 0.0;  // s added by the clock jumps so far
  std::size_t m_nextJump = 0;
  std::mt19937_64 m_rng;
};

}  // namespace armtrack::devices::virtualarm
