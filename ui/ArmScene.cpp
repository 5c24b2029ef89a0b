#include "ui/ArmScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkLineSource.h>
#include <vtkMatrix4x4.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/camera/PinholeCamera.h"
#include "ui/ArmView.h"

namespace armtrack::ui {

namespace {

using Vec3 = Eigen::Vector3d;
using Rgb = std::array<double, 3>;

constexpr double kUpperRadius = 0.042;  // m, drawn thickness of the upper arm
constexpr double kForearmRadius = 0.034;
constexpr double kJointRadius = 0.046;
constexpr double kFloorBelowShoulder = 1.05;  // m: a seated patient's shoulder height
constexpr double kTrunkOffset = 0.19;         // m from the shoulder to the body's midline
constexpr double kHipBelow = 0.45;            // m: the trunk's pivot below the shoulder...
constexpr double kHipMedial = 0.15;           // ...and medial to it (TrunkSimParams::hip)
constexpr double kTorsoDepth = 0.19;          // m: the drawn torso, front to back
constexpr double kSternumThickness = 0.02;    // m: the drawn sternum IMU's thin side

/// An actor drawn from a shared unit shape through its own matrix.
struct Part {
  vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();
  vtkSmartPointer<vtkMatrix4x4> matrix = vtkSmartPointer<vtkMatrix4x4>::New();

  Part(vtkPolyDataMapper* mapper, vtkRenderer* renderer) {
    actor->SetMapper(mapper);
    actor->SetUserMatrix(matrix);
    renderer->AddActor(actor);
  }
  /// Columns a, b, c scaled and placed at origin.
  void place(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& origin) {
    for (int r = 0; r < 3; ++r) {
      matrix->SetElement(r, 0, a(r));
      matrix->SetElement(r, 1, b(r));
      matrix->SetElement(r, 2, c(r));
      matrix->SetElement(r, 3, origin(r));
    }
    matrix->SetElement(3, 0, 0);
    matrix->SetElement(3, 1, 0);
    matrix->SetElement(3, 2, 0);
    matrix->SetElement(3, 3, 1);
    matrix->Modified();
  }
  void setColor(const Rgb& c) { actor->GetProperty()->SetColor(c[0], c[1], c[2]); }
  void setVisible(bool on) { actor->SetVisibility(on); }
};

/// A unit cylinder (radius 1, height 1, axis y) stretched between two points.
void placeCylinder(Part& p, const Vec3& from, const Vec3& to, double radius) {
  Vec3 axis = to - from;
  const double length = axis.norm();
  const Vec3 dir = length > 1e-9 ? Vec3(axis / length) : Vec3::UnitX();
  const Vec3 u = dir.unitOrthogonal();
  const Vec3 v = u.cross(dir);
  p.place(u * radius, dir * std::max(length, 1e-6), v * radius, (from + to) / 2.0);
}

void placeSphere(Part& p, const Vec3& centre, double radius) {
  p.place(Vec3::UnitX() * radius, Vec3::UnitY() * radius, Vec3::UnitZ() * radius, centre);
}

/// A unit cube with the columns of frame as its axes, sizes along each.
void placeBox(Part& p, const Eigen::Matrix3d& frame, const Vec3& size, const Vec3& centre) {
  p.place(frame.col(0) * size(0), frame.col(1) * size(1), frame.col(2) * size(2), centre);
}

/// The drawn arm (estimate or target).
struct ArmParts {
  Part upper, forearm, shoulder, elbow, wrist, hand;
  ArmParts(vtkPolyDataMapper* cylinder, vtkPolyDataMapper* sphere, vtkPolyDataMapper* cube,
           vtkRenderer* r)
      : upper(cylinder, r),
        forearm(cylinder, r),
        shoulder(sphere, r),
        elbow(sphere, r),
        wrist(sphere, r),
        hand(cube, r) {}
  std::array<Part*, 6> all() { return {&upper, &forearm, &shoulder, &elbow, &wrist, &hand}; }
  void place(const ArmFigure& f) {
    placeCylinder(upper, f.shoulder, f.elbow, kUpperRadius);
    placeCylinder(forearm, f.elbow, f.wrist, kForearmRadius);
    placeSphere(shoulder, f.shoulder, kJointRadius * 1.1);
    placeSphere(elbow, f.elbow, kJointRadius * 0.85);
    placeSphere(wrist, f.wrist, kJointRadius * 0.65);
    placeBox(hand, f.hand, Vec3(0.09, 0.08, 0.026), f.wrist + f.hand.col(0) * 0.05);
  }
};

/// An IMU: a box on a strap round its segment.
struct ImuParts {
  Part box, strap;
  ImuParts(vtkPolyDataMapper* cube, vtkPolyDataMapper* cylinder, vtkRenderer* r)
      : box(cube, r), strap(cylinder, r) {}
  void place(const Eigen::Isometry3d& imu, const Vec3& strapCentre, const Vec3& segmentDir,
             double segmentRadius) {
    // The box sits on the skin over the sensor's place, in the sensor's own orientation; its
    // thin side along the sensor's z (which points away from the segment's axis in the model).
    const Eigen::Matrix3d r = imu.linear();
    const Vec3 offset = imu.translation() - strapCentre;
    const Vec3 onAxis = strapCentre + offset.dot(segmentDir) * segmentDir;
    Vec3 out = imu.translation() - onAxis;
    out = out.norm() > 1e-6 ? Vec3(out.normalized()) : Vec3(r.col(2));
    placeBox(box, r, Vec3(0.05, 0.04, 0.02), onAxis + out * (segmentRadius + 0.012));
    const Vec3 half = segmentDir * 0.012;
    placeCylinder(strap, onAxis - half, onAxis + half, segmentRadius + 0.004);
  }
};

Rgb mix(const Rgb& a, const Rgb& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

}  // namespace

struct ArmScene::Impl {
  vtkSmartPointer<vtkRenderer> renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkSmartPointer<vtkCylinderSource> cylinderSource = vtkSmartPointer<vtkCylinderSource>::New();
  vtkSmartPointer<vtkSphereSource> sphereSource = vtkSmartPointer<vtkSphereSource>::New();
  vtkSmartPointer<vtkCubeSource> cubeSource = vtkSmartPointer<vtkCubeSource>::New();
  vtkSmartPointer<vtkPolyDataMapper> cylinder = vtkSmartPointer<vtkPolyDataMapper>::New();
  vtkSmartPointer<vtkPolyDataMapper> sphere = vtkSmartPointer<vtkPolyDataMapper>::New();
  vtkSmartPointer<vtkPolyDataMapper> cube = vtkSmartPointer<vtkPolyDataMapper>::New();

