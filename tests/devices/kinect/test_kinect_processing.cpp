// The Kinect's processing part on synthetic colour + registered depth frames: markers at known
// 3D points in the shoulder frame must come back at those points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <tuple>

#include "devices/kinect/KinectProcessing.h"
#include "tests/devices/vision/Synthetic.h"

using namespace armtrack::devices;
using namespace armtrack::devices::kinect;
using armtrack::test::webcam::drawDisc;

namespace {

const cv::Scalar kGreen(30, 200, 40);
const cv::Scalar kBlue(210, 60, 20);
const cv::Scalar kMagenta(200, 40, 210);  // BGR: hue about 150 of 179

/// A Kinect-like colour camera 2 m in front of the shoulder, looking back at it (the pose of
/// core's frontCamera: image down = +x0, optical axis = -y0).
KinectProcessingParams params(double k1 = 0.0) {
  KinectProcessingParams p;
  p.colour.imageSize = {640, 480};
  p.colour.fx = 525.0;
  p.colour.fy = 523.0;
  p.colour.cx = 319.5;
  p.colour.cy = 239.5;
  p.colour.dist = {k1, 0, 0, 0, 0};
  p.pose.R = cv::Matx33d(0, 0, -1, 1, 0, 0, 0, -1, 0);
  p.pose.t = cv::Vec3d(0, 0, 2.0);
  return p;
}

struct Scene {
  cv::Mat bgr, depth;
};

/// Markers at shoulder-frame points; each sits on a patch of arm surface (a disc of depth equal to
/// the point's camera depth) in front of a wall at 3.5 m.
Scene render(const KinectProcessingParams& p, const std::optional<cv::Vec3d>& wrist,
             const std::optional<cv::Vec3d>& elbow, bool holeUnderWrist = false,
             const std::optional<cv::Vec3d>& shoulder = std::nullopt) {
  Scene s{cv::Mat(480, 640, CV_8UC3, cv::Scalar(100, 100, 100)),
          cv::Mat(480, 640, CV_16UC1, cv::Scalar(3500))};
  cv::Vec3d rvec;
  cv::Rodrigues(p.pose.R, rvec);
  // Far to near, so that a nearer patch hides a farther one, as in a real depth image.
  std::vector<std::tuple<cv::Vec3d, cv::Scalar, bool, double>> markers;
  for (auto [point, colour, hole] :
       {std::tuple{wrist, kGreen, holeUnderWrist}, std::tuple{elbow, kBlue, false},
        std::tuple{shoulder, kMagenta, false}})
    if (point) markers.emplace_back(*point, colour, hole, (p.pose.R * *point + p.pose.t)[2]);
  std::sort(markers.begin(), markers.end(),
            [](const auto& a, const auto& b) { return std::get<3>(a) > std::get<3>(b); });
  for (const auto& [point, colour, hole, z] : markers) {
    std::vector<cv::Point2d> px;
    cv::projectPoints(std::vector<cv::Point3d>{cv::Point3d(point)}, rvec, p.pose.t,
                      p.colour.cameraMatrix(), p.colour.distCoeffs(), px);
    const double mm = hole ? 0.0 : z * 1000.0;
    cv::circle(s.depth, cv::Point(cvRound(px[0].x), cvRound(px[0].y)), 12, cv::Scalar(mm),
               cv::FILLED);
    drawDisc(s.bgr, px[0], 7.0, colour);
  }
  return s;
}

}  // namespace

TEST(KinectProcessing, RecoversKnownPointsInTheShoulderFrame) {
  for (double k1 : {0.0, 0.08}) {
    KinectProcessor proc(params(k1), webcam::MarkerDetector(webcam::ColourMarkerParams{}));
    // Arm poses: hanging, forward, to the side and across.
    const std::vector<std::pair<cv::Vec3d, cv::Vec3d>> poses{
        {{0.30, 0.00, 0.00}, {0.58, 0.02, 0.03}},
        {{0.30, 0.00, 0.02}, {0.30, 0.27, 0.05}},
        {{0.05, 0.10, 0.29}, {0.06, 0.38, 0.30}},
        {{0.25, 0.15, -0.05}, {0.10, 0.30, -0.25}},
    };
    for (const auto& [elbow, wrist] : poses) {
      const Scene s = render(proc.params(), wrist, elbow);
      const KinectFrame f = proc.process(s.bgr, s.depth);
      ASSERT_TRUE(f.wrist && f.elbow);
      EXPECT_EQ(f.depthMissing, 0);
      // Depth is whole mm (0.5 mm rounding) and the marker pixel is good to ~0.1 px, which is
      // 0.4 mm at 2 m: 2 mm leaves room for both.
      EXPECT_LT(cv::norm(*f.wrist - wrist), 0.002) << "k1 " << k1 << " wrist " << wrist;
      EXPECT_LT(cv::norm(*f.elbow - elbow), 0.002) << "k1 " << k1 << " elbow " << elbow;
    }
  }
}

