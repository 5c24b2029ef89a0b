// The patient dialog's birth date typed the ways people type it, in English and German: from the
// keyboard after Tab (with and without a previous date, after Up, after Ctrl+A), pasted, picked
// from the calendar, cleared; the saved date is the one typed. Impossible dates are refused in
// words naming the field and the range, keeping what was typed. Also the dialog's tab order and
// a problem message that goes once its field is mended.
#include <QAbstractSpinBox>
#include <QApplication>
#include <QCalendarWidget>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>

#include "app/gui/common/Forms.h"
#include "app/gui/patients/BirthDateField.h"
#include "app/gui/patients/PatientDialog.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack::gui;
using armtrack::gui::test::findControl;
using armtrack::storage::Patient;

namespace {

QWidget* focused() {
  return QApplication::focusWidget();
}

void typeKeys(const QString& text) {
  QTest::keyClicks(focused(), text);
}

}  // namespace

class TestBirthDate : public QObject {
  Q_OBJECT

  struct Open {
    std::unique_ptr<PatientDialog> dialog;
    std::unique_ptr<QSignalSpy> saved;
  };

  static Open open(const QString& birthDate, bool adding = false) {
    Patient p;
    if (!adding) {
      p.code = QStringLiteral("P100");
      p.name = QStringLiteral("Erna Müller");
    }
    p.birthDate = birthDate;
    Open o;
    o.dialog = std::make_unique<PatientDialog>(p);
    o.saved = std::make_unique<QSignalSpy>(o.dialog.get(), &PatientDialog::saveRequested);
    o.dialog->show();
    if (!test::activate(o.dialog.get())) o.dialog.reset();
    return o;
  }

  /// Tab from the name into Born, as a person reaches it.
  static bool tabIntoBorn(PatientDialog* d) {
    auto* name = findControl<QLineEdit>(d, QStringLiteral("Patient name"));
    name->setFocus();
    QTest::keyClick(name, Qt::Key_Tab);
    return focused() && focused()->accessibleName() == QStringLiteral("Birth date");
  }

  static void setLocale(const QString& name) {
    QLocale::setDefault(name == QLatin1String("de")
                            ? QLocale(QLocale::German, QLocale::Germany)
                            : QLocale(QLocale::English, QLocale::UnitedStates));
  }

 private slots:
  void cleanup() { QLocale::setDefault(QLocale::c()); }

  void theSavedDateIsTheTypedOne_data() {
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("before");
    QTest::addColumn<QString>("keys");  // "|"-separated steps: text, or <Up>, <Down>, ...
    QTest::addColumn<QString>("expected");
    for (const QString& locale : {QStringLiteral("en"), QStringLiteral("de")}) {
      const bool de = locale == QLatin1String("de");
      const QString own = de ? QStringLiteral("02.11.1947") : QStringLiteral("11/2/1947");
      const QString ownShort = de ? QStringLiteral("2.11.47") : QStringLiteral("11/02/47");
      const auto row = [&](const char* what, const QString& before, const QString& keys,
                           const QString& expected) {
        QTest::addRow("%s %s", qPrintable(locale), what) << locale << before << keys << expected;
      };
      const QString d = QStringLiteral("1947-11-02");
      row("ISO after Tab", {}, d, d);
      row("Up then ISO", {}, QStringLiteral("<Up>|") + d, d);
      row("Up then ISO over a date", QStringLiteral("1958-03-14"),
          QStringLiteral("<Up>|<SelectAll>|") + d, d);
      row("ISO over a date", QStringLiteral("1958-03-14"), d, d);
      row("ISO, second case", {}, QStringLiteral("1958-03-14"), QStringLiteral("1958-03-14"));
      row("language's format", {}, own, d);
      row("language's format over a date", QStringLiteral("1958-03-14"), own, d);
      row("two-digit year", {}, ownShort, d);
      row("Ctrl+A then type", QStringLiteral("1958-03-14"),
          QStringLiteral("<End>|<SelectAll>|") + own, d);
      row("pasted", QStringLiteral("1958-03-14"),
          QStringLiteral("<Paste> ") + own + QStringLiteral(" "), d);
      row("Down steps back a day", QStringLiteral("1947-11-03"), QStringLiteral("<Down>"), d);
      row("Up steps on a day", QStringLiteral("1947-11-01"), QStringLiteral("<Up>"), d);
      row("calendar", QStringLiteral("1947-11-01"), QStringLiteral("<Calendar>"), d);
      row("cleared", QStringLiteral("1958-03-14"), QStringLiteral("<Delete>"), QString());
      row("left empty", {}, QString(), QString());
      row("kept", QStringLiteral("1958-03-14"), QString(), QStringLiteral("1958-03-14"));
      row("the earliest", {}, QStringLiteral("1900-01-01"), QStringLiteral("1900-01-01"));
      row("today", {}, QDate::currentDate().toString(Qt::ISODate),
          QDate::currentDate().toString(Qt::ISODate));
    }
  }

