#include "core/reports/ReportData.h"

namespace armtrack::reports {

RomSnapshot romSnapshot(const QString& date, std::optional<qint64> sessionId,
                        const SessionMetrics& metrics) {
  RomSnapshot s;
  s.date = date;
  s.sessionId = sessionId;
  for (std::size_t a = 0; a < s.romRad.size(); ++a) s.romRad[a] = metrics.session.angle[a].romRad;
  return s;
}

ProgressSession progressSession(const storage::SessionInfo& session,
                                const SessionMetrics& metrics) {
  ProgressSession p;
  p.id = session.id;
  p.startedAt = session.startedAt;
  p.protocolName = session.protocolName;
  p.durationS = session.durationS > 0 ? session.durationS : metrics.durationS;
  p.repetitions = static_cast<int>(metrics.repetitions.repetitions.size());
  for (std::size_t a = 0; a < p.romRad.size(); ++a) {
    p.romRad[a] = metrics.session.angle[a].romRad;
    p.maxRad[a] = metrics.session.angle[a].maxRad;
    p.minRad[a] = metrics.session.angle[a].minRad;
  }
  return p;
}

}  // namespace armtrack::reports
