// The clinical records on SQLite and on PostgreSQL (a server started here, durable: fsync on):
// writing a 1 kHz recording of both IMUs plus the Kinect as the recorder does (one ~1 s chunk a
// transaction), its size against the open-format CSV, opening a database of 1,000 sessions and
// listing one patient's, reading a session back, and re-estimating a session read from the
// database against the same recording read from its CSV; and the time of a wrong sign-in for
// an account against one for a name without an account.
// Run: build/tests/benchmarks/bench_storage --benchmark_min_time=1
// Counters: x_real_time = recorded seconds written (or read) per second; MB_per_hour = stored
// bytes for an hour of recording; vs_csv = stored bytes / CSV bytes.
#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QTemporaryDir>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/estimation/RecordingEstimator.h"
#include "core/io/Recording.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/ClinicalStore.h"
#include "tests/support/PostgresServer.h"

namespace armtrack::storage {
namespace {

constexpr double kSeconds = 60.0;  // one minute per iteration; per hour is scaled by 60
constexpr const char* kPassword = "bench password";

enum Engine { kSqlite = 0, kPostgresSocket = 1, kPostgresTcp = 2 };

// One minute at 1 kHz: both IMUs with the paper's noise (Table 5), the Kinect at 30 Hz, no
// true angles (a clinical recording has none). CSV size from the open-format writer.
struct Minute {
  Recording rec;
  double csvBytes = 0;
  QTemporaryDir dir;
  std::filesystem::path csv;
  Minute() {
    SimulationParams sim;
    sim.duration = kSeconds;
    sim.upperArm.gyroNoiseStd = sim.forearm.gyroNoiseStd = Table5::gyroStd();
    sim.upperArm.accelNoiseStd = sim.forearm.accelNoiseStd = Table5::accelStd();
    sim.includeTruth = false;
    TrajectoryOptions options;
    options.seed = 11;
    const auto trajectory = makeTrajectory("multi-joint", options);
    csv = dir.filePath("minute.csv").toStdString();
    writeRecording(csv, simulateRecording(*trajectory, sim));
    rec = readRecording(csv);  // bit for bit what the CSV holds
    csvBytes = static_cast<double>(std::filesystem::file_size(csv));
    // The same chunks in the previous format, and the least any lossless coder can spend on
    // the IMU values: each is a smooth signal plus Gaussian noise of std sigma, so at best
    // log2(sigma / ulp) + log2(sqrt(2 pi e)) bits (the differential entropy of the noise,
    // quantised to the double's spacing).
    std::size_t begin = 0;
    const auto& samples = rec.samples;
    while (begin < samples.size()) {
      std::size_t end = begin;
      while (end < samples.size() && samples[end].t < samples[begin].t + 1.0) ++end;
      legacyBytes += static_cast<double>(
          ChunkCodec::encodeLegacy(std::span<const ArmSample>(samples.data() + begin, end - begin))
              .size());
      begin = end;
    }
    const double gauss = 0.5 * std::log2(2.0 * M_PI * M_E);
    auto bound = [&](double v, double sigma) {
      const double ulp = std::nextafter(std::fabs(v), INFINITY) - std::fabs(v);
      return std::max(0.0, std::log2(sigma / ulp) + gauss) / 8.0;
    };
    for (const ArmSample& a : samples)
      for (const auto* imu : {&a.upperArm, &a.forearm})
        if (*imu)
          for (int i = 0; i < 3; ++i)
            imuFloorBytes += bound((*imu)->gyr[i], Table5::gyroStd()) +
                             bound((*imu)->acc[i], Table5::accelStd());
  }
  double legacyBytes = 0;
  double imuFloorBytes = 0;
};

const Minute& minute() {
  static const Minute m;
  return m;
}

armtrack::test::PostgresServer& server() {
  static armtrack::test::PostgresServer s(/*durable=*/true);
  return s;
}

// A new database of the engine with an administrator and one patient, signed in.
struct Db {
  QTemporaryDir dir;
  std::unique_ptr<Database> db;
  std::unique_ptr<ClinicalStore> store;
  explicit Db(int engine) {
    static int counter = 0;
    QString url = dir.filePath("bench.db");
    if (engine != kSqlite) {
      const QString name = QString("bench%1").arg(counter++);
      url = server().createDatabase(name);
      if (engine == kPostgresTcp) {
        url = server().tcpUrl(name);
        qputenv("ARMTRACK_DB_PASSWORD", armtrack::test::PostgresServer::kPassword);
      }
    }
    db = std::make_unique<Database>(DatabaseUrl::parse(url), Database::Options{true, false});
    store = std::make_unique<ClinicalStore>(*db);
    store->initialise("admin", kPassword);
    store->signIn("admin", kPassword);
    Patient p;
    p.code = "P1";
    p.name = "Bench";
    store->addPatient(p);
  }
};

// Writes the minute as the live recorder does: one chunk per second, each its own transaction.
qint64 writeMinute(ClinicalStore& store) {
  const auto& samples = minute().rec.samples;
  const qint64 id = store.beginSession("P1", "", "{}", 0);
  std::size_t begin = 0;
  while (begin < samples.size()) {
    std::size_t end = begin;
    while (end < samples.size() && samples[end].t < samples[begin].t + 1.0) ++end;
    store.appendChunk(id, std::span<const ArmSample>(samples.data() + begin, end - begin));
    begin = end;
  }
  store.finishSession(id);
  return id;
}

void BM_WriteRecording(benchmark::State& state) {
  Db d(static_cast<int>(state.range(0)));
  qint64 stored = 0;
  for (auto _ : state) stored = d.store->session(writeMinute(*d.store)).storedBytes;
  state.counters["x_real_time"] = benchmark::Counter(
      kSeconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["MB_per_hour"] = static_cast<double>(stored) * 3600.0 / kSeconds / 1e6;
  state.counters["CSV_MB_per_hour"] = minute().csvBytes * 3600.0 / kSeconds / 1e6;
  state.counters["vs_csv"] = static_cast<double>(stored) / minute().csvBytes;
  state.counters["vs_csv_atc1"] = minute().legacyBytes / minute().csvBytes;
  state.counters["imu_floor_vs_csv"] = minute().imuFloorBytes / minute().csvBytes;
}
BENCHMARK(BM_WriteRecording)
    ->ArgName("engine")  // 0 SQLite, 1 PostgreSQL socket, 2 PostgreSQL TCP loopback
    ->Arg(kSqlite)
    ->Arg(kPostgresSocket)
    ->Arg(kPostgresTcp)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Reading a session back, the part of BM_Reestimate that differs between the sources: from its
// CSV (source 0, parsing), or its chunks from the records (1 SQLite, 2 PostgreSQL socket).
// The minute imported into a new database of source (1 SQLite, 2 PostgreSQL socket), and its
// session id; nothing for source 0 (the CSV itself).
std::pair<std::unique_ptr<Db>, qint64> importedMinute(int source) {
  if (source == 0) return {nullptr, 0};
  auto d = std::make_unique<Db>(source == 1 ? kSqlite : kPostgresSocket);
  const qint64 id = d->store->importRecording(minute().csv, "P1");
  return {std::move(d), id};
}

void BM_ReadRecording(benchmark::State& state) {
  const int source = static_cast<int>(state.range(0));
  const auto [d, id] = importedMinute(source);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        (source == 0 ? readRecording(minute().csv) : d->store->readRecording(id)).samples.size());
  state.counters["x_real_time"] = benchmark::Counter(
      kSeconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ReadRecording)
    ->ArgName("source")  // 0 CSV, 1 SQLite, 2 PostgreSQL socket
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Re-estimating a recording (EKF, Method A, Kinect fused, the library defaults) read from its
// CSV (source 0) or from the records (1 SQLite, 2 PostgreSQL socket): reading plus estimating,
// as `estimate` and `session reestimate` do; storing the estimates is not timed.
void BM_Reestimate(benchmark::State& state) {
  const int source = static_cast<int>(state.range(0));
  const auto [d, id] = importedMinute(source);
  std::size_t rows = 0;
  for (auto _ : state) {
    const Recording rec = source == 0 ? readRecording(minute().csv) : d->store->readRecording(id);
    rows = estimateRecording(rec, estimatorParamsFor(rec.meta, EstimateOptions{})).estimates;
  }
  state.counters["x_real_time"] = benchmark::Counter(
      kSeconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["estimates"] = static_cast<double>(rows);
}
BENCHMARK(BM_Reestimate)
    ->ArgName("source")  // 0 CSV, 1 SQLite, 2 PostgreSQL socket
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The minute with its IMU values as sensor `variant` delivers them (see BM_RealSensorResolution).
Recording realSensorMinute(int variant) {
  auto quantise = [variant](ImuReading& r) {
    for (int i = 0; i < 3; ++i) {
      double& g = r.gyr[i];
      double& a = r.acc[i];
      if (variant == 1) {
        const double gc = std::clamp(std::round(g / (M_PI / 180.0) * 65.5), -32768.0, 32767.0);
        g = gc / 65.5 * (M_PI / 180.0);
        const double ac = std::clamp(std::round(a * 83.0 + 2047.0), 0.0, 4095.0);
        a = (ac - 2047.0) / 83.0;
      } else if (variant == 2) {
        g = static_cast<double>(static_cast<float>(g / (M_PI / 180.0))) * (M_PI / 180.0);
        a = static_cast<double>(static_cast<float>(a / 9.80665)) * 9.80665;
      } else if (variant == 3) {
        char text[32];
        std::snprintf(text, sizeof text, "%.4f", g);
        g = std::strtod(text, nullptr);
        std::snprintf(text, sizeof text, "%.4f", a);
        a = std::strtod(text, nullptr);
      }
    }
  };
  Recording rec = minute().rec;
  for (ArmSample& a : rec.samples)
    for (auto* imu : {&a.upperArm, &a.forearm})
      if (*imu) quantise(**imu);
  return rec;
}

// Encoding the minute's chunks, the CPU the recorder spends on them: ATC2 (codec 2) against ATC3
// (codec 3, which also looks for a lattice in every column), for the simulator's full-precision
// readings (sensor 0) and a Shimmer3's (sensor 1). Counter: recorded seconds encoded per second.
void BM_EncodeChunks(benchmark::State& state) {
  const bool atc3 = state.range(0) == 3;
  const Recording rec = realSensorMinute(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    std::size_t begin = 0, bytes = 0;
    while (begin < rec.samples.size()) {
      std::size_t end = begin;
      while (end < rec.samples.size() && rec.samples[end].t < rec.samples[begin].t + 1.0) ++end;
      const std::span<const ArmSample> chunk(rec.samples.data() + begin, end - begin);
      bytes += (atc3 ? ChunkCodec::encode(chunk)
                     : ChunkCodec::encodeLegacy(chunk, ChunkCodec::kAtc2Name))
                   .size();
      begin = end;
    }
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["x_real_time"] = benchmark::Counter(
      kSeconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EncodeChunks)
    ->ArgNames({"codec", "sensor"})
    ->ArgsProduct({{2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// The same minute as real sensors would deliver it (docs/storage.md, "Size of real sensors' data"):
// each IMU value put on the sensor's own lattice by the conversion its plugin makes, the CSV
// written and the chunks encoded as the records store them. 0: full precision (the simulator);
// 1: Shimmer3 counts (gyroscope 65.5 counts per deg/s at +-500 deg/s, low-noise accelerometer
// 83 counts per m/s^2 around 2047 on a 12-bit converter, as devices/shimmer3 converts them);
// 2: NGIMU float32 (deg/s and g, converted as devices/ngimu does); 3: the DIY line protocol
// printing 4 decimals. Counters: the chunks (ATC3, and ATC2 before it) against the CSV, and the
// least a coder storing the counts as integers could spend on the IMU values (the noise's entropy
// in counts), against it.
void BM_RealSensorResolution(benchmark::State& state) {
  const int variant = static_cast<int>(state.range(0));
  constexpr double kGyroCounts = 65.5 * 180.0 / M_PI;  // counts per rad/s
  constexpr double kAccCounts = 83.0;                  // counts per m/s^2
  const Recording rec = realSensorMinute(variant);
  QTemporaryDir dir;
  const std::filesystem::path csv = dir.filePath("q.csv").toStdString();
  double stored = 0, storedAtc2 = 0;
  for (auto _ : state) {
    writeRecording(csv, rec);
    stored = storedAtc2 = 0;
    std::size_t begin = 0;
    while (begin < rec.samples.size()) {
      std::size_t end = begin;
      while (end < rec.samples.size() && rec.samples[end].t < rec.samples[begin].t + 1.0) ++end;
      const std::span<const ArmSample> chunk(rec.samples.data() + begin, end - begin);
      stored += static_cast<double>(ChunkCodec::encode(chunk).size());
      storedAtc2 +=
          static_cast<double>(ChunkCodec::encodeLegacy(chunk, ChunkCodec::kAtc2Name).size());
      begin = end;
    }
  }
  const double csvBytes = static_cast<double>(std::filesystem::file_size(csv));
  // Counts need log2(sigma_counts) + log2(sqrt(2 pi e)) bits each at best (the noise's
  // differential entropy on a unit lattice), whatever coder stores them.
  const double gauss = 0.5 * std::log2(2.0 * M_PI * M_E);
  double floorBytes = 0;
  if (variant == 1)
    for (const ArmSample& a : rec.samples)
      for (const auto* imu : {&a.upperArm, &a.forearm})
        if (*imu)
          floorBytes += 3.0 * (std::log2(Table5::gyroStd() * kGyroCounts) + gauss) / 8.0 +
                        3.0 * (std::log2(Table5::accelStd() * kAccCounts) + gauss) / 8.0;
  state.counters["CSV_MB_per_hour"] = csvBytes * 3600.0 / kSeconds / 1e6;
  state.counters["vs_csv"] = stored / csvBytes;
  state.counters["vs_csv_atc2"] = storedAtc2 / csvBytes;
  state.counters["count_floor_imu_vs_csv"] = floorBytes / csvBytes;
}
BENCHMARK(BM_RealSensorResolution)
    ->ArgName("sensor")  // 0 simulator, 1 Shimmer3 counts, 2 NGIMU float32, 3 4 decimals
    ->DenseRange(0, 3)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// Opening (SQLite: with its integrity check) and listing one patient's 20 sessions among
// 1,000 sessions of 50 patients; the Argon2id sign-in, slow on purpose, is not timed.
void BM_OpenAndListSessions(benchmark::State& state) {
  Db d(static_cast<int>(state.range(0)));
  for (int p = 2; p <= 50; ++p) {
    Patient patient;
    patient.code = QString("P%1").arg(p);
    patient.name = "Bench";
    d.store->addPatient(patient);
  }
  d.db->transaction([&] {
    for (int i = 0; i < 1000; ++i)
      d.db->exec("INSERT INTO sessions (patient_id, started_at, status) VALUES (?, ?, 'complete')",
                 {1 + i % 50, QString("2026-01-01T00:%1:00.000Z").arg(i % 60, 2, 10, QChar('0'))});
  });
  const DatabaseUrl url = d.db->url();
  d.store.reset();
  d.db.reset();
  std::size_t listed = 0;
  for (auto _ : state) {
    Database db(url, {});
    ClinicalStore store(db);
    state.PauseTiming();
    store.signIn("admin", kPassword);
    state.ResumeTiming();
    listed = store.listSessions("P7").size();
  }
  state.counters["sessions_listed"] = static_cast<double>(listed);
}
BENCHMARK(BM_OpenAndListSessions)
    ->ArgName("engine")
    ->Arg(kSqlite)
    ->Arg(kPostgresSocket)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(20);

// A wrong password for an account against the same for a name without one: the answers must
// take the same time, or the time tells which names exist (issue 24, item 12: 250-395 ms
// against 112-286 ms before). Each iteration makes one attempt of each, in alternating order,
// through the whole sign-in (lookups, Argon2id, the failure counted and audited, one commit);
// the counts are reset between attempts, untimed, so throttling never answers early. Counters:
// the median and least time of each (ms) and the median of the pairs' differences.
void BM_SignInWrongPassword(benchmark::State& state) {
  Db d(static_cast<int>(state.range(0)));
  ClinicalStore store(*d.db);
  std::vector<double> known, unknown, difference;
  const auto attempt = [&](const char* name) {
    const auto start = std::chrono::steady_clock::now();
    try {
      store.signIn(name, "a wrong password");
    } catch (const StorageError&) {
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    d.db->exec("UPDATE users SET failed_attempts = 0, last_failed_at = NULL");
    d.db->exec("DELETE FROM sign_in_failures");
    return ms;
  };
  for (auto _ : state) {
    const bool knownFirst = known.size() % 2 == 0;
    const double a = attempt(knownFirst ? "admin" : "nobody");
    const double b = attempt(knownFirst ? "nobody" : "admin");
    known.push_back(knownFirst ? a : b);
    unknown.push_back(knownFirst ? b : a);
    difference.push_back(known.back() - unknown.back());
    state.SetIterationTime((a + b) / 1e3);
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  const auto least = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
  };
  state.counters["known_median_ms"] = median(known);
  state.counters["unknown_median_ms"] = median(unknown);
  state.counters["known_min_ms"] = least(known);
  state.counters["unknown_min_ms"] = least(unknown);
  state.counters["median_difference_ms"] = median(difference);
}
BENCHMARK(BM_SignInWrongPassword)
    ->ArgName("engine")
    ->Arg(kSqlite)
    ->Arg(kPostgresSocket)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(40);

}  // namespace
}  // namespace armtrack::storage

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);  // Qt Sql finds its driver plugins through it
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  try {
    benchmark::RunSpecifiedBenchmarks();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_storage: %s\n", e.what());
    return 1;
  }
  benchmark::Shutdown();
  return 0;
}
