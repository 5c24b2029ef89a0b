// The translations are complete: lupdate runs over today's sources into copies of the shipped
// .ts files (the tree is left alone), and every message of every shipped language must have a
// finished translation with the source's placeholders, mnemonic and outer spaces. A string
// added to the code without a translation fails here; so does one lupdate cannot place in the
// context the program looks it up in. The checker itself is tried on planted faults, and the
// translations built into the program are loaded and used.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QTemporaryDir>

#include "app/i18n/Language.h"
#include "tests/app/i18n/TranslationCheck.h"

namespace {

using armtrack::test::checkTsFile;
using armtrack::test::describe;
using armtrack::test::runLupdate;

const QString kLupdate = QStringLiteral(ARMTRACK_LUPDATE);
const QString kSources = QStringLiteral(ARMTRACK_TRANSLATION_SOURCES_LIST);
const QString kRoot = QStringLiteral(ARMTRACK_SOURCE_DIR);

QStringList translationFiles() {
  return QStringLiteral(ARMTRACK_TS_FILES).split(u',', Qt::SkipEmptyParts);
}

/// A copy of ts in dir, brought up to date with the sources in list.
QString updatedCopy(const QTemporaryDir& dir, const QString& ts, const QString& list,
                    bool pluralOnly, QStringList* misplaced) {
  const QString copy = dir.filePath(QFileInfo(ts).fileName());
  QFile::remove(copy);
  EXPECT_TRUE(QFile::copy(ts, copy)) << ts.toStdString();
  QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
  *misplaced = runLupdate(kLupdate, kRoot, list, copy, pluralOnly);
  return copy;
}

TEST(Translations, EveryStringOfTodaysSourcesHasAFinishedTranslation) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  ASSERT_FALSE(translationFiles().isEmpty());
  for (const QString& ts : translationFiles()) {
    QStringList misplaced;
    const QString copy = updatedCopy(dir, ts, kSources, false, &misplaced);
    EXPECT_TRUE(misplaced.isEmpty()) << misplaced.join(u'\n').toStdString();
    const auto problems = checkTsFile(copy);
    EXPECT_TRUE(problems.empty())
        << problems.size() << " problems in " << ts.toStdString()
        << " (run the update_translations target and translate them; translations/README.md):\n"
        << describe(problems).toStdString();
  }
  QStringList misplaced;
  const QString plurals =
      updatedCopy(dir, QStringLiteral(ARMTRACK_PLURALS_TS), kSources, true, &misplaced);
  const auto problems = checkTsFile(plurals, true);
  EXPECT_TRUE(problems.empty()) << describe(problems).toStdString();
}

// Not a check that passes whatever happens: a string planted in the sources is reported, in
// every language, as the one problem.
TEST(Translations, APlantedUntranslatedStringFailsTheCheck) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString planted = dir.filePath(QStringLiteral("Planted.cpp"));
  {
    QFile f(planted);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("#include <QCoreApplication>\n"
            "QString planted() {\n"
            "  return QCoreApplication::translate(\"armtrack::test::Planted\",\n"
            "                                     \"A sentence no translator has seen yet\");\n"
            "}\n");
  }
  const QString list = dir.filePath(QStringLiteral("sources.lst"));
  {
    QFile in(kSources), out(list);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(in.readAll());
    out.write(planted.toUtf8() + '\n');
  }
  for (const QString& ts : translationFiles()) {
    QStringList misplaced;
    const auto problems = checkTsFile(updatedCopy(dir, ts, list, false, &misplaced));
    ASSERT_EQ(problems.size(), 1u) << ts.toStdString() << "\n" << describe(problems).toStdString();
    EXPECT_EQ(problems[0].context, QStringLiteral("armtrack::test::Planted"));
    EXPECT_EQ(problems[0].source, QStringLiteral("A sentence no translator has seen yet"));
    EXPECT_EQ(problems[0].what, QStringLiteral("translation is unfinished"));
  }
  // And a tr() lupdate cannot place (a class without Q_OBJECT) is reported too.
  {
    QFile f(planted);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write("#include <QObject>\n"
            "namespace armtrack { class Plain { public: QString f(); };\n"
            "QString Plain::f() { return QObject::tr(\"x\") + tr(\"Lost in no context\"); } }\n");
  }
  QStringList misplaced;
  updatedCopy(dir, translationFiles().front(), list, false, &misplaced);
  EXPECT_FALSE(misplaced.isEmpty());
}

