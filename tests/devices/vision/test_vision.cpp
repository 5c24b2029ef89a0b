// The webcam's image side without Qt: marker detectors, chessboard intrinsics, ArUco-board
// registration and the calibration file, on synthetic images with known answers.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "devices/vision/CameraCalibration.h"
#include "devices/vision/CameraFile.h"
#include "devices/vision/MarkerDetection.h"
#include "tests/devices/vision/Synthetic.h"

using namespace armtrack::devices::webcam;
using namespace armtrack::test::webcam;

namespace {

const cv::Scalar kGreen(30, 200, 40);   // BGR: hue about 64 (OpenCV scale)
const cv::Scalar kBlue(210, 60, 20);    // hue about 112
const cv::Scalar kSkin(120, 160, 220);  // a skin-like orange, hue about 13

cv::Mat background(int w = 320, int h = 240) {
  cv::Mat img(h, w, CV_8UC3, cv::Scalar(110, 110, 110));
  cv::RNG rng(7);
  cv::Mat noise(img.size(), CV_8UC3);
  rng.fill(noise, cv::RNG::NORMAL, 0, 4);
  img += noise;
  return img;
}

}  // namespace

TEST(HsvRange, ParsesAndRejects) {
  const auto r = parseHsvRange("45-75:100-255:70-255");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->hueMin, 45);
  EXPECT_EQ(r->valMax, 255);
  EXPECT_EQ(toString(*r), "45-75:100-255:70-255");
  EXPECT_TRUE(parseHsvRange("170-10:80-255:50-255"));  // wraps through red
  for (const char* bad : {"", "45-75", "45-75:100-255", "45-75:100-255:70-256", "45-180:0-1:0-1",
                          "a-b:c-d:e-f", "45-75:200-100:0-255", "45-75:100-255:70-255x"})
    EXPECT_FALSE(parseHsvRange(bad)) << bad;
}

TEST(ColourMarkers, SubPixelCentroidsOfBothMarkersAmongDistractors) {
  ColourMarkerDetector detector;
  for (int k = 0; k < 20; ++k) {
    cv::Mat img = background();
    const cv::Point2d w(60.3 + 9.17 * k, 70.8 + 3.41 * k), e(250.6 - 5.3 * k, 180.2 - 2.9 * k);
    drawDisc(img, {40, 200}, 12, kSkin);    // not a marker colour
    drawDisc(img, {300, 20}, 1.5, kGreen);  // a green speck under the minimum area
    drawDisc(img, w, 7.0, kGreen);
    drawDisc(img, e, 6.0, kBlue);
    const MarkerPair p = detector.detect(img);
    ASSERT_TRUE(p.wrist && p.elbow) << k;
    EXPECT_LT(cv::norm(*p.wrist - w), 0.1) << k;
    EXPECT_LT(cv::norm(*p.elbow - e), 0.1) << k;
  }
}

TEST(ColourMarkers, AbsentMarkerIsNulloptAndSmallBlobsAreIgnored) {
  ColourMarkerDetector detector;
  cv::Mat img = background();
  drawDisc(img, {100, 100}, 7, kBlue);
  drawDisc(img, {200, 100}, 1.5, kGreen);  // about 7 px, under min-area 20
  const MarkerPair p = detector.detect(img);
  EXPECT_FALSE(p.wrist);
  ASSERT_TRUE(p.elbow);
  EXPECT_FALSE(detector.detect(cv::Mat()).wrist);
  EXPECT_THROW(detector.detect(cv::Mat(10, 10, CV_32FC3, cv::Scalar(0))), std::invalid_argument);
}

TEST(ColourMarkers, HueRangeWrapsThroughRed) {
  ColourMarkerParams params;
  params.wrist = *parseHsvRange("170-10:120-255:70-255");
  ColourMarkerDetector detector(params);
  for (const cv::Scalar& red :
       {cv::Scalar(20, 10, 220), cv::Scalar(60, 10, 220)}) {  // hue ~2, ~170
    cv::Mat img = background();
    drawDisc(img, {150.25, 90.5}, 8, red);
    const MarkerPair p = detector.detect(img);
    ASSERT_TRUE(p.wrist);
    EXPECT_LT(cv::norm(*p.wrist - cv::Point2d(150.25, 90.5)), 0.1);
  }
}

