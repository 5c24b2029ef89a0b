// The session report (docs/reports.md, "Session report").
#include <QStringList>
#include <cmath>

#include "core/kinematics/ClinicalAngles.h"
#include "core/metrics/NormativeRanges.h"
#include "core/reports/Charts.h"
#include "core/reports/PdfOutput.h"
#include "core/reports/ReportText.h"
#include "core/reports/Reports.h"

namespace armtrack::reports {
namespace {

QString angleName(int i) {
  const auto name = clinicalAngleInfo()[static_cast<std::size_t>(i)].name;
  return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

std::optional<int> angleIndex(const QString& key) {
  for (int i = 0; i < kNumClinicalAngles; ++i) {
    const auto k = clinicalAngleInfo()[static_cast<std::size_t>(i)].key;
    if (key == QString::fromUtf8(k.data(), static_cast<qsizetype>(k.size()))) return i;
  }
  return std::nullopt;
}

QString measuredSide(const SessionReportData& d) {
  if (!d.side.isEmpty()) return d.side;
  const QString fromCalibration = jsonString(d.session.calibrationJson, QStringLiteral("side"));
  if (!fromCalibration.isEmpty()) return fromCalibration;
  return orDash(d.patient.affectedSide);
}

QString protocolText(const SessionReportData& d) {
  if (!d.protocol)
    return d.session.protocolName.isEmpty() ? QStringLiteral("none") : d.session.protocolName;
  const storage::Protocol& p = *d.protocol;
  const std::optional<int> a = angleIndex(p.angleKey);
  return QStringLiteral("%1: %2, target %3 to %4 deg, %5 repetitions")
      .arg(p.name, a ? angleName(*a) : p.angleKey, formatDeg(p.targetMinDeg),
           formatDeg(p.targetMaxDeg))
      .arg(p.repetitions);
}

void details(PageWriter& w, const SessionReportData& d) {
  w.heading(QStringLiteral("Patient and session"));
  const storage::Patient& p = d.patient;
  std::vector<std::pair<QString, QString>> items = {
      {QStringLiteral("Name"), orDash(p.name)},
      {QStringLiteral("Patient code"), orDash(p.code)},
      {QStringLiteral("Date of birth"), orDash(p.birthDate)},
      {QStringLiteral("Sex"), orDash(p.sex)},
      {QStringLiteral("Affected side"), orDash(p.affectedSide)},
      {QStringLiteral("Side measured"), measuredSide(d)},
      {QStringLiteral("Session"), QString::number(d.session.id)},
      {QStringLiteral("Date"), orDash(formatDateTime(d.session.startedAt))},
      {QStringLiteral("Duration"),
       formatDuration(d.session.durationS > 0 ? d.session.durationS : d.metrics.durationS)},
      {QStringLiteral("Therapist"), orDash(d.therapistName)},
      {QStringLiteral("Status"), orDash(d.session.status)},
      {QStringLiteral("Diagnosis"), orDash(p.diagnosis)},
  };
  w.keyValues(items);
  w.keyValues({{QStringLiteral("Protocol"), protocolText(d)}}, false);
}

void devices(PageWriter& w, const SessionReportData& d) {
  w.heading(QStringLiteral("Devices and calibration"));
  const QStringList dev = summariseJson(d.session.devicesJson);
  const QStringList cal = summariseJson(d.session.calibrationJson, 30);
  w.paragraph(QStringLiteral("Devices"), w.fonts().bold);
  w.paragraph(
      dev.isEmpty() ? QStringLiteral("No devices were recorded for this session.") : dev.join('\n'),
      w.fonts().small);
  w.paragraph(QStringLiteral("Calibration"), w.fonts().bold);
  w.paragraph(cal.isEmpty() ? QStringLiteral("No calibration was recorded for this session.")
                            : cal.join('\n'),
              w.fonts().small);
}

QString smoothness(const char* name, const SmoothnessValue& v) {
  return v.ok() ? QStringLiteral("%1 %2").arg(QLatin1String(name)).arg(v.value, 0, 'f', 2)
                : QStringLiteral("%1 not defined").arg(QLatin1String(name));
}

void metricsTable(PageWriter& w, const SessionReportData& d) {
  w.heading(QStringLiteral("Metrics per clinical angle"));
  Table t;
  t.header = {QStringLiteral("Angle"),
              QStringLiteral("Min (deg)"),
              QStringLiteral("Max (deg)"),
              QStringLiteral("ROM (deg)"),
              QStringLiteral("Peak velocity (deg/s)"),
              QStringLiteral("Mean velocity (deg/s)"),
              QStringLiteral("Moving time (s)")};
  t.widths = {0.28, 0.11, 0.11, 0.11, 0.14, 0.14, 0.11};
  for (int i = 0; i < kNumClinicalAngles; ++i) {
    const AngleMetricsDeg m = inDegrees(d.metrics.session.angle[static_cast<std::size_t>(i)]);
    t.rows.push_back({angleName(i), formatDeg(m.minDeg), formatDeg(m.maxDeg), formatDeg(m.romDeg),
                      formatDeg(m.peakVelocityDegPerS), formatDeg(m.meanVelocityDegPerS),
                      QString::number(m.movementTimeS, 'f', 1)});
  }
  w.table(t);
  w.paragraph(QStringLiteral("%1 samples used, %2 rows rejected (not finite), %3 gaps. Smoothness "
                             "of the wrist path: %4, %5.")
                  .arg(d.metrics.samples)
                  .arg(d.metrics.rejectedNonFinite)
                  .arg(d.metrics.gaps)
                  .arg(smoothness("SPARC", d.metrics.sparc), smoothness("LDLJ", d.metrics.ldlj)),
              w.fonts().small);
}

void plots(PageWriter& w, const SessionReportData& d) {
  w.heading(QStringLiteral("Joint angles over time"), 45);
  const std::optional<int> target = d.protocol ? angleIndex(d.protocol->angleKey) : std::nullopt;
  const std::size_t n = std::min(d.angles.t.size(), d.angles.angle.size());
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    std::vector<double> y(n);
    for (std::size_t i = 0; i < n; ++i)
      y[i] = d.angles.angle[i][static_cast<std::size_t>(a)] * kRadToDeg;
    std::optional<Band> band;
    if (target && *target == a)
      band =
          Band{d.protocol->targetMinDeg, d.protocol->targetMaxDeg,
               QStringLiteral("shaded: protocol target %1 to %2 deg")
                   .arg(formatDeg(d.protocol->targetMinDeg), formatDeg(d.protocol->targetMaxDeg))};
    const QRectF r = w.reserve(w.mm(44));
    // The repetitions' numbers at their peaks on the angle they were counted on ("p": partial).
    std::vector<TimeMark> marks;
    const QString title = angleName(a) + QStringLiteral(" (deg)");
    const RepetitionResult& reps = d.metrics.repetitions;
    if (a == reps.primaryAngle && !reps.repetitions.empty()) {
      for (std::size_t k = 0; k < reps.repetitions.size(); ++k)
        marks.push_back({reps.repetitions[k].peakS,
                         QString::number(k + 1) +
                             (reps.repetitions[k].partial ? QStringLiteral("p") : QString())});
    }
    drawTimePlot(w, r.adjusted(0, 0, 0, -w.mm(2)), title, d.angles.t, y, band, marks);
  }
}

void repetitions(PageWriter& w, const SessionReportData& d) {
  w.heading(QStringLiteral("Repetitions"));
  const RepetitionResult& r = d.metrics.repetitions;
  const std::size_t count = r.repetitions.size();
  if (count == 0) {
    w.paragraph(QStringLiteral("No repetitions were detected (0 repetitions)."), w.fonts().body);
    return;
  }
  const QString primary = angleName(r.primaryAngle);
  w.paragraph(QStringLiteral("%1 repetitions counted on %2: %3 full, %4 partial (judged against a "
                             "reference range of %5 deg); %6 cut by the start or end of the "
                             "recording and not counted.")
                  .arg(count)
                  .arg(primary)
                  .arg(r.fullCount)
                  .arg(r.partialCount)
                  .arg(formatDeg(r.referenceRad * kRadToDeg))
                  .arg(r.truncated),
              w.fonts().body);
  Table t;
  t.header = {QStringLiteral("#"),
              QStringLiteral("Start (s)"),
              QStringLiteral("End (s)"),
              QStringLiteral("ROM of %1 (deg)").arg(primary.toLower()),
              QStringLiteral("Peak velocity (deg/s)"),
              QStringLiteral("Partial")};
  t.widths = {0.08, 0.14, 0.14, 0.26, 0.22, 0.16};
  const double t0 = d.angles.t.empty() ? 0 : d.angles.t.front();
  for (std::size_t i = 0; i < count; ++i) {
    const Repetition& rep = r.repetitions[i];
    const AngleMetricsDeg m =
        inDegrees(rep.metrics.angle[static_cast<std::size_t>(r.primaryAngle)]);
    t.rows.push_back({QString::number(i + 1), QString::number(rep.startS - t0, 'f', 2),
                      QString::number(rep.endS - t0, 'f', 2),
                      formatDeg(rep.excursionRad * kRadToDeg), formatDeg(m.peakVelocityDegPerS),
                      rep.partial ? QStringLiteral("yes") : QStringLiteral("no")});
  }
  w.table(t);
}

void normative(PageWriter& w, const SessionReportData& d) {
  w.heading(QStringLiteral("Comparison with normative ranges"), 50);
  const auto& ranges = aaosNormativeRanges();
  std::vector<NormativeBar> bars;
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    const NormativeRange& n = ranges[static_cast<std::size_t>(a)];
    const AngleMetrics& m = d.metrics.session.angle[static_cast<std::size_t>(a)];
    NormativeBar b;
    b.name = angleName(a);
    if (n.minRad) b.normalLoDeg = *n.minRad * kRadToDeg;
    b.normalHiDeg = n.maxRad * kRadToDeg;
    b.minDeg = m.minRad * kRadToDeg;
    b.maxDeg = m.maxRad * kRadToDeg;
    b.caption =
        QStringLiteral("ROM %1 of %2 deg (%3 %)")
            .arg(formatDeg(m.romRad * kRadToDeg), formatDeg(normativeSpanRad(n) * kRadToDeg))
            .arg(std::lround(100 * fractionOfNormativeSpan(n, m.romRad)));
    bars.push_back(b);
  }
  const QRectF r = w.reserve(normativeBarsHeight(w, bars.size()));
  drawNormativeBars(w, r, bars);
  const std::string_view source = ranges[0].source;
  w.paragraph(QStringLiteral("Grey: the normal active range of motion; blue: this session's range "
                             "(negative = extension, external rotation, supination). Source: %1. "
                             "Shoulder adduction has no normal limit in that source; its range is "
                             "shown from 0.")
                  .arg(QString::fromUtf8(source.data(), static_cast<qsizetype>(source.size()))),
              w.fonts().small);
}

void earlier(PageWriter& w, const SessionReportData& d) {
  w.heading(QStringLiteral("Comparison with earlier sessions"));
  w.paragraph(QStringLiteral("Range of motion (deg) of each angle per session."), w.fonts().small);
  Table t;
  t.header = {QStringLiteral("Session")};
  t.widths = {0.25};
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    t.header << angleName(a);
    t.widths.push_back(0.15);
  }
  auto row = [&](const QString& label, const RomSnapshot& s) {
    QStringList cells{label};
    for (const auto& rom : s.romRad)
      cells << formatDeg(rom ? std::optional<double>(*rom * kRadToDeg) : std::nullopt);
    t.rows.push_back(cells);
  };
  for (const RomSnapshot& s : d.earlierSessions)
    row(formatDate(s.date) + (s.sessionId ? QStringLiteral(" (#%1)").arg(*s.sessionId) : QString()),
        s);
  RomSnapshot now;
  now.date = d.session.startedAt;
  for (int a = 0; a < kNumClinicalAngles; ++a)
    now.romRad[static_cast<std::size_t>(a)] =
        d.metrics.session.angle[static_cast<std::size_t>(a)].romRad;
  row(formatDate(now.date) + QStringLiteral(" this session"), now);
  if (!d.earlierSessions.empty()) {
    QStringList cells{QStringLiteral("Change since last")};
    const RomSnapshot& last = d.earlierSessions.back();
    for (std::size_t a = 0; a < now.romRad.size(); ++a) {
      if (!last.romRad[a]) {
        cells << QStringLiteral("-");
        continue;
      }
      const double diff = (*now.romRad[a] - *last.romRad[a]) * kRadToDeg;
      cells << (diff >= 0 ? QStringLiteral("+") : QString()) + formatDeg(diff);
    }
    t.rows.push_back(cells);
  }
  if (d.otherSide)
    row(QStringLiteral("Other side, ") + formatDate(d.otherSide->date), *d.otherSide);
  w.table(t);
  if (d.earlierSessions.empty())
    w.paragraph(QStringLiteral("No earlier sessions to compare with."), w.fonts().small);
}

