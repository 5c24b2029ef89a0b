// BIDS motion export (docs/exports.md, "BIDS motion"; BIDS 1.9, modality-specific files: motion).
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <system_error>

#include "core/exports/ExportFiles.h"
#include "core/exports/Exports.h"
#include "core/kinematics/ClinicalAngles.h"

namespace armtrack {

namespace fs = std::filesystem;
using exportdetail::appendFixed;
using exportdetail::appendShortest;
using nlohmann::ordered_json;

namespace {

struct Channel {
  std::string name, component, type, trackedPoint, units, referenceFrame, description;
};

// One tracking system: its channels (LATENCY excluded, it is always first) and its rows.
struct System {
  std::string label, trackingSystemName;
  std::vector<Channel> channels;
  std::vector<std::size_t> rows;                                // indices into the source
  std::function<double(std::size_t)> time;                      // s
  std::function<void(std::size_t, std::vector<double>&)> fill;  // one value per channel; NaN = n/a
  int angleDecimals = -1;  // >= 0: fixed decimals (deg); otherwise shortest round-trip form
};

std::string sideWord(Side side) {
  return side == Side::Left ? "Left" : "Right";
}

void addXyz(System& s, const std::string& prefix, const std::string& type, const std::string& point,
            const std::string& units, const std::string& frame, const std::string& what) {
  for (const char* axis : {"x", "y", "z"})
    s.channels.push_back(
        {prefix + "_" + axis, axis, type, point, units, frame, what + ", " + axis + " axis"});
}

bool hasTrunkImu(const Recording& rec) {
  return std::any_of(rec.samples.begin(), rec.samples.end(),
                     [](const ArmSample& a) { return a.trunk.has_value(); });
}

bool hasShoulder(const Recording& rec) {
  return std::any_of(rec.samples.begin(), rec.samples.end(),
                     [](const ArmSample& a) { return a.shoulder.has_value(); });
}

System imuSystem(const Recording& rec, Side side) {
  System s;
  s.label = "imu";
  // The sternum's channels only when the session had a trunk IMU: an export without one keeps
  // its files of before.
  const bool trunk = hasTrunkImu(rec);
  s.trackingSystemName = trunk ? "ArmTrack IMUs (upper arm, forearm and sternum)"
                               : "ArmTrack IMUs (upper arm and forearm)";
  const std::string sw = sideWord(side);
  addXyz(s, "upperarm_gyro", "GYRO", sw + "UpperArm", "rad/s", "sensor",
         "upper-arm IMU angular velocity");
  addXyz(s, "upperarm_acc", "ACCEL", sw + "UpperArm", "m/s^2", "sensor",
         "upper-arm IMU specific force");
  addXyz(s, "forearm_gyro", "GYRO", sw + "Forearm", "rad/s", "sensor",
         "forearm IMU angular velocity");
  addXyz(s, "forearm_acc", "ACCEL", sw + "Forearm", "m/s^2", "sensor",
         "forearm IMU specific force");
  if (trunk) {
    addXyz(s, "trunk_gyro", "GYRO", "Sternum", "rad/s", "sensor",
           "trunk (sternum) IMU angular velocity");
    addXyz(s, "trunk_acc", "ACCEL", "Sternum", "m/s^2", "sensor",
           "trunk (sternum) IMU specific force");
  }
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    const ArmSample& a = rec.samples[i];
    if ((a.hasImu() || a.trunk) && std::isfinite(a.t)) s.rows.push_back(i);
  }
  s.time = [&rec](std::size_t i) { return rec.samples[i].t; };
  s.fill = [&rec, trunk](std::size_t i, std::vector<double>& v) {
    const ArmSample& a = rec.samples[i];
    std::fill(v.begin(), v.end(), NAN);
    int k = 0;
    for (const auto* imu : {&a.upperArm, &a.forearm, &a.trunk}) {
      if (imu == &a.trunk && !trunk) break;
      if (imu->has_value())
        for (int j = 0; j < 3; ++j) {
          v[k + j] = (*imu)->gyr(j);
          v[k + 3 + j] = (*imu)->acc(j);
        }
      k += 6;
    }
  };
  return s;
}

/// Whether the recording's optical positions are in the world frame (docs/recording-format.md,
/// "Trunk": with a trunk IMU or an optical shoulder) rather than the shoulder frame.
bool worldFrame(const Recording& rec) {
  return hasTrunkImu(rec) || hasShoulder(rec) || rec.meta.trunk.has_value();
}

System opticalSystem(const Recording& rec, Side side) {
  System s;
  s.label = "optical";
  const bool shoulder = hasShoulder(rec);
  s.trackingSystemName = shoulder ? "Optical shoulder, elbow and wrist positions (Kinect)"
                                  : "Optical elbow and wrist positions (Kinect)";
  const std::string sw = sideWord(side);
  const std::string frame = worldFrame(rec) ? "world" : "shoulder";
  addXyz(s, "elbow_pos", "POS", sw + "Elbow", "m", frame, "elbow position");
  addXyz(s, "wrist_pos", "POS", sw + "Wrist", "m", frame, "wrist position");
  if (shoulder) addXyz(s, "shoulder_pos", "POS", sw + "Shoulder", "m", frame, "shoulder position");
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    const ArmSample& a = rec.samples[i];
    if ((a.elbow || a.wrist || a.shoulder) && std::isfinite(a.t)) s.rows.push_back(i);
  }
  s.time = [&rec](std::size_t i) { return rec.samples[i].t; };
  s.fill = [&rec, shoulder](std::size_t i, std::vector<double>& v) {
    const ArmSample& a = rec.samples[i];
    std::fill(v.begin(), v.end(), NAN);
    for (int j = 0; j < 3; ++j) {
      if (a.elbow) v[j] = (*a.elbow)(j);
      if (a.wrist) v[3 + j] = (*a.wrist)(j);
      if (shoulder && a.shoulder) v[6 + j] = (*a.shoulder)(j);
    }
  };
  return s;
}

