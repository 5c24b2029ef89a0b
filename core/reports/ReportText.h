// Text formatting shared by the reports: degrees, dates, durations and a readable summary of
// the devices and calibration JSON. Internal to armtrack_reports.
#pragma once

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <optional>

namespace armtrack::reports {

/// s, or "-" when s is empty or blank.
QString orDash(const QString& s);
/// The running foot of every page: "<name> - <kind> - generated YYYY-MM-DD HH:MM UTC", at
/// generatedAt, or now when it is invalid.
QString pageFooter(const QString& patientName, const QString& kind, const QDateTime& generatedAt);
/// Degrees with one decimal ("85.2"); "-" for an empty or non-finite value.
QString formatDeg(std::optional<double> deg);
/// An ISO 8601 date or date-time as "YYYY-MM-DD" (UTC); the text itself if it does not parse.
QString formatDate(const QString& iso);
/// An ISO 8601 date-time as "YYYY-MM-DD HH:MM UTC"; the text itself if it does not parse.
QString formatDateTime(const QString& iso);
/// Parses ISO 8601 (date or date-time, UTC when no offset is given); invalid if it does not.
QDateTime parseIso(const QString& iso);
/// "2 min 05 s" (or "42.0 s" under a minute).
QString formatDuration(double seconds);
/// One "key: value" line per scalar of a JSON object, nested keys joined with ".", number arrays
/// on one line; at most maxLines lines (then "... n more"). Empty for "", "{}" or "null"; a
/// single explanatory line for text that is not JSON.
QStringList summariseJson(const QString& json, int maxLines = 20);
/// The string value of a top-level key of a JSON object, or "".
QString jsonString(const QString& json, const QString& key);

}  // namespace armtrack::reports
