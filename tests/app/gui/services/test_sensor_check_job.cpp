// The home window's sensor check judged off the GUI thread (app/gui/services/SensorCheckJob), on
// simulated check recordings written to a file as the home window writes them: worn right,
// swapped, and files that are not recordings at all.
#include <Eigen/Geometry>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <cmath>
#include <fstream>

#include "app/gui/services/SensorCheckJob.h"
#include "core/io/Recording.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

Q_DECLARE_METATYPE(armtrack::SensorCheckResult)

using namespace armtrack;
using armtrack::gui::SensorCheckJob;

namespace {

std::filesystem::path simulatedCheck(const QTemporaryDir& dir, const char* name, bool swapped) {
  SimulationParams sim = defaultSimulation();
  sim.duration = SensorCheckTrajectory::duration();
  sim.seed = 3;
  sim.kinect.enabled = false;
  sim.upperArm.rateHz = sim.forearm.rateHz = 200;
  Recording rec = simulateRecording(SensorCheckTrajectory(), sim);
  if (swapped)
    for (ArmSample& s : rec.samples) std::swap(s.upperArm, s.forearm);
  const std::filesystem::path csv = dir.filePath(QString::fromLatin1(name)).toStdString();
  writeRecording(csv, rec);
  return csv;
}

// A check with a sternum sensor worn turned by `turn` from the mounting the session assumed
// (the sidecar's trunk block, as a live session writes it).
std::filesystem::path simulatedCheckWithSternum(const QTemporaryDir& dir, const char* name,
                                                const Eigen::Matrix3d& turn) {
  SimulationParams sim = defaultSimulation();
  sim.duration = SensorCheckTrajectory::duration();
  sim.seed = 5;
  sim.kinect.enabled = false;
  sim.upperArm.rateHz = sim.forearm.rateHz = sim.trunkImu.rateHz = 200;
  sim.trunkImu.enabled = true;
  const TrunkMount assumed = defaultSimulatedTrunkMount(sim.side);
  TrunkMount worn = assumed;
  worn.imuRotation = turn * assumed.imuRotation;
  sim.trunkMount = worn;
  Recording rec = simulateRecording(SensorCheckTrajectory(), sim);
  rec.meta.trunk = assumed;
  const std::filesystem::path csv = dir.filePath(QString::fromLatin1(name)).toStdString();
  writeRecording(csv, rec);
  return csv;
}

SensorCheckResult judgeOnJob(SensorCheckJob& job, const std::filesystem::path& csv) {
  QSignalSpy spy(&job, &SensorCheckJob::judged);
  job.start(csv, SensorCheckParams{});
  if (!spy.wait(60000)) qFatal("the sensor check was not judged within a minute");
  return spy.at(0).at(0).value<SensorCheckResult>();
}

}  // namespace

class TestSensorCheckJob : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { qRegisterMetaType<SensorCheckResult>(); }

  void wornRight() {
    QTemporaryDir dir;
    SensorCheckJob job;
    const SensorCheckResult r = judgeOnJob(job, simulatedCheck(dir, "right.csv", false));
    QVERIFY2(r.ok(), r.explanation.c_str());
    QVERIFY(!job.running());
  }

  void swappedIsFound() {
    QTemporaryDir dir;
    SensorCheckJob job;
    const SensorCheckResult r = judgeOnJob(job, simulatedCheck(dir, "swapped.csv", true));
    QCOMPARE(r.status, SensorCheckStatus::Judged);
    QVERIFY(r.has(SensorFinding::Swapped));
  }

  void sternumSensorIsJudgedFromTheRecording() {
    QTemporaryDir dir;
    SensorCheckJob job;
    SensorCheckResult r =
        judgeOnJob(job, simulatedCheckWithSternum(dir, "trunk.csv", Eigen::Matrix3d::Identity()));
    QVERIFY2(r.ok(), r.explanation.c_str());
    QVERIFY(r.trunkAngleDeg < 3.0);  // judged, not NaN
    // Turned end over end on the chest: found, from the sidecar's mounting alone.
    const Eigen::Matrix3d over = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()).matrix();
    r = judgeOnJob(job, simulatedCheckWithSternum(dir, "over.csv", over));
    QCOMPARE(r.findings, std::vector<SensorFinding>{SensorFinding::TrunkUpsideDown});
  }

  void notARecording() {
    QTemporaryDir dir;
    const std::filesystem::path garbage = dir.filePath(QStringLiteral("garbage.csv")).toStdString();
    std::ofstream(garbage) << "this,is\nnot a recording\x01\x02\n";
    SensorCheckJob job;
    SensorCheckResult r = judgeOnJob(job, garbage);
    QCOMPARE(r.status, SensorCheckStatus::MissingUpperArm);
    QVERIFY(!r.explanation.empty());
    r = judgeOnJob(job, dir.filePath(QStringLiteral("missing.csv")).toStdString());
    QCOMPARE(r.status, SensorCheckStatus::MissingUpperArm);
    QVERIFY(!r.explanation.empty());
  }

  void cancelledAnswerIsDropped() {
    QTemporaryDir dir;
    const std::filesystem::path csv = simulatedCheck(dir, "right.csv", false);
    SensorCheckJob job;
    QSignalSpy spy(&job, &SensorCheckJob::judged);
    job.start(csv, SensorCheckParams{});
    job.cancel();
    QVERIFY(!job.running());
    QTest::qWait(3000);
    QCOMPARE(spy.count(), 0);
  }

  void jobGoneBeforeTheAnswer() {
    QTemporaryDir dir;
    const std::filesystem::path csv = simulatedCheck(dir, "right.csv", false);
    { SensorCheckJob(nullptr).start(csv, SensorCheckParams{}); }
    QTest::qWait(3000);  // the worker's answer finds nobody and is dropped, without a crash
  }
};

QTEST_GUILESS_MAIN(TestSensorCheckJob)
#include "test_sensor_check_job.moc"
