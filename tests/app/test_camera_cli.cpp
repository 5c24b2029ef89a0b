// armtrack-cli camera-calibrate and camera-register (app/cli/Camera.cpp), run in-process on
// synthetic chessboard and ArUco-board images written to a temporary folder.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "app/cli/Args.h"
#include "app/cli/Camera.h"
#include "devices/vision/CameraFile.h"
#include "tests/devices/vision/Synthetic.h"

using namespace armtrack;
using namespace armtrack::devices::webcam;
using namespace armtrack::test::webcam;

namespace {

void writeChessboards(const TempDir& dir, int count) {
  const TrueCamera cam;
  const double d = kPi / 180.0;
  const double tilts[][3] = {{0, 0, 0},    {25, 0, 5},   {-25, 0, -5}, {0, 25, 0},
                             {0, -25, 10}, {20, 20, -8}, {-20, 15, 3}, {15, -20, 12}};
  for (int i = 0; i < count; ++i) {
    const auto& t = tilts[i];
    const cv::Vec3d rvec(t[0] * d, t[1] * d, t[2] * d);
    cv::Matx33d R;
    cv::Rodrigues(rvec, R);
    const cv::Vec3d tvec = cv::Vec3d(0.02 * (i % 3 - 1), 0.01, 0.5) - R * cv::Vec3d(0.1, 0.0625, 0);
    cv::imwrite(dir.file("board" + std::to_string(i) + ".png"),
                renderChessboard(cam, {9, 6}, 0.025, rvec, tvec));
  }
}

}  // namespace

TEST(CameraCli, CalibrateThenRegister) {
  const TempDir dir("camera-cli");
  const TempDir images("camera-cli-images");
  writeChessboards(images, 8);
  std::ostringstream out, err;
  const std::string cam = dir.file("cam.json");
  ASSERT_EQ(cli::cameraCalibrateCommand({"--images", images.path().string(), "--board", "9x6",
                                         "--square", "0.025", "--out", cam, "--name", "test"},
                                        out, err),
            0)
      << err.str();
  EXPECT_NE(out.str().find("| fx (px) |"), std::string::npos) << out.str();
  EXPECT_NE(err.str().find("wrote"), std::string::npos);
  CameraFile f = readCameraFile(cam);
  EXPECT_NEAR(f.intrinsics.fx, 800, 8);
  EXPECT_NEAR(f.intrinsics.fy, 790, 8);
  EXPECT_EQ(f.name, "test");
  EXPECT_FALSE(f.extrinsics);

  // Register from one board image; the board's pose in the shoulder frame comes from a file.
  ArucoBoardSpec spec;
  std::vector<std::vector<cv::Point3f>> layout;
  std::vector<int> ids;
  arucoBoardLayout(spec, layout, ids);
  const cv::Vec3d rvecCb(0.2, -0.1, 0.05);
  cv::Matx33d Rcb;
  cv::Rodrigues(rvecCb, Rcb);
  const cv::Vec3d tcb = cv::Vec3d(0, 0, 0.6) - Rcb * cv::Vec3d(0.087, 0.123, 0);
  cv::imwrite(dir.file("reg.png"), renderArucoBoard(TrueCamera{}, layout, ids,
                                                    cv::aruco::DICT_4X4_50, rvecCb, tcb, 0.01));
  std::ofstream(dir.file("pose.json"))
      << R"({"R": [[0,1,0],[0,0,1],[1,0,0]], "t_m": [-0.1, 0.3, 0.05]})";
  out.str("");
  err.str("");
  ASSERT_EQ(cli::cameraRegisterCommand({"--camera", cam, "--image", dir.file("reg.png"),
                                        "--board-pose", dir.file("pose.json"), "--out", cam},
                                       out, err),
            0)
      << err.str();
  f = readCameraFile(cam);
  ASSERT_TRUE(f.extrinsics);
  const cv::Matx33d Rsb(0, 1, 0, 0, 0, 1, 1, 0, 0);
  const cv::Matx33d Rtrue = Rcb * Rsb.t();
  const cv::Vec3d ttrue = tcb - Rtrue * cv::Vec3d(-0.1, 0.3, 0.05);
  // The intrinsics came from calibration (about 0.1% off), hence a looser tolerance than the
  // unit test with exact intrinsics.
  EXPECT_LT(cv::norm(f.extrinsics->t - ttrue), 0.01);
  EXPECT_LT(cv::norm(cv::Mat(f.extrinsics->R - Rtrue)), 0.01);
  EXPECT_NE(out.str().find("camera centre"), std::string::npos);

  // The same with the pose on the command line (identity rotation here).
  out.str("");
  ASSERT_EQ(cli::cameraRegisterCommand({"--camera", cam, "--image", dir.file("reg.png"),
                                        "--board-origin", "0,0,0", "--out", dir.file("cam2.json")},
                                       out, err),
            0);
  const CameraFile g = readCameraFile(dir.file("cam2.json"));
  EXPECT_LT(cv::norm(g.extrinsics->t - tcb), 0.01);
}

TEST(CameraCli, ErrorsAreClear) {
  const TempDir dir("camera-cli-errors");
  const TempDir images("camera-cli-few");
  writeChessboards(images, 2);
  std::ostringstream out, err;
  using cli::UsageError;
  EXPECT_THROW(
      cli::cameraCalibrateCommand({"--board", "9x6", "--square", "0.025", "--out", "x"}, out, err),
      UsageError);  // no images
  EXPECT_THROW(cli::cameraCalibrateCommand({"--images", images.path().string(), "--board", "9by6",
                                            "--square", "0.025", "--out", "x"},
                                           out, err),
               UsageError);
  EXPECT_THROW(cli::cameraCalibrateCommand({"--images", images.path().string(), "--board", "6x6",
                                            "--square", "0.025", "--out", "x"},
                                           out, err),
               UsageError);
  try {
    cli::cameraCalibrateCommand({"--images", images.path().string(), "--board", "9x6", "--square",
                                 "0.025", "--out", dir.file("cam.json")},
                                out, err);
    FAIL();
  } catch (const CalibrationError& e) {
    EXPECT_NE(std::string(e.what()).find("found in 2 of 2 images"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("cam.json")));
  EXPECT_THROW(cli::cameraRegisterCommand({"--camera", "c.json", "--image", "i.png", "--out", "o"},
                                          out, err),
               UsageError);  // no pose
  EXPECT_THROW(cli::cameraRegisterCommand({"--camera", dir.file("none.json"), "--image", "i.png",
                                           "--board-origin", "0,0", "--out", "o"},
                                          out, err),
               UsageError);  // two numbers
  EXPECT_THROW(cli::cameraRegisterCommand({"--camera", dir.file("none.json"), "--image", "i.png",
                                           "--board-origin", "0,0,0", "--out", "o"},
                                          out, err),
               CameraFileError);
  out.str("");
  EXPECT_EQ(cli::cameraCalibrateCommand({"--help"}, out, err), 0);
  EXPECT_NE(out.str().find("Usage: armtrack-cli camera-calibrate"), std::string::npos);
}