TEST(ArucoMarkers, CentresOfWristAndElbowMarkers) {
  ArucoMarkerDetector detector;  // DICT_4X4_50, wrist 0, elbow 1
  for (int k = 0; k < 10; ++k) {
    cv::Mat img = background(640, 480);
    const cv::Point2d w(160.3 + 17.1 * k, 140.7 + 5.3 * k), e(470.6 - 11.2 * k, 330.1 - 4.4 * k);
    drawAruco(img, 0, w, 60, 7.0 * k);
    drawAruco(img, 1, e, 48, -5.0 * k);
    drawAruco(img, 7, {560, 80}, 48, 0.0);  // another id: ignored
    const MarkerPair p = detector.detect(img);
    ASSERT_TRUE(p.wrist && p.elbow) << k;
    EXPECT_LT(cv::norm(*p.wrist - w), 0.3) << k;
    EXPECT_LT(cv::norm(*p.elbow - e), 0.3) << k;
  }
}

TEST(ArucoMarkers, BadParametersAreClearErrors) {
  EXPECT_THROW(ArucoMarkerDetector({"DICT_9X9_1", 0, 1}), std::invalid_argument);
  EXPECT_THROW(ArucoMarkerDetector({"DICT_4X4_50", 0, 50}), std::invalid_argument);
  EXPECT_THROW(ArucoMarkerDetector({"4x4_50", 3, 3}), std::invalid_argument);
  EXPECT_NO_THROW(ArucoMarkerDetector({"aprilTag_36h11", 3, 4}));
  EXPECT_FALSE(arucoDictionaryId("DICT_4X4_51"));
}

TEST(LineIntersection, DiagonalsOfASquare) {
  const auto c = lineIntersection({0, 0}, {2, 2}, {2, 0}, {0, 2});
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->x, 1.0, 1e-12);
  EXPECT_FALSE(lineIntersection({0, 0}, {1, 0}, {0, 1}, {1, 1}));
}

// ---------------------------------------------------------------------------------------------

namespace {

struct BoardPose {
  cv::Vec3d rvec, tvec;
};

/// Views of a 9x6 board (0.25 x 0.175 m with margins) about 0.55 m away, tilted up to 30 deg
/// about both image axes: enough variety to separate focal length from distance.
std::vector<BoardPose> chessboardPoses() {
  std::vector<BoardPose> poses;
  const double d = kPi / 180.0;
  const double tilts[][3] = {{0, 0, 0},     {25, 0, 5},   {-25, 0, -5}, {0, 25, 0},
                             {0, -25, 10},  {20, 20, -8}, {-20, 15, 3}, {15, -20, 12},
                             {-28, -10, 0}, {10, 28, -12}};
  int i = 0;
  for (const auto& t : tilts) {
    const cv::Vec3d rvec(t[0] * d, t[1] * d, t[2] * d);
    // Centre the board (0.1 x 0.0625 m from its first corner) on the optical axis, shifted a bit.
    cv::Matx33d R;
    cv::Rodrigues(rvec, R);
    const cv::Vec3d centre(0.1, 0.0625, 0.0);
    const cv::Vec3d shift(0.03 * ((i % 3) - 1), 0.02 * ((i % 2) ? 1 : -1), 0.5 + 0.02 * (i % 4));
    poses.push_back({rvec, shift - R * centre});
    ++i;
  }
  return poses;
}

}  // namespace

TEST(ChessboardCalibration, RecoversTheIntrinsicsOfSyntheticViews) {
  const TrueCamera cam;
  const ChessboardSpec spec;  // 9x6 inner corners, 25 mm
  std::vector<NamedImage> images;
  for (const BoardPose& p : chessboardPoses())
    images.push_back({"view" + std::to_string(images.size()),
                      renderChessboard(cam, spec.innerCorners, spec.squareSize, p.rvec, p.tvec)});
  images.push_back({"blank", cv::Mat(cam.size, CV_8UC3, cv::Scalar(128, 128, 128))});
  const IntrinsicsResult r = calibrateIntrinsics(images, spec);
  ASSERT_EQ(r.used.size(), images.size() - 1);
  ASSERT_EQ(r.rejected.size(), 1u);
  EXPECT_NE(r.rejected[0].find("blank"), std::string::npos);
  const Intrinsics& in = r.intrinsics;
  EXPECT_EQ(in.imageSize, cam.size);
  EXPECT_NEAR(in.fx, cam.fx, 0.01 * cam.fx);
  EXPECT_NEAR(in.fy, cam.fy, 0.01 * cam.fy);
  EXPECT_NEAR(in.cx, cam.cx, 0.01 * cam.cx);
  EXPECT_NEAR(in.cy, cam.cy, 0.01 * cam.cy);
  EXPECT_LT(in.rmsPx, 0.3);
  for (double k : in.dist) EXPECT_LT(std::abs(k), 0.05);
  EXPECT_EQ(in.boards, static_cast<int>(r.used.size()));
  std::printf("calibration: fx %.2f fy %.2f cx %.2f cy %.2f rms %.3f px\n", in.fx, in.fy, in.cx,
              in.cy, in.rmsPx);
}