// Each fault a translator can make, in a file made here, is named; a good entry is not.
TEST(Translations, TheCheckNamesEveryKindOfFault) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString ts = dir.filePath(QStringLiteral("faults_de.ts"));
  QFile f(ts);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(R"(<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>Faults</name>
    <message><source>&amp;Good %1</source><translation>&amp;Gut %1</translation></message>
    <message><source>Unfinished</source><translation type="unfinished">Fast</translation></message>
    <message><source>Gone</source><translation type="vanished">Weg</translation></message>
    <message><source>Empty</source><translation></translation></message>
    <message><source>%1 of %2</source><translation>%1 von %1</translation></message>
    <message><source>%L1 cm</source><translation>%1 cm</translation></message>
    <message><source>&amp;Save</source><translation>Speichern</translation></message>
    <message><source> cm</source><translation>cm</translation></message>
    <message numerus="yes"><source>%n pages</source><translation><numerusform>%n Seite</numerusform><numerusform></numerusform></translation></message>
    <message numerus="yes"><source>%n rows</source><translation><numerusform>eine Zeile</numerusform><numerusform>%n Zeilen</numerusform></translation></message>
</context>
</TS>
)");
  f.close();
  const auto problems = checkTsFile(ts);
  QStringList faulty;
  for (const auto& p : problems) faulty << p.source;
  EXPECT_EQ(faulty, (QStringList{"Unfinished", "Gone", "Empty", "%1 of %2", "%L1 cm", "&Save",
                                 " cm", "%n pages", "%n rows"}))
      << describe(problems).toStdString();
  // The plural-only file must hold texts with %n only.
  const auto plurals = checkTsFile(ts, true);
  EXPECT_GT(plurals.size(), problems.size());
  // Not a .ts file, or none at all.
  EXPECT_EQ(checkTsFile(dir.filePath(QStringLiteral("missing.ts"))).size(), 1u);
}

// The .qm files built into the program load and translate: the words on screen and the
// locale's numbers change with the language, and English gives its plural forms.
TEST(Translations, TheBuiltInTranslationsAreUsed) {
  using namespace armtrack::i18n;
  QStringList codes;
  for (const Language& l : shippedLanguages()) codes << l.code;
  EXPECT_EQ(codes, (QStringList{"en", "de", "es"}));
  EXPECT_EQ(shippedLanguages()[1].nativeName, QStringLiteral("Deutsch"));
  EXPECT_EQ(shippedLanguages()[2].nativeName, QStringLiteral("Español"));
  EXPECT_EQ(shippedLanguageFor(QStringLiteral("de_AT")), QStringLiteral("de"));
  EXPECT_EQ(shippedLanguageFor(QStringLiteral("es-MX")), QStringLiteral("es"));
  EXPECT_EQ(shippedLanguageFor(QStringLiteral("fr")), QString());
  EXPECT_EQ(shippedLanguageFor(QStringLiteral("xx-garbage")), QString());

  const auto flexion = [] {
    return QCoreApplication::translate("armtrack::ui::Angles", "Shoulder flexion");
  };
  const auto pages = [](int n) {
    return QCoreApplication::translate("armtrack::gui::ReviewScreen",
                                       "Session report written: %1 (%n page(s)).", nullptr, n)
        .arg(QStringLiteral("a.pdf"));
  };
  {
    const ScopedLanguage de(QStringLiteral("de"));
    EXPECT_EQ(de.language(), QStringLiteral("de"));
    EXPECT_EQ(flexion(), QStringLiteral("Schulterflexion"));
    EXPECT_EQ(pages(1), QStringLiteral("Sitzungsbericht geschrieben: a.pdf (1 Seite)."));
    EXPECT_EQ(QStringLiteral("%L1").arg(85.2, 0, 'f', 1), QStringLiteral("85,2"));
  }
  EXPECT_EQ(flexion(), QStringLiteral("Shoulder flexion")) << "the scope removes the translators";
  {
    const ScopedLanguage es(QStringLiteral("es_ES"));
    EXPECT_EQ(flexion(), QStringLiteral("Flexión de hombro"));
    EXPECT_EQ(pages(3), QStringLiteral("Informe de la sesión escrito: a.pdf (3 páginas)."));
  }
  {
    const ScopedLanguage en(QStringLiteral("en"));
    EXPECT_EQ(pages(1), QStringLiteral("Session report written: a.pdf (1 page)."));
    EXPECT_EQ(pages(2), QStringLiteral("Session report written: a.pdf (2 pages)."));
  }
  {
    // A language ArmTrack does not speak: English words, French numbers.
    const ScopedLanguage fr(QStringLiteral("fr_FR"));
    EXPECT_EQ(fr.language(), QStringLiteral("en"));
    EXPECT_EQ(flexion(), QStringLiteral("Shoulder flexion"));
    EXPECT_EQ(QLocale().decimalPoint(), QStringLiteral(","));
  }
}

}  // namespace
