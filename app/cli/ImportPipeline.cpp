#include "app/cli/ImportPipeline.h"

#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/estimation/RecordingEstimator.h"

namespace armtrack::cli {

namespace {

/// The chunks stored and not yet estimated, bounded so that a slow estimator holds the import
/// back instead of the memory growing (32 chunks: about 32 s at 1 kHz, 11 MB).
class ChunkQueue {
 public:
  /// Waits while the queue is full. Once the analysis has stopped (it failed: the session's
  /// analysis stays pending) the chunks are not kept: the import goes on without it.
  void push(qint64 id, std::span<const ArmSample> samples) {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [&] { return m_chunks.size() < kCapacity || m_stopped; });
    if (m_stopped) return;
    m_id = id;
    m_chunks.emplace_back(samples.begin(), samples.end());
    m_changed.notify_all();
  }
  /// The next chunk, or false once the import has ended and everything was taken.
  bool pop(std::vector<ArmSample>& chunk) {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [&] { return !m_chunks.empty() || m_ended; });
    if (m_chunks.empty()) return false;
    chunk = std::move(m_chunks.front());
    m_chunks.pop_front();
    m_changed.notify_all();
    return true;
  }
  /// The session id, once the first chunk is stored; 0 when the import ended without one.
  qint64 waitForId() {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [&] { return m_id != 0 || m_ended; });
    return m_id;
  }
  /// The import has ended (failed: the analysis is to be abandoned).
  void end(bool failed) {
    const std::lock_guard lock(m_mutex);
    m_ended = true;
    m_failed = failed;
    m_changed.notify_all();
  }
  bool failed() {
    const std::lock_guard lock(m_mutex);
    return m_failed;
  }
  /// The analysis has ended: the import no longer waits for it.
  void stop() {
    const std::lock_guard lock(m_mutex);
    m_stopped = true;
    m_chunks.clear();
    m_changed.notify_all();
  }

 private:
  static constexpr std::size_t kCapacity = 32;
  std::mutex m_mutex;
  std::condition_variable m_changed;
  std::deque<std::vector<ArmSample>> m_chunks;
  qint64 m_id = 0;
  bool m_ended = false, m_failed = false, m_stopped = false;
};

}  // namespace

PipelinedImport importAndAnalyse(ClinicalContext& c, const std::string& csv,
                                 const QString& patientCode, const QString& protocolName,
                                 std::ostream& err) {
  PipelinedImport out;
  if (c.store().user().role == storage::Role::Home) {
    out.id = c.store().importRecording(csv, patientCode, protocolName, &out.report);
    return out;
  }
  ChunkQueue queue;
  std::thread analyst([&] {
    try {
      const qint64 id = queue.waitForId();
      if (id == 0) return;  // nothing was stored
      ClinicalContext::Connection connection = c.connectAgain();
      storage::AnalysisOptions options;
      options.samples = [&](const std::function<bool(std::span<const ArmSample>)>& consume) {
        std::vector<ArmSample> chunk;
        while (queue.pop(chunk))
          if (!consume(chunk)) return false;
        if (queue.failed()) throw std::runtime_error("the import failed");
        return true;
      };
      out.analysis = storage::analyseSession(*connection.store, id, options);
    } catch (...) {
      out.analysisError = std::current_exception();
    }
    queue.stop();
  });

  // Progress by the part of the file read, for files long enough to wait for.
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(csv, ec);
  const bool reporting = !ec && bytes > kProgressRows * 300;
  int nextPercent = 10;
  try {
    out.id = c.store().importRecording(
        csv, patientCode, protocolName, &out.report,
        [&](qint64 id, std::span<const ArmSample> samples, double fraction) {
          queue.push(id, samples);
          for (; reporting && fraction * 100 >= nextPercent && nextPercent < 100; nextPercent += 10)
            err << "progress: " << nextPercent << "%\n";
        });
  } catch (...) {
    queue.end(/*failed=*/true);
    analyst.join();
    throw;
  }
  queue.end(/*failed=*/false);
  analyst.join();
  if (reporting) err << "progress: 100%\n";
  return out;
}

}  // namespace armtrack::cli
