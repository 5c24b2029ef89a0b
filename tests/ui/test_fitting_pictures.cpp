// The user guide's pictures of where the sensors and the camera go (docs/user-guide.md, "Fitting
// the sensors"), made from the program's own 3D arm view under Xvfb, grabbed from the screen and
// labelled. Before a picture is saved the test checks what it claims:
// - the arrow drawn on a sensor is the axis the sensor check expects to point up when the arm
//   hangs (the accelerometer's reading of gravity that core/calibration/SensorCheck predicts from
//   the arm model), for either arm;
// - each sensor shows on the screen where an independent projection of the model puts it, and
//   its arrow points, on the screen, at the shoulder (hanging upper arm) or the elbow (forearm);
// - the webcam's lines of sight drawn by the view meet the elbow and the wrist.
#include <QPainter>
#include <QPainterPath>
#include <QStyle>
#include <QStyleFactory>
#include <QWidget>
#include <cmath>
#include <numbers>

#include "core/camera/PinholeCamera.h"
#include "core/kinematics/ArmModel.h"
#include "tests/support/GuiTestMain.h"
#include "tests/ui/ArmViewTesting.h"
#include "ui/ArmFigure.h"
#include "ui/ArmView.h"

using namespace armtrack;
using namespace armtrack::ui;
using armtrack::test::project;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kWidth = 760, kHeight = 560;

/// The sensors are drawn orange (ui/ArmScene), lit and shaded.
bool isSensorOrange(QRgb c) {
  const QColor q(c);
  return q.hsvHue() >= 18 && q.hsvHue() <= 45 && q.hsvSaturation() > 130 && q.value() > 90;
}

/// The webcam's lines of sight are drawn yellow, unlit.
bool isRayYellow(QRgb c) {
  const QColor q(c);
  return q.hsvHue() >= 46 && q.hsvHue() <= 62 && q.hsvSaturation() > 150 && q.value() > 180;
}

/// The arrow's direction in the sensor's own frame: worn right, it points towards the shoulder
/// along the segment, which is the sensor's -y axis (docs/arm-model.md).
const Eigen::Vector3d kArrowInSensor(0.0, -1.0, 0.0);

/// A label: a white box at topLeft, width wide and as high as its text, with a dark frame and a
/// leader line to what it names.
void drawLabel(QPainter& p, QPointF topLeft, double width, const QString& text, QPointF target) {
  const QRect textRect = p.fontMetrics().boundingRect(
      QRect(0, 0, static_cast<int>(width) - 20, 1000), Qt::TextWordWrap, text);
  const QRectF box(topLeft, QSizeF(width, textRect.height() + 14));
  const QPointF from(std::clamp(target.x(), box.left(), box.right()),
                     std::clamp(target.y(), box.top(), box.bottom()));
  p.setPen(QPen(QColor(0x20, 0x20, 0x24), 2.0));
  p.drawLine(from, target);
  p.setBrush(QColor(0x20, 0x20, 0x24));
  p.drawEllipse(target, 3.5, 3.5);
  p.setBrush(QColor(255, 255, 255, 235));
  p.drawRoundedRect(box, 6, 6);
  p.setPen(QColor(0x10, 0x10, 0x12));
  p.drawText(box.adjusted(10, 7, -10, -7), Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap,
             text);
}