System angleSystem(const AngleSeries& series, const TrunkColumns* trunk, Side side,
                   std::size_t& skipped) {
  System s;
  s.label = "angles";
  s.trackingSystemName = "ArmTrack estimated joint angles";
  s.angleDecimals = 6;
  const std::string sw = sideWord(side);
  const char* points[kNumClinicalAngles] = {"Shoulder", "Shoulder", "Shoulder", "Elbow", "Forearm"};
  const auto& info = clinicalAngleInfo();
  for (int a = 0; a < kNumClinicalAngles; ++a)
    s.channels.push_back(
        {std::string(info[a].key), "n/a", "JNTANG", sw + points[a], "deg", "n/a",
         std::string(info[a].name) + ", positive = " + std::string(info[a].positive)});
  // The trunk's angles from the upright start (core/kinematics/Trunk.h), the same for both sides.
  static constexpr const char* kTrunk[3][2] = {
      {"trunk_flex", "Trunk flexion, positive = leaning forward"},
      {"trunk_lat", "Trunk lateral bending, positive = leaning to the patient's right"},
      {"trunk_rot", "Trunk axial rotation, positive = the right shoulder forward"}};
  if (trunk)
    for (const auto& [key, what] : kTrunk)
      s.channels.push_back({key, "n/a", "JNTANG", "Thorax", "deg", "n/a", what});
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    if (std::isfinite(series.t[i]))
      s.rows.push_back(i);
    else
      ++skipped;
  }
  s.time = [&series](std::size_t i) { return series.t[i]; };
  s.fill = [&series, trunk](std::size_t i, std::vector<double>& v) {
    for (int a = 0; a < kNumClinicalAngles; ++a) v[a] = series.angle[i][a] * kRadToDeg;
    if (trunk)
      for (int k = 0; k < 3; ++k) v[kNumClinicalAngles + k] = trunk->angleRad[i](k) * kRadToDeg;
  };
  return s;
}

std::string tsvCell(const std::string& s) {
  return s.empty() ? "n/a" : s;
}

