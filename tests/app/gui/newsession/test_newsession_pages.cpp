// The new-session steps under Xvfb: the devices page builds specs from the plugins' own option
// help and checks a real connection; the calibration guide follows the simulated protocol
// exactly; a whole guided calibration with the virtual arm playing the protocol gives a good
// verdict; the camera page calibrates a synthetic camera from generated chessboard views.
#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "app/gui/common/CalibrationGuide.h"
#include "app/gui/common/SensorCalibrationPage.h"
#include "app/gui/newsession/CameraCalibrationPage.h"
#include "app/gui/newsession/DevicesPage.h"
#include "app/plugins/PluginRegistry.h"
#include "core/simulation/Trajectory.h"
#include "tests/support/GuiTestMain.h"
#include "ui/AngleReadouts.h"
#include "ui/DeviceHealthPanel.h"
#include "ui/DeviceOptionsForm.h"

using namespace armtrack;
using namespace armtrack::app;
using namespace armtrack::app::gui;

namespace {

constexpr double kRad = std::numbers::pi / 180.0;  // rad per degree

/// Views of a 9 x 6 chessboard (25 mm squares) seen by a pinhole camera without distortion
/// (fx = fy = 600, 640 x 480), the board placed over a 4 x 4 grid of image positions at 0.5-0.8
/// m, tilted up to 25 deg. Rendered by warping a drawn board through the true homography.
class SyntheticChessboard {
 public:
  static constexpr double kFx = 600, kFy = 600, kCx = 320, kCy = 240;
  explicit SyntheticChessboard(int views = 16) {
    const int px = 40, squaresX = 10, squaresY = 7;  // texture: 40 px a square, 1 square margin
    m_texture = cv::Mat(px * (squaresY + 2), px * (squaresX + 2), CV_8UC1, cv::Scalar(255));
    for (int y = 0; y < squaresY; ++y)
      for (int x = 0; x < squaresX; ++x)
        if ((x + y) % 2 == 0)
          cv::rectangle(m_texture, cv::Rect((x + 1) * px, (y + 1) * px, px, px), cv::Scalar(0),
                        cv::FILLED);
    const double s = 0.025;
    // Texture pixels to board metres, board centred on its origin.
    const cv::Matx33d a(s / px, 0, -s * (squaresX + 2) / 2.0, 0, s / px, -s * (squaresY + 2) / 2.0,
                        0, 0, 1);
    const cv::Matx33d k(kFx, 0, kCx, 0, kFy, kCy, 0, 0, 1);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> tilt(-25 * kRad, 25 * kRad), depth(0.5, 0.8);
    for (int i = 0; i < views; ++i) {
      const double u = 110 + 140 * (i % 4), v = 90 + 100 * ((i / 4) % 4);
      cv::Vec3d rvec(tilt(rng), tilt(rng), 0.3 * tilt(rng));
      cv::Matx33d r;
      cv::Rodrigues(rvec, r);
      const double z = depth(rng);
      const cv::Vec3d t(z * (u - kCx) / kFx, z * (v - kCy) / kFy, z);
      const cv::Matx33d rt(r(0, 0), r(0, 1), t[0], r(1, 0), r(1, 1), t[1], r(2, 0), r(2, 1), t[2]);
      const cv::Matx33d h = k * rt * a;
      cv::Mat image(480, 640, CV_8UC1, cv::Scalar(140));
      cv::warpPerspective(m_texture, image, cv::Mat(h), image.size(), cv::INTER_LINEAR,
                          cv::BORDER_TRANSPARENT);
      cv::Mat bgr;
      cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
      m_views.push_back(bgr);
    }
  }
  /// Each view a few times (as a camera would show it), then the next, round and round.
  FrameProvider provider() {
    auto next = std::make_shared<int>(0);
    auto views = m_views;
    return [views, next]() {
      const cv::Mat f = views[static_cast<std::size_t>(*next / 3) % views.size()];
      ++*next;
      return f;
    };
  }

 private:
  cv::Mat m_texture;
  std::vector<cv::Mat> m_views;
};

CalibrationResult resultWith(double rms, bool converged = true) {
  CalibrationResult r;
  r.converged = converged;
  r.rmsUpperGyro = r.rmsUpperAcc = r.rmsForearmGyro = r.rmsForearmAcc = rms;
  return r;
}

}  // namespace