TEST(KinectProcessing, JointDepthMovesThePointAlongTheRay) {
  KinectProcessingParams p = params();
  p.jointDepth = 0.04;
  KinectProcessor proc(p, webcam::MarkerDetector(webcam::ColourMarkerParams{}));
  const cv::Vec3d elbow(0.0, 0.0, 0.0);  // on the optical axis, where the ray is -y0
  const Scene s = render(p, std::nullopt, elbow);
  const KinectFrame f = proc.process(s.bgr, s.depth);
  ASSERT_TRUE(f.elbow);
  EXPECT_LT(cv::norm(*f.elbow - (elbow + cv::Vec3d(0, -0.04, 0))), 0.002);
}

TEST(KinectProcessing, MissingMarkersAndMissingDepth) {
  KinectProcessor proc(params(), webcam::MarkerDetector(webcam::ColourMarkerParams{}));
  const cv::Vec3d elbow(0.3, 0, 0), wrist(0.58, 0.02, 0.03);
  // No wrist marker: wrist absent, elbow present.
  Scene s = render(proc.params(), std::nullopt, elbow);
  KinectFrame f = proc.process(s.bgr, s.depth);
  EXPECT_FALSE(f.pixels.wrist);
  EXPECT_FALSE(f.wrist);
  EXPECT_TRUE(f.elbow);
  // The wrist marker seen, but no depth under it (a hole, as on a shiny surface).
  s = render(proc.params(), wrist, elbow, true);
  f = proc.process(s.bgr, s.depth);
  EXPECT_TRUE(f.pixels.wrist);
  EXPECT_FALSE(f.wrist);
  EXPECT_TRUE(f.elbow);
  EXPECT_EQ(f.depthMissing, 1);
  // Depth out of range (a wall at 6 m behind a marker drawn on nothing).
  cv::Mat farDepth(480, 640, CV_16UC1, cv::Scalar(6000));
  f = proc.process(s.bgr, farDepth);
  EXPECT_FALSE(f.wrist || f.elbow);
  EXPECT_EQ(f.depthMissing, 2);
  // Frames that do not fit.
  EXPECT_THROW(proc.process(s.bgr, cv::Mat(240, 320, CV_16UC1)), std::invalid_argument);
  EXPECT_THROW(proc.process(s.bgr, cv::Mat(480, 640, CV_32FC1)), std::invalid_argument);
  EXPECT_THROW(proc.process(cv::Mat(480, 640, CV_8UC1), s.depth), std::invalid_argument);
}

TEST(KinectProcessing, ArucoMarkersToo) {
  KinectProcessor proc(params(), webcam::MarkerDetector(webcam::ArucoMarkerParams{}));
  const cv::Vec3d elbow(0.3, 0, 0);
  Scene s = render(proc.params(), std::nullopt, elbow);
  s.bgr.setTo(cv::Scalar(100, 100, 100));
  cv::Vec3d rvec;
  cv::Rodrigues(proc.params().pose.R, rvec);
  std::vector<cv::Point2d> px;
  cv::projectPoints(std::vector<cv::Point3d>{cv::Point3d(elbow)}, rvec, proc.params().pose.t,
                    proc.params().colour.cameraMatrix(), cv::noArray(), px);
  armtrack::test::webcam::drawAruco(s.bgr, 1, px[0], 40, 10.0);
  const KinectFrame f = proc.process(s.bgr, s.depth);
  ASSERT_TRUE(f.elbow);
  EXPECT_LT(cv::norm(*f.elbow - elbow), 0.003);
}

TEST(KinectProcessing, BadParametersAreRefused) {
  KinectProcessingParams p = params();
  p.depthWindowPx = 4;
  EXPECT_THROW(KinectProcessor(p, webcam::MarkerDetector(webcam::ColourMarkerParams{})),
               std::invalid_argument);
  p = params();
  p.colour.fx = 0;
  EXPECT_THROW(KinectProcessor(p, webcam::MarkerDetector(webcam::ColourMarkerParams{})),
               std::invalid_argument);
  p = params();
  p.pose.R(0, 0) = 1;
  EXPECT_THROW(KinectProcessor(p, webcam::MarkerDetector(webcam::ColourMarkerParams{})),
               std::invalid_argument);
}

