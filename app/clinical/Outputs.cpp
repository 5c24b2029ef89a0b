#include "app/clinical/Outputs.h"

#include <QDate>
#include <algorithm>

#include "core/exports/Exports.h"
#include "core/kinematics/ClinicalAngles.h"
#include "core/reports/Reports.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::clinical {

namespace {

QString dateOf(const QString& iso) {
  return iso.left(10);
}

std::string ss(const QString& s) {
  return s.toStdString();
}

QString qpath(const std::filesystem::path& p) {
  return QString::fromStdString(p.string());
}

// What every report and export checks before it writes anything, for the CLI and the GUI alike:
// no file of the open database is written over, whatever the path or --overwrite say, and the
// audit entry it owes can be written.
void checkOutput(storage::ClinicalStore& store, const std::vector<std::filesystem::path>& files,
                 const QString& what) {
  for (const std::filesystem::path& f : files) store.database().refuseOwnFile(qpath(f), what);
  store.database().requireWritable(what + " must be written to the audit log, which cannot be");
}

}  // namespace

std::array<std::optional<double>, kNumClinicalAngles> angleFieldOf(const QJsonObject& metrics,
                                                                   const char* fieldDeg) {
  std::array<std::optional<double>, kNumClinicalAngles> values{};
  const QJsonObject angles = metrics["angles"].toObject();
  for (int i = 0; i < kNumClinicalAngles; ++i) {
    const std::string_view key = clinicalAngleInfo()[static_cast<std::size_t>(i)].key;
    const QJsonValue v = angles[QString::fromUtf8(key.data(), static_cast<qsizetype>(key.size()))]
                             .toObject()[QLatin1String(fieldDeg)];
    if (v.isDouble()) values[static_cast<std::size_t>(i)] = v.toDouble() * kDegToRad;
  }
  return values;
}

std::array<std::optional<double>, kNumClinicalAngles> romOf(const QJsonObject& metrics) {
  return angleFieldOf(metrics, "rom_deg");
}

reports::SessionReportData sessionReportData(storage::ClinicalStore& store, qint64 id) {
  // What the analysis stored (its metrics and the rows they come from); an analysis made before
  // those rows were stored is computed again from its estimates.
  std::optional<storage::SessionAngles> stored = storage::storedSessionAngles(store, id);
  const storage::SessionAngles s = stored ? std::move(*stored) : storage::sessionAngles(store, id);
  reports::SessionReportData d;
  d.session = s.info;
  d.patient = store.patient(s.info.patientCode);
  if (!s.info.protocolName.isEmpty()) d.protocol = store.protocol(s.info.protocolName);
  if (s.info.therapistId && store.user().role != storage::Role::Home)
    d.therapistName = store.userName(*s.info.therapistId);
  d.side = s.side == Side::Left ? "left" : "right";
  d.angles = s.series;
  d.metrics = s.metrics;
  // The trunk's compensation as the analysis stored it, when its metrics are those of the
  // estimates reported (the same repetitions).
  if (const std::optional<QJsonObject> m = storage::latestMetricsJson(store, id);
      m && (*m)["estimate_version"].toInt() == s.version) {
    d.trunk = storage::trunkCompensationFromJson(*m);
    if (d.trunk && d.trunk->repetitions.size() != d.metrics.repetitions.repetitions.size())
      d.trunk->repetitions.clear();  // not the same repetitions: the session's values only
    const QJsonValue limit = (*m)["trunk"].toObject()["flexion_limit_deg"];
    if (limit.isDouble()) d.trunkFlexionLimitDeg = limit.toDouble();
  }
  // Times in recording time, from the first recorded row, as the review shows them.
  d.recordingStartS = store.recordingStartS(id);
  d.events =
      parseEventMarks(s.info.notes.toStdString(),
                      d.recordingStartS.value_or(s.series.t.empty() ? 0.0 : s.series.t.front()));
  // Earlier sessions of the patient with metrics, oldest first; the latest of the other arm.
  std::vector<storage::SessionInfo> all = store.listSessions(s.info.patientCode);
  std::sort(all.begin(), all.end(),
            [](const auto& x, const auto& y) { return x.startedAt < y.startedAt; });
  for (const storage::SessionInfo& e : all) {
    if (e.id == id || e.startedAt > s.info.startedAt) continue;
    const std::optional<QJsonObject> m = storage::latestMetricsJson(store, e.id);
    if (!m) continue;
    reports::RomSnapshot snap{dateOf(e.startedAt), e.id, romOf(*m)};
    if (store.recordingMeta(e.id).side == s.side)
      d.earlierSessions.push_back(snap);
    else
      d.otherSide = snap;
  }
  return d;
}

reports::ProgressReportData progressReportData(storage::ClinicalStore& store, const QString& code,
                                               const QString& from, const QString& to) {
  reports::ProgressReportData d;
  d.patient = store.patient(code);
  d.fromDate = from;
  d.toDate = to;
  d.therapistName = store.user().role == storage::Role::Home ? QString() : store.user().name;
  for (const storage::SessionInfo& e : store.listSessions(code)) {
    const QString date = dateOf(e.startedAt);
    if ((!from.isEmpty() && date < from) || (!to.isEmpty() && date > to)) continue;
    reports::ProgressSession p;
    p.id = e.id;
    p.startedAt = e.startedAt;
    p.protocolName = e.protocolName;
    p.durationS = e.durationS;
    if (const std::optional<QJsonObject> m = storage::latestMetricsJson(store, e.id)) {
      p.romRad = romOf(*m);
      p.maxRad = angleFieldOf(*m, "max_deg");
      p.minRad = angleFieldOf(*m, "min_deg");
      const QJsonValue reps = (*m)["repetitions"].toObject()["count"];
      if (reps.isDouble()) p.repetitions = reps.toInt();
      const QJsonValue trunk = (*m)["trunk"].toObject()["max_flexion_deg"];
      if (trunk.isDouble()) p.trunkFlexionDeg = trunk.toDouble();
    }
    d.sessions.push_back(p);
  }
  // No bound asked for (the patient page: all sessions): the period is the sessions' first and
  // last day, for the report's header and the audit entry, not "- to -".
  for (const reports::ProgressSession& p : d.sessions) {
    const QString date = dateOf(p.startedAt);
    if (from.isEmpty() && (d.fromDate.isEmpty() || date < d.fromDate)) d.fromDate = date;
    if (to.isEmpty() && (d.toDate.isEmpty() || date > d.toDate)) d.toDate = date;
  }
  return d;
}