class TestNewSessionPages : public QObject {
  Q_OBJECT
  PluginRegistry m_registry;

 private slots:
  void initTestCase() {
    m_registry.load({QStringLiteral(ARMTRACK_PLUGIN_DIR)});
    QVERIFY(m_registry.plugin(QStringLiteral("virtual-arm")));
  }

  void optionsFormReadsThePluginsHelp() {
    const auto fields =
        ui::parseOptionsHelp(m_registry.plugin(QStringLiteral("virtual-arm"))->optionsHelp());
    auto find = [&](const QString& key) -> const ui::OptionField* {
      for (const ui::OptionField& f : fields)
        if (f.key == key) return &f;
      return nullptr;
    };
    QVERIFY(find(QStringLiteral("sensors")));
    QCOMPARE(find(QStringLiteral("sensors"))->defaultValue, QStringLiteral("upper+forearm+kinect"));
    QCOMPARE(find(QStringLiteral("imu-rate"))->defaultValue, QStringLiteral("1000"));
    QVERIFY(find(QStringLiteral("dropout"))->defaultValue.isEmpty());
    QCOMPARE(find(QStringLiteral("dropout"))->placeholder, QStringLiteral("STREAM@START+SECONDS"));
    QVERIFY(find(QStringLiteral("dropout"))->section.startsWith(QStringLiteral("Faults")));
    // A continuation line joins its option's meaning; junk lines do not make options.
    const auto odd = ui::parseOptionsHelp(
        QStringLiteral("a=1   first\n    more of it\n=x broken\nplain heading:\nb=   second\n"));
    QCOMPARE(odd.size(), std::size_t{2});
    QCOMPARE(odd[0].meaning, QStringLiteral("first more of it"));
    QCOMPARE(odd[1].section, QStringLiteral("plain heading"));
    QVERIFY(odd[1].defaultValue.isEmpty());
  }

  // A serial port option gets a button listing the ports found, read afresh at each press; one
  // picked fills the field. The serial IMU plugins' port options are recognised from their help.
  void serialPortOptionsListThePortsFound() {
    for (const char* plugin : {"line-imu", "shimmer3"}) {
      devices::DevicePlugin* p = m_registry.plugin(QString::fromLatin1(plugin));
      QVERIFY2(p, plugin);
      bool found = false;
      for (const ui::OptionField& f : ui::parseOptionsHelp(p->optionsHelp()))
        found = found || (f.key == QStringLiteral("port") && ui::isSerialPortOption(f));
      QVERIFY2(found, plugin);
    }
    if (devices::DevicePlugin* p = m_registry.plugin(QStringLiteral("ngimu")))
      for (const ui::OptionField& f : ui::parseOptionsHelp(p->optionsHelp()))
        QVERIFY2(!ui::isSerialPortOption(f), qPrintable(f.key));  // its port is UDP's

    ui::DeviceOptionsForm form;
    form.resize(560, 220);
    std::vector<ui::SerialPortChoice> ports;
    int looks = 0;
    form.setPortLister([&] {
      ++looks;
      return ports;
    });
    form.setOptionsHelp(
        QStringLiteral("port=   serial port of the sensor, required\n"
                       "rate=100   samples per second\n"));
    form.show();
    QVERIFY(QTest::qWaitForWindowExposed(&form));
    QVERIFY(!form.portsButton(QStringLiteral("rate")));
    QToolButton* button = form.portsButton(QStringLiteral("port"));
    QVERIFY(button);
    const auto openMenu = [&]() -> QMenu* {
      button->click();
      QMenu* menu = nullptr;
      [&] { QTRY_VERIFY((menu = form.findChild<QMenu*>(QStringLiteral("serialPorts")))); }();
      return menu;
    };
    // None plugged in: said, nothing to pick.
    QMenu* menu = openMenu();
    QVERIFY(menu);
    QCOMPARE(menu->actions().size(), 1);
    QVERIFY(!menu->actions().front()->isEnabled());
    QVERIFY(menu->actions().front()->text().contains(QStringLiteral("No serial port found")));
    menu->close();
    QTRY_VERIFY(!form.findChild<QMenu*>(QStringLiteral("serialPorts")));
    // Plugged in since: the next press lists them, with what each is.
    ports = {{QStringLiteral("/dev/ttyUSB0"), QStringLiteral("CP2102 USB to UART")},
             {QStringLiteral("/dev/rfcomm0"), QString()}};
    menu = openMenu();
    QVERIFY(menu);
    QCOMPARE(looks, 2);
    QCOMPARE(menu->actions().size(), 2);
    QVERIFY(menu->actions()[0]->text().contains(QStringLiteral("CP2102")));
    QVERIFY(QTest::qWaitForWindowExposed(menu));
    test::saveScreenshot(test::grabFromScreen(&form), QStringLiteral("device_serial_ports"));
    menu->actions()[1]->trigger();
    QCOMPARE(form.edit(QStringLiteral("port"))->text(), QStringLiteral("/dev/rfcomm0"));
    QCOMPARE(form.optionsText(), QStringLiteral("port=/dev/rfcomm0"));
    menu->close();
  }

