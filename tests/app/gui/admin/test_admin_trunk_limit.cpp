// The trunk limit in the administrator's protocol and exercise forms (issue 26): a spin box whose
// lowest value says "Off" (a protocol) or "the protocol's (...)" (an exercise), reached from the
// keyboard, giving an empty limit there and the degrees above it.
#include <QDoubleSpinBox>
#include <QTest>

#include "app/gui/admin/AdminDialogs.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack;
using namespace armtrack::gui::admin;
using armtrack::gui::test::findControl;

namespace {

storage::Protocol reach(std::optional<double> limit) {
  storage::Protocol p;
  p.name = QStringLiteral("Reach");
  p.angleKey = QStringLiteral("shoulder_flexion");
  p.targetMaxDeg = 100;
  p.repetitions = 8;
  p.trunkLimitDeg = limit;
  return p;
}

}  // namespace

class TestAdminTrunkLimit : public QObject {
  Q_OBJECT

 private slots:
  void aProtocolsLimitIsOffAtTheBottom() {
    ProtocolDialog dialog(reach(std::nullopt), nullptr);
    auto* box = findControl<QDoubleSpinBox>(&dialog, QStringLiteral("Trunk limit"));
    QVERIFY(box);
    QCOMPARE(box->value(), 0.0);
    QCOMPARE(box->text(), QStringLiteral("Off"));
    QVERIFY(!dialog.protocol().trunkLimitDeg);
    // Keyboard: up once from Off gives 1 deg, typing gives any whole value up to 90.
    dialog.show();
    box->setFocus();
    QTest::keyClick(box, Qt::Key_Up);
    QCOMPARE(dialog.protocol().trunkLimitDeg, std::optional(1.0));
    box->selectAll();
    QTest::keyClicks(box, QStringLiteral("15"));
    QCOMPARE(dialog.protocol().trunkLimitDeg, std::optional(15.0));
    box->selectAll();
    QTest::keyClicks(box, QStringLiteral("500"));
    box->interpretText();
    QVERIFY(dialog.protocol().trunkLimitDeg.value_or(0) <= 90.0);
    box->setValue(0);
    QVERIFY(!dialog.protocol().trunkLimitDeg);
  }

  void aProtocolWithALimitShowsIt() {
    ProtocolDialog dialog(reach(12.0), nullptr);
    auto* box = findControl<QDoubleSpinBox>(&dialog, QStringLiteral("Trunk limit"));
    QVERIFY(box);
    QCOMPARE(box->value(), 12.0);
    QCOMPARE(dialog.protocol().trunkLimitDeg, std::optional(12.0));
  }

  void anExerciseTakesItsProtocolsUnlessGivenItsOwn() {
    const std::vector<storage::Protocol> protocols{reach(15.0), [] {
                                                     storage::Protocol p = reach(std::nullopt);
                                                     p.name = QStringLiteral("Bend");
                                                     return p;
                                                   }()};
    ExerciseDialog dialog(protocols, std::nullopt, nullptr);
    auto* box = findControl<QDoubleSpinBox>(&dialog, QStringLiteral("Trunk limit"));
    QVERIFY(box);
    QCOMPARE(box->text(), QStringLiteral("the protocol's (15 deg)"));
    QVERIFY(!dialog.item().trunkLimitDeg);
    auto* protocol = findControl<QComboBox>(&dialog, QStringLiteral("Protocol"));
    QVERIFY(protocol);
    protocol->setCurrentIndex(1);
    QCOMPARE(box->text(), QStringLiteral("the protocol's (off)"));
    box->setValue(20);
    QCOMPARE(dialog.item().trunkLimitDeg, std::optional(20.0));
    // An existing exercise with its own limit opens with it.
    storage::ProgrammeItem own;
    own.protocolName = QStringLiteral("Reach");
    own.trunkLimitDeg = 8;
    ExerciseDialog edit(protocols, own, nullptr);
    QCOMPARE(findControl<QDoubleSpinBox>(&edit, QStringLiteral("Trunk limit"))->value(), 8.0);
    QCOMPARE(edit.item().trunkLimitDeg, std::optional(8.0));
  }
};

QTEST_MAIN(TestAdminTrunkLimit)
#include "test_admin_trunk_limit.moc"
