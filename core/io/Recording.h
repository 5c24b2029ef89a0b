// The open recording format (docs/recording-format.md): a CSV of samples plus a JSON sidecar.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/ArmSample.h"
#include "core/camera/CameraParams.h"
#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"

namespace armtrack {

/// Where the sternum IMU sits (the sidecar's "trunk" block), in frame 0 with the trunk upright at
/// the start.
struct TrunkMount {
  Eigen::Vector3d imuPosition = Eigen::Vector3d::Zero();  ///< m, relative to the shoulder centre
  /// Columns: the IMU's axes in frame 0 (the sidecar stores it row-major).
  Eigen::Matrix3d imuRotation = Eigen::Matrix3d::Identity();
};

/// The mounting a reader assumes for a recording with a trunk IMU (tr_* columns) whose sidecar has
/// no "trunk" block (with a warning, docs/recording-format.md): the sensor flat on the middle of
/// the sternum, its axes those of frame 0 (x down the sternum, y out of the chest, z to the
/// patient's right), 0.10 m below, 0.06 m in front of and 0.18 m medial to the shoulder centre
/// (z0 points to the patient's right for both arms, so medial is -z for a right arm, +z for a
/// left one).
inline TrunkMount defaultTrunkMount(Side side) {
  TrunkMount m;
  m.imuPosition = Eigen::Vector3d(0.10, 0.06, side == Side::Left ? 0.18 : -0.18);
  return m;
}

/// The mounting of the same sensor on the other side's mirror image (core/kinematics/Side.h).
inline TrunkMount mirrorMount(const TrunkMount& m) {
  return {mirrorPoint(m.imuPosition), mirrorRotation(m.imuRotation)};
}

/// The sidecar's contents.
struct RecordingMeta {
  ArmGeometry geometry;
  Eigen::Vector3d up{-1.0, 0.0, 0.0};  ///< unit vector pointing up, shoulder-frame axes
  double g = 9.81;                     ///< m/s^2
  std::optional<CameraParams> camera;
  Side side = Side::Right;  ///< which arm; a left arm's data are in its own shoulder frame
  /// The sternum IMU's mounting; present when the recording has a trunk IMU.
  std::optional<TrunkMount> trunk;

  Eigen::Vector3d gUp() const { return g * up; }
};

struct Recording {
  RecordingMeta meta;
  std::vector<ArmSample> samples;
  std::vector<std::string> warnings;  ///< e.g. a missing sidecar (defaults used)
};

/// A malformed recording. what() reads "<file>:<line>:<column>: <message>" (line and column are
/// 1-based; 0 where they do not apply, and then left out of what()).
class RecordingError : public std::runtime_error {
 public:
  RecordingError(std::string file, int line, int column, const std::string& message);
  const std::string& file() const { return m_file; }
  int line() const { return m_line; }
  int column() const { return m_column; }
  const std::string& message() const { return m_message; }