namespace {

// The shoulder marker's detector: magenta, as the docs suggest.
std::optional<webcam::MarkerDetector> shoulderDetector() {
  webcam::ColourMarkerParams c;
  c.wrist = c.elbow = *webcam::parseHsvRange("140-170:100-255:70-255");
  return webcam::MarkerDetector(c);
}

// A trunk leaning forward by `lean` rad about a hip 0.45 m below and 0.15 m medial to the
// shoulder, in the registered frame (x down, y forward, z to the right): the shoulder centre
// moves to h - R h and everything on the trunk turns with it.
cv::Vec3d onLeaningTrunk(const cv::Vec3d& p, double lean) {
  const cv::Vec3d hip(0.45, 0.0, -0.15);
  const double c = std::cos(lean), s = std::sin(lean);
  const cv::Matx33d r(c, s, 0, -s, c, 0, 0, 0, 1);  // about z0, x0 (down) towards +y0 (forward)
  return hip - r * hip + r * p;
}

}  // namespace

// Without a shoulder detector nothing changes; with one, elbow and wrist are the same and the
// shoulder marker comes back where it is, in the same (registered, world) frame.
TEST(KinectProcessing, AShoulderMarkerInTheSameFrame) {
  const cv::Vec3d elbow(0.30, 0.00, 0.02), wrist(0.30, 0.27, 0.05);
  const cv::Vec3d shoulder(-0.05, 0.0, 0.03);  // the acromion, above the joint centre
  KinectProcessor plain(params(), webcam::MarkerDetector(webcam::ColourMarkerParams{}));
  KinectProcessor withShoulder(params(), webcam::MarkerDetector(webcam::ColourMarkerParams{}),
                               shoulderDetector());
  const Scene s = render(plain.params(), wrist, elbow, false, shoulder);
  const KinectFrame a = plain.process(s.bgr, s.depth);
  const KinectFrame b = withShoulder.process(s.bgr, s.depth);
  ASSERT_TRUE(a.wrist && a.elbow && b.wrist && b.elbow);
  EXPECT_FALSE(a.shoulder || a.shoulderPixel);
  ASSERT_TRUE(b.shoulder);
  EXPECT_EQ(cv::norm(*a.wrist - *b.wrist), 0.0);
  EXPECT_EQ(cv::norm(*a.elbow - *b.elbow), 0.0);
  EXPECT_LT(cv::norm(*b.shoulder - shoulder), 0.002);
  EXPECT_EQ(b.depthMissing, 0);
  // No shoulder marker in view: no shoulder, the rest as before.
  const Scene none = render(plain.params(), wrist, elbow);
  const KinectFrame c = withShoulder.process(none.bgr, none.depth);
  EXPECT_FALSE(c.shoulder || c.shoulderPixel);
  ASSERT_TRUE(c.wrist && c.elbow);
  EXPECT_LT(cv::norm(*c.wrist - wrist), 0.002);
}

// A trunk that leans 10 deg forward about the hips moves the shoulder marker by
// |h - R h + (R - I) p| (about 8 cm); a still trunk leaves it where it was.
TEST(KinectProcessing, ALeaningTrunkMovesTheShoulderMarker) {
  const double kLean = 10.0 * CV_PI / 180.0;
  const cv::Vec3d elbow(0.30, 0.00, 0.02), wrist(0.30, 0.27, 0.05), shoulder(-0.05, 0.0, 0.03);
  KinectProcessor proc(params(), webcam::MarkerDetector(webcam::ColourMarkerParams{}),
                       shoulderDetector());
  const Scene still = render(proc.params(), wrist, elbow, false, shoulder);
  const KinectFrame f0 = proc.process(still.bgr, still.depth);
  const Scene leaning =
      render(proc.params(), onLeaningTrunk(wrist, kLean), onLeaningTrunk(elbow, kLean), false,
             onLeaningTrunk(shoulder, kLean));
  const KinectFrame f1 = proc.process(leaning.bgr, leaning.depth);
  ASSERT_TRUE(f0.shoulder && f1.shoulder && f1.elbow && f1.wrist);
  const cv::Vec3d moved = onLeaningTrunk(shoulder, kLean) - shoulder;
  EXPECT_GT(cv::norm(moved), 0.07);
  EXPECT_LT(cv::norm((*f1.shoulder - *f0.shoulder) - moved), 0.003);
  // Elbow and wrist are where the lean carried them in the world, not relative to the shoulder.
  EXPECT_LT(cv::norm(*f1.elbow - onLeaningTrunk(elbow, kLean)), 0.002);
  EXPECT_LT(cv::norm(*f1.wrist - onLeaningTrunk(wrist, kLean)), 0.002);
}