  std::unique_ptr<ArmParts> arm, target;
  std::unique_ptr<ImuParts> upperImu, forearmImu;
  std::unique_ptr<Part> kinectElbow, kinectWrist, trunk, head, sternumImu;
  std::optional<TrunkMount> sternum;  // the sternum IMU's mounting (frame 0, trunk upright)
  std::array<vtkSmartPointer<vtkLineSource>, 2> raySources;
  std::array<vtkSmartPointer<vtkActor>, 2> rays;
  vtkSmartPointer<vtkPlaneSource> floorSource = vtkSmartPointer<vtkPlaneSource>::New();
  vtkSmartPointer<vtkActor> floor = vtkSmartPointer<vtkActor>::New();
  vtkSmartPointer<vtkTextActor> label = vtkSmartPointer<vtkTextActor>::New();

  ArmGeometry geometry;
  Side side = Side::Right;
  Vec3 up = -Vec3::UnitX();
  std::optional<PinholeCamera> camera;
  JointVector pose = JointVector::Zero();
  std::optional<JointVector> targetPose;
  ArmFigure figure;
  bool dark = true;
  // The trunk's pose in the world: the torso, the head and the arms move with it.
  Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
  std::optional<TrunkAngles> trunkAngles;

  Vec3 forward() const {
    Vec3 f = Vec3::UnitY() - Vec3::UnitY().dot(up) * up;
    return f.norm() > 1e-6 ? Vec3(f.normalized()) : up.unitOrthogonal();
  }
  Vec3 medial() const {
    Vec3 m = medialDirection(side);
    m -= m.dot(up) * up;
    return m.norm() > 1e-6 ? Vec3(m.normalized()) : up.cross(forward());
  }

  Vec3 hip() const { return -up * kHipBelow + medial() * kHipMedial; }

