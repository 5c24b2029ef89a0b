// The session report (docs/reports.md, "Session report").
#include <QLocale>
#include <QStringList>
#include <cmath>

#include "core/kinematics/ClinicalAngles.h"
#include "core/metrics/NormativeRanges.h"
#include "core/metrics/PatientNorms.h"
#include "core/reports/Charts.h"
#include "core/reports/PdfOutput.h"
#include "core/reports/ReportText.h"
#include "core/reports/Reports.h"

namespace armtrack::reports {
namespace {

QString measuredSide(const SessionReportData& d) {
  if (!d.side.isEmpty()) return word(d.side);
  const QString fromCalibration = jsonString(d.session.calibrationJson, QStringLiteral("side"));
  if (!fromCalibration.isEmpty()) return word(fromCalibration);
  return word(d.patient.affectedSide);
}

QString protocolText(const SessionReportData& d) {
  if (!d.protocol)
    return d.session.protocolName.isEmpty() ? Text::tr("none") : nameText(d.session.protocolName);
  const storage::Protocol& p = *d.protocol;
  const std::optional<int> a = angleIndex(p.angleKey);
  return Text::tr("%1: %2, target %3 to %4 deg, %n repetitions", nullptr, p.repetitions)
      .arg(nameText(p.name), a ? angleName(*a) : p.angleKey, formatDeg(p.targetMinDeg),
           formatDeg(p.targetMaxDeg));
}

void details(PageWriter& w, const SessionReportData& d) {
  w.heading(Text::tr("Patient and session"));
  const storage::Patient& p = d.patient;
  std::vector<std::pair<QString, QString>> items = {
      {Text::tr("Name"), nameText(p.name)},
      {Text::tr("Patient code"), nameText(p.code)},
      {Text::tr("Date of birth"), orDash(formatDate(p.birthDate))},
      {Text::tr("Sex"), word(p.sex)},
      {Text::tr("Affected side"), word(p.affectedSide)},
      {Text::tr("Side measured"), measuredSide(d)},
      {Text::tr("Session"), QString::number(d.session.id)},
      {Text::tr("Date"), orDash(formatDateTime(d.session.startedAt))},
      {Text::tr("Duration"),
       formatDuration(d.session.durationS > 0 ? d.session.durationS : d.metrics.durationS)},
      {Text::tr("Therapist"), nameText(d.therapistName)},
      {Text::tr("Status"), word(d.session.status)},
      {Text::tr("Diagnosis"), orDash(p.diagnosis)},
  };
  w.keyValues(items);
  w.keyValues({{Text::tr("Protocol"), protocolText(d)}}, false);
}

void devices(PageWriter& w, const SessionReportData& d) {
  w.heading(Text::tr("Devices and calibration"));
  const QStringList dev = devicesText(d.session.devicesJson);
  const QStringList cal = calibrationText(d.session.calibrationJson, d.session.filterJson);
  w.paragraph(Text::tr("Devices"), w.fonts().bold);
  w.paragraph(
      dev.isEmpty() ? Text::tr("No devices were recorded for this session.") : dev.join('\n'),
      w.fonts().small);
  w.paragraph(Text::tr("Calibration"), w.fonts().bold);
  w.paragraph(cal.join('\n'), w.fonts().small);
}

/// A recording time as the review's slider shows it ("0:15.4").
QString clockText(double s) {
  const long tenths = std::lround(std::abs(s) * 10);
  return QStringLiteral("%1%2:%3%4%5")
      .arg(s < 0 && tenths > 0 ? QStringLiteral("-") : QString())
      .arg(tenths / 600)
      .arg((tenths / 10) % 60, 2, 10, QLatin1Char('0'))
      .arg(reportLocale().decimalPoint())
      .arg(tenths % 10);
}

QString smoothness(const char* name, const SmoothnessValue& v) {
  return v.ok() ? QStringLiteral("%1 %2").arg(QLatin1String(name),
                                              reportLocale().toString(v.value, 'f', 2))
                : Text::tr("%1 not defined").arg(QLatin1String(name));
}

void metricsTable(PageWriter& w, const SessionReportData& d) {
  w.heading(Text::tr("Metrics per clinical angle"));
  Table t;
  t.header = {Text::tr("Angle"),
              Text::tr("Min (deg)"),
              Text::tr("Max (deg)"),
              Text::tr("ROM (deg)"),
              Text::tr("Peak velocity (deg/s)"),
              Text::tr("Mean velocity (deg/s)"),
              Text::tr("Moving time (s)")};
  t.widths = {0.28, 0.11, 0.11, 0.11, 0.14, 0.14, 0.11};
  for (int i = 0; i < kNumClinicalAngles; ++i) {
    const AngleMetricsDeg m = inDegrees(d.metrics.session.angle[static_cast<std::size_t>(i)]);
    t.rows.push_back({angleName(i), formatDeg(m.minDeg), formatDeg(m.maxDeg), formatDeg(m.romDeg),
                      formatDeg(m.peakVelocityDegPerS), formatDeg(m.meanVelocityDegPerS),
                      reportLocale().toString(m.movementTimeS, 'f', 1)});
  }
  w.table(t);
  const QLocale locale = reportLocale();
  w.paragraph(Text::tr("%1 samples used, %2 rows rejected (not finite), %3 gaps. Smoothness "
                       "of the wrist path: %4, %5.")
                  .arg(locale.toString(static_cast<qulonglong>(d.metrics.samples)),
                       locale.toString(static_cast<qulonglong>(d.metrics.rejectedNonFinite)),
                       locale.toString(static_cast<qulonglong>(d.metrics.gaps)))
                  .arg(smoothness("SPARC", d.metrics.sparc), smoothness("LDLJ", d.metrics.ldlj)),
              w.fonts().small);
}

void plots(PageWriter& w, const SessionReportData& d) {
  w.heading(Text::tr("Joint angles over time"), 45);
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
               Text::tr("shaded: protocol target %1 to %2 deg")
                   .arg(formatDeg(d.protocol->targetMinDeg), formatDeg(d.protocol->targetMaxDeg))};
    const QRectF r = w.reserve(w.mm(44));
    // The repetitions' numbers at their peaks on the angle they were counted on ("p": partial).
    std::vector<TimeMark> marks;
    const QString title = Text::tr("%1 (deg)").arg(angleName(a));
    const RepetitionResult& reps = d.metrics.repetitions;
    if (a == reps.primaryAngle && !reps.repetitions.empty()) {
      for (std::size_t k = 0; k < reps.repetitions.size(); ++k)
        marks.push_back({reps.repetitions[k].peakS,
                         QString::number(k + 1) +
                             (reps.repetitions[k].partial
                                  ? Text::tr("p", "a partial repetition's mark on the plot")
                                  : QString())});
    }
    std::vector<TimeMark> events;  // on the session clock, as the angles' times
    for (const EventMark& e : d.events)
      events.push_back({e.recordingS + timeOrigin(d), QString::fromStdString(e.label)});
    drawTimePlot(w, r.adjusted(0, 0, 0, -w.mm(2)), title, d.angles.t, y, band, marks, timeOrigin(d),
                 events);
  }
}

