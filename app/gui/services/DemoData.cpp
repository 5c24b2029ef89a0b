#include "app/gui/services/DemoData.h"

#include <QDateTime>
#include <QFile>
#include <QTemporaryDir>
#include <cmath>
#include <numbers>

#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::gui {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

using storage::StorageError;

/// A shoulder-flexion exercise at 0.2 Hz (a repetition every 5 s), starting from the arm at rest:
/// flexion 0..flexionRom, the elbow 20..20+elbowRom, a little abduction and pronation.
SinusoidTrajectory exercise(const SimulatedSession& s) {
  SinusoidTrajectory t;
  const double f = 0.2;
  const double phase = -std::numbers::pi / 2;  // starts at the bottom of each swing
  const double flex = s.flexionRomDeg / 2 * kDeg, elbow = s.elbowRomDeg / 2 * kDeg;
  // DH joints (docs/arm-model.md): th0 flexion, th1 abduction, th2 rotation (-internal),
  // th4 (index 3) = -elbow flexion, th5 (index 4) = -pronation.
  t.offset << flex, 10 * kDeg, 0, -(20 * kDeg + elbow), -10 * kDeg;
  t.amplitude << flex, 5 * kDeg, 5 * kDeg, elbow, 15 * kDeg;
  t.frequency << f, f, f, f, f;
  t.phase << phase, phase, 0, phase, 0;
  return t;
}

void check(const std::atomic<bool>* cancel, bool& cancelled) {
  if (cancel && cancel->load()) cancelled = true;
}

}  // namespace

qint64 addSimulatedSession(storage::Database& db, storage::ClinicalStore& store,
                           const SimulatedSession& s) {
  SimulationParams sim = defaultSimulation();
  sim.duration = s.durationS;
  sim.seed = s.seed;
  sim.side = s.side;
  sim.upperArm.rateHz = sim.forearm.rateHz = s.imuRateHz;
  const SinusoidTrajectory trajectory = exercise(s);
  const Recording recording = simulateRecording(trajectory, sim);
  QTemporaryDir dir;
  if (!dir.isValid())
    throw StorageError(StorageError::Kind::Io, "cannot create a temporary folder for the demo");
  const std::string csv = dir.filePath(QStringLiteral("session.csv")).toStdString();
  writeRecording(csv, recording);
  const qint64 id = store.importRecording(csv, s.patientCode, s.protocol);
  storage::analyseSession(store, id);
  // The records date a session by its import; the demo's history lies in the past.
  const QDateTime when = QDateTime::currentDateTimeUtc().addSecs(
      -static_cast<qint64>(std::llround(s.daysAgo * 86400)));
  db.exec(QStringLiteral("UPDATE sessions SET started_at = ? WHERE id = ?"),
          {when.toString(Qt::ISODateWithMs), id});
  return id;
}