TEST(ChessboardCalibration, TooFewBoardsIsAClearError) {
  const TrueCamera cam;
  const ChessboardSpec spec;
  const auto poses = chessboardPoses();
  std::vector<NamedImage> images;
  for (int i = 0; i < 2; ++i)
    images.push_back({"view", renderChessboard(cam, spec.innerCorners, spec.squareSize,
                                               poses[static_cast<std::size_t>(i)].rvec,
                                               poses[static_cast<std::size_t>(i)].tvec)});
  images.push_back({"noise", background(640, 480)});
  try {
    calibrateIntrinsics(images, spec);
    FAIL() << "no error";
  } catch (const CalibrationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("found in 2 of 3 images"), std::string::npos) << what;
    EXPECT_NE(what.find("at least 4"), std::string::npos) << what;
  }
  // A wrong board size finds nothing.
  EXPECT_THROW(calibrateIntrinsics(images, ChessboardSpec{{10, 7}, 0.025}), CalibrationError);
  EXPECT_THROW(calibrateIntrinsics({}, spec), CalibrationError);
  EXPECT_THROW(calibrateIntrinsics(images, ChessboardSpec{{6, 6}, 0.025}), CalibrationError);
}

// ---------------------------------------------------------------------------------------------

namespace {

double angleBetween(const cv::Matx33d& a, const cv::Matx33d& b) {
  cv::Vec3d r;
  cv::Rodrigues(a.t() * b, r);
  return cv::norm(r);
}

}  // namespace

TEST(ArucoRegistration, RecoversTheCameraPoseInTheShoulderFrame) {
  const TrueCamera cam;
  ArucoBoardSpec spec;  // 5 x 7 markers of 30 mm, 6 mm apart, DICT_4X4_50
  std::vector<std::vector<cv::Point3f>> layout;
  std::vector<int> ids;
  arucoBoardLayout(spec, layout, ids);
  ASSERT_EQ(layout.size(), 35u);

  // The board stands 0.3 m in front of the shoulder (arm-model frame: x0 down, y0 forward, z0
  // lateral): board x along z0, board y along x0, printed face toward +y0 (the camera).
  Pose boardInShoulder;
  boardInShoulder.R = cv::Matx33d(0, 1, 0,  //
                                  0, 0, 1,  //
                                  1, 0, 0);
  ASSERT_TRUE(isRotation(boardInShoulder.R));
  boardInShoulder.t = cv::Vec3d(-0.1, 0.3, 0.05);

  // Several camera poses looking at the board from 0.5 to 0.7 m, tilted.
  const double d = kPi / 180.0;
  const double views[][4] = {{0, 0, 0, 0.5}, {20, -10, 5, 0.6}, {-15, 25, -10, 0.7}};
  for (const auto& v : views) {
    const cv::Vec3d rvecCb(v[0] * d, v[1] * d, v[2] * d);
    cv::Matx33d Rcb;
    cv::Rodrigues(rvecCb, Rcb);
    const cv::Vec3d centre(0.087, 0.123, 0.0);  // middle of the 0.174 x 0.246 m board
    const cv::Vec3d tcb = cv::Vec3d(0.01, -0.015, v[3]) - Rcb * centre;
    const cv::Mat img =
        renderArucoBoard(cam, layout, ids, cv::aruco::DICT_4X4_50, rvecCb, tcb, 0.01);

    Intrinsics in;
    in.imageSize = cam.size;
    in.fx = cam.fx, in.fy = cam.fy, in.cx = cam.cx, in.cy = cam.cy;
    const Extrinsics e = registerCamera(img, in, spec, boardInShoulder);
    const cv::Matx33d Rtrue = Rcb * boardInShoulder.R.t();
    const cv::Vec3d ttrue = tcb - Rtrue * boardInShoulder.t;
    EXPECT_EQ(e.markers, 35);
    EXPECT_LT(e.rmsPx, 0.5);
    // Tolerances: corners located to about 0.1-0.2 px over a board spanning ~250 px give the
    // board's pose to ~0.1 deg and ~1 mm (depth error ~ distance x corner error / board size in
    // px); the limits leave 3x margin.
    EXPECT_LT(angleBetween(e.R, Rtrue) / d, 0.3) << v[3];
    EXPECT_LT(cv::norm(e.t - ttrue), 0.003) << v[3];
    // And a shoulder-frame point projects where the true camera puts it.
    const cv::Vec3d p(0.25, 0.1, 0.2);
    EXPECT_LT(cv::norm((e.R * p + e.t) - (Rtrue * p + ttrue)), 0.003);
    std::printf("registration at %.1f m: %.3f deg, %.2f mm, rms %.3f px\n", v[3],
                angleBetween(e.R, Rtrue) / d, cv::norm(e.t - ttrue) * 1000, e.rmsPx);
  }
}