 private:
  std::string m_file;
  int m_line;
  int m_column;
  std::string m_message;
};

/// The column groups a RecordingWriter writes (fixed when it opens), or a file's header holds.
struct RecordingColumns {
  bool upperArm = false, forearm = false;   ///< gyroscope and accelerometer of each IMU
  bool elbow = false, wrist = false;        ///< optical positions
  bool trunk = false;                       ///< tr_*: the sternum IMU
  bool shoulder = false;                    ///< shoulder_*: optical shoulder position
  bool trueTrunk = false;                   ///< true_trunk_*
  bool camWrist = false, camElbow = false;  ///< marker pixels
  bool truth = false;                       ///< true_th*
  bool estimate = false;                    ///< est_th*
};

/// What keeps a sample from being the next row of a recording with these columns, after a row at
/// prevT (NaN or -infinity before the first row) of a recording whose first row was at firstT
/// (NaN before it): a non-finite time, one beyond any clock or more than the longest recording
/// after the first (RecordingLimits: what the reader would refuse), a time before prevT, a sensor
/// the columns do not hold, or a non-finite value. The one check every writer of rows makes
/// (RecordingWriter, core/storage's DatabaseRecordingSink).
struct RowProblem {
  int column = 1;       ///< the CSV column (1-based, the time is 1) as these columns number them
  std::string message;  ///< e.g. "cannot write non-finite value nan in column \"ua_ax\""
};
/// Empty when sample may be appended.
std::optional<RowProblem> checkRow(const ArmSample& sample, const RecordingColumns& columns,
                                   double prevT,
                                   double firstT = std::numeric_limits<double>::quiet_NaN());

/// What the recording reader accepts at the door (docs/recording-format.md, "Limits"). A file or
/// a row outside them is refused with a RecordingError naming the file, line and column.
struct RecordingLimits {
  /// The largest CSV (bytes): 32 GiB. An hour at 1 kHz with two IMUs, a Kinect and true angles is
  /// 1.26 GB, so the longest recording (kMaxRecordingSeconds) with every column a live session
  /// writes stays near 20 GB; a larger file is not a recording.
  static constexpr std::uint64_t kMaxFileBytes = std::uint64_t{32} << 30;
  /// The largest sidecar (bytes): 1 MiB. A real one is under 1 KiB.
  static constexpr std::uint64_t kMaxSidecarBytes = std::uint64_t{1} << 20;
  /// Bytes read and checked for text before anything is parsed: 64 KiB. They, and every byte
  /// after, must hold no control byte other than tab, CR and LF (a NUL says binary, or a sparse
  /// file's hole).
  static constexpr std::size_t kSniffBytes = std::size_t{64} << 10;
  /// The longest line (bytes, without its line end): 64 KiB. The widest valid row, 45 numbers, is
  /// about 1 KiB.
  static constexpr std::size_t kMaxLineBytes = std::size_t{64} << 10;
  /// The longest span of a recording (s): 12 h. A row more than this after the first row is
  /// refused (a clock jump, a corrupted time), so a recording's analysis stays bounded.
  static constexpr double kMaxRecordingSeconds = 12.0 * 3600.0;
  /// The largest |t| of the first row (s): 1e10, beyond any Unix time of this century
  /// (1e10 s is the year 2286).
  static constexpr double kMaxAbsTimeSeconds = 1e10;
  /// A step forward in t longer than this (s) is a gap: accepted and counted (TimeGaps). The
  /// estimator restarts after the same step (EstimatorParams::maxGap's default).
  static constexpr double kGapSeconds = 0.1;
};

/// The gaps in a recording's time: steps from one row to the next longer than
/// RecordingLimits::kGapSeconds, over the rows read so far.
struct TimeGaps {
  std::uint64_t count = 0;      ///< number of gaps
  double totalSeconds = 0.0;    ///< their summed length (s)
  double longestSeconds = 0.0;  ///< the longest (s); 0 when there is none
  double longestFromT = 0.0;    ///< the time of the row before the longest gap (s)
  int longestLine = 0;          ///< the CSV line of the row after it (the jump); 0 when none
};

/// Reads a CSV recording row by row, holding one chunk of the file in memory, not the whole
/// recording (a replay of an hour at 1 kHz). The constructor checks the file at the door (a
/// regular file, at most RecordingLimits::kMaxFileBytes, text in its first kSniffBytes), reads
/// the sidecar and the header; next() the rows, checked as readRecording checks them (lines at
/// most kMaxLineBytes, no control bytes, times within the limits). Memory: one 1 MiB chunk plus
/// at most one line. Throws RecordingError. One thread at a time.
class RecordingReader {
 public:
  explicit RecordingReader(const std::filesystem::path& csvPath);
  ~RecordingReader();
  RecordingReader(const RecordingReader&) = delete;
  RecordingReader& operator=(const RecordingReader&) = delete;

  const RecordingMeta& meta() const { return m_meta; }
  /// The column groups of the header (a group may still be empty in every row).
  const RecordingColumns& columns() const { return m_columns; }
  /// The next row into sample; false at the end. A last line cut short by a kill ends the file
  /// with a warning instead of an error.
  bool next(ArmSample& sample);
  /// A missing sidecar, a last line cut short.
  const std::vector<std::string>& warnings() const { return m_warnings; }
  std::uint64_t rows() const { return m_rows; }
  /// Whether the file ended in a last line cut short (a recording interrupted while it was
  /// written), which next() dropped with a warning. Known once next() has returned false.
  bool cutShort() const { return m_cutShort; }
  /// The gaps in time among the rows read so far (complete once next() has returned false).
  const TimeGaps& gaps() const;
  /// For progress: bytes consumed so far, and the file's size (0 when unknown).
  std::uint64_t bytesRead() const;
  std::uint64_t fileSize() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
  RecordingMeta m_meta;
  RecordingColumns m_columns;
  std::vector<std::string> m_warnings;
  std::uint64_t m_rows = 0;
  bool m_cutShort = false;
};

/// Reads a CSV recording and its sidecar (<name>.json beside it) into memory. Throws
/// RecordingError.
Recording readRecording(const std::filesystem::path& csvPath);
/// Writes the CSV and its sidecar. Only the sensors present in some sample get columns.
/// Throws RecordingError when the file cannot be written (e.g. a full disk).
void writeRecording(const std::filesystem::path& csvPath, const Recording& recording);

/// Writes a recording row by row, for live sessions. The CSV goes straight to its final name, so
/// a session that is killed leaves a readable file up to the last flush (readRecording drops a
/// last line cut short, with a warning). Throws RecordingError on every failure (a full disk, a
/// removed folder), with the operating system's reason; rows appended before a failure that were
/// flushed stay on disk, and rows not yet written stay buffered for the next flush.
///
/// Opening checks the metadata (metaProblem) and that neither the CSV nor the sidecar path is a
/// directory before creating anything; then it opens the CSV (an existing file is replaced: the
/// caller decides whether that is allowed) and takes an exclusive lock on it (flock), held until
/// the writer is closed or destroyed: a second writer on the same file, in this process or
/// another, is refused with a message saying so, before it changes the file or its sidecar. Only
/// then is the sidecar written (all or nothing) and the CSV emptied. A CSV the constructor
/// created is removed again if a later step fails. One thread at a time.
/// Where a live session's rows go: a recording file (RecordingWriter) or the clinical records
/// (core/storage's DatabaseRecordingSink). Used from one thread, the session's recorder.
class RecordingSink {
 public:
  virtual ~RecordingSink() = default;
  /// Takes one row. Throws RecordingError for a row that cannot be kept (non-finite, out of time
  /// order, a sensor the columns do not hold); the sink stays usable.
  virtual void append(const ArmSample& sample) = 0;
  /// Hands what is buffered to the storage, as far as the sink's unit of writing allows.
  /// Throws RecordingError when the storage fails; the rows stay buffered for the next call.
  virtual void flush() = 0;
  /// Everything appended made durable (fsync, a committed transaction). Throws as flush().
  virtual void sync() = 0;
  /// sync() and release the storage. Further calls throw.
  virtual void close() = 0;
  /// Rows appended.
  virtual std::uint64_t rows() const = 0;
  /// Rows the storage has accepted; rows() - rowsWritten() are still buffered.
  virtual std::uint64_t rowsWritten() const = 0;
};

class RecordingWriter : public RecordingSink {
 public:
  RecordingWriter(const std::filesystem::path& csvPath, const RecordingMeta& meta,
                  const RecordingColumns& columns);
  ~RecordingWriter() override;  ///< closes (and syncs) without throwing
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  /// Buffers one row. Throws for a non-finite value, a time before the previous row's, or a
  /// sensor the columns do not hold; the row is then not written and the writer stays usable.
  void append(const ArmSample& sample) override;
  /// Writes the buffered rows to the file (no fsync).
  void flush() override;
  /// flush() and force the file to disk (fsync).
  void sync() override;
  /// sync() and close. Further calls throw.
  void close() override;