  void placeBody() {
    // Frame 0 turns with the thorax about the hip h: a point p of the trunk's frame is at
    // h + R (p - h) in the world. In an arm's own frame 0 (z0 to the patient's right for either
    // side) the trunk's rotation is trunkRotation(angles) for both sides (core/kinematics/Trunk.h).
    body = Eigen::Isometry3d::Identity();
    if (trunkAngles) {
      const Eigen::Matrix3d r = trunkRotation(*trunkAngles, Side::Right);
      const Vec3 h = hip();
      body.linear() = r;
      body.translation() = h - r * h;
    }
    // Trunk and head on the body's side of the shoulder.
    const Vec3 m = medial();
    const Vec3 trunkCentre = m * kTrunkOffset - up * 0.21;
    Eigen::Matrix3d trunkFrame;
    trunkFrame.col(0) = m;
    trunkFrame.col(1) = up;
    trunkFrame.col(2) = m.cross(up);
    placeBox(*trunk, body.linear() * trunkFrame, Vec3(0.30, 0.52, kTorsoDepth), body * trunkCentre);
    placeSphere(*head, body * Vec3(m * kTrunkOffset + up * 0.2), 0.1);
    placeSternum();
  }

  void placeSternum() {
    sternumImu->setVisible(sternum.has_value());
    if (!sternum) return;
    // On the chest over the sensor's place: its height and side as mounted, on the torso's front
    // (the drawn torso is a box; the mounting's depth is the real chest's). Its thin side is the
    // axis that points most out of the chest.
    const Vec3 f = forward();
    const Vec3 p = sternum->imuPosition - f * f.dot(sternum->imuPosition) +
                   f * (0.5 * kTorsoDepth + 0.5 * kSternumThickness);
    const Eigen::Matrix3d& r = sternum->imuRotation;
    Eigen::Index thin = 0;
    (r.transpose() * f).cwiseAbs().maxCoeff(&thin);
    Vec3 size(0.05, 0.04, 0.04);
    size(thin) = kSternumThickness;
    placeBox(*sternumImu, body.linear() * r, size, body * p);
  }

  void placeStatic() {
    // The floor below, where the patient sits (it does not lean).
    placeBody();
    const Vec3 f = forward(), m = medial();
    const Vec3 centre = -up * kFloorBelowShoulder + m * kTrunkOffset + f * 0.25;
    const Vec3 a = f * 1.0, b = m * 1.0;
    const Vec3 o = centre - a - b;
    floorSource->SetOrigin(o.x(), o.y(), o.z());
    floorSource->SetPoint1(o.x() + 2 * a.x(), o.y() + 2 * a.y(), o.z() + 2 * a.z());
    floorSource->SetPoint2(o.x() + 2 * b.x(), o.y() + 2 * b.y(), o.z() + 2 * b.z());
  }

  void placeArm() {
    figure = transformed(armFigure(geometry, pose, side), body);
    arm->place(figure);
    const Vec3 upperDir = (figure.elbow - figure.shoulder).normalized();
    const Vec3 foreDir = (figure.wrist - figure.elbow).normalized();
    upperImu->place(figure.upperImu, figure.upperStrap, upperDir, kUpperRadius);
    forearmImu->place(figure.forearmImu, figure.forearmStrap, foreDir, kForearmRadius);
    if (targetPose) target->place(transformed(armFigure(geometry, *targetPose, side), body));
  }

