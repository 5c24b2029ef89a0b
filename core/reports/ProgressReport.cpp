// The progress report (docs/reports.md, "Progress report").
#include <QDate>
#include <algorithm>
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

std::optional<double> deg(const std::optional<double>& rad) {
  return rad ? std::optional<double>(*rad * kRadToDeg) : std::nullopt;
}

/// A direction's name for its chart: the angle's name for the named direction, but for the
/// forearm, whose name some languages give to the whole axis ("Pronation/Supination") while
/// supination has a chart of its own; the opposite directions by their own names.
QString motionName(const MotionDirection& m) {
  if (!m.opposite)
    return m.angle == 4 ? Text::tr("Forearm pronation", "the motion, beside the supination chart")
                        : angleName(m.angle);
  switch (m.angle) {
    case 0:
      return Text::tr("Shoulder extension");
    case 2:
      return Text::tr("Shoulder external rotation");
    case 4:
      return Text::tr("Forearm supination");
    default:
      return angleName(m.angle);
  }
}

/// A date of the period: the asked-for one when it is a date, else the first (or last)
/// session's; "" when neither is known.
QString periodDate(const QString& asked, const std::vector<ProgressSession>& sessions, bool last) {
  const QDate date = QDate::fromString(asked.trimmed().left(10), Qt::ISODate);
  if (date.isValid()) return formatDate(date);
  QDateTime found;
  for (const ProgressSession& s : sessions) {
    const QDateTime t = parseIso(s.startedAt);
    if (t.isValid() && (!found.isValid() || (last ? t > found : t < found))) found = t;
  }
  return found.isValid() ? formatDate(found.date()) : QString();
}

/// The period the report covers, "12.11.2026 to 26.11.2026": the dates asked for, or where one
/// is missing (or not a date) the first or last session's date.
QString periodText(const ProgressReportData& d, const std::vector<ProgressSession>& sessions) {
  const QString from = periodDate(d.fromDate, sessions, false);
  const QString to = periodDate(d.toDate, sessions, true);
  if (from.isEmpty() && to.isEmpty()) return Text::tr("no sessions");
  if (from.isEmpty()) return Text::tr("until %1").arg(to);
  if (to.isEmpty()) return Text::tr("from %1").arg(from);
  return Text::tr("%1 to %2").arg(from, to);
}

