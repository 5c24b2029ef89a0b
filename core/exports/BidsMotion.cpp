// BIDS motion export (docs/exports.md, "BIDS motion"; BIDS 1.9, modality-specific files: motion).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
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

System imuSystem(const Recording& rec, Side side) {
  System s;
  s.label = "imu";
  s.trackingSystemName = "ArmTrack IMUs (upper arm and forearm)";
  const std::string sw = sideWord(side);
  addXyz(s, "upperarm_gyro", "GYRO", sw + "UpperArm", "rad/s", "sensor",
         "upper-arm IMU angular velocity");
  addXyz(s, "upperarm_acc", "ACCEL", sw + "UpperArm", "m/s^2", "sensor",
         "upper-arm IMU specific force");
  addXyz(s, "forearm_gyro", "GYRO", sw + "Forearm", "rad/s", "sensor",
         "forearm IMU angular velocity");
  addXyz(s, "forearm_acc", "ACCEL", sw + "Forearm", "m/s^2", "sensor",
         "forearm IMU specific force");
  for (std::size_t i = 0; i < rec.samples.size(); ++i)
    if (rec.samples[i].hasImu() && std::isfinite(rec.samples[i].t)) s.rows.push_back(i);
  s.time = [&rec](std::size_t i) { return rec.samples[i].t; };
  s.fill = [&rec](std::size_t i, std::vector<double>& v) {
    const ArmSample& a = rec.samples[i];
    std::fill(v.begin(), v.end(), NAN);
    int k = 0;
    for (const auto* imu : {&a.upperArm, &a.forearm}) {
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

System opticalSystem(const Recording& rec, Side side) {
  System s;
  s.label = "optical";
  s.trackingSystemName = "Optical elbow and wrist positions (Kinect)";
  const std::string sw = sideWord(side);
  addXyz(s, "elbow_pos", "POS", sw + "Elbow", "m", "shoulder", "elbow position");
  addXyz(s, "wrist_pos", "POS", sw + "Wrist", "m", "shoulder", "wrist position");
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    const ArmSample& a = rec.samples[i];
    if ((a.elbow || a.wrist) && std::isfinite(a.t)) s.rows.push_back(i);
  }
  s.time = [&rec](std::size_t i) { return rec.samples[i].t; };
  s.fill = [&rec](std::size_t i, std::vector<double>& v) {
    const ArmSample& a = rec.samples[i];
    std::fill(v.begin(), v.end(), NAN);
    for (int j = 0; j < 3; ++j) {
      if (a.elbow) v[j] = (*a.elbow)(j);
      if (a.wrist) v[3 + j] = (*a.wrist)(j);
    }
  };
  return s;
}

System angleSystem(const AngleSeries& series, Side side, std::size_t& skipped) {
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
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    if (std::isfinite(series.t[i]))
      s.rows.push_back(i);
    else
      ++skipped;
  }
  s.time = [&series](std::size_t i) { return series.t[i]; };
  s.fill = [&series](std::size_t i, std::vector<double>& v) {
    for (int a = 0; a < kNumClinicalAngles; ++a) v[a] = series.angle[i][a] * kRadToDeg;
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

void makeDirs(const fs::path& dir, CreatedDirs& created) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && ec)
      throw ExportError(*it, "cannot create the folder: " + ec.message());
    created.dirs.push_back(*it);
  }
  if (!fs::is_directory(dir, ec)) throw ExportError(dir, "is not a folder");
}

}  // namespace

std::string bidsLabel(const std::string& text) {
  std::string out;
  for (unsigned char c : text)
    if (c < 128 && std::isalnum(c)) out += static_cast<char>(c);
  if (out.empty())
    throw std::invalid_argument("\"" + text + "\" has no letter or digit to make a BIDS label");
  return out;
}

BidsExportResult writeBidsMotion(const fs::path& root, const Recording* recording,
                                 const AngleSeries* angles, Side side, const BidsOptions& options) {
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

  BidsExportResult result;
  std::vector<System> systems;
  if (recording) {
    systems.push_back(imuSystem(*recording, side));
    systems.push_back(opticalSystem(*recording, side));
  }
  if (angles) systems.push_back(angleSystem(*angles, side, result.skippedAngleRows));
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

  CreatedDirs created;
  makeDirs(dir, created);
  exportdetail::FileSet files;
  const fs::path description = root / "dataset_description.json";
  std::error_code ec;
  if (!fs::exists(description, ec)) {
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
    if (s.label == "optical")
      levels["shoulder"]["Description"] =
          "ArmTrack's shoulder frame, fixed to the trunk with its origin at the shoulder joint: "
          "x down, y forward, z to the patient's right (docs/arm-model.md)";
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