  void applyColours() {
    const Rgb bg = dark ? Rgb{0.12, 0.13, 0.15} : Rgb{0.95, 0.96, 0.97};
    const Rgb bg2 = dark ? Rgb{0.22, 0.24, 0.28} : Rgb{0.80, 0.84, 0.90};
    renderer->SetBackground(bg[0], bg[1], bg[2]);
    renderer->SetBackground2(bg2[0], bg2[1], bg2[2]);
    renderer->GradientBackgroundOn();
    const Rgb armColour = dark ? Rgb{0.38, 0.64, 0.98} : Rgb{0.14, 0.40, 0.82};
    for (Part* p : arm->all()) {
      p->setColor(armColour);
      p->actor->GetProperty()->SetAmbient(0.25);
      p->actor->GetProperty()->SetSpecular(0.25);
      p->actor->GetProperty()->SetSpecularPower(20);
    }
    arm->shoulder.setColor(mix(armColour, {1, 1, 1}, 0.35));
    arm->elbow.setColor(mix(armColour, {1, 1, 1}, 0.35));
    arm->wrist.setColor(mix(armColour, {1, 1, 1}, 0.35));
    const Rgb targetColour = dark ? Rgb{0.45, 0.92, 0.55} : Rgb{0.10, 0.60, 0.25};
    for (Part* p : target->all()) {
      p->setColor(targetColour);
      p->actor->GetProperty()->SetOpacity(0.35);
    }
    const Rgb imu{0.98, 0.62, 0.12};
    upperImu->box.setColor(imu);
    forearmImu->box.setColor(imu);
    sternumImu->setColor(imu);
    const Rgb strap = dark ? Rgb{0.08, 0.08, 0.09} : Rgb{0.25, 0.25, 0.27};
    upperImu->strap.setColor(strap);
    forearmImu->strap.setColor(strap);
    const Rgb kinect{0.93, 0.25, 0.62};
    kinectElbow->setColor(kinect);
    kinectWrist->setColor(kinect);
    for (auto& r : rays) r->GetProperty()->SetColor(0.98, 0.88, 0.2);
    // Opaque and pale: any translucent prop switches VTK to its order-independent translucency
    // passes, which cost more than the rest of the scene in software OpenGL.
    const Rgb body = dark ? Rgb{0.34, 0.35, 0.38} : Rgb{0.93, 0.93, 0.95};
    for (Part* p : {trunk.get(), head.get()}) {
      p->setColor(body);
      p->actor->GetProperty()->SetAmbient(0.55);
      p->actor->GetProperty()->SetDiffuse(0.4);
    }
    const Rgb grid = dark ? Rgb{0.42, 0.45, 0.5} : Rgb{0.62, 0.65, 0.7};
    floor->GetProperty()->SetColor(grid[0], grid[1], grid[2]);
    const Rgb text = dark ? Rgb{0.92, 0.93, 0.95} : Rgb{0.1, 0.1, 0.12};
    label->GetTextProperty()->SetColor(text[0], text[1], text[2]);
  }
};

ArmScene::ArmScene() : m(new Impl) {
  Impl& s = *m;
  s.cylinderSource->SetRadius(1.0);
  s.cylinderSource->SetHeight(1.0);
  s.cylinderSource->SetResolution(28);
  s.sphereSource->SetRadius(1.0);
  s.sphereSource->SetThetaResolution(24);
  s.sphereSource->SetPhiResolution(16);
  s.cylinder->SetInputConnection(s.cylinderSource->GetOutputPort());
  s.sphere->SetInputConnection(s.sphereSource->GetOutputPort());
  s.cube->SetInputConnection(s.cubeSource->GetOutputPort());
  vtkRenderer* r = s.renderer;
  s.trunk = std::make_unique<Part>(s.cube, r);
  s.head = std::make_unique<Part>(s.sphere, r);
  s.sternumImu = std::make_unique<Part>(s.cube, r);
  s.sternumImu->setVisible(false);
  s.arm = std::make_unique<ArmParts>(s.cylinder, s.sphere, s.cube, r);
  s.target = std::make_unique<ArmParts>(s.cylinder, s.sphere, s.cube, r);
  for (Part* p : s.target->all()) p->setVisible(false);
  s.upperImu = std::make_unique<ImuParts>(s.cube, s.cylinder, r);
  s.forearmImu = std::make_unique<ImuParts>(s.cube, s.cylinder, r);
  s.kinectElbow = std::make_unique<Part>(s.sphere, r);
  s.kinectWrist = std::make_unique<Part>(s.sphere, r);
  s.kinectElbow->setVisible(false);
  s.kinectWrist->setVisible(false);
  for (std::size_t i = 0; i < 2; ++i) {
    s.raySources[i] = vtkSmartPointer<vtkLineSource>::New();
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(s.raySources[i]->GetOutputPort());
    s.rays[i] = vtkSmartPointer<vtkActor>::New();
    s.rays[i]->SetMapper(mapper);
    s.rays[i]->GetProperty()->SetLineWidth(3.0f);
    s.rays[i]->GetProperty()->LightingOff();
    s.rays[i]->SetVisibility(false);
    r->AddActor(s.rays[i]);
  }
  s.floorSource->SetResolution(20, 20);
  auto floorMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  floorMapper->SetInputConnection(s.floorSource->GetOutputPort());
  s.floor->SetMapper(floorMapper);
  s.floor->GetProperty()->SetRepresentationToWireframe();
  s.floor->GetProperty()->LightingOff();
  r->AddActor(s.floor);
  s.label->GetTextProperty()->SetFontSize(18);
  s.label->GetTextProperty()->BoldOn();
  s.label->SetDisplayPosition(12, 12);
  r->AddViewProp(s.label);
  s.placeStatic();
  s.placeArm();
  s.applyColours();
  resetCamera();
}

ArmScene::~ArmScene() = default;

vtkRenderer* ArmScene::renderer() const {
  return m->renderer;
}

void ArmScene::setArm(const ArmGeometry& geometry, Side side, const Eigen::Vector3d& up) {
  const bool reset = side != m->side || !up.isApprox(m->up);
  m->geometry = geometry;
  m->side = side;
  m->up = up.norm() > 1e-9 ? Vec3(up.normalized()) : -Vec3::UnitX();
  m->placeStatic();
  m->placeArm();
  if (reset) resetCamera();
}

void ArmScene::setCameraModel(const std::optional<CameraParams>& camera) {
  m->camera.reset();
  if (!camera) return;
  try {
    m->camera.emplace(*camera);
  } catch (const std::invalid_argument&) {
    // An invalid model: marker pixels are not drawn.
  }
}

void ArmScene::setPose(const JointVector& th) {
  m->pose = th;
  m->placeArm();
}

void ArmScene::setTrunk(const std::optional<TrunkAngles>& angles) {
  m->trunkAngles = angles && angles->allFinite() ? angles : std::nullopt;
  m->placeBody();
  m->placeArm();
}

void ArmScene::setSternumImu(const std::optional<TrunkMount>& mount) {
  const bool valid = mount && mount->imuPosition.allFinite() && mount->imuRotation.allFinite() &&
                     mount->imuRotation.isUnitary(1e-3) && mount->imuRotation.determinant() > 0.0;
  m->sternum = valid ? mount : std::nullopt;
  m->placeBody();
}

Eigen::Vector3d ArmScene::hipPivot() const {
  return m->hip();
}

Eigen::Isometry3d ArmScene::trunkPose() const {
  return m->body;
}

const ArmFigure& ArmScene::figure() const {
  return m->figure;
}

namespace {
Eigen::Vector3d actorOrigin(const Part& p) {
  return {p.matrix->GetElement(0, 3), p.matrix->GetElement(1, 3), p.matrix->GetElement(2, 3)};
}
/// The part's axes as drawn (unit columns; its matrix scales them by the part's size).
Eigen::Matrix3d actorAxes(const Part& p) {
  Eigen::Matrix3d a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a(r, c) = p.matrix->GetElement(r, c);
  return a.colwise().normalized();
}
}  // namespace

std::optional<Eigen::Isometry3d> ArmScene::sternumImuPose() const {
  if (!m->sternum) return std::nullopt;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = actorAxes(*m->sternumImu);
  pose.translation() = actorOrigin(*m->sternumImu);
  return pose;
}

Eigen::Vector3d ArmScene::shoulderActorCentre() const {
  return actorOrigin(m->arm->shoulder);
}

Eigen::Matrix3d ArmScene::torsoAxes() const {
  return actorAxes(*m->trunk);
}

Eigen::Vector3d ArmScene::torsoCentre() const {
  return actorOrigin(*m->trunk);
}

Eigen::Vector3d ArmScene::headCentre() const {
  return actorOrigin(*m->head);
}

void ArmScene::setTargetPose(const std::optional<JointVector>& th) {
  for (Part* p : m->target->all()) p->setVisible(th.has_value());
  m->targetPose = th;
  if (th) m->target->place(transformed(armFigure(m->geometry, *th, m->side), m->body));
}

void ArmScene::setOptical(const OpticalMarks& marks) {
  Impl& s = *m;
  const std::array<const std::optional<Vec3>*, 2> points{&marks.elbow, &marks.wrist};
  const std::array<Part*, 2> spheres{s.kinectElbow.get(), s.kinectWrist.get()};
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& p = *points[i];
    const bool show = p && p->allFinite();
    spheres[i]->setVisible(show);
    if (show) placeSphere(*spheres[i], *p, 0.022);
  }
  // A marker pixel is a ray from the camera; draw the part of it that passes the estimated joint.
  const std::array<const std::optional<Eigen::Vector2d>*, 2> pixels{&marks.camElbow,
                                                                    &marks.camWrist};
  const std::array<Vec3, 2> joints{s.figure.elbow, s.figure.wrist};
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& px = *pixels[i];
    bool show = s.camera && px && px->allFinite();
    if (show) {
      Vec3 origin, dir;
      s.camera->ray(*px, origin, dir);
      const double along = (joints[i] - origin).dot(dir);
      show = origin.allFinite() && dir.allFinite() && along > 0.0;
      if (show) {
        const Vec3 a = origin + dir * std::max(0.0, along - 0.3);
        const Vec3 b = origin + dir * (along + 0.15);
        s.raySources[i]->SetPoint1(a.x(), a.y(), a.z());
        s.raySources[i]->SetPoint2(b.x(), b.y(), b.z());
      }
    }
    s.rays[i]->SetVisibility(show);
  }
}