bool buildDemoDatabase(const storage::DatabaseUrl& url, const std::function<void(int)>& progress,
                       const std::atomic<bool>* cancel) {
  const auto report = [&](int p) {
    if (progress) progress(p);
  };
  if (url.engine == storage::DatabaseUrl::Engine::Sqlite) {
    for (const QString& suffix : {QString(), QStringLiteral("-wal"), QStringLiteral("-shm")})
      if (QFile::exists(url.path + suffix) && !QFile::remove(url.path + suffix))
        throw StorageError(StorageError::Kind::Io,
                           "cannot replace the old demo database " + url.path.toStdString());
  }
  bool cancelled = false;
  {
    storage::Database db(url, {.create = true, .migrate = false});
    storage::ClinicalStore store(db);
    store.initialise(QString::fromLatin1(DemoAccounts::kAdmin), DemoAccounts::kPassword);
    store.signIn(QString::fromLatin1(DemoAccounts::kAdmin), DemoAccounts::kPassword);
    store.addUser(QString::fromLatin1(DemoAccounts::kTherapist), storage::Role::Therapist,
                  DemoAccounts::kPassword);
    report(5);

    const auto patient = [&](const char* code, const char* name, const char* born, const char* sex,
                             const char* side, const char* diagnosis, const char* lengths,
                             const char* notes) {
      storage::Patient p;
      p.code = QString::fromUtf8(code);
      p.name = QString::fromUtf8(name);
      p.birthDate = QString::fromUtf8(born);
      p.sex = QString::fromUtf8(sex);
      p.affectedSide = QString::fromUtf8(side);
      p.diagnosis = QString::fromUtf8(diagnosis);
      p.segmentLengthsJson = QString::fromUtf8(lengths);
      p.notes = QString::fromUtf8(notes);
      store.addPatient(p);
    };
    patient(
        "P001", "Ada Example", "1951-04-12", "f", "right",
        "Ischaemic stroke, left hemisphere; right hemiparesis",
        R"({"upper_arm_m":0.29,"forearm_m":0.24,"upper_arm_strap_m":0.12,"forearm_strap_m":0.18})",
        "Demo patient. Shoulder flexion improving week by week.");
    patient("P002", "Bruno Muster", "1967-09-30", "m", "left",
            "Frozen shoulder (adhesive capsulitis), left",
            R"({"upper_arm_m":0.32,"forearm_m":0.27})", "Demo patient.");
    patient("P003", "Carmen Ejemplo", "1980-01-22", "f", "right",
            "Distal radius fracture, right; after cast removal", R"({"forearm_m":0.25})",
            "Demo patient without sessions yet.");
    storage::Protocol flexion;
    flexion.name = QString::fromLatin1(DemoAccounts::kLiveProtocol);
    flexion.angleKey = QStringLiteral("shoulder_flexion");
    flexion.targetMinDeg = 90;
    flexion.targetMaxDeg = 150;
    flexion.repetitions = 10;
    store.addProtocol(flexion);
    storage::Protocol elbow;
    elbow.name = QStringLiteral("Elbow flexion");
    elbow.angleKey = QStringLiteral("elbow_flexion");
    elbow.targetMinDeg = 30;
    elbow.targetMaxDeg = 130;
    elbow.repetitions = 12;
    store.addProtocol(elbow);
    // Ada's home programme: the elbow first (measured well by the IMUs alone), then the
    // shoulder; two short sets each.
    storage::ProgrammeItem homeElbow;
    homeElbow.protocolName = elbow.name;
    homeElbow.sessionsPerWeek = 5;
    homeElbow.sets = 2;
    homeElbow.repetitions = 5;
    homeElbow.targetMinDeg = 30;
    homeElbow.targetMaxDeg = 120;
    homeElbow.restS = 20;
    homeElbow.notes = QStringLiteral("Slowly, stop before it hurts.");
    store.setProgrammeExercise(QStringLiteral("P001"), homeElbow);
    storage::ProgrammeItem homeFlexion = homeElbow;
    homeFlexion.protocolName = flexion.name;
    homeFlexion.sessionsPerWeek = 3;
    homeFlexion.targetMinDeg = 20;
    homeFlexion.targetMaxDeg = 110;
    homeFlexion.notes = QStringLiteral("Keep the elbow straight.");
    store.setProgrammeExercise(QStringLiteral("P001"), homeFlexion);
    store.addUser(QString::fromLatin1(DemoAccounts::kHome), storage::Role::Home,
                  DemoAccounts::kPassword, QStringLiteral("P001"));
    store.assignProtocol(QStringLiteral("P002"), flexion.name, 2);
    report(10);

    // Ada: six weekly sessions, flexion 70 -> 125 deg; Bruno: four, 60 -> 95 deg.
    std::vector<SimulatedSession> sessions;
    for (int week = 0; week < 6; ++week) {
      SimulatedSession s;
      s.patientCode = QStringLiteral("P001");
      s.protocol = flexion.name;
      s.daysAgo = 42 - 7 * week + 0.4;
      s.flexionRomDeg = 70 + 11 * week;
      s.elbowRomDeg = 50 + 6 * week;
      s.seed = 100 + static_cast<std::uint64_t>(week);
      sessions.push_back(s);
    }
    for (int week = 0; week < 4; ++week) {
      SimulatedSession s;
      s.patientCode = QStringLiteral("P002");
      s.protocol = flexion.name;
      s.side = Side::Left;
      s.daysAgo = 30 - 8 * week + 0.2;
      s.flexionRomDeg = 60 + 12 * week;
      s.elbowRomDeg = 70;
      s.seed = 200 + static_cast<std::uint64_t>(week);
      sessions.push_back(s);
    }
    for (std::size_t i = 0; i < sessions.size(); ++i) {
      check(cancel, cancelled);
      if (cancelled) break;
      addSimulatedSession(db, store, sessions[i]);
      report(10 + static_cast<int>(90 * (i + 1) / sessions.size()));
    }
  }
  if (cancelled && url.engine == storage::DatabaseUrl::Engine::Sqlite) QFile::remove(url.path);
  return !cancelled;
}

}  // namespace armtrack::gui