  void devicesPageBuildsSpecsAndChecksTheConnection() {
    gui::LiveSessionConfig base;
    DevicesPage page(m_registry, base);
    page.resize(1100, 600);
    page.show();
    QVERIFY(!page.isComplete());
    const auto items =
        page.pluginList()->findItems(QStringLiteral("virtual-arm"), Qt::MatchExactly);
    QCOMPARE(items.size(), 1);
    page.pluginList()->setCurrentItem(items.front());
    items.front()->setCheckState(Qt::Checked);
    QVERIFY(page.isComplete());
    QCOMPARE(page.devices(), QStringList{QStringLiteral("virtual-arm")});  // all at defaults
    QLineEdit* sensors = page.optionsForm()->edit(QStringLiteral("sensors"));
    QVERIFY(sensors);
    // Issue 25, item 12: the options were shown as raw keys ("wrist-hsv") alone. Each field now
    // has its meaning written under it.
    QString meaning;
    for (const ui::OptionField& f : page.optionsForm()->fields())
      if (f.key == QLatin1String("sensors")) meaning = f.meaning;
    QVERIFY(meaning.contains(QStringLiteral("joined by")));
    const QList<QLabel*> labels = page.optionsForm()->findChildren<QLabel*>();
    QVERIFY(std::any_of(labels.cbegin(), labels.cend(), [&](const QLabel* l) {
      return l->objectName() == QLatin1String("optionMeaning") && l->text() == meaning &&
             l->wordWrap();
    }));
    sensors->setText(QStringLiteral("upper+forearm+kinect+webcam"));
    QCOMPARE(page.devices(),
             QStringList{QStringLiteral("virtual-arm:sensors=upper+forearm+kinect+webcam")});
    QSignalSpy finished(&page, &DevicesPage::checkFinished);
    page.checkButton()->click();
    QVERIFY(page.checking());
    QVERIFY(finished.wait(20000));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
    QVERIFY(page.checkPassed());
    // Passed, the check goes on streaming: the angles keep following the arm (the virtual arm
    // moves all the time) until the therapist stops it or goes on.
    const auto* controller = page.findChild<gui::SessionController*>();
    QVERIFY(controller);
    QVERIFY(page.checking());
    QVERIFY(controller->busy());
    QVERIFY(page.checkButton()->isEnabled());
    QCOMPARE(page.checkButton()->text().remove(u'&'), QStringLiteral("Stop check"));
    const auto* readouts = page.findChild<ui::AngleReadouts*>();
    QVERIFY(readouts);
    for (int second = 0; second < 4; ++second) {
      QStringList before;
      for (int a = 0; a < 5; ++a) before << readouts->valueText(a);
      QTRY_VERIFY_WITH_TIMEOUT(
          [&] {
            for (int a = 0; a < 5; ++a)
              if (readouts->valueText(a) != before[a]) return true;
            return false;
          }(),
          3000);
      QTest::qWait(1000);
      QVERIFY(page.checking());
    }
    QCOMPARE(finished.count(), 1);  // the verdict once
    page.stopCheck();
    QVERIFY(!page.checking());
    QVERIFY(page.checkPassed());
    QVERIFY2(page.statusText().startsWith(QStringLiteral("Connected:")),
             qPrintable(page.statusText()));
    QCOMPARE(finished.count(), 1);
    // Until the check's devices are released (the controller's reply needs this thread's event
    // loop, which has not run since), the button is off: a check started now would be refused.
    QVERIFY(controller->busy());
    QVERIFY(!page.checkButton()->isEnabled());
    // The rate in the locale's digits ("1000", "1,000", "1.000"), as measured over the last
    // second: 999 to 1,001 on a loaded machine, further off on a heavily loaded one.
    const QRegularExpression upperRate(QStringLiteral("upper (\\S+) Hz"));
    const QRegularExpressionMatch rate = upperRate.match(page.statusText());
    QVERIFY2(rate.hasMatch(), qPrintable(page.statusText()));
    bool parsed = false;
    const int hz = QLocale().toInt(rate.captured(1), &parsed);
    QVERIFY2(parsed && std::abs(hz - 1000) <= 20, qPrintable(page.statusText()));
    // The virtual arm's battery (battery=80 by default, 1 % a minute) in the summary and on
    // every stream's row.
    const QString percent = QLocale().toString(80) + QStringLiteral(" %");
    QVERIFY2(page.statusText().contains(QStringLiteral("Battery: virtual-arm#1 ") + percent),
             qPrintable(page.statusText()));
    const ui::DeviceHealthModel* health = page.health()->model();
    QCOMPARE(health->rowCount(), 5);  // upper, forearm, Kinect, webcam, truth
    for (int row = 0; row < health->rowCount(); ++row)
      QCOMPARE(health->data(health->index(row, ui::DeviceHealthModel::Battery)).toString(),
               percent);
    test::saveScreenshot(test::grabFromScreen(&page), QStringLiteral("new_session_devices"));
    // A low battery is said so, and the check still passes.
    QLineEdit* battery = page.optionsForm()->edit(QStringLiteral("battery"));
    QVERIFY(battery);
    battery->setText(QStringLiteral("12"));
    // Again as soon as the button is back, as a therapist would: the first check has let go of
    // its devices by then.
    QTRY_VERIFY_WITH_TIMEOUT(page.checkButton()->isEnabled(), 10000);
    QVERIFY(!controller->busy());
    finished.clear();
    page.checkButton()->click();
    QVERIFY(finished.wait(20000));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
    QVERIFY2(page.statusText().contains(QStringLiteral("Battery: virtual-arm#1 12 % (low")),
             qPrintable(page.statusText()));
    page.stopCheck();
    battery->setText(QString());
    // A bad option: the plugin's own message, once the previous check has let go of its devices
    // (until then the controller refuses to start).
    sensors->setText(QStringLiteral("upper+banana"));
    QTRY_VERIFY_WITH_TIMEOUT(!page.checking(), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(!controller->busy(), 10000);
    finished.clear();
    page.startCheck();
    QVERIFY(finished.wait(20000));
    QVERIFY(!finished.at(0).at(0).toBool());
    QVERIFY2(page.statusText().contains(QStringLiteral("banana")), qPrintable(page.statusText()));
    // Specs given back choose the plugins again; an unknown one is named.
    DevicesPage other(m_registry, base);
    other.setDevices({QStringLiteral("virtual-arm:sensors=upper"), QStringLiteral("nope")});
    QCOMPARE(other.devices(), QStringList{QStringLiteral("virtual-arm:sensors=upper")});
    QVERIFY(other.statusText().contains(QStringLiteral("nope")));
  }

  void calibrationGuideFollowsTheSimulatedProtocol() {
    const CalibrationProtocolTrajectory protocol;
    QVERIFY(std::abs(protocolSeconds() - protocol.duration()) < 1e-9);
    double t = 0;
    for (const CalibrationPhase& p : calibrationPhases()) {
      QCOMPARE(p.startS, t);
      QVERIFY(p.endS > p.startS);
      t = p.endS;
      if (p.poseDeg) {  // the pose is reached by the end of the phase
        const JointMotion m = protocol.at(p.endS);
        for (int j = 0; j < kNumJoints; ++j)
          QVERIFY2(std::abs(m.th(j) - (*p.poseDeg)[j] * kRad) < 1e-9,
                   qPrintable(p.title + QString::number(j)));
      }
      if (p.hold) {  // and the arm is still while it is held
        for (double f : {0.1, 0.5, 0.9}) {
          const JointMotion m = protocol.at(p.startS + f * (p.endS - p.startS));
          QVERIFY2(m.thd.norm() < 1e-9, qPrintable(p.title));
        }
      }
    }
    QCOMPARE(&phaseAt(-1.0), &calibrationPhases().front());
    QCOMPARE(&phaseAt(1e9), &calibrationPhases().back());
    QCOMPARE(phaseAt(5.0).title, QStringLiteral("Arm forward"));
  }

  void verdictsFromResiduals() {
    QString why;
    QCOMPARE(judgeCalibration(resultWith(1.0), &why), CalibrationVerdict::Good);
    QVERIFY(why.startsWith(QStringLiteral("Good")));
    QCOMPARE(judgeCalibration(resultWith(2.0), &why), CalibrationVerdict::Usable);
    QCOMPARE(judgeCalibration(resultWith(5.0), &why), CalibrationVerdict::Poor);
    QVERIFY(why.contains(QStringLiteral("redo")));
    QCOMPARE(judgeCalibration(resultWith(1.0, false), &why), CalibrationVerdict::Poor);
    CalibrationResult nan = resultWith(1.0);
    nan.rmsPosition = std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(judgeCalibration(nan, &why), CalibrationVerdict::Poor);
    CalibrationResult warned = resultWith(1.0);
    warned.warnings.push_back("the start was not held still");
    QCOMPARE(judgeCalibration(warned, &why), CalibrationVerdict::Usable);
    QVERIFY(why.contains(QStringLiteral("not held still")));
  }

  void guidedCalibrationWithTheVirtualArm() {
    QTemporaryDir dir;
    gui::LiveSessionConfig c;
    c.devices = {QStringLiteral("virtual-arm:sensors=upper+forearm+kinect,trajectory=calibration")};
    // A folder that does not exist yet: the recording makes it (off the GUI thread).
    SensorCalibrationPage page(m_registry, c,
                               dir.filePath(QStringLiteral("calibration/today")).toStdString());
    page.resize(1100, 650);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    QSignalSpy finished(&page, &SensorCalibrationPage::finished);
    page.start();
    QCOMPARE(page.state(), SensorCalibrationPage::State::Recording);
    QTRY_VERIFY_WITH_TIMEOUT(page.instructionTitle() == QStringLiteral("Arm forward"), 15000);
    test::saveScreenshot(test::grabFromScreen(&page), QStringLiteral("new_session_calibration"));
    QVERIFY(finished.wait(150000));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(page.verdictText()));
    QCOMPARE(page.state(), SensorCalibrationPage::State::Done);
    QVERIFY(page.isComplete());
    QVERIFY(page.result().has_value());
    QVERIFY2(page.verdictText().startsWith(QStringLiteral("Good")), qPrintable(page.verdictText()));
    // The virtual arm's straps sit where the default geometry says.
    QVERIFY(std::abs(page.result()->calibration.geometry.thu4 - std::numbers::pi / 2) < 3 * kRad);
    QVERIFY(std::filesystem::exists(page.recordingPath()));
    test::saveScreenshot(test::grabFromScreen(&page),
                         QStringLiteral("new_session_calibration_done"));
  }

