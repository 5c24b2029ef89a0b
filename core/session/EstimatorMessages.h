// What the estimator did that the user must hear about, as rate-limited session messages: the
// readings it refused at the door (which stream, why, how many), its recoveries after losing the
// arm, and its restarts after gaps. Plain C++ (no Qt). See docs/session.md, "Messages".
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/estimation/ArmFilter.h"
#include "core/estimation/SampleGate.h"

namespace armtrack::session {

/// Turns the estimator's counters into messages. Feed it the counters after every update; it
/// says once when refusals start, then sums them up when they stop (no refusal for
/// quietSeconds) or every summarySeconds while they go on. Recoveries and restarts are told at
/// most once per second each; those in between are counted in the next message. Not
/// thread-safe: the worker thread owns it.
class EstimatorMessages {
 public:
  /// blockStreams: for each SensorBlock, the name of the stream that feeds it (e.g.
  /// "arm1 upper"); empty when the session has none.
  explicit EstimatorMessages(std::array<std::string, kNumSensorBlocks> blockStreams,
                             double quietSeconds = 0.5, double summarySeconds = 5.0);

  /// After an update for the row at time t (s, session time): appends what is new to out.
  void update(const EstimatorCounters& counters, double t, std::vector<std::string>& out);
  /// At the end of the session: the summary of refusals not yet summed up, and the recoveries
  /// and restarts not yet told.
  void finish(std::vector<std::string>& out);

 private:
  void summarise(const GateCounters& now, bool goingOn, std::vector<std::string>& out);
  std::string streamsOf(const GateCounters& delta) const;

  std::array<std::string, kNumSensorBlocks> m_blockStreams;
  double m_quiet, m_every;
  GateCounters m_summarised;    // counters at the last summary
  GateCounters m_latest;        // counters at the newest refusal
  std::uint64_t m_seen = 0;     // refusals at the last update
  bool m_refusing = false;      // an episode of refusals is open
  double m_sinceT = 0.0;        // time of the first refusal not yet summed up
  double m_lastRefusalT = 0.0;  // time of the newest refusal (row time)
  double m_summaryT = 0.0;      // time of the last summary (or of the episode's start)

  struct Throttle {
    std::uint64_t told = 0;    // count at the last message
    std::uint64_t latest = 0;  // count at the last update
    double lastT = -std::numeric_limits<double>::infinity();
    double pendingT = 0.0;  // time of the first untold event
    double latestT = 0.0;   // time of the newest event
  };
  /// event: what happened ("restarted after a gap in the data"); tail: what it means.
  static void tell(Throttle& th, std::uint64_t count, double t, const std::string& event,
                   const std::string& tail, std::vector<std::string>& out, bool force);
  Throttle m_recoveries, m_restarts;
};

}  // namespace armtrack::session