void repetitions(PageWriter& w, const SessionReportData& d) {
  w.heading(Text::tr("Repetitions"));
  const RepetitionResult& r = d.metrics.repetitions;
  const std::size_t count = r.repetitions.size();
  if (count == 0) {
    w.paragraph(Text::tr("No repetitions were detected (0 repetitions)."), w.fonts().body);
    return;
  }
  const QString primary = angleName(r.primaryAngle);
  w.paragraph(Text::tr("%n repetitions counted on %1: %2 full, %3 partial (judged against a "
                       "reference range of %4 deg); %5 cut by the start or end of the "
                       "recording and not counted.",
                       nullptr, static_cast<int>(count))
                  .arg(primary)
                  .arg(r.fullCount)
                  .arg(r.partialCount)
                  .arg(formatDeg(r.referenceRad * kRadToDeg))
                  .arg(r.truncated),
              w.fonts().body);
  Table t;
  t.header = {Text::tr("#"),
              Text::tr("Start (s)"),
              Text::tr("End (s)"),
              Text::tr("ROM of %1 (deg)").arg(primary),
              Text::tr("Peak velocity (deg/s)"),
              Text::tr("Partial")};
  t.widths = {0.08, 0.14, 0.14, 0.26, 0.22, 0.16};
  const double t0 = timeOrigin(d);
  for (std::size_t i = 0; i < count; ++i) {
    const Repetition& rep = r.repetitions[i];
    const AngleMetricsDeg m =
        inDegrees(rep.metrics.angle[static_cast<std::size_t>(r.primaryAngle)]);
    t.rows.push_back({QString::number(i + 1),
                      reportLocale().toString(recordingTime(rep.startS, t0), 'f', 2),
                      reportLocale().toString(recordingTime(rep.endS, t0), 'f', 2),
                      formatDeg(rep.excursionRad * kRadToDeg), formatDeg(m.peakVelocityDegPerS),
                      rep.partial ? Text::tr("yes") : Text::tr("no")});
  }
  w.table(t);
}

