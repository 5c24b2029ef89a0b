// The trunk's angles in the clinical records (issue 26): a session with a sternum IMU keeps the
// estimated trunk angles with its estimates and exports them in the clinical CSV, the same numbers
// `estimate --out` writes of its recording; a database written before (schema version 8, a copy
// in tests/data/storage) migrates, and its sessions export the same bytes as the build that wrote
// it exported, until a session is estimated again.
#include <gtest/gtest.h>

#include <QFile>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <sstream>

#include "core/io/Recording.h"
#include "core/storage/Schema.h"
#include "tests/app/StorageCliFixture.h"
#include "tests/support/FileInspection.h"
#include "tests/support/LeaningPatient.h"

namespace armtrack::test {
namespace {

namespace fs = std::filesystem;

const fs::path kOldData = fs::path(ARMTRACK_SOURCE_DIR) / "tests/data/storage";

/// A CSV file as its header's names and its rows' cells (text).
struct Csv {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> rows;
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return static_cast<int>(i);
    return -1;
  }
};

std::vector<std::string> cellsOf(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

Csv readCsv(const fs::path& p) {
  Csv csv;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (csv.names.empty())
      csv.names = cellsOf(line);
    else
      csv.rows.push_back(cellsOf(line));
  }
  return csv;
}

// An empty cell is NaN.
double numberOf(const std::string& cell) {
  return cell.empty() ? std::nan("") : std::strtod(cell.c_str(), nullptr);
}

class TrunkExportCli : public CliFixture {
 protected:
  void SetUp() override { init(Engine::Sqlite); }
};

// A simulated session whose patient leans with each reach, with a sternum IMU: imported (and so
// analysed) into the records, read back and exported as CSV, its trunk columns are the estimator's
// own, as `estimate --out` writes them for the same recording (rad there, deg here), row for row;
// the BIDS and OpenSim exports carry the same numbers.
TEST_F(TrunkExportCli, TrunkAnglesAreStoredAndExportedAsEstimated) {
  const Recording rec = leaningReaches(12, 841);
  writeRecording(path("lean.csv"), rec);
  const Result estimated = cli({"estimate", path("lean.csv"), "--out", path("est.csv")});
  ASSERT_EQ(estimated.code, 0) << estimated.err;
  ASSERT_EQ(run({"patient", "add", "--code", "P01", "--name", "Name P01"}).code, 0);
  const std::string id = importFor("P01", path("lean.csv"));
  const Result exported = run({"export", id, "--format", "csv", "--out", path("angles.csv")});
  ASSERT_EQ(exported.code, 0) << exported.err;

  const Csv est = readCsv(path("est.csv"));
  const Csv out = readCsv(path("angles.csv"));
  const char* keys[] = {"trunk_flex", "trunk_lat", "trunk_rot"};
  // The columns after the arm's, only these.
  ASSERT_EQ(out.names.size(), 17u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(out.names[11 + k], std::string(keys[k]) + "_deg");
    EXPECT_EQ(out.names[14 + k], std::string(keys[k]) + "_sd_deg");
  }
  // The estimator's rows by time (the export writes times to the microsecond).
  std::map<long long, const std::vector<std::string>*> byTime;
  for (const auto& row : est.rows) byTime[std::llround(numberOf(row[0]) * 1e6)] = &row;
  ASSERT_GT(out.rows.size(), 1500u);
  std::size_t measured = 0;
  for (const auto& row : out.rows) {
    ASSERT_EQ(row.size(), out.names.size()) << row[0];
    const auto it = byTime.find(std::llround(numberOf(row[0]) * 1e6));
    ASSERT_NE(it, byTime.end()) << "no estimate at " << row[0];
    for (int k = 0; k < 3; ++k)
      for (const bool sd : {false, true}) {
        const int e = est.column((sd ? "sd_" : "") + std::string(keys[k]));
        ASSERT_GE(e, 0) << keys[k];
        const double want =
            numberOf((*it->second)[static_cast<std::size_t>(e)]) * 180.0 / std::numbers::pi;
        const double got = numberOf(row[static_cast<std::size_t>(11 + k + (sd ? 3 : 0))]);
        if (std::isnan(want)) {
          EXPECT_TRUE(std::isnan(got)) << row[0] << " " << keys[k];
          continue;
        }
        EXPECT_NEAR(got, want, 0.6e-6) << row[0] << " " << keys[k] << (sd ? " sd" : "");
        if (!sd && k == 0) ++measured;
      }
  }
  EXPECT_EQ(measured, out.rows.size());  // a sternum IMU measures every row
  // The patient leaned: the exported flexion reaches the simulated lean.
  double largest = 0;
  for (const auto& row : out.rows) largest = std::max(largest, numberOf(row[11]));
  EXPECT_NEAR(largest, trueLeanDeg(rec), 1.5);

  // The BIDS export's estimated angles carry the same three trunk channels, row for row.
  const Result bids = run({"export", id, "--format", "bids", "--out", path("bids")});
  ASSERT_EQ(bids.code, 0) << bids.err;
  fs::path channelsTsv, motionTsv;
  for (const auto& e : fs::recursive_directory_iterator(path("bids"))) {
    const std::string name = e.path().filename().string();
    if (name.ends_with("tracksys-angles_channels.tsv")) channelsTsv = e.path();
    if (name.ends_with("tracksys-angles_motion.tsv")) motionTsv = e.path();
  }
  ASSERT_FALSE(channelsTsv.empty());
  ASSERT_FALSE(motionTsv.empty());
  std::vector<std::string> channels;
  {
    std::ifstream in(channelsTsv);
    std::string line;
    std::getline(in, line);  // the header
    while (std::getline(in, line)) channels.push_back(line.substr(0, line.find('\t')));
  }
  // After the arm's five angles (the motion file's columns are the channels in order).
  std::size_t column[3] = {};
  for (int k = 0; k < 3; ++k) {
    const auto at = std::find(channels.begin(), channels.end(), keys[k]);
    ASSERT_NE(at, channels.end()) << keys[k];
    column[k] = static_cast<std::size_t>(at - channels.begin());
    EXPECT_EQ(channels[column[k] - 1 - k], "forearm_pronation");
  }
  std::ifstream motion(motionTsv);
  std::string line;
  std::size_t row = 0;
  while (std::getline(motion, line)) {
    ASSERT_LT(row, out.rows.size());
    std::vector<std::string> cells;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, '\t');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), channels.size()) << line;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(numberOf(cells[column[k]]), numberOf(out.rows[row][11 + k]), 1e-6) << line;
    ++row;
  }
  EXPECT_EQ(row, out.rows.size());

  // The OpenSim export carries them as the model's lumbar coordinates (docs/exports.md):
  // extension is the negative of the flexion, bending and rotation the same, row for row.
  const Result mot = run({"export", id, "--format", "mot", "--out", path("angles.mot")});
  ASSERT_EQ(mot.code, 0) << mot.err;
  std::ifstream motIn(path("angles.mot"));
  while (std::getline(motIn, line) && line != "endheader") {
  }
  ASSERT_TRUE(std::getline(motIn, line));
  EXPECT_EQ(line,
            "time\tarm_flex_r\tarm_add_r\tarm_rot_r\telbow_flex_r\tpro_sup_r\tlumbar_extension"
            "\tlumbar_bending\tlumbar_rotation");
  row = 0;
  while (std::getline(motIn, line)) {
    ASSERT_LT(row, out.rows.size());
    std::vector<double> cells;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, '\t');) cells.push_back(numberOf(cell));
    ASSERT_EQ(cells.size(), 9u) << line;
    EXPECT_NEAR(cells[0], numberOf(out.rows[row][0]), 1e-6) << line;
    EXPECT_NEAR(cells[6], -numberOf(out.rows[row][11]), 1e-6) << line;
    EXPECT_NEAR(cells[7], numberOf(out.rows[row][12]), 1e-6) << line;
    EXPECT_NEAR(cells[8], numberOf(out.rows[row][13]), 1e-6) << line;
    ++row;
  }
  EXPECT_EQ(row, out.rows.size());  // every row has the trunk: none left out
}