  void calibrationCanBeCancelledAndRedone() {
    QTemporaryDir dir;
    gui::LiveSessionConfig c;
    c.devices = {QStringLiteral("virtual-arm:sensors=upper+forearm,trajectory=calibration")};
    SensorCalibrationPage page(m_registry, c, dir.path().toStdString());
    page.show();
    page.start();
    QTRY_VERIFY_WITH_TIMEOUT(page.instructionTitle() == QStringLiteral("Start pose"), 10000);
    page.cancel();
    QCOMPARE(page.state(), SensorCalibrationPage::State::Ready);
    QVERIFY(!page.isComplete());
    // Start stays off until the cancelled run has let go of its devices (the controller's reply
    // needs this thread's event loop, which has not run since the cancel), then comes back.
    const auto* controller = page.findChild<gui::SessionController*>();
    QVERIFY(controller);
    QVERIFY(controller->busy());
    QVERIFY(!page.startButton()->isEnabled());
    QTRY_VERIFY_WITH_TIMEOUT(page.startButton()->isEnabled(), 10000);
    QVERIFY(!controller->busy());
    page.startButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(page.instructionTitle() == QStringLiteral("Start pose"), 10000);
    page.cancel();
  }

  void cameraCalibrationFromChessboardViews() {
    SyntheticChessboard board;
    CameraCalibrationPage page(board.provider(), devices::webcam::ChessboardSpec{});
    page.resize(1000, 500);
    page.show();
    page.startCamera();
    QTRY_VERIFY_WITH_TIMEOUT(page.capturedViews() >= 12, 30000);
    QVERIFY2(page.coverage().fraction() > 0.6,
             qPrintable(QString::number(page.coverage().fraction())));
    test::saveScreenshot(test::grabFromScreen(&page), QStringLiteral("new_session_camera"));
    page.stopCamera();
    QSignalSpy calibrated(&page, &CameraCalibrationPage::calibrated);
    page.calibrate();
    QVERIFY(calibrated.wait(30000));
    QVERIFY2(calibrated.at(0).at(0).toBool(), qPrintable(page.verdictText()));
    QVERIFY(page.isComplete());
    const auto& in = page.result()->intrinsics;
    QVERIFY2(std::abs(in.fx - SyntheticChessboard::kFx) < 0.02 * SyntheticChessboard::kFx,
             qPrintable(QString::number(in.fx)));
    QVERIFY(std::abs(in.fy - SyntheticChessboard::kFy) < 0.02 * SyntheticChessboard::kFy);
    QVERIFY(std::abs(in.cx - SyntheticChessboard::kCx) < 10);
    QVERIFY(std::abs(in.cy - SyntheticChessboard::kCy) < 10);
    QVERIFY(in.rmsPx < 0.5);
    QVERIFY(page.verdictText().contains(QStringLiteral("Reprojection error")));
    page.reset();
    QCOMPARE(page.capturedViews(), 0);
    QVERIFY(!page.isComplete());
  }