QString cm(const std::optional<double>& v) {
  return v ? reportLocale().toString(*v, 'f', 1) : QStringLiteral("-");
}

// How far the patient leaned and turned the trunk to move the arm, and how far the shoulder
// moved (docs/reports.md, "Session report"); "not measured" without the sensors for it.
void trunk(PageWriter& w, const SessionReportData& d) {
  if (!d.trunk) return;  // analysed before the trunk was measured
  w.heading(Text::tr("Trunk compensation"));
  const TrunkExtremes& x = d.trunk->session;
  const auto deg = [](const std::optional<double>& v) {
    return v ? Text::tr("%1 deg").arg(formatDeg(v)) : Text::tr("not measured");
  };
  if (!(x.maxFlexionDeg || x.maxLateralDeg || x.maxRotationDeg || x.maxShoulderDisplacementCm)) {
    w.paragraph(Text::tr("Not measured: the session had no sternum sensor (trunk IMU) and no "
                         "optical shoulder position."),
                w.fonts().body);
    return;
  }
  w.paragraph(Text::tr("The largest trunk flexion (forward lean), lateral bending and axial "
                       "rotation from the upright start pose, and the largest displacement of "
                       "the shoulder, over the session and in each repetition."),
              w.fonts().small);
  w.keyValues({{Text::tr("Trunk flexion"), deg(x.maxFlexionDeg)},
               {Text::tr("Lateral bending"), deg(x.maxLateralDeg)},
               {Text::tr("Axial rotation"), deg(x.maxRotationDeg)},
               {Text::tr("Shoulder displacement"),
                x.maxShoulderDisplacementCm ? Text::tr("%1 cm").arg(cm(x.maxShoulderDisplacementCm))
                                            : Text::tr("not measured")}});
  if (d.trunk->repetitionsWithCompensation && d.trunkFlexionLimitDeg)
    w.paragraph(Text::tr("%1 of %2 repetitions were made with trunk compensation (trunk flexion "
                         "over %3 deg).")
                    .arg(*d.trunk->repetitionsWithCompensation)
                    .arg(d.trunk->repetitions.size())
                    .arg(formatDeg(d.trunkFlexionLimitDeg)),
                w.fonts().body);
  if (d.trunk->repetitions.empty()) return;
  w.ensureSpace(w.mm(22));  // the label with the table's header and first row
  w.paragraph(Text::tr("Per repetition"), w.fonts().bold);
  Table t;
  t.header = {Text::tr("#"),
              Text::tr("Trunk flexion (deg)"),
              Text::tr("Lateral bending (deg)"),
              Text::tr("Axial rotation (deg)"),
              Text::tr("Shoulder (cm)"),
              Text::tr("Compensated")};
  t.widths = {0.08, 0.18, 0.19, 0.19, 0.18, 0.18};
  for (std::size_t i = 0; i < d.trunk->repetitions.size(); ++i) {
    const TrunkExtremes& r = d.trunk->repetitions[i];
    t.rows.push_back({QString::number(i + 1), formatDeg(r.maxFlexionDeg),
                      formatDeg(r.maxLateralDeg), formatDeg(r.maxRotationDeg),
                      cm(r.maxShoulderDisplacementCm),
                      r.compensated ? (*r.compensated ? Text::tr("yes") : Text::tr("no"))
                                    : QStringLiteral("-")});
  }
  w.table(t);
}

QString sourceName(NormSource s) {
  const std::string_view n = normSourceShortName(s);
  return QString::fromUtf8(n.data(), static_cast<qsizetype>(n.size()));
}

/// "females aged 45-69" for the patient's Soucie group.
QString soucieGroup(const PatientNorms& n) {
  if (!n.ageGroup) return {};
  const SoucieAgeGroup& g = kSoucieAgeGroups[static_cast<std::size_t>(*n.ageGroup)];
  return (n.sex == Sex::Female ? Text::tr("females aged %1-%2") : Text::tr("males aged %1-%2"))
      .arg(g.fromYears)
      .arg(g.toYears);
}

