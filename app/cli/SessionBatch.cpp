#include "app/cli/SessionBatch.h"

#include <QJsonDocument>
#include <algorithm>
#include <chrono>
#include <memory>

#include "app/cli/Batch.h"
#include "app/cli/Text.h"

namespace armtrack::cli {

int reestimateSessions(ClinicalContext& c, const std::vector<qint64>& ids, unsigned threads,
                       const storage::AnalysisOptions& options, std::ostream& out,
                       std::ostream& err) {
  std::vector<BatchJob> jobs(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    jobs[i].name = "session " + std::to_string(ids[i]);
    try {
      jobs[i].weight =
          static_cast<std::uint64_t>(std::max<qint64>(c.store().session(ids[i]).sampleRows, 1));
    } catch (const storage::StorageError&) {
      // Reported by the job itself.
    }
  }
  std::vector<storage::AnalysisResult> results(ids.size());
  std::vector<QString> patients(ids.size());
  std::vector<qint64> rows(ids.size(), -1);
  const bool overrides = options.filter || options.model || options.noOptical;
  const auto start = std::chrono::steady_clock::now();

  const BatchWorkFactory makeWork = [&]() -> BatchWork {
    // One connection per pool thread, made and closed on it.
    auto connection = std::make_shared<ClinicalContext::Connection>(c.connectAgain());
    return [&, connection](std::size_t i, const BatchProgress& progress) {
      storage::ClinicalStore& store = *connection->store;
      const storage::SessionInfo info = store.session(ids[i]);
      patients[i] = info.patientCode;
      rows[i] = info.sampleRows;
      storage::AnalysisOptions o = options;
      o.progress = [&progress](int percent) { progress(percent / 100.0); };
      results[i] = storage::analyseSession(store, ids[i], o);
      if (overrides)
        store.updateSessionFilterSettings(
            ids[i], QString::fromUtf8(QJsonDocument(storage::filterSettingsJson(results[i].settings,
                                                                                info.filterJson))
                                          .toJson(QJsonDocument::Compact)));
    };
  };
  const std::vector<BatchOutcome> outcomes =
      runBatch(jobs, threads, makeWork, BatchDisplay{&err, isTerminal(err), "session reestimate"});

  out << "| session | patient | rows | estimates | optical | seconds | version | result |\n"
      << "|---:|---|---:|---:|---|---:|---:|---|\n";
  std::size_t failed = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const BatchOutcome& o = outcomes[i];
    const storage::AnalysisResult& r = results[i];
    out << "| " << ids[i] << " | " << (patients[i].isEmpty() ? "-" : tableCell(ss(patients[i])))
        << " | " << (rows[i] >= 0 ? std::to_string(rows[i]) : "-") << " | ";
    if (o.ok) {
      out << r.stats.estimates << " | " << (r.stats.opticalUsed ? "yes" : "no") << " | "
          << fixed(o.seconds, 2) << " | " << r.estimateVersion << " | ok |\n";
    } else {
      ++failed;
      out << "- | - | " << fixed(o.seconds, 2) << " | - | failed: " << tableCell(o.error) << " |\n";
    }
  }
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  err << "session reestimate: " << ids.size() - failed << " of " << ids.size()
      << " sessions re-estimated, " << failed << " failed, in " << fixed(seconds.count(), 2)
      << " s on " << std::min<std::size_t>(threads, ids.size()) << " threads\n";
  return failed > 0 ? 1 : 0;
}

}  // namespace armtrack::cli
