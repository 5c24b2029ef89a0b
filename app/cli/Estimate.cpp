#include "app/cli/Estimate.h"

#include <algorithm>
#include <array>
#include <exception>
#include <stdexcept>
#include <thread>
#include <vector>

#include "app/cli/Handoff.h"
#include "app/cli/Text.h"

namespace armtrack::cli {

namespace {

constexpr const char* kJointLabels[kNumJoints] = {
    "th0 shoulder flexion/extension", "th1 shoulder abduction/adduction",
    "th2 shoulder internal/external rotation", "th4 elbow flexion/extension",
    "th5 forearm pronation/supination"};

}  // namespace

FilterKind parseFilter(const Args& a) {
  const auto v = a.value("--filter");
  if (!v || *v == "ekf" || *v == "EKF") return FilterKind::Ekf;
  if (*v == "ukf" || *v == "UKF") return FilterKind::Ukf;
  a.fail("--filter: expected ekf or ukf, got " + inQuotes(*v));
}

EstimatorParams makeParams(const RecordingMeta& meta, const EstimateOptions& options) {
  return estimatorParamsFor(meta, options);
}

namespace {

/// The values of one output row after its time, as CsvOutput::row takes them.
/// The trunk's six follow; a writer whose header has no trunk columns takes the first 11.
using RowValues = std::array<double, 2 * kNumJoints + 1 + 6>;

void fillValues(const EstimateRow& r, RowValues& values) {
  std::copy(r.th.data(), r.th.data() + kNumJoints, values.begin());
  std::copy(r.sd.data(), r.sd.data() + kNumJoints, values.begin() + kNumJoints);
  values[2 * kNumJoints] = r.status;
  std::copy(r.trunk.data(), r.trunk.data() + 3, values.begin() + 2 * kNumJoints + 1);
  std::copy(r.trunkSd.data(), r.trunkSd.data() + 3, values.begin() + 2 * kNumJoints + 4);
}

// Rows between two looks at the cancel flag and the progress.
constexpr std::uint64_t kCheckRows = 4096;

}  // namespace

EstimateStats estimateRecording(const Recording& recording, const EstimatorParams& params,
                                CsvOutput* writer, const EstimateProgress& progress) {
  EstimateCallbacks callbacks;
  RowValues values{};
  if (writer) {
    callbacks.row = [&](const EstimateRow& r) {
      fillValues(r, values);
      writer->row(r.t, values.data(), writer->columns() - 1);
    };
  }
  if (progress && recording.samples.size() > kProgressRows) callbacks.progress = progress;
  return armtrack::estimateRecording(recording, params, callbacks);
}

namespace {

EstimateStats estimateSerially(RecordingReader& reader, const EstimatorParams& params,
                               const Calibration* calibration, CsvOutput* writer,
                               const FileProgress& progress, const std::atomic<bool>* cancel) {
  StreamingEstimator estimator(params);
  ArmSample sample;
  EstimateRow row;
  RowValues values{};
  bool cancelled = false;
  std::uint64_t n = 0;
  while (reader.next(sample)) {
    if (calibration) applyCalibration(*calibration, sample);
    if (estimator.push(sample, row) && writer) {
      fillValues(row, values);
      writer->row(row.t, values.data(), writer->columns() - 1);
    }
    if (++n % kCheckRows == 0) {
      if (cancel && cancel->load(std::memory_order_relaxed)) {
        cancelled = true;
        break;
      }
      if (progress) progress(n, reader.bytesRead(), reader.fileSize());
    }
  }
  if (progress && !cancelled) progress(n, reader.bytesRead(), reader.bytesRead());
  EstimateStats st = estimator.stats();
  st.cancelled = cancelled;
  return st;
}

// Rows per batch between the threads of estimateOverlapped; a divisor of kCheckRows, so every
// look at the cancel flag and the progress falls on the end of a batch, where the bytes read are
// those a serial loop would see.
constexpr std::size_t kBatchRows = 1024;
static_assert(kCheckRows % kBatchRows == 0);
// Batches in flight between two threads: enough to ride out a slow read or write, and a fixed
// amount of memory (about 1.3 MB of samples, 0.4 MB of rows).
constexpr std::size_t kBatchesInFlight = 4;

struct SampleBatch {
  std::vector<ArmSample> samples;
  std::size_t count = 0;
  std::uint64_t bytesRead = 0;  // the reader's position after the batch's last row
};

struct RowBatch {
  std::vector<EstimateRow> rows;
  std::size_t count = 0;
};

/// estimateSerially with the reading and parsing in one thread, the formatting and writing in
/// another, and the filter in the caller's: the same rows in the same order, so the same bytes.
EstimateStats estimateOverlapped(RecordingReader& reader, const EstimatorParams& params,
                                 const Calibration* calibration, CsvOutput* writer,
                                 const FileProgress& progress, const std::atomic<bool>* cancel) {
  StreamingEstimator estimator(params);
  const std::uint64_t fileSize = reader.fileSize();
  Handoff<SampleBatch> in(kBatchesInFlight);
  Handoff<RowBatch> out(kBatchesInFlight);
  std::exception_ptr writeError;

  std::thread readThread([&] {
    for (;;) {
      SampleBatch* b = in.acquire();
      if (!b) return;  // the filter stopped
      b->samples.resize(kBatchRows);
      b->count = 0;
      std::exception_ptr error;
      try {
        while (b->count < kBatchRows && reader.next(b->samples[b->count])) ++b->count;
      } catch (...) {
        error = std::current_exception();  // after the rows before it, as a serial loop would
      }
      b->bytesRead = reader.bytesRead();
      const bool last = error || b->count < kBatchRows;
      in.send(b);
      if (last) {
        in.finish(error);
        return;
      }
    }
  });
  std::thread writeThread;
  if (writer) {
    writeThread = std::thread([&] {
      try {
        RowValues values{};
        while (RowBatch* b = out.receive()) {
          for (std::size_t i = 0; i < b->count; ++i) {
            fillValues(b->rows[i], values);
            writer->row(b->rows[i].t, values.data(), writer->columns() - 1);
          }
          out.release(b);
        }
      } catch (...) {
        writeError = std::current_exception();
        out.stop();
      }
    });
  }

  bool cancelled = false;
  std::uint64_t n = 0;
  std::exception_ptr error;
  RowBatch* rows = nullptr;
  try {
    EstimateRow row;
    while (!cancelled) {
      SampleBatch* b = in.receive();
      if (!b) break;
      for (std::size_t i = 0; i < b->count; ++i) {
        ArmSample& sample = b->samples[i];
        if (calibration) applyCalibration(*calibration, sample);
        if (estimator.push(sample, row) && writer) {
          if (!rows) {
            rows = out.acquire();
            if (!rows) throw std::runtime_error("the writer stopped");  // writeError says why
            rows->rows.resize(kBatchRows);
            rows->count = 0;
          }
          rows->rows[rows->count++] = row;
          if (rows->count == kBatchRows) {
            out.send(rows);
            rows = nullptr;
          }
        }
        if (++n % kCheckRows == 0) {
          if (cancel && cancel->load(std::memory_order_relaxed)) {
            cancelled = true;
            break;
          }
          if (progress) progress(n, b->bytesRead, fileSize);
        }
      }
      in.release(b);
    }
  } catch (...) {
    error = std::current_exception();
  }
  // The writer gets every row made before a stop or an error, as in a serial loop.
  if (rows) out.send(rows);
  out.finish();
  in.stop();
  readThread.join();
  if (writeThread.joinable()) writeThread.join();
  // A failed write came before anything the filter met later.
  if (writeError) std::rethrow_exception(writeError);
  if (error) std::rethrow_exception(error);
  if (progress && !cancelled) progress(n, reader.bytesRead(), reader.bytesRead());
  EstimateStats st = estimator.stats();
  st.cancelled = cancelled;
  return st;
}

}  // namespace

EstimateStats estimateStream(RecordingReader& reader, const EstimatorParams& params,
                             const Calibration* calibration, CsvOutput* writer,
                             const FileProgress& progress, const std::atomic<bool>* cancel,
                             bool overlap) {
  return overlap ? estimateOverlapped(reader, params, calibration, writer, progress, cancel)
                 : estimateSerially(reader, params, calibration, writer, progress, cancel);
}

void writeDiagnostics(std::ostream& err, const EstimateStats& st, const EstimatorParams& params) {
  const EstimatorCounters& c = st.counters;
  if (c.implausible.total() > 0) {
    err << "filter: " << c.implausible.summary() << "; " << st.predicted
        << " rows were estimated by prediction alone (status 1 in --out)\n";
  }
  if (c.rejectedTime || c.restarts || c.skippedUpdates || c.recoveries) {
    err << "filter: rejected time " << c.rejectedTime << ", restarts after gaps " << c.restarts
        << " (status 2 in --out), recoveries after losing the arm " << c.recoveries
        << " (status 3), skipped updates " << c.skippedUpdates << "\n";
  }
  if (st.estimates < st.imuRows) {
    err << "warning: " << st.imuRows - st.estimates << " of " << st.imuRows
        << " rows with IMU data got no estimate (before start-up, or in stretches of refused "
           "readings longer than "
        << shortest(params.maxGap) << " s)\n";
  }
  if (c.rejectedTrunk > 0)
    err << "trunk: " << c.rejectedTrunk
        << " trunk IMU readings or optical shoulder positions refused (not finite, beyond a "
           "sensor's range, or no sternum mounting known)\n";
  if (!st.trunkMovedSpans.empty()) {
    // The patient leaned or turned with no trunk IMU to measure it: say when, so nobody reads
    // the lean as shoulder range of motion.
    double total = 0.0, largest = 0.0;
    for (const TrunkMotionSpan& span : st.trunkMovedSpans) {
      total += span.endS - span.startS;
      largest = std::max(largest, span.maxDisplacementM);
    }
    err << "trunk: the trunk moved from its start pose with no trunk IMU to measure it, in "
        << st.trunkMovedSpans.size() << (st.trunkMovedSpans.size() == 1 ? " span" : " spans")
        << " (" << fixed(total, 1) << " s in all; the shoulder moved up to "
        << fixed(100.0 * largest, 1) << " cm):";
    constexpr std::size_t kListed = 5;
    for (std::size_t i = 0; i < st.trunkMovedSpans.size() && i < kListed; ++i)
      err << (i ? ", " : " ") << fixed(st.trunkMovedSpans[i].startS, 1) << "-"
          << fixed(st.trunkMovedSpans[i].endS, 1) << " s";
    if (st.trunkMovedSpans.size() > kListed)
      err << " and " << st.trunkMovedSpans.size() - kListed << " more";
    err << ". Shoulder angles there include the lean (status 4 in --out); a sternum IMU "
           "measures it.\n";
  }
  if (c.implausible.totalHeld() > 0)
    err << "filter: " << c.implausible.heldSummary()
        << " (the logger repeated a sensor's last value: not a new measurement)\n";
  if (c.restWindows[0] + c.restWindows[1] > 0) {
    // The gyroscope bias taken from the still moments: said, so a large one can be questioned.
    err << "filter: gyroscope bias at rest removed:";
    const char* names[2] = {" upper arm ", " forearm "};
    bool first = true;
    for (int i = 0; i < 2; ++i) {
      if (c.restWindows[i] == 0) continue;
      err << (first ? "" : ",") << names[i] << fixed(c.restBias[i].norm() / kDeg, 2)
          << " deg/s (from " << shortest(double(c.restWindows[i]) * params.restBias.windowSeconds)
          << " s of rest)";
      first = false;
    }
    err << "\n";
  }
  const std::uint64_t gatedPixels = c.rejectedOutliers - c.gatedPositions;
  if (c.gatedPositions > 0)
    err << "kinect: " << c.opticalUpdates << " positions fused, " << c.gatedPositions
        << " gated as outliers\n";
  if (c.cameraUpdates || gatedPixels || c.cameraNotVisible) {
    err << "webcam: " << c.cameraUpdates << " marker pixels fused, " << gatedPixels
        << " gated as outliers, " << c.cameraNotVisible
        << " with the marker predicted out of view\n";
  }
  if (st.truthCount == 0 && st.truthRows > 0)
    err << "estimate: no error statistics: every estimate with true angles lies in the first "
        << shortest(1.0) << " s after a (re)start, which the statistics leave out\n";
  else if (st.truthCount == 0 && st.opticalUsed)
    err << "estimate: no true angles in the recording, so no error statistics\n";
}

std::string formatReport(const EstimateStats& st) {
  std::string s;
  if (st.truthCount > 0) {
    s += "Error against the true angles (" + std::to_string(st.truthCount) +
         " samples; the first second after start-up is left out):\n\n";
    s += "| joint | RMSE (deg) | peak (deg) |\n|---|---:|---:|\n";
    for (int j = 0; j < kNumJoints; ++j) {
      s += "| " + std::string(kJointLabels[j]) + " | " + fixed(st.rmseDeg(j), 3) + " | " +
           fixed(st.peakDeg(j), 3) + " |\n";
    }
  }
  if (st.trunkTruthCount > 0) {
    constexpr const char* kTrunkLabels[3] = {"trunk flexion", "trunk lateral bending",
                                             "trunk axial rotation"};
    if (!s.empty()) s += "\n";
    s += "Error against the true trunk angles (" + std::to_string(st.trunkTruthCount) +
         " samples):\n\n| trunk angle | RMSE (deg) | peak (deg) |\n|---|---:|---:|\n";
    for (int i = 0; i < 3; ++i)
      s += "| " + std::string(kTrunkLabels[i]) + " | " + fixed(st.trunkRmseDeg(i), 3) + " | " +
           fixed(st.trunkPeakDeg(i), 3) + " |\n";
  }
  if (!st.opticalUsed) {
    if (!s.empty()) s += "\n";
    s += "No optical data: the arm's heading about the vertical is not observable from IMUs "
         "alone; shoulder angles rest on the start-pose assumption and drift with it.\n";
    if (st.truthCount > 0) {
      s += "\nRMSE (deg) early vs late, to show the drift:\n\n";
      s += "| window | th0 | th1 | th2 | th4 | th5 |\n|---|---:|---:|---:|---:|---:|\n";
      for (const auto& [name, w] :
           {std::pair{"first", &st.firstWindow}, std::pair{"last", &st.lastWindow}}) {
        if (w->count == 0) continue;  // a recording too short for two windows has one
        s += "| " + std::string(name) + " " + fixed(w->to - w->from, 1) + " s (" +
             fixed(w->from, 1) + "-" + fixed(w->to, 1) + " s) |";
        for (int j = 0; j < kNumJoints; ++j) {
          s += " " + (w->count > 0 ? fixed(w->rmseDeg(j), 3) : std::string("-")) + " |";
        }
        s += "\n";
      }
    }
  }
  return s;
}

}  // namespace armtrack::cli