  void theSavedDateIsTheTypedOne() {
    QFETCH(QString, locale);
    QFETCH(QString, before);
    QFETCH(QString, keys);
    QFETCH(QString, expected);
    setLocale(locale);
    Open o = open(before);
    QVERIFY(o.dialog);
    QVERIFY(tabIntoBorn(o.dialog.get()));
    for (const QString& step : keys.split(u'|', Qt::SkipEmptyParts)) {
      if (step == QLatin1String("<Up>")) {
        QTest::keyClick(focused(), Qt::Key_Up);
      } else if (step == QLatin1String("<Down>")) {
        QTest::keyClick(focused(), Qt::Key_Down);
      } else if (step == QLatin1String("<End>")) {
        QTest::keyClick(focused(), Qt::Key_End);
      } else if (step == QLatin1String("<SelectAll>")) {
        QTest::keyClick(focused(), Qt::Key_A, Qt::ControlModifier);
      } else if (step == QLatin1String("<Delete>")) {
        QTest::keyClick(focused(), Qt::Key_Delete);
      } else if (step.startsWith(QLatin1String("<Paste>"))) {
        QApplication::clipboard()->setText(step.mid(7));
        QTest::keyClick(focused(), Qt::Key_V, Qt::ControlModifier);
      } else if (step == QLatin1String("<Calendar>")) {
        QTest::keyClick(focused(), Qt::Key_Down, Qt::AltModifier);
        QCalendarWidget* calendar = nullptr;
        QTRY_VERIFY((calendar = o.dialog->findChild<QCalendarWidget*>()) && calendar->isVisible());
        QTest::keyClick(focused(), Qt::Key_Right);  // the next day
        QTest::keyClick(focused(), Qt::Key_Return);
        QTRY_VERIFY(!calendar->isVisible());
      } else {
        typeKeys(step);
      }
    }
    QTest::keyClick(focused(), Qt::Key_Return);  // Save is the default button
    QVERIFY2(o.saved->count() == 1,
             qPrintable(armtrack::gui::test::visibleMessage(o.dialog.get())));
    const Patient saved = o.saved->at(0).at(0).value<Patient>();
    QCOMPARE(saved.birthDate, expected);
  }

  void impossibleDatesAreRefusedInWords_data() {
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("typed");
    for (const QString& locale : {QStringLiteral("en"), QStringLiteral("de")})
      for (const QString& typed :
           {QStringLiteral("1800-01-01"), QStringLiteral("1899-12-31"),
            QDate::currentDate().addDays(1).toString(Qt::ISODate), QStringLiteral("2230-01-01"),
            QStringLiteral("1947-02-30"), QStringLiteral("31.02.1947"),
            QStringLiteral("13/13/1947"), QStringLiteral("not given9471102"),
            QStringLiteral("yesterday"), QStringLiteral("1947"), QStringLiteral("1.2.3.4"),
            QStringLiteral("99999-01-01"), QStringLiteral("'; DROP TABLE patients; --")})
        QTest::addRow("%s %s", qPrintable(locale), qPrintable(typed)) << locale << typed;
  }