void ArmScene::setSideLabel(const std::string& text) {
  m->label->SetInput(text.c_str());
}

void ArmScene::setLabelScale(double scale) {
  m->label->GetTextProperty()->SetFontSize(static_cast<int>(std::lround(18 * scale)));
  m->label->SetDisplayPosition(static_cast<int>(12 * scale), static_cast<int>(12 * scale));
}

void ArmScene::setDark(bool dark) {
  m->dark = dark;
  m->applyColours();
}

void ArmScene::resetCamera() {
  const Vec3 f = m->forward(), med = m->medial();
  CameraView v;
  // In front of the patient and a little to the arm's side, looking at the space the arm
  // reaches (about 0.45 m round the shoulder), the trunk at the side.
  // The view takes in the head (its top 0.3 m above the shoulder) and the trunk down to the
  // hips, whatever the pane's shape (prepareFrame()).
  v.focalPoint = -m->up * 0.08 - med * 0.08 + f * 0.1;
  v.position = v.focalPoint + f * 1.3 - med * 0.65 + m->up * 0.4;
  v.viewUp = m->up;
  v.viewAngleDeg = 38.0;
  setCamera(v);
}

CameraView ArmScene::camera() const {
  vtkCamera* c = m->renderer->GetActiveCamera();
  CameraView v;
  double p[3];
  c->GetPosition(p);
  v.position = {p[0], p[1], p[2]};
  c->GetFocalPoint(p);
  v.focalPoint = {p[0], p[1], p[2]};
  c->GetViewUp(p);
  v.viewUp = {p[0], p[1], p[2]};
  v.viewAngleDeg = c->GetViewAngle();
  return v;
}

