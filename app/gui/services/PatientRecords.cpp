#include "app/gui/services/PatientRecords.h"

#include <QCoreApplication>
#include <QDate>
#include <QJsonDocument>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>

#include "app/clinical/Outputs.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::gui {

namespace {

// This file's texts (context "armtrack::gui::PatientRecords" in translations/armtrack_<code>.ts).
struct Tr {
  Q_DECLARE_TR_FUNCTIONS(armtrack::gui::PatientRecords)
};

struct LengthKey {
  const char* key;
  std::optional<double> SegmentLengths::*field;
};
constexpr LengthKey kLengthKeys[] = {
    {"upper_arm_m", &SegmentLengths::upperArmM},
    {"forearm_m", &SegmentLengths::forearmM},
    {"upper_arm_strap_m", &SegmentLengths::upperStrapM},
    {"forearm_strap_m", &SegmentLengths::forearmStrapM},
};

}  // namespace

SegmentLengths SegmentLengths::fromJson(const QString& json, int* ignored) {
  SegmentLengths s;
  int bad = 0;
  s.others = QJsonDocument::fromJson(json.toUtf8()).object();
  for (const LengthKey& k : kLengthKeys) {
    const QString key = QString::fromLatin1(k.key);
    if (!s.others.contains(key)) continue;
    const QJsonValue v = s.others.take(key);
    if (v.isDouble() && std::isfinite(v.toDouble()) && v.toDouble() > 0)
      s.*k.field = v.toDouble();
    else
      ++bad;
  }
  if (ignored) *ignored = bad;
  return s;
}

QString SegmentLengths::toJson() const {
  QJsonObject o = others;
  for (const LengthKey& k : kLengthKeys)
    if (const auto& v = this->*k.field) o.insert(QString::fromLatin1(k.key), *v);
  return QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact));
}

PatientOverview loadPatientOverview(storage::ClinicalStore& store, const QString& code) {
  PatientOverview o;
  o.patient = store.patient(code);
  o.programme = store.programme(code);
  o.protocols = store.listProtocols();
  o.sessions = store.listSessions(code);
  std::sort(o.sessions.begin(), o.sessions.end(), [](const auto& a, const auto& b) {
    return a.startedAt != b.startedAt ? a.startedAt > b.startedAt : a.id > b.id;
  });
  for (auto e = o.sessions.rbegin(); e != o.sessions.rend(); ++e) {  // oldest first
    const std::optional<QJsonObject> metrics = storage::latestMetricsJson(store, e->id);
    if (!metrics) continue;
    SessionExtremes x{e->id, e->startedAt, clinical::angleFieldOf(*metrics, "min_deg"),
                      clinical::angleFieldOf(*metrics, "max_deg"), std::nullopt};
    const QJsonValue trunk = (*metrics)["trunk"].toObject()["max_flexion_deg"];
    if (trunk.isDouble() && std::isfinite(trunk.toDouble())) x.trunkFlexionDeg = trunk.toDouble();
    if (std::any_of(x.maxRad.begin(), x.maxRad.end(), [](const auto& v) { return v.has_value(); }))
      o.progress.push_back(std::move(x));
  }
  return o;
}

QString patientProblem(const storage::Patient& p, const QDate& today, QString* field) {
  const auto fail = [&](const char* name, const QString& text) {
    if (field) *field = QString::fromLatin1(name);
    return text;
  };
  static const QRegularExpression codeRe(QStringLiteral("^[A-Za-z0-9][A-Za-z0-9_-]{0,31}$"));
  if (p.code.trimmed().isEmpty())
    return fail("code", Tr::tr("Give the patient a code, e.g. P001: it names the patient in files "
                               "and exports."));
  if (!codeRe.match(p.code).hasMatch())
    return fail("code",
                Tr::tr("The code may hold letters, digits, '-' and '_' (at most 32, starting "
                       "with a letter or digit): \"%1\" does not.")
                    .arg(p.code));
  if (p.name.trimmed().isEmpty()) return fail("name", Tr::tr("Give the patient's name."));
  if (!p.birthDate.isEmpty()) {
    const QDate d = QDate::fromString(p.birthDate, Qt::ISODate);
    if (!d.isValid()) return fail("birthDate", Tr::tr("The birth date is not a date."));
    if (d > today) return fail("birthDate", Tr::tr("The birth date lies in the future."));
    if (d.year() < 1900) return fail("birthDate", Tr::tr("The birth date is before 1900."));
  }
  const SegmentLengths s = SegmentLengths::fromJson(p.segmentLengthsJson);
  const auto check = [&](const std::optional<double>& v, double lo, double hi, const char* name,
                         const QString& what) -> QString {
    if (v && (*v < lo || *v > hi))
      return fail(name, Tr::tr("The %1 of %L2 cm is outside %L3-%L4 cm: check the measurement.")
                            .arg(what)
                            .arg(*v * 100, 0, 'f', 1)
                            .arg(lo * 100, 0, 'f', 0)
                            .arg(hi * 100, 0, 'f', 0));
    return {};
  };
  for (const QString& problem :
       {check(s.upperArmM, 0.15, 0.50, "upperArm", Tr::tr("upper arm length")),
        check(s.forearmM, 0.12, 0.45, "forearm", Tr::tr("forearm length")),
        check(s.upperStrapM, 0.02, 0.45, "upperStrap", Tr::tr("upper-arm IMU distance")),
        check(s.forearmStrapM, 0.02, 0.40, "forearmStrap", Tr::tr("forearm IMU distance"))})
    if (!problem.isEmpty()) return problem;
  if (s.upperArmM && s.upperStrapM && *s.upperStrapM >= *s.upperArmM)
    return fail("upperStrap", Tr::tr("The upper-arm IMU sits farther from the shoulder than the "
                                     "elbow is: check both measurements."));
  if (s.forearmM && s.forearmStrapM && *s.forearmStrapM >= *s.forearmM)
    return fail("forearmStrap", Tr::tr("The forearm IMU sits farther from the elbow than the wrist "
                                       "is: check both measurements."));
  return {};
}

}  // namespace armtrack::gui