// A schema version 8 database (written by main's build before the trunk's angles were stored):
// refused until migrated, then both its sessions export what that build exported, byte for byte
// (no trunk columns: the estimates were made without them). The session with a sternum IMU,
// estimated again, gains the trunk's columns while its arm columns stay where they were.
TEST_F(TrunkExportCli, OldDatabaseMigratesAndExportsAsBefore) {
  const fs::path db = path("old.db");
  fs::copy_file(kOldData / "v8_sessions.db", db);
  fs::permissions(db, fs::perms::owner_read | fs::perms::owner_write);
  m_db = db.string();
  const Result refused = run({"export", "1", "--format", "csv", "--out", path("no.csv")});
  EXPECT_NE(refused.code, 0);
  EXPECT_NE(refused.err.find("db migrate"), std::string::npos) << refused.err;
  const Result migrated = run({"db", "migrate"});
  ASSERT_EQ(migrated.code, 0) << migrated.err;
  EXPECT_NE(
      migrated.out.find(std::to_string(storage::latestSchemaVersion() - 8) + " step(s) applied"),
      std::string::npos)
      << migrated.out;

  for (const auto& [id, name] : {std::pair{"1", "v8_arm_angles"}, {"2", "v8_lean_angles"}}) {
    const std::string target = path((std::string(name) + ".csv").c_str());
    const Result r = run({"export", id, "--format", "csv", "--out", target});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(bytesOf(target), bytesOf(kOldData / (std::string(name) + ".csv"))) << name;
    EXPECT_EQ(bytesOf(path((std::string(name) + "_metrics.csv").c_str())),
              bytesOf(kOldData / (std::string(name) + "_metrics.csv")))
        << name;
  }

  const Result again = run({"session", "reestimate", "2"});
  ASSERT_EQ(again.code, 0) << again.err;
  ASSERT_EQ(run({"export", "2", "--format", "csv", "--out", path("new.csv")}).code, 0);
  const Csv before = readCsv(kOldData / "v8_lean_angles.csv");
  const Csv after = readCsv(path("new.csv"));
  ASSERT_EQ(after.names.size(), 17u);
  EXPECT_EQ(std::vector<std::string>(after.names.begin(), after.names.begin() + 11), before.names);
  EXPECT_EQ(after.names[11], "trunk_flex_deg");
  ASSERT_EQ(after.rows.size(), before.rows.size());
  for (std::size_t i = 0; i < after.rows.size(); ++i) {
    ASSERT_EQ(after.rows[i].size(), 17u);
    // The same rows and times; the arm's angles as the build before estimated them, within
    // what the estimator has changed since (the trunk's pose uncertainty now widens the arm's
    // sd, and the hip is fitted from the arm's points: docs/estimator.md, "Trunk").
    EXPECT_EQ(after.rows[i][0], before.rows[i][0]) << "row " << i;
    for (int k = 1; k <= 5; ++k)
      EXPECT_NEAR(std::stod(after.rows[i][k]), std::stod(before.rows[i][k]), 0.25)
          << "row " << i << " " << before.names[k];
    for (int k = 6; k <= 10; ++k) EXPECT_GT(std::stod(after.rows[i][k]), 0.0) << "row " << i;
    EXPECT_FALSE(after.rows[i][11].empty()) << "row " << i;
  }
}

}  // namespace
}  // namespace armtrack::test
