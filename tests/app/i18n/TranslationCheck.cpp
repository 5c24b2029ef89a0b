#include "tests/app/i18n/TranslationCheck.h"

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QXmlStreamReader>
#include <stdexcept>

namespace armtrack::test {

namespace {

struct Message {
  QString context, source;
  bool numerus = false;
  QString type;            // translation type: "", "unfinished", "vanished", "obsolete"
  QStringList forms;       // the translation, or its numerus forms
};

std::vector<Message> readTs(const QString& path, QString* error) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) {
    *error = QStringLiteral("cannot read %1: %2").arg(path, f.errorString());
    return {};
  }
  std::vector<Message> out;
  QXmlStreamReader xml(&f);
  QString context;
  while (!xml.atEnd()) {
    xml.readNext();
    if (!xml.isStartElement()) continue;
    if (xml.name() == QLatin1String("name")) {
      // <context><name>: the context of the messages that follow.
      context = xml.readElementText();
    } else if (xml.name() == QLatin1String("message")) {
      Message m;
      m.context = context;
      m.numerus = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
      while (!(xml.isEndElement() && xml.name() == QLatin1String("message")) && !xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement()) continue;
        if (xml.name() == QLatin1String("source")) {
          m.source = xml.readElementText();
        } else if (xml.name() == QLatin1String("translation")) {
          m.type = xml.attributes().value(QLatin1String("type")).toString();
          if (!m.numerus) m.forms << xml.readElementText(QXmlStreamReader::IncludeChildElements);
        } else if (xml.name() == QLatin1String("numerusform")) {
          m.forms << xml.readElementText();
        }
      }
      out.push_back(m);
    }
  }
  if (xml.hasError())
    *error = QStringLiteral("%1: not a .ts file (%2 at line %3)")
                 .arg(path, xml.errorString())
                 .arg(xml.lineNumber());
  return out;
}

/// %1..%99, %L1.., %n: each with its count, so a placeholder used twice must stay twice.
QMap<QString, int> placeholders(const QString& text) {
  static const QRegularExpression re(QStringLiteral("%(L?\\d{1,2}|n)"));
  QMap<QString, int> out;
  for (auto it = re.globalMatch(text); it.hasNext();) ++out[it.next().captured(0)];
  return out;
}

/// The keyboard mnemonic: an '&' before a letter or digit ("&&" is a plain ampersand, "&amp;"
/// and the like are HTML).
bool hasMnemonic(const QString& text) {
  static const QRegularExpression re(QStringLiteral("(?<!&)&(?!&)(?![a-z]+;)\\w"));
  return re.match(text).hasMatch();
}

}  // namespace

std::vector<TranslationProblem> checkTsFile(const QString& path, bool pluralOnly) {
  QString error;
  const std::vector<Message> messages = readTs(path, &error);
  if (!error.isEmpty()) return {{QString(), QString(), error}};
  if (messages.empty()) return {{QString(), QString(), QStringLiteral("no messages in %1").arg(path)}};
  std::vector<TranslationProblem> problems;
  for (const Message& m : messages) {
    const auto fail = [&](const QString& what) { problems.push_back({m.context, m.source, what}); };
    if (!m.type.isEmpty()) {
      fail(QStringLiteral("translation is %1").arg(m.type));
      continue;
    }
    if (pluralOnly && !m.numerus) fail(QStringLiteral("a text without %n in the plural-only file"));
    if (m.forms.isEmpty()) {
      fail(QStringLiteral("no translation"));
      continue;
    }
    const QMap<QString, int> wanted = placeholders(m.source);
    for (const QString& form : m.forms) {
      if (form.trimmed().isEmpty()) {
        fail(m.numerus ? QStringLiteral("an empty plural form") : QStringLiteral("empty"));
        continue;
      }
      if (placeholders(form) != wanted)
        fail(QStringLiteral("placeholders differ: \"%1\"").arg(form));
      if (hasMnemonic(m.source) != hasMnemonic(form))
        fail(QStringLiteral("the keyboard mnemonic (&) is %1: \"%2\"")
                 .arg(hasMnemonic(m.source) ? QStringLiteral("missing") : QStringLiteral("extra"),
                      form));
      const auto edges = [](const QString& s) {
        return QStringLiteral("%1%2").arg(s.front().isSpace()).arg(s.back().isSpace());
      };
      if (!m.source.isEmpty() && edges(m.source) != edges(form))
        fail(QStringLiteral("leading or trailing space differs: \"%1\"").arg(form));
    }
  }
  return problems;
}

QStringList runLupdate(const QString& lupdate, const QString& includeDir, const QString& listFile,
                       const QString& tsFile, bool pluralOnly) {
  QStringList args{QStringLiteral("-no-obsolete"), QStringLiteral("-locations"),
                   QStringLiteral("none"),         QStringLiteral("-I"),
                   includeDir,                     QLatin1Char('@') + listFile,
                   QStringLiteral("-ts"),          tsFile};
  if (pluralOnly) args.prepend(QStringLiteral("-pluralonly"));
  QProcess p;
  p.start(lupdate, args);
  if (!p.waitForFinished(120000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0)
    throw std::runtime_error(QStringLiteral("%1 failed: %2%3")
                                 .arg(lupdate, p.errorString(),
                                      QString::fromLocal8Bit(p.readAllStandardError()))
                                 .toStdString());
  // Strings lupdate could not give the context the program looks them up in.
  static const QRegularExpression misplaced(
      QStringLiteral("lacks Q_OBJECT|unknown namespace/class|Cannot invoke tr\\(\\)|"
                     "Discarding unconsumed|Circular namespace"));
  QStringList out;
  const QString all = QString::fromLocal8Bit(p.readAllStandardError() + p.readAllStandardOutput());
  for (const QString& line : all.split(u'\n'))
    if (misplaced.match(line).hasMatch()) out << line.trimmed();
  return out;
}

QString describe(const std::vector<TranslationProblem>& problems) {
  QStringList lines;
  for (const TranslationProblem& p : problems)
    lines << QStringLiteral("%1: \"%2\": %3").arg(p.context, p.source.left(80), p.what);
  return lines.join(u'\n');
}

}  // namespace armtrack::test