TEST(ArucoRegistration, ClearErrors) {
  const TrueCamera cam;
  Intrinsics in;
  in.imageSize = cam.size;
  in.fx = cam.fx, in.fy = cam.fy, in.cx = cam.cx, in.cy = cam.cy;
  const cv::Mat empty(cam.size, CV_8UC3, cv::Scalar(200, 200, 200));
  try {
    registerCamera(empty, in, ArucoBoardSpec{}, Pose{});
    FAIL();
  } catch (const CalibrationError& e) {
    EXPECT_NE(std::string(e.what()).find("found 0 of the board's 35 markers"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(registerCamera(cv::Mat(100, 100, CV_8UC3), in, ArucoBoardSpec{}, Pose{}),
               CalibrationError);  // size differs from the intrinsics
  ArucoBoardSpec tooMany;
  tooMany.markersX = 10;
  tooMany.markersY = 10;  // 100 ids do not fit in DICT_4X4_50
  EXPECT_THROW(registerCamera(empty, in, tooMany, Pose{}), CalibrationError);
  Pose notRotation;
  notRotation.R = cv::Matx33d(1, 0, 0, 0, 1, 0, 0, 0, 2);
  EXPECT_THROW(registerCamera(empty, in, ArucoBoardSpec{}, notRotation), CalibrationError);
}

// ---------------------------------------------------------------------------------------------

namespace {

CameraFile sampleFile() {
  CameraFile f;
  f.id = "0";
  f.name = "test camera";
  f.intrinsics.imageSize = {640, 480};
  f.intrinsics.fx = 801.25;
  f.intrinsics.fy = 799.5;
  f.intrinsics.cx = 321.125;
  f.intrinsics.cy = 239.75;
  f.intrinsics.dist = {-0.1, 0.02, 0.001, -0.002, 0.0};
  f.intrinsics.rmsPx = 0.21;
  f.intrinsics.boards = 12;
  f.chessboard = ChessboardSpec{{9, 6}, 0.025};
  Extrinsics e;
  cv::Rodrigues(cv::Vec3d(0.3, -1.2, 0.5), e.R);
  e.t = {0.1, -0.2, 1.9};
  e.rmsPx = 0.33;
  e.markers = 30;
  f.extrinsics = e;
  return f;
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string errorOf(const std::string& path) {
  try {
    readCameraFile(path);
  } catch (const CameraFileError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(CameraFile, SaveLoadRoundTrip) {
  const TempDir dir("camfile");
  const std::string path = dir.file("cam.json");
  const CameraFile f = sampleFile();
  writeCameraFile(path, f);
  const CameraFile g = readCameraFile(path);
  EXPECT_EQ(g.id, f.id);
  EXPECT_EQ(g.name, f.name);
  EXPECT_EQ(g.intrinsics.imageSize, f.intrinsics.imageSize);
  EXPECT_EQ(g.intrinsics.fx, f.intrinsics.fx);
  EXPECT_EQ(g.intrinsics.cy, f.intrinsics.cy);
  EXPECT_EQ(g.intrinsics.dist, f.intrinsics.dist);
  EXPECT_EQ(g.intrinsics.rmsPx, f.intrinsics.rmsPx);
  EXPECT_EQ(g.intrinsics.boards, 12);
  ASSERT_TRUE(g.chessboard && g.extrinsics);
  EXPECT_EQ(g.chessboard->innerCorners, cv::Size(9, 6));
  for (int i = 0; i < 9; ++i) EXPECT_EQ(g.extrinsics->R.val[i], f.extrinsics->R.val[i]);
  EXPECT_EQ(g.extrinsics->t, f.extrinsics->t);
  EXPECT_EQ(g.extrinsics->markers, 30);
  EXPECT_EQ(toJson(g), toJson(f));

  // Without extrinsics (after camera-calibrate, before camera-register).
  CameraFile h = f;
  h.extrinsics.reset();
  h.chessboard.reset();
  writeCameraFile(path, h);
  EXPECT_FALSE(readCameraFile(path).extrinsics);
}

TEST(CameraFile, CorruptFilesAreClearErrors) {
  const TempDir dir("camfile-bad");
  const std::string good = toJson(sampleFile());
  const std::string path = dir.file("cam.json");
  const auto expectError = [&](const std::string& text, const std::string& needle) {
    writeText(path, text);
    const std::string e = errorOf(path);
    EXPECT_NE(e.find(path), std::string::npos) << e;
    EXPECT_NE(e.find(needle), std::string::npos) << "expected '" << needle << "' in: " << e;
  };
  expectError(good.substr(0, good.size() / 2), "not valid JSON");
  expectError("", "not valid JSON");
  expectError(std::string("\x00\xff\x13garbage", 10), "not valid JSON");
  expectError("[1, 2]", "expected a JSON object");
  expectError("{\"version\": 1}", "format");
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  expectError(replaced("\"fx\": 801.25", "\"fx\": -801.25"), "'intrinsics.fx': must be > 0");
  expectError(replaced("\"fx\": 801.25", "\"fx\": \"big\""), "'intrinsics.fx': expected a number");
  expectError(replaced("\"version\": 1", "\"version\": 7"), "newer");
  expectError(replaced("\"image_size\"", "\"size\""), "'image_size': missing");
  // A number beyond double's range is a JSON error, not an escaping library exception.
  expectError(replaced("\"fx\": 801.25", "\"fx\": 4e3333"), "not valid JSON");
  expectError(replaced("0.1,\n      -0.2", "0.1,\n      -0.2, 4"), "'extrinsics.t_m'");
  std::string notRotation = good;
  {
    CameraFile f = sampleFile();
    f.extrinsics->R(0, 0) += 0.01;
    notRotation = toJson(f);
  }
  expectError(notRotation, "'extrinsics.R': not a rotation");
  EXPECT_NE(errorOf(dir.file("missing.json")).find("no such file"), std::string::npos);
  // The text parser alone never throws anything but CameraFileError.
  for (std::size_t n = 0; n < good.size(); n += 7)
    EXPECT_THROW(cameraFileFromJson(good.substr(0, n), "x"), CameraFileError) << n;
}

namespace {

std::string loadError(const std::string& path) {
  try {
    loadImage(path);
  } catch (const CalibrationError& e) {
    return e.what();
  }
  return "";
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace

TEST(ImageFiles, CameraFormatsLoadAndOthersAreRefusedBeforeDecoding) {
  const TempDir dir("images");
  const cv::Mat img = background(64, 48);
  for (const char* ext : {".png", ".bmp", ".jpg"}) {
    const std::string path = dir.file(std::string("board") + ext);
    ASSERT_TRUE(cv::imwrite(path, img)) << ext;
    const cv::Mat back = loadImage(path);
    ASSERT_EQ(back.size(), img.size()) << ext;
    ASSERT_EQ(back.type(), CV_8UC3) << ext;
    // PNG and BMP are lossless; JPEG stays close.
    const double worst = cv::norm(back, img, cv::NORM_INF);
    if (std::string(ext) == ".jpg")
      EXPECT_LT(cv::norm(back, img, cv::NORM_L1) / img.total() / 3.0, 6.0);
    else
      EXPECT_EQ(worst, 0.0) << ext;
  }
  // A DICOM header claiming a 4 GB element: OpenCV's GDCM reader would try to allocate it.
  std::string dicom(128, '\0');
  dicom += "DICM";
  dicom += std::string("\x02\x00\x10\x00OB\x00\x00\xf0\xff\xff\xff", 12);
  writeBytes(dir.file("scan.dcm"), dicom);
  EXPECT_NE(loadError(dir.file("scan.dcm")).find("not a JPEG, PNG or BMP"), std::string::npos);
  // A PNG signature with a broken line-ending check (what a text-mode copy does to a PNG).
  writeBytes(dir.file("mangled.png"), std::string("\x89PNG\r\x00\x00\x00", 8) + dicom);
  EXPECT_NE(loadError(dir.file("mangled.png")).find("not a JPEG, PNG or BMP"), std::string::npos);
  // A real PNG cut short, an empty file and a missing one.
  std::vector<unsigned char> png;
  cv::imencode(".png", img, png);
  writeBytes(dir.file("cut.png"), std::string(png.begin(), png.begin() + png.size() / 3));
  EXPECT_NE(loadError(dir.file("cut.png")).find("does not decode"), std::string::npos);
  writeBytes(dir.file("empty.png"), "");
  EXPECT_NE(loadError(dir.file("empty.png")).find("empty"), std::string::npos);
  const std::string missing = loadError(dir.file("missing.png"));
  EXPECT_NE(missing.find("missing.png"), std::string::npos);
  EXPECT_NE(missing.find("cannot open"), std::string::npos);
}