  void impossibleDatesAreRefusedInWords() {
    QFETCH(QString, locale);
    QFETCH(QString, typed);
    setLocale(locale);
    Open o = open(QStringLiteral("1958-03-14"));
    QVERIFY(o.dialog);
    QVERIFY(tabIntoBorn(o.dialog.get()));
    typeKeys(typed);
    QTest::keyClick(focused(), Qt::Key_Return);
    QCOMPARE(o.saved->count(), 0);
    const QString said = armtrack::gui::test::visibleMessage(o.dialog.get());
    // The field, and the range with its first year.
    QVERIFY2(said.startsWith(QStringLiteral("Born:")) && said.contains(QStringLiteral("1900")),
             qPrintable(said));
    QCOMPARE(focused()->accessibleName(), QStringLiteral("Birth date"));
    QCOMPARE(qobject_cast<QLineEdit*>(focused())->text(), typed);  // nothing changed behind
    // Mended, it saves; the problem goes as soon as the date is right.
    QTest::keyClick(focused(), Qt::Key_A, Qt::ControlModifier);
    typeKeys(QStringLiteral("1947-11-02"));
    QCOMPARE(armtrack::gui::test::visibleMessage(o.dialog.get()), QString());
    QTest::keyClick(focused(), Qt::Key_Return);
    QCOMPARE(o.saved->count(), 1);
    QCOMPARE(o.saved->at(0).at(0).value<Patient>().birthDate, QStringLiteral("1947-11-02"));
  }

  void twoDigitYearsAreTheLatestPast() {
    const QDate today(2026, 11, 28);
    const QLocale de(QLocale::German, QLocale::Germany);
    QCOMPARE(BirthDateField::parse(QStringLiteral("02.11.47"), de, today), QDate(1947, 11, 2));
    QCOMPARE(BirthDateField::parse(QStringLiteral("02.11.05"), de, today), QDate(2005, 11, 2));
    QCOMPARE(BirthDateField::parse(QStringLiteral("28.11.26"), de, today), QDate(2026, 11, 28));
    QCOMPARE(BirthDateField::parse(QStringLiteral("29.11.26"), de, today), QDate(1926, 11, 29));
    QCOMPARE(BirthDateField::parse(QStringLiteral("19471102"), de, today), QDate(1947, 11, 2));
    QVERIFY(!BirthDateField::parse(QStringLiteral("29.02.47"), de, today).isValid());
  }

  void tabFollowsTheScreen() {
    Open o = open({}, true);
    QVERIFY(o.dialog);
    QCOMPARE(focused()->accessibleName(), QStringLiteral("Patient code"));
    QStringList seen;
    for (int i = 0; i < 11; ++i) {
      seen << focused()->accessibleName();
      QTest::keyClick(focused(), Qt::Key_Tab);
    }
    const QStringList expected = {QStringLiteral("Patient code"),
                                  QStringLiteral("Patient name"),
                                  QStringLiteral("Birth date"),
                                  QStringLiteral("Sex"),
                                  QStringLiteral("Affected side"),
                                  QStringLiteral("Diagnosis"),
                                  QStringLiteral("Upper arm length"),
                                  QStringLiteral("Forearm length"),
                                  QStringLiteral("Upper-arm IMU distance from the shoulder"),
                                  QStringLiteral("Forearm IMU distance from the elbow"),
                                  QStringLiteral("Notes")};
    QCOMPARE(seen, expected);
    // From the notes on to the buttons, not back to the code.
    QVERIFY(qobject_cast<QPushButton*>(focused()));
  }

  void aMendedProblemGoes() {
    Open o = open({}, true);
    QVERIFY(o.dialog);
    QTest::keyClick(focused(), Qt::Key_Return);
    QVERIFY2(armtrack::gui::test::visibleMessage(o.dialog.get()).contains(QStringLiteral("code")),
             qPrintable(armtrack::gui::test::visibleMessage(o.dialog.get())));
    typeKeys(QStringLiteral("P7"));
    QCOMPARE(armtrack::gui::test::visibleMessage(o.dialog.get()), QString());
    QCOMPARE(o.saved->count(), 0);
  }
};

ARMTRACK_APP_TEST_MAIN(TestBirthDate)
#include "test_birth_date.moc"
