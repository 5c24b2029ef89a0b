// Export writers for a session's estimated angles and raw sensor data (docs/exports.md): clinical
// CSV (angles in degrees and a metrics table), OpenSim motion files (.mot) and BIDS motion files.
// They take plain data, not the database, and write every file all or nothing: each goes to a
// hidden temporary file beside its target (core/io/AtomicFile.h) and is renamed into place only
// once all files of the export are complete. Qt-free. Any thread; one export per target at a time.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/io/Recording.h"
#include "core/kinematics/Side.h"
#include "core/metrics/ClinicalMetrics.h"
#include "core/metrics/RangeOfMotion.h"

namespace armtrack {

/// An export that could not be written. what() starts with the path concerned; path() is that
/// path (empty when the problem is the input, e.g. an empty series). Nothing of the export is left
/// on disk when this is thrown before the files are renamed into place (see docs/exports.md).
class ExportError : public std::runtime_error {
 public:
  ExportError(std::filesystem::path path, const std::string& message);
  const std::filesystem::path& path() const { return m_path; }

 private:
  std::filesystem::path m_path;
};

// ---------------------------------------------------------------- clinical CSV

/// What a CSV export wrote.
struct CsvExportResult {
  std::filesystem::path anglesCsv;   ///< time + five angles (deg) (+ their sd)
  std::filesystem::path metricsCsv;  ///< session and per-repetition metrics
  std::size_t rows = 0;              ///< angle rows written
  std::size_t skippedRows = 0;       ///< rows dropped for a non-finite time
  std::size_t emptyCells = 0;        ///< non-finite angles or sd written as empty cells
};

/// The metrics file written beside an angles CSV: "<stem>_metrics.csv" in the same folder.
std::filesystem::path metricsCsvPath(const std::filesystem::path& anglesCsv);

/// The trunk's angles of an export, one row per row of its series (rad; flexion, lateral
/// bending, axial rotation, core/kinematics/Trunk.h; NaN where not measured).
struct TrunkColumns {
  std::vector<Eigen::Vector3d> angleRad;
  std::vector<Eigen::Vector3d> sdRad;  ///< their standard deviations; empty = no sd columns
};

/// Writes the angles CSV at anglesCsv and the metrics CSV at metricsCsvPath(anglesCsv).
/// series: times (s) and angles (rad) in clinicalAngleInfo() order; sdRad: optional per-row
/// standard deviations (rad), same shape as series.angle (nullptr = no sd columns); trunk:
/// optional trunk angles (nullptr or empty = no trunk columns), written after the arm's as
/// trunk_flex_deg, trunk_lat_deg, trunk_rot_deg and, with sdRad, trunk_flex_sd_deg ... (the
/// names of `estimate --out`'s columns, in degrees as every angle of this file). A row whose
/// time is not finite is skipped; a non-finite angle or sd is written as an empty cell.
/// Throws std::invalid_argument when sdRad, the trunk's columns or the angle column does not
/// match series.t in length, ExportError when no row has a finite time or a file cannot be
/// written.
CsvExportResult writeClinicalCsv(const std::filesystem::path& anglesCsv, const AngleSeries& series,
                                 const SessionMetrics& metrics,
                                 const std::vector<ClinicalRow>* sdRad = nullptr,
                                 const TrunkColumns* trunk = nullptr);

// ---------------------------------------------------------------- OpenSim .mot

/// OpenSim coordinate names, in clinicalAngleInfo() order, for one side: arm_flex, arm_add,
/// arm_rot, elbow_flex, pro_sup with the suffix _r or _l (the Rajagopal et al. 2015 full-body
/// model's upper limb, after Holzbaur et al. 2005).
std::vector<std::string> openSimCoordinateNames(Side side);

/// OpenSim coordinate values (deg) of one row of clinical angles (rad): flexion, -abduction,
/// internal rotation, elbow flexion, pronation (docs/exports.md explains each sign).
ClinicalRow openSimCoordinatesDeg(const ClinicalRow& clinicalRad);

/// The model's lumbar coordinates, written when the export has the trunk's angles:
/// lumbar_extension, lumbar_bending, lumbar_rotation (the Rajagopal model's `back` joint, pelvis
/// to torso; the same names for both arms).
std::vector<std::string> openSimLumbarNames();

/// Their values (deg) for the trunk's angles (rad; flexion, lateral bending, axial rotation,
/// core/kinematics/Trunk.h): -flexion, lateral bending, axial rotation. The pelvis is taken as
/// upright and still (a seated patient): the trunk's angles are the thorax's from the upright
/// start, written as the torso's turn on the pelvis.
Eigen::Vector3d openSimLumbarDeg(const Eigen::Vector3d& trunkRad);

struct MotOptions {
  std::string name = "armtrack_clinical_angles";  ///< first header line (the storage's name)
  /// Added to pro_sup (deg). ArmTrack's pronation is 0 with the thumb forward; a model whose
  /// pro_sup is 0 in full supination (the ISB convention) needs 90. docs/exports.md explains why
  /// the default is 0.
  double proSupOffsetDeg = 0.0;
};

struct MotExportResult {
  std::size_t rows = 0;         ///< data rows written (nRows)
  std::size_t skippedRows = 0;  ///< rows with a non-finite time or angle, left out
  /// Of those, rows left out only because their trunk angles were not finite (the trunk's
  /// columns written).
  std::size_t skippedTrunkRows = 0;
  bool trunk = false;  ///< the lumbar coordinates were written
};

/// Writes an OpenSim motion file: the name line, version=1, nRows, nColumns (time included),
/// inDegrees=yes, endheader, then the tab-separated labels (time and the coordinates of
/// openSimCoordinateNames(side)) and one row per sample. trunk (nullptr, empty or without one
/// finite row: none): the trunk's angles of the series' rows, written after the arm's as the
/// coordinates of openSimLumbarNames(). Rows with any non-finite value are left out (OpenSim
/// cannot use them). Throws std::invalid_argument for mismatched lengths, ExportError when no
/// usable row is left, when the kept times do not increase strictly (naming the row), or when the
/// file cannot be written.
MotExportResult writeOpenSimMot(const std::filesystem::path& motPath, const AngleSeries& series,
                                Side side, const MotOptions& options = {},
                                const TrunkColumns* trunk = nullptr);

// ---------------------------------------------------------------- BIDS motion

struct BidsOptions {
  std::string subject;  ///< sub-<label>; letters and digits only (see bidsSubjectLabel())
  /// Whose data this is (the patient code), written to the dataset's participants.tsv with the
  /// subject and checked against it: an export never adds to a subject that is someone else's.
  /// Empty = the subject label.
  std::string patientCode;
  std::string session;            ///< ses-<label>; empty = no session level
  std::string task = "armtrack";  ///< task-<label>
  std::string taskName;           ///< TaskName field; empty = the task label
  std::string taskDescription;    ///< TaskDescription field; empty = left out
  /// Replace files of the same subject, session, task and tracking system. Without it an export
  /// that would write over any existing file is refused before anything is written.
  bool overwrite = false;
  /// Called with every file the export will write, before any is created; throws to refuse
  /// (e.g. a path that is the open database). May be empty.
  std::function<void(const std::filesystem::path&)> checkTarget;
};

/// A BIDS label from any text: its ASCII letters and digits, in order ("P-001" -> "P001").
/// Throws std::invalid_argument when none is left. Not one-to-one: for subjects use
/// bidsSubjectLabel().
std::string bidsLabel(const std::string& text);

/// The subject label of a patient code, different for different codes: the code itself when it
/// is ASCII letters and digits only, otherwise its ASCII letters and digits followed by "h" and
/// the 8 hex digits of the code's FNV-1a 32-bit hash ("P-01" -> "P01h" + 8 hex digits), so
/// "P-01" and "P01" never share sub-P01. Throws std::invalid_argument for an empty code.
std::string bidsSubjectLabel(const std::string& patientCode);

/// One tracking system's file set.
struct BidsTrackingSystemFiles {
  std::string label;  ///< tracksys-<label>: "imu", "optical" or "angles"
  std::filesystem::path motionTsv, channelsTsv, channelsJson, motionJson;
  std::size_t rows = 0;           ///< rows of motion.tsv
  std::size_t channels = 0;       ///< columns of motion.tsv = rows of channels.tsv
  std::size_t missingValues = 0;  ///< cells written as n/a
};

struct BidsExportResult {
  std::filesystem::path motionDir;  ///< <root>/sub-<s>[/ses-<s>]/motion
  std::vector<BidsTrackingSystemFiles> systems;
  std::size_t skippedAngleRows = 0;  ///< angle rows dropped for a non-finite time
  /// What was left out and why, e.g. a tracking system with a single sample (no rate).
  std::vector<std::string> notes;
};

/// Writes BIDS motion files (BIDS 1.9, motion modality) under root: one file set per tracking
/// system present: "imu" (both IMUs' gyroscopes and accelerometers, sensor axes, SI units),
/// "optical" (elbow and wrist positions in the shoulder frame, m) when the recording holds any,
/// and "angles" (the five clinical angles, JNTANG, deg) when angles is given and not empty.
/// Each motion.tsv starts with a LATENCY channel (s from that system's first sample), because
/// sample times need not be regular; SamplingFrequency is the nominal rate (the median interval's
/// inverse) and SamplingFrequencyEffective the mean rate. A missing or non-finite value is "n/a".
/// root/dataset_description.json is written when absent; root/participants.tsv gets the
/// subject's row (participant_id, patient_code) when it has none, and participants.json is
/// written when absent. recording may be nullptr (angles only); angles may be nullptr (raw data
/// only). Refused with ExportError before anything is written: a file that exists (without
/// options.overwrite), a subject whose participants.tsv row names another patient code, or a
/// subject folder that no row claims. trunk (nullptr or empty: none): the trunk's angles of the
/// rows of angles, three more channels of the angles' tracking system (trunk_flex, trunk_lat,
/// trunk_rot, deg; n/a where not measured). Throws std::invalid_argument for a bad label or
/// mismatched angle or trunk lengths, ExportError when there is nothing to export or a file cannot
/// be written, and whatever options.checkTarget throws.
BidsExportResult writeBidsMotion(const std::filesystem::path& root, const Recording* recording,
                                 const AngleSeries* angles, Side side, const BidsOptions& options,
                                 const TrunkColumns* trunk = nullptr);

}  // namespace armtrack