void draw(PageWriter& w, const ProgressReportData& d,
          const std::vector<ProgressSession>& sessions) {
  w.title(Text::tr("Progress report"));
  w.heading(Text::tr("Patient and period"));
  const storage::Patient& p = d.patient;
  w.keyValues({{Text::tr("Name"), nameText(p.name)},
               {Text::tr("Patient code"), nameText(p.code)},
               {Text::tr("Date of birth"), orDash(formatDate(p.birthDate))},
               {Text::tr("Affected side"), word(p.affectedSide)},
               {Text::tr("Period"), periodText(d, sessions)},
               {Text::tr("Therapist"), nameText(d.therapistName)},
               {Text::tr("Sessions"), QString::number(sessions.size())}});

  w.heading(Text::tr("Range of motion over time"), 50);
  if (sessions.empty()) {
    w.paragraph(Text::tr("No sessions in the period (%1).").arg(periodText(d, sessions)),
                w.fonts().body);
  } else {
    std::vector<QDateTime> when;
    for (const ProgressSession& s : sessions) when.push_back(parseIso(s.startedAt));
    const auto& ranges = aaosNormativeRanges();
    // Each direction against its own normal range from the neutral position: the largest angle
    // in the named direction, which is what the named motion's normal range measures (a range
    // of motion would add extension to flexion), and the opposite one where the range gives it
    // a limit (shoulder extension, external rotation, supination).
    for (const MotionDirection& m : motionDirections(ranges)) {
      const auto a = static_cast<std::size_t>(m.angle);
      std::vector<std::optional<double>> largest;
      for (const ProgressSession& s : sessions)
        largest.push_back(deg(largestInDirection(s.minRad[a], s.maxRad[a], m.opposite)));
      // The latest session's "% of normal", as the patient page shows it.
      QString title = Text::tr("%1: largest angle reached (deg)").arg(motionName(m));
      for (auto s = sessions.rbegin(); s != sessions.rend(); ++s)
        if (const auto pc = sessionPercentOfNormal(
                parseIsoDate(d.patient.birthDate.toStdString()),
                sexFromCode(d.patient.sex.toStdString()), parseIsoDate(s->startedAt.toStdString()),
                m.angle, s->minRad[a], s->maxRad[a], m.opposite)) {
          title += Text::tr("; latest %1 % of normal")
                       .arg(reportLocale().toString(static_cast<qlonglong>(std::lround(*pc))));
          break;
        }
      const QRectF r = w.reserve(w.mm(44));
      drawDateChart(w, r.adjusted(0, 0, 0, -w.mm(2)), title, when, largest,
                    motionNormalRad(ranges[a], m.opposite) * kRadToDeg);
    }
    // The trunk's compensation over the weeks, when sessions measured it (a sternum sensor):
    // how far the patient leaned forward at most, which therapy means to bring down.
    std::vector<std::optional<double>> trunk;
    for (const ProgressSession& s : sessions) trunk.push_back(s.trunkFlexionDeg);
    if (std::any_of(trunk.begin(), trunk.end(), [](const auto& v) { return v.has_value(); })) {
      const QRectF r = w.reserve(w.mm(44));
      drawDateChart(w, r.adjusted(0, 0, 0, -w.mm(2)),
                    Text::tr("Trunk compensation: largest trunk flexion (deg)"), when, trunk,
                    std::nullopt);
    }
    const std::string_view source = normSourceCitation(NormSource::Aaos);
    w.paragraph(Text::tr("Normal ranges: %1.")
                    .arg(QString::fromUtf8(source.data(), static_cast<qsizetype>(source.size()))),
                w.fonts().small);
  }

  w.heading(Text::tr("Sessions"));
  Table t;
  t.small = true;
  t.header = {Text::tr("Date"), Text::tr("Id"), Text::tr("Protocol"), Text::tr("Duration"),
              Text::tr("Reps")};
  t.widths = {0.11, 0.06, 0.15, 0.1, 0.06};
  t.rightAligned = {false, true, false, true, true};
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    t.header << Text::tr("%1 ROM").arg(angleName(a));
    t.widths.push_back(0.104);
    t.rightAligned.push_back(true);
  }
  for (const ProgressSession& s : sessions) {
    QStringList row{formatDate(s.startedAt), QString::number(s.id), nameText(s.protocolName),
                    formatDuration(s.durationS),
                    s.repetitions ? QString::number(*s.repetitions) : QStringLiteral("-")};
    for (const auto& rom : s.romRad) row << formatDeg(deg(rom));
    t.rows.push_back(row);
  }
  w.table(t);
  w.paragraph(Text::tr("ROM in degrees (maximum minus minimum over the session)."),
              w.fonts().small);
}

}  // namespace

QString progressPeriod(const ProgressReportData& d) {
  return periodText(d, d.sessions);
}

int writeProgressReport(const ProgressReportData& d, const QString& pdfPath) {
  std::vector<ProgressSession> sessions = d.sessions;
  std::stable_sort(sessions.begin(), sessions.end(),
                   [](const ProgressSession& a, const ProgressSession& b) {
                     return parseIso(a.startedAt) < parseIso(b.startedAt);
                   });
  const QString period = periodText(d, sessions);
  // Names as nameText() draws them: on one line, in their own direction.
  const QString name = nameText(d.patient.name);
  const QString head = Text::tr("%1 (%2), progress %3").arg(name, nameText(d.patient.code), period);
  const QString footer = pageFooter(name, Text::tr("progress report"), d.generatedAt);
  return writePdf(pdfPath, Text::tr("Progress report: %1, %2").arg(name, period), head, footer,
                  [&](PageWriter& w) { draw(w, d, sessions); });
}

}  // namespace armtrack::reports