/// Where one angle's normal range comes from, in a table cell.
QString sourceCell(const NormativeRange& r, const PatientNorms& n) {
  auto name = [&](NormSource s) {
    return s == NormSource::Soucie2011 ? QStringLiteral("%1, %2").arg(sourceName(s), soucieGroup(n))
                                       : sourceName(s);
  };
  if (!r.minRad || r.minSource == r.maxSource) return name(r.maxSource);
  return Text::tr("%1 (maximum); %2 (minimum)").arg(name(r.maxSource), name(r.minSource));
}

/// Why the age- and sex-specific values were not used ("" when they were).
QString fallbackSentence(const PatientNorms& n) {
  switch (n.fallback) {
    case NormFallback::None:
      return {};
    case NormFallback::AgeUnknown:
      return Text::tr(
          "Reference values by age and sex (Soucie et al. 2011) are not used: the "
          "date of birth is not recorded.");
    case NormFallback::AgeOutsideStudy:
      return Text::tr(
                 "Reference values by age and sex (Soucie et al. 2011) are not used: the "
                 "patient was %1 on the day of the session, outside the study's 2 to 69 "
                 "years.")
          .arg(*n.ageYears);
    case NormFallback::SexUnknown:
      return Text::tr(
          "Reference values by age and sex (Soucie et al. 2011) are not used: the "
          "patient's sex is not recorded as female or male.");
    case NormFallback::NoValues:
      break;
  }
  return Text::tr(
             "Reference values by age and sex (Soucie et al. 2011) are not used: this "
             "version has none for %1.")
      .arg(soucieGroup(n));
}

void normative(PageWriter& w, const SessionReportData& d) {
  w.heading(Text::tr("Comparison with normative ranges"), 50);
  const std::optional<CivilDate> on = parseIsoDate(d.session.startedAt.toStdString());
  const PatientNorms norms =
      patientNorms(parseIsoDate(d.patient.birthDate.toStdString()), on.value_or(CivilDate{}),
                   sexFromCode(d.patient.sex.toStdString()), d.soucieValues);
  std::vector<NormativeBar> bars;
  Table sources;
  sources.small = true;
  sources.header = {Text::tr("Angle"), Text::tr("Normal range (deg)"), Text::tr("Source")};
  sources.widths = {0.28, 0.2, 0.52};
  sources.rightAligned = {false, true, false};
  bool aaos = false;
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    const NormativeRange& n = norms.ranges[static_cast<std::size_t>(a)];
    const AngleMetrics& m = d.metrics.session.angle[static_cast<std::size_t>(a)];
    NormativeBar b;
    b.name = angleName(a);
    if (n.minRad) b.normalLoDeg = *n.minRad * kRadToDeg;
    b.normalHiDeg = n.maxRad * kRadToDeg;
    b.minDeg = m.minRad * kRadToDeg;
    b.maxDeg = m.maxRad * kRadToDeg;
    // "% of normal" as the patient page shows it (percentOfNormal): the largest angle in the
    // named direction against that motion's normal range.
    const std::optional<double> percent = percentOfNormal(n, m.minRad, m.maxRad);
    b.caption =
        Text::tr("%1 of %2 deg, %3 %", "the largest angle, its normal, the percent of normal")
            .arg(formatDeg(m.maxRad * kRadToDeg), formatDeg(motionNormalRad(n, false) * kRadToDeg),
                 percent ? reportLocale().toString(static_cast<qlonglong>(std::lround(*percent)))
                         : QStringLiteral("-"));
    bars.push_back(b);
    sources.rows.push_back({b.name,
                            QStringLiteral("%1 – %2").arg(formatDeg(b.normalLoDeg.value_or(0)),
                                                          formatDeg(b.normalHiDeg)),
                            sourceCell(n, norms)});
    aaos = aaos || n.maxSource == NormSource::Aaos || (n.minRad && n.minSource == NormSource::Aaos);
  }
  const QRectF r = w.reserve(normativeBarsHeight(w, bars.size()));
  drawNormativeBars(w, r, bars);
  w.table(sources);
  QStringList cited;
  for (const NormSource s : {NormSource::Soucie2011, NormSource::Aaos}) {
    if (s == NormSource::Soucie2011 ? !norms.usesSoucie() : !aaos) continue;
    const std::string_view c = normSourceCitation(s);
    cited << sourceName(s) + QStringLiteral(": ") +
                 QString::fromUtf8(c.data(), static_cast<qsizetype>(c.size()));
  }
  QString text = Text::tr(
                     "Grey: the normal range of motion; blue: this session's range "
                     "(negative = extension, external rotation, supination). Shoulder "
                     "adduction has no normal limit in the sources; its range is shown from "
                     "0. Beside each bar: the largest angle reached in the motion the angle is "
                     "named after (flexion, abduction, internal rotation, elbow flexion, "
                     "pronation), that motion's normal range, and the first as a percentage of "
                     "the second, as on the patient's page. Sources: %1.")
                     .arg(cited.join(QStringLiteral("; ")));
  if (norms.usesSoucie())
    text += ' ' + Text::tr(
                      "Soucie et al. give the mean passive range of motion of healthy %1; "
                      "the patient was %2 on the day of the session.")
                      .arg(soucieGroup(norms))
                      .arg(*norms.ageYears);
  else
    text += ' ' + fallbackSentence(norms);
  w.paragraph(text, w.fonts().small);
}

