// The calibration from ordinary movement in a live session (docs/session.md, "Calibration from
// movement"; docs/calibration.md, "Used automatically"): when the patient has no calibration
// for these sensors, the worker keeps the newest rows in a window, fits the straps on a thread
// of its own (core/calibration/AutoCalibration.h, the rule `estimate` uses) and hands back a
// calibration to use only when it explains the readings clearly better than the one in use.
// Refits at intervals on a longer window refine it by the same rule. Plain C++ (no Qt).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include "core/calibration/AutoCalibration.h"
#include "core/estimation/RestBias.h"

namespace armtrack::session {

/// When and on what the session fits.
struct LiveCalibrationParams {
  /// Fit the straps from the movement. The GUI and `live` switch it off when a calibration file
  /// for these sensors is used.
  bool enabled = false;
  double firstSeconds = 30.0;   ///< s of rows before the first fit
  double retrySeconds = 15.0;   ///< s between fits until one could be made
  double refineSeconds = 60.0;  ///< s between refits once one was made
  /// s of the newest rows kept and fitted on. Once the session is longer, a refit's window
  /// starts at its first rest (when at least half of it is left after that): the check that
  /// decides whether a fit is used runs the estimator over the window, and one started mid-reach
  /// with IMUs only may lose the arm (applyAtRest), which made the check a matter of chance.
  double windowSeconds = 90.0;
  /// Each IMU's readings are kept at most this often (Hz): arm movement lies below 10 Hz, and a
  /// 1 kHz sensor would otherwise fill the window with 90 000 rows (45 MB) for nothing.
  double maxRateHz = 200.0;
  /// The fit is used only when its ReadingFit score is below this fraction of the mounting's in
  /// use (AutoCalibrationParams::betterFraction).
  double betterFraction = 0.7;
  /// The worker waits for each fit at the row it started it on instead of going on beside it, so
  /// the fit is used from that row (as `estimate` does): the session's estimates then no longer
  /// depend on how long the fit took in real time. For replays faster than real time (at 10x a
  /// fit of 1-3 s lands 10-30 s of session time later, later still on a loaded machine) and
  /// tests; never for live devices, whose samples would queue meanwhile.
  bool waitForFit = false;
  /// A fit to be used waits for the arm to rest: a new estimator started during a reach loses the
  /// arm on the next ones with IMUs only (on the turned-straps patient of the tests, 4.5-16 deg
  /// off over the next 50 s), and one started in a pause at a reach's end (0.4-0.8 s) does worse
  /// than one started with the hand at rest. Off: used at once.
  bool applyAtRest = true;
  /// At rest: the estimator's own rule for a still sensor (RestBias: over the last
  /// `windowSeconds`, 1 s, each axis's rate varies less than `maxGyroStd` and stays under
  /// `maxBias`, the mean specific force of the two halves differs by less than
  /// `maxAccelChange`, at least `minSamples` readings), for both arm IMUs at once.
  RestBiasParams rest;
  /// A fit waiting this long (s) for a rest is told once (hold the arm still for a moment); it
  /// keeps waiting: used mid-movement it would be no better than the straps as they are.
  double restWaitTellSeconds = 20.0;
};

/// Whether an IMU was still over its newest readings (RestBiasParams's rule, on a sliding
/// window).
class ImuStillness {
 public:
  void add(double t, const ImuReading& r, double seconds);
  bool still(const RestBiasParams& p) const;