  /// Rows appended (buffered or written).
  std::uint64_t rows() const override { return m_rows; }
  /// Rows whose every byte the operating system has accepted (write(); fsync is another matter).
  /// rows() - rowsWritten() rows are still buffered, e.g. while the disk is full.
  std::uint64_t rowsWritten() const override;
  const std::filesystem::path& path() const { return m_path; }

 private:
  void writeAll(std::string_view data, std::size_t& written);

  std::filesystem::path m_path;
  std::array<bool, 14> m_present{};
  std::string m_buf;
  int m_fd = -1;
  double m_prevT;
  double m_firstT = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t m_rows = 0;
  std::uint64_t m_linesWritten = 0;  // newline-terminated lines written, the header's included
};

/// What a real arm, IMU mounting and camera can never exceed; a sidecar outside these limits is
/// refused by readSidecar (and never written). docs/recording-format.md explains each limit.
struct MetaLimits {
  static constexpr double kMinSegment = 0.10;        ///< l3, l6 at least (m)
  static constexpr double kMaxSegment = 0.60;        ///< l3, l6 at most (m)
  static constexpr double kStrapMargin = 0.10;       ///< lu3 <= l3 + margin, lf6 <= l6 + margin (m)
  static constexpr double kMaxStrapRadius = 0.15;    ///< |lu5|, |lf8| at most (m)
  static constexpr double kMaxStrapAngle = 6.3;      ///< |thu4|, |thf7| at most (rad, about 2 pi)
  static constexpr double kMinG = 9.5;               ///< g at least (m/s^2)
  static constexpr double kMaxG = 10.2;              ///< g at most (m/s^2)
  static constexpr double kMaxFocal = 1e6;           ///< fx, fy at most (pixels)
  static constexpr double kMaxPrincipal = 1e6;       ///< |cx|, |cy| at most (pixels)
  static constexpr double kMaxCameraDistance = 100;  ///< |t| at most (m)
  static constexpr double kRotationTolerance = 1e-3;  ///< max |R^T R - I|, as PinholeCamera
  /// |trunk.imu_position| at most (m): a sternum IMU is within about 0.3 m of either shoulder.
  static constexpr double kMaxTrunkImuDistance = 1.0;
};

/// The first value of meta that is not finite or outside MetaLimits, as a message that starts
/// with its sidecar key in quotes (e.g. "\"geometry.l3\" is 0 m: ..."); empty when every value
/// is possible. Any thread.
std::string metaProblem(const RecordingMeta& meta);

/// The sidecar path for a CSV path: same name, extension .json.
std::filesystem::path sidecarPath(const std::filesystem::path& csvPath);
RecordingMeta readSidecar(const std::filesystem::path& jsonPath);  // throws RecordingError
/// Writes the sidecar as pretty-printed JSON, via a temporary file renamed into place.
/// Throws RecordingError when it cannot be written.
void writeSidecar(const std::filesystem::path& jsonPath, const RecordingMeta& meta);

}  // namespace armtrack
