// Sensor-to-segment calibration: the IMU mounting (strap distances and angles, a small residual
// rotation of each IMU), the segment lengths and a constant gyroscope bias per IMU, as estimated
// by calibrate() (core/calibration/Calibrator.h) and applied before the joint-angle filter.
// File format and the therapist's protocol: docs/calibration.md.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/ArmSample.h"
#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"
#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"

namespace armtrack {

/// One IMU's correction. The physical sensor reads rotation^T * (model reading) + gyroBias on the
/// gyroscope and rotation^T * (model reading) on the accelerometer (the simulator's
/// ImuSimParams::misalignment is `rotation`), so the model frame's readings are recovered as
///   gyr' = rotation * (gyr - gyroBias),   acc' = rotation * acc.
/// Both are in the recording's own sensor axes (for a left arm: the real left sensor's axes).
struct ImuCalibration {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< sensor axes -> model IMU frame
  Eigen::Vector3d gyroBias = Eigen::Vector3d::Zero();      ///< rad/s, sensor axes
};

/// A complete calibration of one arm.
struct Calibration {
  Side side = Side::Right;  ///< the arm it was estimated for; applying it to the other is an error
  ArmGeometry geometry;     ///< segment lengths and strap distances/angles (m, rad)
  ImuCalibration upperArm;
  ImuCalibration forearm;
  /// The sternum sensor's mounting (frame 0 of the side, the trunk upright), its tilt levelled
  /// from the start pose (core/calibration/TrunkMounting.h); empty when the recording had no
  /// sternum sensor. The file's "trunk" block: {"imu_position": [3], "imu_rotation": [9,
  /// row-major]}.
  std::optional<TrunkMount> trunk;

  // What the estimate rests on (written to the file for the record; not needed to apply it).
  bool opticalUsed = false;                ///< optical positions took part in the fit
  bool headingFromStartPoseOnly = true;    ///< heading about the vertical fixed by the start pose
  std::vector<std::string> estimated;      ///< parameters fitted from the data
  std::vector<std::string> fromStartPose;  ///< parameters that rest on the start-pose assumption
  std::vector<std::string> heldFixed;      ///< parameters kept at the recording's values
};

/// A calibration file that cannot be read or written. what() reads "<file>: <message>".
class CalibrationError : public std::runtime_error {
 public:
  CalibrationError(const std::string& file, const std::string& message)
      : std::runtime_error(file + ": " + message) {}
};

/// The start pose of the calibration protocol (docs/calibration.md): upper arm hanging, elbow
/// flexed 90 deg, forearm pointing forward, thumb up; th = [0 0 0 -90 0] deg, in rad.
JointVector protocolStartPose();

/// The correction of one reading (see ImuCalibration).
ImuReading applyCalibration(const ImuCalibration& c, const ImuReading& r);
/// Corrects both IMU readings of a sample in place (optical positions are left as they are).
void applyCalibration(const Calibration& c, ArmSample& s);
/// Puts the calibrated geometry (and the sternum sensor's mounting, when calibrated) into a
/// recording's metadata, for a recording whose samples are
/// corrected one by one as they are read. Throws std::invalid_argument when the recording's side
/// differs from the calibration's.
void applyCalibration(const Calibration& c, RecordingMeta& meta);
/// Corrects every sample and puts the calibrated geometry into the sidecar metadata, so filter
/// parameters made from rec.meta afterwards use it. Throws std::invalid_argument when the
/// recording's side differs from the calibration's.
void applyCalibration(const Calibration& c, Recording& rec);
/// Puts the calibrated geometry into filter parameters. Throws std::invalid_argument when
/// params.side differs from the calibration's.
void applyCalibration(const Calibration& c, EstimatorParams& params);

/// A left-arm sensor's calibration expressed for its right-arm twin (core/kinematics/Side.h), or
/// back (an involution): the rotation is mirror-conjugated, D R D with D = diag(1, 1, -1), and
/// the gyroscope bias, an axial vector, maps as b -> -D b.
ImuCalibration mirrorImuCalibration(const ImuCalibration& c);

/// The first value of the calibration that no real arm and IMU mounting can have, as a message
/// that starts with its key in quotes (e.g. "\"geometry.l3\" is 0.05 m: ..."): a non-finite or
/// non-rotation IMU correction, or a geometry outside the sidecar limits (MetaLimits and
/// metaProblem in core/io/Recording.h: l3, l6 0.1-0.6 m, strap distances within the segment +
/// 0.1 m, ...). Empty when every value is possible. Any thread.
std::string calibrationProblem(const Calibration& c);

/// The calibration as a calibration file holds it (JSON text), e.g. to be stored with a session
/// in the records. Throws CalibrationError naming `name` as writeCalibration() refuses.
std::string calibrationText(const Calibration& c, const std::filesystem::path& name);
/// A calibration from the text of a calibration file; name says where it came from in errors.
/// Throws CalibrationError as readCalibration() does.
Calibration parseCalibration(const std::string& text, const std::filesystem::path& name);

/// Writes the calibration as pretty-printed JSON (docs/calibration.md), via a temporary file
/// renamed into place. Throws CalibrationError, also when calibrationProblem() finds a value no
/// real arm has (nothing is written then).
void writeCalibration(const std::filesystem::path& path, const Calibration& c);
/// Reads a calibration file. Throws CalibrationError naming the file and what is wrong, also
/// when calibrationProblem() finds a value no real arm has.
Calibration readCalibration(const std::filesystem::path& path);

}  // namespace armtrack