 private:
  struct Reading {
    double t;
    Eigen::Vector3d gyr, acc;
  };
  std::deque<Reading> m_readings;
};

/// What the session's calibration from movement did so far; Session::movementCalibration().
struct LiveCalibrationStatus {
  enum class State {
    Off,         ///< not asked for (a calibration file is in use), or no estimator
    Collecting,  ///< waiting for the first window
    Fitting,     ///< the first fit that could be made runs
    AsFitted,    ///< fits were made and none was better: the straps sit as the sidecar says
    Applied,     ///< a fitted calibration is in use
  };
  State state = State::Off;
  bool fitting = false;  ///< a fit (or refit) runs now
  /// A fit to be used is ready and waits for the arm to rest (LiveCalibrationParams::applyAtRest)
  /// since readyAt (session time, s).
  bool waitingForRest = false;
  double readyAt = std::numeric_limits<double>::quiet_NaN();
  int fits = 0;     ///< fits finished (any outcome)
  int applied = 0;  ///< of which applied (the first, and each better refit)
  /// The calibration in use, its summary and when it was applied: the session time (s) of the
  /// row from which the estimator used it; the first application's too (a refit may apply
  /// another later).
  std::optional<Calibration> calibration;
  std::optional<MountingSummary> summary;
  double appliedAt = std::numeric_limits<double>::quiet_NaN();
  double firstAppliedAt = std::numeric_limits<double>::quiet_NaN();
  /// The session time (s) of the row at which the fit now in use started (its window ended).
  double fittedAt = std::numeric_limits<double>::quiet_NaN();
  /// The newest fit's line ("calibration from movement: ..."), as told in the session messages.
  std::string line;
};

/// Where a session recorded at csv keeps the calibration it fitted and used:
/// "rec.csv" -> "rec.movement-calibration.json" (a calibration file, docs/calibration.md), so
/// `armtrack-cli estimate rec.csv --calibration rec.movement-calibration.json` uses it again.
std::filesystem::path movementCalibrationPath(const std::filesystem::path& csv);

/// Owned by the session's worker thread: add() every row, poll() for a finished fit. status()
/// may be called from any thread.
class LiveCalibration {
 public:
  /// meta: the session's sidecar (the fit's prior); paramsFor: the session's filter for a meta.
  LiveCalibration(const LiveCalibrationParams& params, RecordingMeta meta,
                  FilterParamsFor paramsFor);
  ~LiveCalibration();  ///< cancels a running fit and waits for it
  LiveCalibration(const LiveCalibration&) = delete;
  LiveCalibration& operator=(const LiveCalibration&) = delete;

  /// A row as the devices gave it (session time).
  void add(const ArmSample& row);
  /// When a fit has finished: its result (a calibration set only when it is to be used from now
  /// on; the status is updated already). A fit to be used is handed back only at a row at which
  /// the arm rests (applyAtRest). Starts the next fit when it is due (not while one waits).
  std::optional<AutoCalibrationResult> poll(double t);
  /// What to tell in the session messages besides the fits' lines (waiting for a rest), once.
  std::vector<std::string> takeNotes();
  /// Both arm IMUs were still over their last rest.windowSeconds of readings, as of the last
  /// look (at most kRestCheckSeconds of session time before the newest row).
  bool atRest() const;
  /// How often (session time, s) add() looks whether the arm rests.
  static constexpr double kRestCheckSeconds = 0.05;
  /// Cancels a running fit and waits for it (the session stops).
  void finish();

  LiveCalibrationStatus status() const;

 private:
  void startFit(double t);
  /// The index of m_window's row a fit starts at (windowSeconds).
  std::size_t windowStart() const;
  std::optional<AutoCalibrationResult> finishFit(double t);
  std::optional<AutoCalibrationResult> release(double t);

  LiveCalibrationParams m_params;
  RecordingMeta m_meta;
  FilterParamsFor m_paramsFor;
  std::deque<ArmSample> m_window;
  std::deque<bool> m_windowRest;  // whether the arm rested at each row of m_window
  bool m_windowCut = false;       // m_window no longer starts at the session's first row
  double m_firstT = std::numeric_limits<double>::quiet_NaN();
  double m_nextUpperT = -std::numeric_limits<double>::infinity();  // next upper-arm reading kept
  double m_nextForearmT = -std::numeric_limits<double>::infinity();
  double m_nextFitT = 0.0;   // session time of the next fit
  double m_fitStartT = 0.0;  // session time of the row the running fit started at
  bool m_madeOne = false;    // a fit was made (not merely "not tried")
  std::optional<Calibration> m_current;
  bool m_currentRollSeen = false;  // m_current has the forearm's roll from the start pose
  ImuStillness m_upperStill, m_forearmStill;
  bool m_rest = false;  // atRest() as of m_restCheckedT
  double m_restCheckedT = -std::numeric_limits<double>::infinity();
  std::optional<AutoCalibrationResult> m_pending;  // a fit to be used, waiting for a rest
  double m_pendingSince = 0.0;
  bool m_toldWaiting = false;
  std::vector<std::string> m_notes;

  std::thread m_thread;
  std::atomic<bool> m_cancel{false}, m_done{false};
  AutoCalibrationResult m_result;  // written by the fit thread before m_done

  mutable std::mutex m_statusMutex;
  LiveCalibrationStatus m_status;
};

}  // namespace armtrack::session
