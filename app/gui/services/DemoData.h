// The demo records of `armtrack --demo`: three patients, two protocols, a home programme, and
// earlier sessions with progress over weeks, made the way real ones are: simulated recordings
// (core/simulation) imported and analysed through the clinical records' own services. Qt Core,
// no widgets; runs on any thread (it opens its own connection).
#pragma once

#include <QString>
#include <atomic>
#include <functional>

#include "core/kinematics/Side.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/DatabaseUrl.h"

namespace armtrack::gui {

/// The demo's accounts (the passwords are printed in the user guide: it is a demo).
struct DemoAccounts {
  static constexpr const char* kAdmin = "demo-admin";
  static constexpr const char* kTherapist = "demo";
  static constexpr const char* kPassword = "demo-password";
  /// The home account of the live patient (`armtrack --home --demo` signs in with it).
  static constexpr const char* kHome = "demo-home";
  /// The patient the demo's live session is recorded for.
  static constexpr const char* kLivePatient = "P001";
  static constexpr const char* kLiveProtocol = "Shoulder flexion";
};

/// One simulated exercise session.
struct SimulatedSession {
  QString patientCode;
  QString protocol;  ///< "" = none
  Side side = Side::Right;
  double daysAgo = 0;         ///< its start is set this long before now
  double flexionRomDeg = 90;  ///< shoulder flexion swings 0..this
  double elbowRomDeg = 60;    ///< elbow flexion swings 20..20+this
  double durationS = 20;
  double imuRateHz = 100;  ///< the earlier sessions' IMUs (a Shimmer3-like rate)
  std::uint64_t seed = 1;
};

/// Simulates s (both IMUs and a Kinect, Table 5 noise), imports it as a session of its patient
/// through ClinicalStore::importRecording, analyses it (storage::analyseSession), and moves its
/// start s.daysAgo into the past. db must be the store's database. Returns the session id.
/// Throws StorageError or RecordingError.
qint64 addSimulatedSession(storage::Database& db, storage::ClinicalStore& store,
                           const SimulatedSession& s);

/// Creates a fresh demo database at url (an existing SQLite file there is replaced): accounts,
/// patients, protocols, a home account and home programme (two exercises) for the live patient,
/// and about a dozen analysed sessions over six weeks. progress
/// gets 0-100; cancel (may be null) stops it between sessions (the half-made file is removed).
/// Returns false when cancelled. Throws StorageError or RecordingError.
bool buildDemoDatabase(const storage::DatabaseUrl& url, const std::function<void(int)>& progress,
                       const std::atomic<bool>* cancel = nullptr);

}  // namespace armtrack::gui
