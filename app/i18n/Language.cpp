#include "app/i18n/Language.h"

#include <QCoreApplication>
#include <QHash>
#include <QLibraryInfo>
#include <QLocale>
#include <QStringList>
#include <QTranslator>
#include <memory>
#include <optional>

namespace armtrack::i18n {

namespace {

// The translations built into the program (qt_add_translations, app/i18n/CMakeLists.txt).
constexpr auto kResourceFolder = ":/i18n";

struct Installed {
  std::unique_ptr<QTranslator> qt, own;
  QString language = QStringLiteral("en");
  std::optional<QLocale> localeBefore;  // QLocale's default before the first setLanguage()
};

Installed& installed() {
  static Installed i;
  return i;
}

void remove(std::unique_ptr<QTranslator>& t) {
  if (!t) return;
  QCoreApplication::removeTranslator(t.get());
  t.reset();
}

}  // namespace

const std::vector<Language>& shippedLanguages() {
  static const std::vector<Language> languages = [] {
    std::vector<Language> out{{QStringLiteral("en"), QStringLiteral("English")}};
    // Qt's own names may carry a country ("español de España"); the list shows the language.
    const QHash<QString, QString> names = {{QStringLiteral("de"), QStringLiteral("Deutsch")},
                                           {QStringLiteral("es"), QStringLiteral("Español")}};
    for (const QString& code :
         QStringLiteral(ARMTRACK_TRANSLATIONS).split(u',', Qt::SkipEmptyParts)) {
      QString name = names.value(code, QLocale(code).nativeLanguageName());
      if (!name.isEmpty()) name[0] = name[0].toUpper();
      out.push_back({code, name});
    }
    return out;
  }();
  return languages;
}

QString shippedLanguageFor(const QString& codeOrLocale) {
  if (codeOrLocale.isEmpty()) return {};
  const QLocale wanted(codeOrLocale);
  if (wanted.language() == QLocale::C) return {};
  for (const Language& l : shippedLanguages())
    if (QLocale(l.code).language() == wanted.language()) return l.code;
  return {};
}

QString shippedLanguageList() {
  QStringList codes;
  for (const Language& l : shippedLanguages()) codes << l.code;
  return codes.join(QStringLiteral(", "));
}

QString setLanguage(const QString& code) {
  Installed& i = installed();
  if (!i.localeBefore) i.localeBefore = QLocale();
  remove(i.own);
  remove(i.qt);
  QLocale locale = code.isEmpty() ? QLocale::system() : QLocale(code);
  // The C locale (a machine without a configured language) has no national convention: plain
  // numbers, as files and the command line print them.
  if (locale.language() == QLocale::C) locale.setNumberOptions(QLocale::OmitGroupSeparator);
  QLocale::setDefault(locale);
  const QString shipped = shippedLanguageFor(locale.name());
  i.language = shipped.isEmpty() ? QStringLiteral("en") : shipped;
  const QLocale language(i.language);
  // Qt's own words (standard buttons, context menus); English needs none.
  if (i.language != QLatin1String("en")) {
    i.qt = std::make_unique<QTranslator>();
    if (i.qt->load(language, QStringLiteral("qtbase"), QStringLiteral("_"),
                   QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
      QCoreApplication::installTranslator(i.qt.get());
    else
      i.qt.reset();  // Debian's qt6-translations-l10n is not installed: they stay English
  }
  // ArmTrack's: a translation, or for English the plural forms of texts with %n.
  i.own = std::make_unique<QTranslator>();
  if (i.own->load(language, QStringLiteral("armtrack"), QStringLiteral("_"),
                  QLatin1String(kResourceFolder))) {
    QCoreApplication::installTranslator(i.own.get());
  } else {
    i.own.reset();
    i.language = QStringLiteral("en");
  }
  return i.language;
}

QString currentLanguage() {
  return installed().language;
}

void resetLanguage() {
  Installed& i = installed();
  remove(i.own);
  remove(i.qt);
  if (i.localeBefore) QLocale::setDefault(*i.localeBefore);
  i.language = QStringLiteral("en");
}

}  // namespace armtrack::i18n
