// Text formatting shared by the reports: degrees, dates, durations and a readable summary of
// the devices and calibration JSON, in the language and locale in effect (the installed
// translators, QLocale()). Internal to armtrack_reports, except fullYearDateFormat(), which the
// GUI shares.
#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QLocale>
#include <QString>
#include <QStringList>
#include <optional>

namespace armtrack::reports {

/// The reports' words in the language of the installed translators (context
/// "armtrack::reports" in translations/armtrack_<code>.ts).
struct Text {
  Q_DECLARE_TR_FUNCTIONS(armtrack::reports)
};

/// The locale of the report's numbers and dates: QLocale(), with plain digits (no group
/// separator) for the C locale, the one of a machine without a configured language.
QLocale reportLocale();

/// The locale's numeric date format with the year in full ("dd.MM.yyyy" for German,
/// "dd/MM/yyyy" for Spanish); ISO 8601 ("yyyy-MM-dd") for the C locale, which has no national
/// convention.
QString fullYearDateFormat(const QLocale& locale);

/// The clinical angle's name (clinicalAngleInfo() order) in the current language.
QString angleName(int index);
/// The index of a clinical angle's key ("shoulder_flexion"), if it is one.
std::optional<int> angleIndex(const QString& key);

/// A word the records store ("left", "f", "complete", ...) in the reader's language; other
/// text as it is, "-" for none.
QString word(const QString& stored);

/// s, or "-" when s is empty or blank.
QString orDash(const QString& s);
/// A stored name, code or account as the report draws it: "-" when blank; otherwise each
/// control character (C0, DEL, C1) and direction control (storage::isLayoutControl) drawn as
/// U+FFFD, and the whole isolated (U+2068 ... U+2069). So a name stays on its line, shows the
/// characters stored in their own order, and cannot reorder the text beside it (a name typed
/// before the records refused such characters).
QString nameText(const QString& s);
/// The running foot of every page: "<name> - <kind> - generated YYYY-MM-DD HH:MM UTC", at
/// generatedAt, or now when it is invalid.
QString pageFooter(const QString& patientName, const QString& kind, const QDateTime& generatedAt);
/// Degrees with one decimal in the locale's digits ("85.2", "85,2"); "-" for an empty or
/// non-finite value.
QString formatDeg(std::optional<double> deg);
/// A date in the locale's numeric format with the full year (fullYearDateFormat()).
QString formatDate(const QDate& date);
/// An ISO 8601 date or date-time as formatDate(QDate) (UTC); the text itself if it does not parse.
QString formatDate(const QString& iso);
/// An ISO 8601 date-time as the date, "HH:MM" and "UTC"; the text itself if it does not parse.
QString formatDateTime(const QString& iso);
/// Parses ISO 8601 (date or date-time, UTC when no offset is given); invalid if it does not.
QDateTime parseIso(const QString& iso);
/// "2 min 05 s" (or "42.0 s" under a minute), in the current language.
QString formatDuration(double seconds);
/// One "key: value" line per scalar of a JSON object, nested keys joined with ".", number arrays
/// on one line; at most maxLines lines (then "... n more"). Empty for "", "{}" or "null"; a
/// single explanatory line for text that is not JSON.
QStringList summariseJson(const QString& json, int maxLines = 20);
/// The devices of a session's devices JSON (docs/storage.md, "Sessions"), one line each: the
/// plugin, its streams and the options it was made with. Empty when none were stored.
QStringList devicesText(const QString& devicesJson);
/// A session's calibration in words: the sensor calibration's verdict and its reason (stored as
/// "sensor_calibration" in the session's filter settings by the GUI), or that none was made;
/// the segment lengths in cm, the sensors' mounting (distance in cm, angle in deg), the arm and
/// whether a camera was calibrated. No raw keys or matrices.
QStringList calibrationText(const QString& calibrationJson, const QString& filterJson);
/// The string value of a top-level key of a JSON object, or "".
QString jsonString(const QString& json, const QString& key);

}  // namespace armtrack::reports
