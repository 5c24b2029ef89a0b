// The languages ArmTrack speaks: Qt's translators for the user interface and the reports, and
// the default QLocale for numbers, dates and units. English is the source language; the
// translations (translations/armtrack_<code>.ts) are built into the program.
#pragma once

#include <QString>
#include <vector>

namespace armtrack::i18n {

struct Language {
  QString code;        ///< "en", "de", "es"
  QString nativeName;  ///< as its speakers write it: "English", "Deutsch", "Español"
};

/// The languages shipped: English (the source) first, then every translation, in the order of
/// the language list in app/i18n/CMakeLists.txt.
const std::vector<Language>& shippedLanguages();

/// The shipped language a code or locale name asks for ("de", "de_AT", "es-MX" -> "de", "es"),
/// or "" when ArmTrack has no translation for it.
QString shippedLanguageFor(const QString& codeOrLocale);

/// "en, de, es": for error messages.
QString shippedLanguageList();

/// Installs Qt's own and ArmTrack's translators for code ("de", "es", "en" or a locale name
/// such as "de_AT"; "" = the system's locale), replacing any installed before, and makes its
/// locale the default (QLocale::setDefault) so numbers and dates follow it. Widgets receive a
/// LanguageChange event. Returns the shipped language now in effect: "en" when ArmTrack has no
/// translation for the locale (the text stays English, numbers and dates still follow the
/// locale). Needs a QCoreApplication; call on its thread.
QString setLanguage(const QString& code);

/// The shipped language in effect ("en" before any setLanguage()).
QString currentLanguage();

/// Removes the translators setLanguage() installed and gives QLocale back the default it had
/// before the first setLanguage().
void resetLanguage();

/// setLanguage() for a scope (e.g. one command of armtrack-cli run inside a test), then
/// resetLanguage().
class ScopedLanguage {
 public:
  explicit ScopedLanguage(const QString& code) : m_language(setLanguage(code)) {}
  ~ScopedLanguage() { resetLanguage(); }
  ScopedLanguage(const ScopedLanguage&) = delete;
  ScopedLanguage& operator=(const ScopedLanguage&) = delete;
  /// The shipped language in effect.
  const QString& language() const { return m_language; }

 private:
  QString m_language;
};

}  // namespace armtrack::i18n
