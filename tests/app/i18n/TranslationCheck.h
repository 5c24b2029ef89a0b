// Checks a Qt Linguist .ts file the way a reader of the program would: every message has a
// finished translation that keeps the source's placeholders, its keyboard mnemonic and its
// outer spaces. Used by test_translations (translations/README.md).
#pragma once

#include <QString>
#include <QStringList>
#include <vector>

namespace armtrack::test {

struct TranslationProblem {
  QString context, source, what;
};

/// The problems of a .ts file. pluralOnly: the file holds only the plural forms of texts with
/// %n (armtrack_en.ts), so every message must be numerus. A file that cannot be read is one
/// problem.
std::vector<TranslationProblem> checkTsFile(const QString& path, bool pluralOnly = false);

/// Runs lupdate over the sources named in listFile (an lupdate "@list" file) into tsFile, as
/// the update_translations target does (plural forms only with pluralOnly). Returns lupdate's
/// messages about strings it could not place in a context (empty when there are none); throws
/// std::runtime_error when lupdate cannot run.
QStringList runLupdate(const QString& lupdate, const QString& includeDir, const QString& listFile,
                       const QString& tsFile, bool pluralOnly = false);

/// "context: source: what", one per line.
QString describe(const std::vector<TranslationProblem>& problems);

}  // namespace armtrack::test