void notes(PageWriter& w, const SessionReportData& d) {
  w.heading(QStringLiteral("Therapist's notes"), 10);
  if (d.session.notes.trimmed().isEmpty())
    w.paragraph(QStringLiteral("No notes."), w.fonts().body);
  else
    w.paragraph(d.session.notes, w.fonts().body);
}

}  // namespace

int writeSessionReport(const SessionReportData& d, const QString& pdfPath) {
  if (d.angles.t.empty() || d.angles.angle.empty() || d.metrics.samples == 0)
    throw ReportError("session " + std::to_string(d.session.id) +
                      ": no clinical angles or metrics to report; estimate the session first");
  const QString date = formatDate(d.session.startedAt);
  const QString head =
      QStringLiteral("%1 (%2), session of %3").arg(orDash(d.patient.name), d.patient.code, date);
  const QString footer = pageFooter(d.patient.name, QStringLiteral("session report"), d.generatedAt);
  return writePdf(pdfPath, QStringLiteral("Session report: %1, %2").arg(d.patient.name, date), head,
                  footer, [&](PageWriter& w) {
                    w.title(QStringLiteral("Session report"));
                    details(w, d);
                    devices(w, d);
                    metricsTable(w, d);
                    plots(w, d);
                    repetitions(w, d);
                    normative(w, d);
                    earlier(w, d);
                    notes(w, d);
                  });
}

}  // namespace armtrack::reports