/// The arrow on a sensor: white with a dark outline, centred on the sensor, along dir (unit,
/// screen).
void drawArrow(QPainter& p, QPointF centre, QPointF dir, double length) {
  const QPointF tail = centre - dir * (length / 2), tip = centre + dir * (length / 2);
  const QPointF side(-dir.y(), dir.x());
  QPainterPath path;
  path.moveTo(tail);
  path.lineTo(tip);
  path.moveTo(tip - dir * (length * 0.4) + side * (length * 0.3));
  path.lineTo(tip);
  path.lineTo(tip - dir * (length * 0.4) - side * (length * 0.3));
  p.setBrush(Qt::NoBrush);
  p.setPen(QPen(QColor(0x10, 0x10, 0x12), 7, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  p.drawPath(path);
  p.setPen(QPen(Qt::white, 3.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  p.drawPath(path);
}

QPointF unit(QPointF v) {
  const double n = std::hypot(v.x(), v.y());
  return n > 0 ? v / n : QPointF();
}

double dot(QPointF a, QPointF b) {
  return a.x() * b.x() + a.y() * b.y();
}

/// Whether p lies along the screen segment from a to b between fractions lo and hi of its length.
bool between(QPointF p, QPointF a, QPointF b, double lo, double hi) {
  const QPointF ab = b - a;
  const double t = dot(p - a, ab) / dot(ab, ab);
  return t > lo && t < hi;
}

}  // namespace

class TestFittingPictures : public QObject {
  Q_OBJECT

  QWidget* m_window = nullptr;
  ArmView* m_view = nullptr;

  QPointF at(const Eigen::Vector3d& p) const {
    return project(m_view->camera(), p, m_view->width(), m_view->height());
  }

  /// The centre of the orange pixels within radius of where the model puts a sensor, and how
  /// many there are (logical pixels).
  std::pair<QPointF, int> sensorOnScreen(const QImage& img, QPointF expected, double radius) {
    const double dpr = m_view->devicePixelRatioF();
    double sx = 0, sy = 0;
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
      for (int x = 0; x < img.width(); ++x) {
        const QPointF p(x / dpr, y / dpr);
        if (std::hypot(p.x() - expected.x(), p.y() - expected.y()) > radius) continue;
        if (!isSensorOrange(img.pixel(x, y))) continue;
        sx += p.x();
        sy += p.y();
        ++n;
      }
    return {n > 0 ? QPointF(sx / n, sy / n) : expected, static_cast<int>(n / (dpr * dpr))};
  }

  QPointF arrowOnScreen(const Eigen::Isometry3d& imu) const {
    const Eigen::Vector3d a = imu.linear() * kArrowInSensor;
    return unit(at(imu.translation() + 0.05 * a) - at(imu.translation()));
  }

  /// A painter on the grabbed picture draws in the view's logical pixels, smoothly, in the
  /// labels' font.
  void prepareLabels(QPainter& p) const {
    p.setRenderHint(QPainter::Antialiasing);
    p.scale(m_view->devicePixelRatioF(), m_view->devicePixelRatioF());
    QFont f = m_window->font();
    f.setPixelSize(15);
    p.setFont(f);
  }

 private slots:
  void initTestCase() {
    QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    // The light appearance: the pictures are printed with the guide.
    QApplication::setPalette(QApplication::style()->standardPalette());
    m_window = new QWidget;
    m_view = new ArmView(m_window);
    m_view->setGeometry(0, 0, kWidth, kHeight);
    m_window->resize(kWidth, kHeight);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window));
    QTRY_VERIFY_WITH_TIMEOUT(m_view->framesRendered() > 0, 10000);
    QVERIFY2(!m_view->failed(), qPrintable(m_view->problem()));
    m_view->setRefreshRate(0);  // frames only when the test asks
  }

  void cleanupTestCase() { delete m_window; }

  /// The arrow of the pictures is what the sensor check calls "the right way round": with the arm
  /// hanging, the accelerometer of a sensor worn right reads gravity's reaction (up) along it.
  void theArrowIsTheAxisTheSensorCheckExpectsUp() {
    const ArmGeometry geo;
    const JointVector zero = JointVector::Zero();
    const Eigen::Vector3d up(-1.0, 0.0, 0.0);
    const ArmPrediction hanging = predictSensors(geo, zero, zero, zero, 9.81 * up);
    QVERIFY(hanging.upper.acc.normalized().dot(kArrowInSensor) > 0.999);
    QVERIFY(hanging.forearm.acc.normalized().dot(kArrowInSensor) > 0.999);
    // In the room: up, and from each sensor towards the shoulder, on either arm.
    for (Side side : {Side::Right, Side::Left}) {
      const ArmFigure f = armFigure(geo, zero, side);
      for (const Eigen::Isometry3d& imu : {f.upperImu, f.forearmImu}) {
        const Eigen::Vector3d arrow = imu.linear() * kArrowInSensor;
        QVERIFY(arrow.dot(up) > 0.999);
      }
      // Along each segment, towards the shoulder.
      QVERIFY((f.upperImu.linear() * kArrowInSensor).dot((f.shoulder - f.elbow).normalized()) >
              0.999);
      QVERIFY((f.forearmImu.linear() * kArrowInSensor).dot((f.elbow - f.wrist).normalized()) >
              0.999);
    }
  }

  /// The upper-arm sensor: the arm hanging, seen from the front and a little to the arm's side.
  void upperArmPicture() {
    const ArmGeometry geo;  // 22 cm upper arm, the strap 11 cm below the shoulder
    m_view->setArm(geo, Side::Right);
    m_view->setPose(JointVector::Zero());
    m_view->setTargetPose(std::nullopt);
    m_view->setOptical({});
    CameraView v;
    v.focalPoint = {0.18, 0.0, 0.03};
    v.position = {-0.05, 0.55, 0.95};  // in front and to the arm's side, a little above
    v.viewUp = {-1, 0, 0};
    v.viewAngleDeg = 30;
    m_view->setCamera(v);
    QImage img = test::freshShot(m_view);
    QVERIFY(!img.isNull());
    const ArmFigure f = armFigure(geo, JointVector::Zero(), Side::Right);
    const auto [upper, upperPixels] = sensorOnScreen(img, at(f.upperImu.translation()), 45);
    QVERIFY2(upperPixels > 150, qPrintable(QString::number(upperPixels)));
    const QPointF arrow = arrowOnScreen(f.upperImu);
    QVERIFY(dot(arrow, unit(at(f.shoulder) - at(f.elbow))) > 0.95);  // up the arm
    QVERIFY(between(upper, at(f.shoulder), at(f.elbow), 0.3, 0.7));  // about halfway down

    QPainter p(&img);
    prepareLabels(p);
    drawArrow(p, upper, arrow, 30);
    drawLabel(p, QPointF(upper.x() - 300, upper.y() - 150), 260,
              QStringLiteral("Upper-arm sensor: on the outside of the upper arm, about halfway "
                             "between shoulder and elbow (here 11 cm below the shoulder)."),
              upper + QPointF(-12, -8));
    drawLabel(p, QPointF(upper.x() - 300, upper.y() + 60), 260,
              QStringLiteral("Its arrow points up the arm, towards the shoulder."),
              upper + arrow * 15);
    p.end();
    test::saveScreenshot(img, QStringLiteral("fitting-upper-arm"));
  }

  /// The forearm sensor: in the calibration's start pose (elbow at 90 degrees, thumb up), seen
  /// from the front and the body's side, where the sensor faces.
  void forearmPicture() {
    const ArmGeometry geo;  // 20 cm forearm, the sensor 20 cm from the elbow: at the wrist
    JointVector th = JointVector::Zero();
    th(3) = -90 * kDeg;
    m_view->setArm(geo, Side::Right);
    m_view->setPose(th);
    CameraView v;
    v.focalPoint = {0.2, 0.16, -0.02};
    v.position = {-0.45, 1.15, -0.45};  // above, in front, on the body's side of the arm
    v.viewUp = {-1, 0, 0};
    v.viewAngleDeg = 30;
    m_view->setCamera(v);
    QImage img = test::freshShot(m_view);
    QVERIFY(!img.isNull());
    const ArmFigure f = armFigure(geo, th, Side::Right);
    const auto [fore, forePixels] = sensorOnScreen(img, at(f.forearmImu.translation()), 45);
    QVERIFY2(forePixels > 150, qPrintable(QString::number(forePixels)));
    const QPointF arrow = arrowOnScreen(f.forearmImu);
    QVERIFY(dot(arrow, unit(at(f.elbow) - at(f.wrist))) > 0.95);  // along the forearm to the elbow
    QVERIFY(between(fore, at(f.elbow), at(f.wrist), 0.75, 1.1));  // near the wrist

    QPainter p(&img);
    prepareLabels(p);
    drawArrow(p, fore, arrow, 30);
    drawLabel(p, QPointF(fore.x() - 330, fore.y() + 60), 300,
              QStringLiteral("Forearm sensor: just above the wrist, on the side that faces the "
                             "body when the arm hangs with the thumb forward."),
              fore + QPointF(0, 12));
    drawLabel(p, QPointF(fore.x() - 330, fore.y() - 150), 300,
              QStringLiteral("Arrow along the forearm towards the elbow (up, towards the "
                             "shoulder, when the arm hangs)."),
              fore + arrow * 15);
    p.end();
    test::saveScreenshot(img, QStringLiteral("fitting-forearm"));
  }

  /// Where the camera stands: 2 m in front of the shoulder at shoulder height, looking at the
  /// patient; the view draws its lines of sight to the elbow and wrist markers.
  void cameraPicture() {
    const ArmGeometry geo;
    JointVector th = JointVector::Zero();
    th(0) = 25 * kDeg;
    th(3) = -60 * kDeg;
    const CameraParams cam = frontCamera(2.0);
    m_view->setArm(geo, Side::Right, Eigen::Vector3d(-1, 0, 0), cam);
    m_view->setPose(th);
    const ArmFigure f = armFigure(geo, th, Side::Right);
    const PinholeCamera pinhole(cam);
    Eigen::Vector2d elbowPx, wristPx;
    QVERIFY(pinhole.project(f.elbow, elbowPx));
    QVERIFY(pinhole.project(f.wrist, wristPx));
    OpticalMarks marks;
    marks.camElbow = elbowPx;
    marks.camWrist = wristPx;
    m_view->setOptical(marks);
    CameraView v;
    v.focalPoint = {0.15, 1.0, 0.0};
    v.position = {-1.5, 1.0, 2.7};  // above, to the patient's right, halfway to the camera
    v.viewUp = {-1, 0, 0};
    v.viewAngleDeg = 30;
    m_view->setCamera(v);
    QImage img = test::freshShot(m_view);
    QVERIFY(!img.isNull());
    // The camera's centre, in the shoulder frame: p_camera = R p + t = 0.
    const Eigen::Vector3d centre = -cam.R.transpose() * cam.t;
    QVERIFY((centre - Eigen::Vector3d(0, 2, 0)).norm() < 1e-9);
    // The view's yellow lines of sight run from the elbow and the wrist towards the camera (the
    // joints themselves are inside the drawn arm).
    const double dpr = m_view->devicePixelRatioF();
    for (const Eigen::Vector3d& joint : {f.elbow, f.wrist}) {
      const Eigen::Vector3d towardsCamera = (centre - joint).normalized();
      int yellow = 0;
      for (double along : {0.12, 0.18, 0.24}) {
        const QPointF j = at(joint + along * towardsCamera);
        for (int dy = -4; dy <= 4; ++dy)
          for (int dx = -4; dx <= 4; ++dx) {
            const QPoint q(static_cast<int>((j.x() + dx) * dpr),
                           static_cast<int>((j.y() + dy) * dpr));
            if (img.rect().contains(q) && isRayYellow(img.pixel(q))) ++yellow;
          }
      }
      QVERIFY2(yellow > 6, qPrintable(QStringLiteral("%1 yellow pixels").arg(yellow)));
    }

    QPainter p(&img);
    prepareLabels(p);
    // The camera: a box with a lens, facing the patient, and dashed lines of sight.
    const QPointF c = at(centre), e = at(f.elbow), w = at(f.wrist);
    p.setPen(QPen(QColor(0x20, 0x20, 0x24), 1.5, Qt::DashLine));
    p.drawLine(c, e);
    p.drawLine(c, w);
    p.setPen(QPen(QColor(0x10, 0x10, 0x12), 2));
    p.setBrush(QColor(0x3a, 0x3d, 0x44));
    p.drawRoundedRect(QRectF(c.x() - 18, c.y() - 12, 36, 24), 4, 4);
    p.setBrush(QColor(0x9a, 0xc8, 0xf0));
    p.drawEllipse(c, 7, 7);
    p.setBrush(QColor(0x00, 0xa0, 0x40));  // the colour markers: green wrist, blue elbow
    p.drawEllipse(w, 6, 6);
    p.setBrush(QColor(0x20, 0x50, 0xe0));
    p.drawEllipse(e, 6, 6);
    drawLabel(p, QPointF(std::min(c.x() - 150, kWidth - 310.0), c.y() + 40), 300,
              QStringLiteral("Webcam or Kinect: about 2 m in front of the patient, at shoulder "
                             "height, facing the arm; the whole arm in view."),
              c + QPointF(0, 12));
    drawLabel(p, QPointF(std::max(10.0, w.x() - 200), w.y() + 90), 280,
              QStringLiteral("Markers facing the camera: green on the wrist, blue on the "
                             "elbow."),
              w);
    p.end();
    test::saveScreenshot(img, QStringLiteral("fitting-camera"));
  }
};

ARMTRACK_GUI_TEST_MAIN(TestFittingPictures)
#include "test_fitting_pictures.moc"
