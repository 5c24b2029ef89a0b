#include "core/storage/TextRules.h"

#include <QList>

#include "core/storage/StorageError.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

std::string hex(char32_t c, int digits) {
  return QString::number(static_cast<uint>(c), 16)
      .toUpper()
      .rightJustified(digits, QLatin1Char('0'))
      .toStdString();
}

/// "U+000A (a line feed)": what the message calls a refused character.
std::string describe(char32_t c) {
  const char* name = nullptr;
  switch (c) {
    case 0x00:
      name = "a NUL";
      break;
    case 0x09:
      name = "a tab";
      break;
    case 0x0A:
      name = "a line feed";
      break;
    case 0x0D:
      name = "a carriage return";
      break;
    case 0x1B:
      name = "an escape";
      break;
    case 0x7F:
      name = "a delete";
      break;
    case 0x85:
      name = "a next-line";
      break;
    case 0x061C:
      name = "arabic letter mark";
      break;
    case 0x200E:
      name = "left-to-right mark";
      break;
    case 0x200F:
      name = "right-to-left mark";
      break;
    case 0x202A:
      name = "left-to-right embedding";
      break;
    case 0x202B:
      name = "right-to-left embedding";
      break;
    case 0x202C:
      name = "pop directional formatting";
      break;
    case 0x202D:
      name = "left-to-right override";
      break;
    case 0x202E:
      name = "right-to-left override";
      break;
    case 0x2066:
      name = "left-to-right isolate";
      break;
    case 0x2067:
      name = "right-to-left isolate";
      break;
    case 0x2068:
      name = "first strong isolate";
      break;
    case 0x2069:
      name = "pop directional isolate";
      break;
    case 0x2028:
      name = "line separator";
      break;
    case 0x2029:
      name = "paragraph separator";
      break;
    default:
      break;
  }
  const std::string code = "U+" + hex(c, 4);
  return name ? code + " (" + name + ")" : code;
}

}  // namespace

qsizetype codePoints(const QString& s) {
  qsizetype n = 0;
  for (qsizetype i = 0; i < s.size(); ++i) {
    if (s[i].isHighSurrogate() && i + 1 < s.size() && s[i + 1].isLowSurrogate()) ++i;
    ++n;
  }
  return n;
}

QString nameKey(const QString& name) {
  return name.toCaseFolded().normalized(QString::NormalizationForm_C);
}

void checkName(const QString& what, const QString& text, int maxLength) {
  const std::string w = what.toStdString();
  if (text.trimmed().isEmpty()) throw StorageError(Kind::Usage, "the " + w + " is empty: give one");
  const qsizetype n = codePoints(text);
  if (n > maxLength)
    throw StorageError(Kind::Usage, "the " + w + " is " + std::to_string(n) +
                                        " characters long; at most " + std::to_string(maxLength) +
                                        " are allowed: shorten it");
  qsizetype position = 0;
  for (const uint c : text.toUcs4()) {
    ++position;
    if (isControlCharacter(c))
      throw StorageError(Kind::Usage, "the " + w + " holds a control character, " + describe(c) +
                                          ", at character " + std::to_string(position) +
                                          ": names and codes are one line of visible text "
                                          "(no tabs or line breaks); remove it");
    if (isLayoutControl(c))
      throw StorageError(Kind::Usage, "the " + w + " holds " + describe(c) + " at character " +
                                          std::to_string(position) +
                                          ", which changes how the text around it is shown "
                                          "(a name could look like another); remove it");
  }
}

void checkFreeText(const QString& what, const QString& text, int maxLength) {
  const qsizetype n = codePoints(text);
  if (n > maxLength)
    throw StorageError(Kind::Usage, "the " + what.toStdString() + " is " + std::to_string(n) +
                                        " characters long; at most " + std::to_string(maxLength) +
                                        " are allowed: shorten it");
}

void checkNewPassword(const std::string& password) {
  const qsizetype n =
      codePoints(QString::fromUtf8(password.data(), static_cast<qsizetype>(password.size())));
  if (n < kMinPasswordLength)
    throw StorageError(Kind::Usage, "the new password has " + std::to_string(n) +
                                        " characters; it needs at least " +
                                        std::to_string(kMinPasswordLength) +
                                        ": choose a longer one (a few words are easy to remember)");
}

QString escapedForLine(const QString& text) {
  bool plain = true;
  for (const QChar c : text)
    if (c == u'\\' || isControlCharacter(c.unicode()) || isLayoutControl(c.unicode())) {
      plain = false;
      break;
    }
  if (plain) return text;
  QString out;
  out.reserve(text.size() + 8);
  for (const QChar c : text) {
    const char16_t u = c.unicode();
    if (u == u'\\')
      out += QLatin1String("\\\\");
    else if (u == u'\t')
      out += QLatin1String("\\t");
    else if (u == u'\n')
      out += QLatin1String("\\n");
    else if (u == u'\r')
      out += QLatin1String("\\r");
    else if (isControlCharacter(u))
      out += QString::fromStdString("\\x" + hex(u, 2));
    else if (isLayoutControl(u))
      out += QString::fromStdString("\\u" + hex(u, 4));
    else
      out += c;
  }
  return out;
}

}  // namespace armtrack::storage