  void everyWebcamIsRecognised() {
    // The virtual arm's simulated webcam gives marker pixels: it is a webcam among the devices,
    // with its own camera model (no images for a chessboard).
    auto cams = camerasAmong(m_registry,
                             {QStringLiteral("virtual-arm:sensors=upper+forearm+kinect+webcam")});
    QCOMPARE(cams.size(), std::size_t{1});
    QCOMPARE(cams[0].plugin, QStringLiteral("virtual-arm"));
    QVERIFY(!cams[0].images);
    const QString text = cameraStepText(cams);
    QVERIFY2(text.contains(QStringLiteral("virtual-arm")), qPrintable(text));
    QVERIFY2(!text.contains(QStringLiteral("No ")), qPrintable(text));
    // The demo's devices (and so the wizard's default) have one.
    QCOMPARE(camerasAmong(m_registry, gui::demoDevices()).size(), std::size_t{1});
    // Without a webcam stream, or with specs that are not devices: none.
    QVERIFY(
        camerasAmong(m_registry, {QStringLiteral("virtual-arm:sensors=upper+forearm")}).empty());
    QVERIFY(camerasAmong(m_registry,
                         {QStringLiteral("nope:x=1"), QStringLiteral(""), QStringLiteral(":::"),
                          QStringLiteral("virtual-arm:sensors=banana")})
                .empty());
    QVERIFY(cameraStepText({}).startsWith(QStringLiteral("No device")));
    // A real camera (the webcam plugin, when it is built) is calibrated with the chessboard.
    if (m_registry.plugin(QStringLiteral("webcam"))) {
      cams = camerasAmong(m_registry, {QStringLiteral("virtual-arm:sensors=upper+forearm"),
                                       QStringLiteral("webcam:source=0")});
      QCOMPARE(cams.size(), std::size_t{1});
      QVERIFY(cams[0].images);
      QVERIFY(cameraStepText(cams).isEmpty());
    }
  }

  void cameraWithoutABoardOrWithoutPictures() {
    std::mt19937 rng(3);
    CameraCalibrationPage noise(
        [&rng] {
          cv::Mat m(240, 320, CV_8UC3);
          cv::randu(m, cv::Scalar::all(0), cv::Scalar::all(255));
          return m;
        },
        devices::webcam::ChessboardSpec{});
    noise.show();
    noise.startCamera();
    QTRY_VERIFY_WITH_TIMEOUT(noise.framesSeen() >= 10, 20000);
    QCOMPARE(noise.capturedViews(), 0);
    QVERIFY(!noise.boardInView());
    noise.calibrate();
    QVERIFY(noise.verdictText().contains(QStringLiteral("at least 4")));
    CameraCalibrationPage dark([] { return cv::Mat(); }, devices::webcam::ChessboardSpec{});
    dark.show();
    dark.startCamera();
    QTRY_VERIFY_WITH_TIMEOUT(
        dark.findChild<QLabel*>()->text().contains(QStringLiteral("No picture")), 10000);
  }
};

ARMTRACK_GUI_TEST_MAIN(TestNewSessionPages)
#include "test_newsession_pages.moc"