void ArmScene::setCamera(const CameraView& v) {
  vtkCamera* c = m->renderer->GetActiveCamera();
  c->SetPosition(v.position.x(), v.position.y(), v.position.z());
  c->SetFocalPoint(v.focalPoint.x(), v.focalPoint.y(), v.focalPoint.z());
  c->SetViewUp(v.viewUp.x(), v.viewUp.y(), v.viewUp.z());
  c->SetViewAngle(v.viewAngleDeg);
  c->OrthogonalizeViewUp();
  m->renderer->ResetCameraClippingRange();
}

void ArmScene::orbit(double azimuthDeg, double elevationDeg) {
  vtkCamera* c = m->renderer->GetActiveCamera();
  c->Azimuth(azimuthDeg);
  // Keep the view direction away from straight up or down, where the view-up flips.
  double dop[3];
  c->GetDirectionOfProjection(dop);
  const double elevationNow =
      std::asin(std::clamp(-Vec3(dop[0], dop[1], dop[2]).dot(m->up), -1.0, 1.0)) * 180.0 /
      std::numbers::pi;
  const double allowed = std::clamp(elevationNow + elevationDeg, -80.0, 80.0) - elevationNow;
  c->Elevation(allowed);
  c->SetViewUp(m->up.x(), m->up.y(), m->up.z());
  c->OrthogonalizeViewUp();
  m->renderer->ResetCameraClippingRange();
}

void ArmScene::zoom(double factor) {
  vtkCamera* c = m->renderer->GetActiveCamera();
  const double distance = c->GetDistance();
  // Between 0.3 m and 8 m from the focal point.
  const double wanted = std::clamp(distance / factor, 0.3, 8.0);
  c->Dolly(distance / wanted);
  m->renderer->ResetCameraClippingRange();
}

void ArmScene::prepareFrame() {
  // The view angle spans the pane's shorter side: a narrow, tall pane (the review's) sees as
  // much across as a wide one sees up and down, instead of cutting the trunk at its sides.
  const int* size = m->renderer->GetSize();
  if (size && size[0] > 0 && size[1] > 0)
    m->renderer->GetActiveCamera()->SetUseHorizontalViewAngle(size[0] < size[1]);
  m->renderer->ResetCameraClippingRange();
}

}  // namespace armtrack::ui