// Removes the folders this export created (deepest first), after a failure.
struct CreatedDirs {
  std::vector<fs::path> dirs;
  bool keep = false;
  ~CreatedDirs() {
    if (keep) return;
    std::error_code ec;
    for (auto it = dirs.rbegin(); it != dirs.rend(); ++it) fs::remove(*it, ec);  // only if empty
  }
};

// Creates the missing folders of dir with mode 0700 whatever the umask (they hold a patient's
// data); folders that exist are left as they are.
void makeDirs(const fs::path& dir, CreatedDirs& created) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (::mkdir(it->c_str(), S_IRWXU) != 0)
      throw ExportError(*it, "cannot create the folder: " + std::generic_category().message(errno));
    created.dirs.push_back(*it);
    ::chmod(it->c_str(), S_IRWXU);  // the umask may have taken the owner's bits away
  }
  if (!fs::is_directory(dir, ec)) throw ExportError(dir, "is not a folder");
}

std::string readWhole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ExportError(file, "cannot be read");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw ExportError(file, "cannot be read");
  return text;
}

std::vector<std::string> splitTabs(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (std::size_t tab; (tab = line.find('\t', start)) != std::string::npos; start = tab + 1)
    cells.push_back(line.substr(start, tab - start));
  cells.push_back(line.substr(start));
  return cells;
}

std::string joinTabs(const std::vector<std::string>& cells) {
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) line += (i ? "\t" : "") + cells[i];
  return line;
}

// Whether a path names anything, a dangling symbolic link included.
bool present(const fs::path& p) {
  std::error_code ec;
  return fs::exists(fs::symlink_status(p, ec));
}

// The subject's claim in the dataset's participants.tsv (participant_id, patient_code): whose
// data a subject folder holds. Returns the file's new text when a row must be added, an empty
// string when the row is there and names this patient; throws ExportError, before anything is
// written, when the subject is another patient's, or is there but nobody's that the file says.
std::string claimSubject(const fs::path& root, const std::string& participant,
                         const std::string& code) {
  const fs::path tsv = root / "participants.tsv";
  const fs::path subjectDir = root / participant;
  const std::string nothing = "; nothing was written";
  const std::string unknown =
      "exists, but participants.tsv does not say whose data it holds (ArmTrack lists each "
      "subject's patient_code there)" +
      nothing + ": export into another folder, or add the subject's row by hand";
  if (!present(tsv)) {
    if (present(subjectDir)) throw ExportError(subjectDir, unknown);
    return "participant_id\tpatient_code\n" + participant + "\t" + code + "\n";
  }
  std::vector<std::vector<std::string>> rows;
  {
    const std::string text = readWhole(tsv);
    std::size_t start = 0;
    while (start < text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      std::string line = text.substr(start, end - start);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (!line.empty()) rows.push_back(splitTabs(line));
      start = end + 1;
    }
  }
  const auto column = [&](const char* name) -> std::ptrdiff_t {
    if (rows.empty()) return -1;
    const auto it = std::find(rows[0].begin(), rows[0].end(), name);
    return it == rows[0].end() ? -1 : it - rows[0].begin();
  };
  const std::ptrdiff_t id = column("participant_id");
  std::ptrdiff_t owner = column("patient_code");
  if (id < 0)
    throw ExportError(tsv, "has no participant_id column, so it is not a BIDS participants file" +
                               nothing + ": export into another folder");
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    if (static_cast<std::size_t>(id) >= row.size() || row[id] != participant) continue;
    const std::string who =
        owner >= 0 && static_cast<std::size_t>(owner) < row.size() ? row[owner] : "";
    if (who == code) return {};
    if (who.empty() || who == "n/a") throw ExportError(subjectDir, unknown);
    throw ExportError(subjectDir,
                      "holds the data of another patient (participants.tsv: "
                      "patient_code '" +
                          who + "', not '" + code + "')" + nothing +
                          ": export into another folder");
  }
  if (present(subjectDir)) throw ExportError(subjectDir, unknown);
  if (owner < 0) {  // a dataset made elsewhere: the column is added, n/a for its subjects
    for (auto& row : rows) row.push_back(&row == &rows[0] ? "patient_code" : "n/a");
    owner = static_cast<std::ptrdiff_t>(rows[0].size()) - 1;
  }
  std::vector<std::string> added(rows[0].size(), "n/a");
  added[id] = participant;
  added[owner] = code;
  rows.push_back(added);
  std::string text;
  for (const auto& row : rows) text += joinTabs(row) + "\n";
  return text;
}

