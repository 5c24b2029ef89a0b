// The camera-calibrate and camera-register commands of armtrack-cli: a webcam's (or the Kinect
// colour camera's) intrinsics from chessboard images, then its pose in the shoulder frame from one
// image of an ArUco board (docs/devices/webcam.md).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace armtrack::cli {

/// armtrack-cli camera-calibrate --images DIR --board 9x6 --square 0.025 --out CAM.json.
/// Writes the camera file (without a pose), prints the intrinsics and per-image errors to out,
/// progress and warnings to err. Throws UsageError (exit 2) for usage mistakes and
/// std::exception for input and runtime errors (exit 1), like the other commands.
int cameraCalibrateCommand(const std::vector<std::string>& args, std::ostream& out,
                           std::ostream& err);

/// armtrack-cli camera-register --camera CAM.json --image BOARD.png --board-pose POSE.json
/// --out CAM.json. Adds the camera's pose in the shoulder frame to the camera file. Same
/// conventions as cameraCalibrateCommand.
int cameraRegisterCommand(const std::vector<std::string>& args, std::ostream& out,
                          std::ostream& err);

}  // namespace armtrack::cli
