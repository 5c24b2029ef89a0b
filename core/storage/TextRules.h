// What the clinical records accept as names, codes, free text and new passwords, the key under
// which names are unique, and how stored text is shown on one line (docs/storage.md, "Security").
#pragma once

#include <QString>
#include <string>

namespace armtrack::storage {

/// Least length of a new password, in Unicode code points (at db init, user add, password
/// change; existing accounts keep signing in with shorter ones).
inline constexpr int kMinPasswordLength = 10;
/// Longest account name and patient code, in code points: identifiers, in files and the log.
inline constexpr int kMaxAccountNameLength = 64;
inline constexpr int kMaxCodeLength = 64;
/// Longest patient or protocol name, in code points.
inline constexpr int kMaxNameLength = 200;
/// Longest free text (a patient's diagnosis and notes), in code points.
inline constexpr int kMaxFreeTextLength = 10000;

/// The number of Unicode code points in s (a surrogate pair counts once).
qsizetype codePoints(const QString& s);
/// A control character: C0 (U+0000-U+001F), DEL (U+007F) or C1 (U+0080-U+009F).
constexpr bool isControlCharacter(char32_t c) {
  return c <= 0x1F || (c >= 0x7F && c <= 0x9F);
}
/// A character that changes the direction of the text around it, or breaks a line where a
/// viewer does not expect one: U+200E, U+200F, U+061C, U+202A-U+202E, U+2066-U+2069 (bidi
/// controls) and U+2028, U+2029 (line and paragraph separators).
constexpr bool isLayoutControl(char32_t c) {
  return c == 0x200E || c == 0x200F || c == 0x061C || (c >= 0x202A && c <= 0x202E) ||
         (c >= 0x2066 && c <= 0x2069) || c == 0x2028 || c == 0x2029;
}

/// The key under which account names, patient codes and protocol names are unique and found:
/// Unicode case folding (QString::toCaseFolded), then canonical composition (NFC), so "BOSS",
/// "boss" and "Boss" are one name, and "é" typed as one character or as e + accent too.
QString nameKey(const QString& name);

/// Refuses (StorageError(Usage), naming what and saying what to do) a name or code that is
/// blank, longer than maxLength code points, or holds a control character or a layout control
/// (isControlCharacter, isLayoutControl). what is e.g. "patient code".
void checkName(const QString& what, const QString& text, int maxLength);
/// Refuses free text (notes, a diagnosis) longer than maxLength code points; line breaks and
/// tabs are allowed there.
void checkFreeText(const QString& what, const QString& text, int maxLength = kMaxFreeTextLength);
/// Refuses a new password (UTF-8) shorter than kMinPasswordLength code points.
void checkNewPassword(const std::string& password);

/// text for one field of a line of text output (tab-separated lists, the audit log): a
/// backslash becomes \\, a tab \t, a line feed \n, a carriage return \r, any other control
/// character \xHH and a layout control \uHHHH, so stored text can neither start a line nor
/// split or reorder a field. Text without them is returned as it is.
QString escapedForLine(const QString& text);

}  // namespace armtrack::storage