void earlier(PageWriter& w, const SessionReportData& d) {
  w.heading(Text::tr("Comparison with earlier sessions"));
  w.paragraph(Text::tr("Range of motion (deg) of each angle per session."), w.fonts().small);
  Table t;
  t.header = {Text::tr("Session")};
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
  row(Text::tr("%1 this session").arg(formatDate(now.date)), now);
  if (!d.earlierSessions.empty()) {
    QStringList cells{Text::tr("Change since last")};
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
  if (d.otherSide) row(Text::tr("Other side, %1").arg(formatDate(d.otherSide->date)), *d.otherSide);
  w.table(t);
  if (d.earlierSessions.empty())
    w.paragraph(Text::tr("No earlier sessions to compare with."), w.fonts().small);
}

void notes(PageWriter& w, const SessionReportData& d) {
  w.heading(Text::tr("Therapist's notes"), 10);
  if (!d.events.empty()) {
    QStringList events;
    for (const EventMark& e : d.events)
      events << QStringLiteral("%1 %2").arg(clockText(e.recordingS),
                                            QString::fromStdString(e.label));
    w.paragraph(Text::tr("Events marked (time since the recording began, as in the review): %1")
                    .arg(events.join(QStringLiteral("; "))),
                w.fonts().body);
  }
  // The event lines are listed above in recording time; the rest as written.
  const QString text =
      d.events.empty() ? d.session.notes
                       : QString::fromStdString(notesWithoutEvents(d.session.notes.toStdString()));
  if (!text.trimmed().isEmpty())
    w.paragraph(text, w.fonts().body);
  else if (d.events.empty())
    w.paragraph(Text::tr("No notes."), w.fonts().body);
}

}  // namespace

double timeOrigin(const SessionReportData& d) {
  if (d.recordingStartS && std::isfinite(*d.recordingStartS)) return *d.recordingStartS;
  return d.angles.t.empty() ? 0.0 : d.angles.t.front();
}

int writeSessionReport(const SessionReportData& d, const QString& pdfPath) {
  if (d.angles.t.empty() || d.angles.angle.empty() || d.metrics.samples == 0)
    throw ReportError("session " + std::to_string(d.session.id) +
                      ": no clinical angles or metrics to report; estimate the session first");
  const QString date = formatDate(d.session.startedAt);
  // Names as nameText() draws them: on one line, in their own direction.
  const QString name = nameText(d.patient.name);
  const QString head = Text::tr("%1 (%2), session of %3").arg(name, nameText(d.patient.code), date);
  const QString footer = pageFooter(name, Text::tr("session report"), d.generatedAt);
  return writePdf(pdfPath, Text::tr("Session report: %1, %2").arg(name, date), head, footer,
                  [&](PageWriter& w) {
                    w.title(Text::tr("Session report"));
                    details(w, d);
                    devices(w, d);
                    metricsTable(w, d);
                    plots(w, d);
                    repetitions(w, d);
                    trunk(w, d);
                    normative(w, d);
                    earlier(w, d);
                    notes(w, d);
                  });
}

}  // namespace armtrack::reports