int writeSessionReport(storage::ClinicalStore& store, qint64 id, const QString& pdf) {
  checkOutput(store, {pdf.toStdString()}, "the report");
  store.requireIntactRecording(id);  // a report of a damaged recording is refused, saying so
  const reports::SessionReportData d = sessionReportData(store, id);
  const int pages = reports::writeSessionReport(d, pdf);
  store.audit("export", "session", QString::number(id), "report pdf");
  return pages;
}

int writeProgressReport(storage::ClinicalStore& store, const reports::ProgressReportData& d,
                        const QString& pdf) {
  checkOutput(store, {pdf.toStdString()}, "the report");
  const int pages = reports::writeProgressReport(d, pdf);
  store.audit("export", "patient", d.patient.code,
              "progress report pdf " + d.fromDate + " to " + d.toDate);
  return pages;
}

std::optional<ExportFormat> parseExportFormat(const std::string& name) {
  if (name == "recording") return ExportFormat::Recording;
  if (name == "csv") return ExportFormat::Csv;
  if (name == "mot") return ExportFormat::Mot;
  if (name == "bids") return ExportFormat::Bids;
  return std::nullopt;
}

std::string exportFormatName(ExportFormat format) {
  switch (format) {
    case ExportFormat::Recording:
      return "recording";
    case ExportFormat::Csv:
      return "csv";
    case ExportFormat::Mot:
      return "mot";
    case ExportFormat::Bids:
      break;
  }
  return "bids";
}

ExportSummary exportSession(storage::ClinicalStore& store, qint64 id, ExportFormat format,
                            const std::filesystem::path& target, bool overwrite) {
  ExportSummary out;
  switch (format) {  // BIDS checks each of its files below, before it creates any
    case ExportFormat::Recording:
      checkOutput(store, {target, sidecarPath(target)}, "the export");
      break;
    case ExportFormat::Csv:
      checkOutput(store, {target, metricsCsvPath(target)}, "the export");
      break;
    case ExportFormat::Mot:
    case ExportFormat::Bids:
      checkOutput(store, {target}, "the export");
      break;
  }
  if (format == ExportFormat::Recording) {
    store.exportRecording(id, target);  // audits itself
    out.what = target.string();
    out.files = {target, sidecarPath(target)};
    return out;
  }
  // csv and mot come from the estimates, which outlive a damaged recording: refused as the
  // recording and bids formats are (they read the recording, which checks itself).
  if (format != ExportFormat::Bids) store.requireIntactRecording(id);
  const storage::SessionAngles s = storage::sessionAngles(store, id, storage::SeriesRows::All);
  if (format == ExportFormat::Csv) {
    // The trunk's columns when the estimates hold them (a trunk IMU or an optical shoulder).
    const TrunkColumns trunk{s.trunkRad, s.trunkSdRad};
    const CsvExportResult r = writeClinicalCsv(target, s.series, s.metrics, &s.sdRad, &trunk);
    out.what = std::to_string(r.rows) + " rows to " + r.anglesCsv.string() +
               " and its metrics to " + r.metricsCsv.string();
    out.files = {r.anglesCsv, r.metricsCsv};
  } else if (format == ExportFormat::Mot) {
    // The lumbar coordinates when the estimates hold the trunk's angles.
    const TrunkColumns trunk{s.trunkRad, {}};
    const MotExportResult r = writeOpenSimMot(target, s.series, s.side, {}, &trunk);
    out.what = std::to_string(r.rows) + " rows to " + target.string();
    if (r.skippedRows > 0)
      out.what += " (" + std::to_string(r.skippedRows) +
                  " left out: OpenSim cannot use a row with a missing value)";
    out.files = {target};
  } else {
    const Recording recording = store.readRecording(id);
    BidsOptions o;
    o.subject = bidsSubjectLabel(ss(s.info.patientCode));
    o.patientCode = ss(s.info.patientCode);
    o.overwrite = overwrite;
    o.checkTarget = [&store](const std::filesystem::path& file) {
      store.database().refuseOwnFile(qpath(file), "the export");
    };
    o.session = bidsLabel(std::to_string(id));
    o.task = bidsLabel(s.info.protocolName.isEmpty() ? std::string("armtrack")
                                                     : ss(s.info.protocolName));
    o.taskName = s.info.protocolName.isEmpty() ? "ArmTrack session" : ss(s.info.protocolName);
    const TrunkColumns trunk{s.trunkRad, {}};
    const BidsExportResult r = writeBidsMotion(target, &recording, &s.series, s.side, o, &trunk);
    out.what = std::to_string(r.systems.size()) + " tracking systems to " + r.motionDir.string();
    out.files = {r.motionDir};
    out.notes = r.notes;
  }
  store.audit("export", "session", QString::number(id),
              QString::fromStdString("format " + exportFormatName(format)));
  return out;
}

}  // namespace armtrack::clinical
