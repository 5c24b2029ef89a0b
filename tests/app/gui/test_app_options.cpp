// armtrack's command line and its answer on a machine without a display: plain words and the
// xvfb-run command, never Qt's platform-plugin abort.
#include <QProcess>
#include <QTest>

#include "app/gui/AppOptions.h"
#include "app/gui/services/AppSettings.h"

using armtrack::gui::parseAppOptions;

class TestAppOptions : public QObject {
  Q_OBJECT

 private:
  static QStringList line(std::initializer_list<const char*> words) {
    QStringList l{QStringLiteral("armtrack")};
    for (const char* w : words) l << QString::fromUtf8(w);
    return l;
  }
  struct Run {
    int code;
    QString out, err;
  };
  static Run run(const QStringList& args, const QProcessEnvironment& env) {
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(ARMTRACK_GUI), args);
    if (!p.waitForFinished(30000)) {
      p.kill();
      p.waitForFinished();
      return {-1, {}, QStringLiteral("did not finish")};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2,
            QString::fromLocal8Bit(p.readAllStandardOutput()),
            QString::fromLocal8Bit(p.readAllStandardError())};
  }
  static QProcessEnvironment withoutDisplay() {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));
    return env;
  }

 private slots:
  void parsesEveryOption() {
    const auto o = parseAppOptions(
        line({"--db", "/tmp/x.db", "--demo", "--plugins", "/a", "--plugins=/b", "--lang=de"}));
    QVERIFY2(o.error.isEmpty(), qPrintable(o.error));
    QCOMPARE(o.database, QStringLiteral("/tmp/x.db"));
    QVERIFY(o.demo);
    QCOMPARE(o.pluginFolders, (QStringList{QStringLiteral("/a"), QStringLiteral("/b")}));
    QCOMPARE(o.language, QStringLiteral("de"));
    QVERIFY(!o.help && !o.version);
    const auto u = parseAppOptions(line({"--quit-after", "2.5", "--screenshot=/tmp/a.png"}));
    QVERIFY2(u.error.isEmpty(), qPrintable(u.error));
    QCOMPARE(u.quitAfterSeconds, 2.5);
    QCOMPARE(u.screenshot, QStringLiteral("/tmp/a.png"));
    QVERIFY(!u.quitWhenLive);
    const auto l = parseAppOptions(line({"--demo", "--quit-when-live", "--screenshot", "s.png"}));
    QVERIFY2(l.error.isEmpty(), qPrintable(l.error));
    QVERIFY(l.quitWhenLive);
    QCOMPARE(l.quitAfterSeconds, 0.0);
    QCOMPARE(l.screenshot, QStringLiteral("s.png"));
    const auto h = parseAppOptions(line({"--home", "--demo"}));
    QVERIFY2(h.error.isEmpty(), qPrintable(h.error));
    QVERIFY(h.home && h.demo);
    QVERIFY(!o.home);
  }

  void leavesQtOptionsForQApplication() {
    const auto o = parseAppOptions(line({"-platform", "xcb", "--demo", "-reverse"}));
    QVERIFY2(o.error.isEmpty(), qPrintable(o.error));
    QCOMPARE(o.qtArguments, (QStringList{QStringLiteral("armtrack"), QStringLiteral("-platform"),
                                         QStringLiteral("xcb"), QStringLiteral("-reverse")}));
  }

  void refusesWhatItDoesNotKnow_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("says");
    QTest::newRow("unknown") << line({"--frobnicate"}) << QStringLiteral("--frobnicate");
    QTest::newRow("stray word") << line({"patients.db"}) << QStringLiteral("patients.db");
    QTest::newRow("db without value") << line({"--db"}) << QStringLiteral("--db needs a value");
    QTest::newRow("empty db") << line({"--db="}) << QStringLiteral("--db needs a value");
    QTest::newRow("plugins without value")
        << line({"--demo", "--plugins"}) << QStringLiteral("--plugins needs a value");
    QTest::newRow("quit-after text") << line({"--quit-after", "soon"}) << QStringLiteral("'soon'");
    QTest::newRow("quit-after negative")
        << line({"--quit-after=-3"}) << QStringLiteral("positive number");
    QTest::newRow("quit-after nan") << line({"--quit-after", "nan"}) << QStringLiteral("'nan'");
    QTest::newRow("home without demo")
        << line({"--home"}) << QStringLiteral("--home goes with --demo");
    QTest::newRow("screenshot alone")
        << line({"--screenshot", "x.png"}) << QStringLiteral("--screenshot needs --quit-after");
    QTest::newRow("quit-when-live with a value")
        << line({"--quit-when-live=yes"}) << QStringLiteral("'--quit-when-live=yes'");
  }
  void refusesWhatItDoesNotKnow() {
    QFETCH(QStringList, args);
    QFETCH(QString, says);
    const auto o = parseAppOptions(args);
    QVERIFY2(o.error.contains(says), qPrintable(o.error));
  }

  void noDisplayIsExplainedWithXvfbRun() {
    const Run r = run({QStringLiteral("--demo")}, withoutDisplay());
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QStringLiteral("no")) && r.err.contains(QStringLiteral("display")),
             qPrintable(r.err));
    QVERIFY2(r.err.contains(QStringLiteral("xvfb-run -a -s '-screen 0 1280x800x24' armtrack")),
             qPrintable(r.err));
    QVERIFY2(!r.err.contains(QStringLiteral("qt.qpa")), qPrintable(r.err));
  }

  void unreachableDisplayIsExplained() {
    QProcessEnvironment env = withoutDisplay();
    env.insert(QStringLiteral("DISPLAY"), QStringLiteral(":93"));  // no server there
    const Run r = run({}, env);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QStringLiteral("\":93\"")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QStringLiteral("xvfb-run")), qPrintable(r.err));
    QVERIFY2(!r.err.contains(QStringLiteral("qt.qpa")), qPrintable(r.err));
  }

  void helpAndVersionNeedNoDisplay() {
    const Run help = run({QStringLiteral("--help")}, withoutDisplay());
    QCOMPARE(help.code, 0);
    QVERIFY(help.out.contains(QStringLiteral("--demo")));
    QVERIFY(help.out.contains(QStringLiteral("--plugins DIR")));
    QVERIFY(help.out.contains(QStringLiteral("--quit-when-live")));
    const Run version = run({QStringLiteral("--version")}, withoutDisplay());
    QCOMPARE(version.code, 0);
    QVERIFY2(version.out.startsWith(QStringLiteral("armtrack ")), qPrintable(version.out));
    const Run bad = run({QStringLiteral("--nonsense")}, withoutDisplay());
    QCOMPARE(bad.code, 2);
    QVERIFY2(bad.err.contains(QStringLiteral("--nonsense")), qPrintable(bad.err));
  }

  void settingsRoundTripAndRefuseGarbage() {
    QSettings s(QSettings::IniFormat, QSettings::UserScope, QStringLiteral("ArmTrackTest"),
                QStringLiteral("options"));
    s.clear();
    armtrack::gui::AppSettings a;
    a.dataFolder = QStringLiteral("/srv/armtrack");
    a.pluginFolders = {QStringLiteral("/opt/p1"), QStringLiteral("/opt/p2")};
    a.units = armtrack::gui::AppSettings::AngleUnit::Radians;
    a.filter = QStringLiteral("ukf");
    a.method = QStringLiteral("B");
    a.language = QStringLiteral("es");
    a.save(s);
    const auto b = armtrack::gui::AppSettings::load(s);
    QCOMPARE(b.dataFolder, a.dataFolder);
    QCOMPARE(b.pluginFolders, a.pluginFolders);
    QCOMPARE(b.units, a.units);
    QCOMPARE(b.filter, a.filter);
    QCOMPARE(b.method, a.method);
    QCOMPARE(b.language, a.language);
    QCOMPARE(b.effectiveDatabase().path, QStringLiteral("/srv/armtrack/armtrack.db"));
    // A hand-edited file with nonsense falls back to the defaults.
    s.setValue("analysis/filter", "kalman9000");
    s.setValue("analysis/method", "Z");
    s.setValue("display/units", 42);
    const auto c = armtrack::gui::AppSettings::load(s);
    QCOMPARE(c.filter, QStringLiteral("ekf"));
    QCOMPARE(c.method, QStringLiteral("A"));
    QCOMPARE(c.units, armtrack::gui::AppSettings::AngleUnit::Degrees);
    s.clear();
  }
};

QTEST_GUILESS_MAIN(TestAppOptions)
#include "test_app_options.moc"