std::uint32_t fnv1a32(const std::string& text) {
  std::uint32_t h = 2166136261u;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 16777619u;
  }
  return h;
}

}  // namespace

std::string bidsSubjectLabel(const std::string& patientCode) {
  if (patientCode.empty()) throw std::invalid_argument("an empty patient code has no BIDS label");
  std::string label;
  for (unsigned char c : patientCode)
    if (c < 128 && std::isalnum(c)) label += static_cast<char>(c);
  if (label == patientCode) return label;
  // Characters were dropped: the hash of the whole code keeps "P-01" apart from "P01".
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", fnv1a32(patientCode));
  return label + "h" + hex;
}

std::string bidsLabel(const std::string& text) {
  std::string out;
  for (unsigned char c : text)
    if (c < 128 && std::isalnum(c)) out += static_cast<char>(c);
  if (out.empty())
    throw std::invalid_argument("\"" + text + "\" has no letter or digit to make a BIDS label");
  return out;
}

BidsExportResult writeBidsMotion(const fs::path& root, const Recording* recording,
                                 const AngleSeries* angles, Side side, const BidsOptions& options,
                                 const TrunkColumns* trunk) {
  for (const auto& [what, label] :
       {std::pair<const char*, const std::string*>{"subject", &options.subject},
        {"task", &options.task}}) {
    if (label->empty() || bidsLabel(*label) != *label)
      throw std::invalid_argument(std::string("BIDS ") + what + " label \"" + *label +
                                  "\" must be letters and digits only");
  }
  if (!options.session.empty() && bidsLabel(options.session) != options.session)
    throw std::invalid_argument("BIDS session label \"" + options.session +
                                "\" must be letters and digits only");
  if (angles && angles->angle.size() != angles->t.size())
    throw std::invalid_argument("BIDS export: " + std::to_string(angles->t.size()) + " times but " +
                                std::to_string(angles->angle.size()) + " angle rows");
  if (trunk && trunk->angleRad.empty()) trunk = nullptr;
  if (trunk && (!angles || trunk->angleRad.size() != angles->t.size()))
    throw std::invalid_argument("BIDS export: " + std::to_string(trunk->angleRad.size()) +
                                " trunk rows for " + std::to_string(angles ? angles->t.size() : 0) +
                                " angle rows");

  BidsExportResult result;
  std::vector<System> systems;
  if (recording) {
    systems.push_back(imuSystem(*recording, side));
    systems.push_back(opticalSystem(*recording, side));
  }
  if (angles) systems.push_back(angleSystem(*angles, trunk, side, result.skippedAngleRows));
  std::vector<System> kept;
  for (System& s : systems) {
    if (s.rows.size() >= 2) {
      kept.push_back(std::move(s));
    } else if (!s.rows.empty()) {
      result.notes.push_back("tracksys-" + s.label +
                             " left out: a single sample has no sampling frequency");
    }
  }
  if (kept.empty())
    throw ExportError(root, "nothing to export: no tracking system has two or more samples");

  fs::path dir = root / ("sub-" + options.subject);
  std::string prefix = "sub-" + options.subject;
  if (!options.session.empty()) {
    dir /= "ses-" + options.session;
    prefix += "_ses-" + options.session;
  }
  dir /= "motion";
  prefix += "_task-" + options.task;
  result.motionDir = dir;

  // Rates and time order, before anything is created.
  struct Timing {
    double first, nominal, effective, duration;
  };
  std::vector<Timing> timing;
  for (const System& s : kept) {
    std::vector<double> dt;
    dt.reserve(s.rows.size());
    for (std::size_t k = 1; k < s.rows.size(); ++k) {
      const double d = s.time(s.rows[k]) - s.time(s.rows[k - 1]);
      // Equal times are kept (a live session's synchroniser can give two readings one time;
      // the latency channel shows it); a time that goes back is refused.
      if (!(d >= 0))
        throw ExportError(dir / (prefix + "_tracksys-" + s.label + "_motion.tsv"),
                          "time goes back at sample " + std::to_string(s.rows[k] + 1));
      if (d > 0) dt.push_back(d);
    }
    if (dt.empty())
      throw ExportError(dir / (prefix + "_tracksys-" + s.label + "_motion.tsv"),
                        "every sample has the same time; a rate cannot be given");
    std::nth_element(dt.begin(), dt.begin() + dt.size() / 2, dt.end());
    double nominal = 1.0 / dt[dt.size() / 2];
    if (std::abs(nominal - std::round(nominal)) < 1e-3 * nominal) nominal = std::round(nominal);
    const double first = s.time(s.rows.front());
    const double duration = s.time(s.rows.back()) - first;
    timing.push_back({first, nominal, (s.rows.size() - 1) / duration, duration});
  }

  // Every file of the export and whose data the subject holds, checked before anything is
  // created: no existing file is replaced without overwrite, no subject of another patient is
  // added to, and the caller may refuse a path (the open database).
  const std::string code = options.patientCode.empty() ? options.subject : options.patientCode;
  if (std::any_of(code.begin(), code.end(), [](unsigned char c) { return c < 32 || c == 127; }))
    throw std::invalid_argument("patient code \"" + code +
                                "\" has a control character, which participants.tsv cannot hold");
  const std::string participants = claimSubject(root, "sub-" + options.subject, code);
  const fs::path description = root / "dataset_description.json";
  const fs::path participantsJson = root / "participants.json";
  std::vector<fs::path> planned;
  if (!participants.empty()) planned.push_back(root / "participants.tsv");
  if (!present(participantsJson)) planned.push_back(participantsJson);
  if (!present(description)) planned.push_back(description);
  for (const System& s : kept) {
    const std::string base = prefix + "_tracksys-" + s.label;
    for (const char* kind : {"_channels.tsv", "_channels.json", "_motion.json", "_motion.tsv"}) {
      if (std::string(kind) == "_channels.json" && s.label != "imu" && s.label != "optical")
        continue;  // only systems with reference frames have one
      const fs::path file = dir / (base + kind);
      if (!options.overwrite && present(file))
        throw ExportError(file,
                          "exists; nothing was written: export with overwrite (armtrack-cli "
                          "export --overwrite) to replace this subject's files of this session, "
                          "or choose another folder");
      planned.push_back(file);
    }
  }
  if (options.checkTarget)
    for (const fs::path& file : planned) options.checkTarget(file);

  CreatedDirs created;
  makeDirs(dir, created);
  exportdetail::FileSet files;
  if (!participants.empty()) files.write(files.add(root / "participants.tsv"), participants);
  if (!present(participantsJson)) {
    ordered_json pj;
    pj["participant_id"]["Description"] = "the subject's label";
    pj["patient_code"]["Description"] =
        "the ArmTrack patient code whose data the subject's folder holds (n/a: not exported by "
        "ArmTrack)";
    files.write(files.add(participantsJson), pj.dump(2) + "\n");
  }
  if (!present(description)) {
    ordered_json d;
    d["Name"] = "ArmTrack export";
    d["BIDSVersion"] = "1.9.0";
    d["DatasetType"] = "raw";
    d["GeneratedBy"] = ordered_json::array({{{"Name", "ArmTrack"}}});
    files.write(files.add(description), d.dump(2) + "\n");
  }

  for (std::size_t k = 0; k < kept.size(); ++k) {
    const System& s = kept[k];
    const Timing& tm = timing[k];
    BidsTrackingSystemFiles out;
    out.label = s.label;
    const std::string base = prefix + "_tracksys-" + s.label;
    out.motionTsv = dir / (base + "_motion.tsv");
    out.motionJson = dir / (base + "_motion.json");
    out.channelsTsv = dir / (base + "_channels.tsv");
    out.channelsJson = dir / (base + "_channels.json");
    out.rows = s.rows.size();
    out.channels = s.channels.size() + 1;

    // channels.tsv: LATENCY first, then the data channels, in motion.tsv's column order.
    std::string ch = "name\tcomponent\ttype\ttracked_point\tunits\treference_frame\tdescription\n";
    ch += "latency\tn/a\tLATENCY\tn/a\ts\tn/a\ttime since this system's first sample\n";
    std::map<std::string, int> typeCount{{"LATENCY", 1}};
    std::set<std::string> points;
    for (const Channel& c : s.channels) {
      ch += c.name + "\t" + c.component + "\t" + c.type + "\t" + c.trackedPoint + "\t" + c.units +
            "\t" + tsvCell(c.referenceFrame) + "\t" + c.description + "\n";
      ++typeCount[c.type];
      points.insert(c.trackedPoint);
    }
    files.write(files.add(out.channelsTsv), ch);

    ordered_json cj;
    ordered_json levels;
    if (s.label == "imu")
      levels["sensor"]["Description"] =
          "the IMU's own axes as the sensor reports them (for a left arm, as recorded)";
    if (s.label == "optical" && s.channels.front().referenceFrame == "shoulder")
      levels["shoulder"]["Description"] =
          "ArmTrack's shoulder frame, fixed to the trunk with its origin at the shoulder joint: "
          "x down, y forward, z to the patient's right (docs/arm-model.md)";
    if (s.label == "optical" && s.channels.front().referenceFrame == "world")
      levels["world"]["Description"] =
          "ArmTrack's world frame: the shoulder frame as it was with the trunk upright at the "
          "start (origin at the shoulder joint then; x down, y forward, z to the patient's "
          "right), fixed while the trunk moves (docs/recording-format.md, \"Trunk\")";
    if (!levels.empty()) {
      cj["reference_frame"]["Description"] = "frame the channel's axes belong to";
      cj["reference_frame"]["Levels"] = levels;
      files.write(files.add(out.channelsJson), cj.dump(2) + "\n");
    } else {
      out.channelsJson.clear();
    }

    ordered_json mj;
    mj["TaskName"] = options.taskName.empty() ? options.task : options.taskName;
    if (!options.taskDescription.empty()) mj["TaskDescription"] = options.taskDescription;
    mj["TrackingSystemName"] = s.trackingSystemName;
    mj["SamplingFrequency"] = tm.nominal;
    mj["SamplingFrequencyEffective"] = tm.effective;
    mj["RecordingDuration"] = tm.duration;
    mj["MotionChannelCount"] = out.channels;
    for (const auto& [type, n] : typeCount) mj[type + "ChannelCount"] = n;
    mj["TrackedPointsCount"] = points.size();
    mj["MissingValues"] = "n/a";
    mj["SubjectArtefactDescription"] = "n/a";
    mj["SoftwareVersions"] = "ArmTrack";
    files.write(files.add(out.motionJson), mj.dump(2) + "\n");

    const std::size_t f = files.add(out.motionTsv);
    std::string& buf = files.buffer(f);
    std::vector<double> v(s.channels.size());
    for (std::size_t i : s.rows) {
      appendFixed(buf, s.time(i) - tm.first, 6);
      s.fill(i, v);
      for (double x : v) {
        buf += '\t';
        if (!std::isfinite(x)) {
          buf += "n/a";
          ++out.missingValues;
        } else if (s.angleDecimals >= 0) {
          appendFixed(buf, x, s.angleDecimals);
        } else {
          appendShortest(buf, x);
        }
      }
      buf += '\n';
      files.maybeFlush(f);
    }
    result.systems.push_back(std::move(out));
  }
  files.commit();
  created.keep = true;
  return result;
}

}  // namespace armtrack
