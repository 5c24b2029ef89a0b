#include "app/gui/common/CalibrationGuide.h"

#include <QCoreApplication>

namespace armtrack::app::gui {

namespace {

constexpr auto kContext = "armtrack::app::gui::CalibrationGuide";

// The texts are kept in English and translated when shown (CalibrationPhase::shownTitle()).
struct Guide {
  Q_DECLARE_TR_FUNCTIONS(armtrack::app::gui::CalibrationGuide)
 public:
  static std::vector<CalibrationPhase> makePhases();
};

QString text(const char* english) {
  return QString::fromUtf8(english);
}

std::vector<CalibrationPhase> Guide::makePhases() {
  using Pose = std::array<double, 5>;
  const Pose start{0, 0, 0, -90, 0};
  std::vector<CalibrationPhase> p;
  double t = 0;
  auto add = [&](double seconds, bool hold, const QString& title, const QString& text,
                 std::optional<Pose> pose) {
    p.push_back({t, t + seconds, hold, title, text, pose});
    t += seconds;
  };
  const QString startText = text(QT_TR_NOOP(
      "Sit upright. Let the upper arm hang at the side, bend the elbow to a right angle, "
      "forearm pointing straight forward, thumb up. Keep still."));
  const QString holdStill = text(QT_TR_NOOP("Hold still."));
  const QString startPose = text(QT_TR_NOOP("Start pose"));
  add(4.0, true, startPose, startText, start);
  const struct {
    Pose pose;
    QString title;
    QString text;
  } poses[] = {
      {{90, 0, 0, -10, 0},
       text(QT_TR_NOOP("Arm forward")),
       text(QT_TR_NOOP("Raise the arm forward to shoulder height, elbow almost straight."))},
      {{20, 60, 0, -10, 0},
       text(QT_TR_NOOP("Arm to the side")),
       text(QT_TR_NOOP("Lift the arm out to the side, about 60 degrees, elbow almost straight."))},
      {{45, 20, 45, -90, 60},
       text(QT_TR_NOOP("Hand across")),
       text(QT_TR_NOOP("Bring the hand across the body, elbow at a right angle, palm down."))},
      {{0, 10, -30, -100, -60},
       text(QT_TR_NOOP("Hand out")),
       text(QT_TR_NOOP("Take the hand out to the side, elbow bent, palm up."))},
  };
  for (const auto& s : poses) {
    add(2.0, false, s.title, s.text, s.pose);
    add(2.0, true, s.title, holdStill, s.pose);
  }
  add(8.5, false, text(QT_TR_NOOP("Elbow bends")),
      text(QT_TR_NOOP(
          "Bend and straighten the elbow four times, turning the palm down while straightening "
          "and up while bending.")),
      std::nullopt);
  add(6.5, false, text(QT_TR_NOOP("Shoulder rotation")),
      text(QT_TR_NOOP(
          "Elbow at a right angle: swing the hand in to the belly and out, three times.")),
      std::nullopt);
  add(7.2, false, text(QT_TR_NOOP("Reach and mouth")),
      text(QT_TR_NOOP("Reach forward and up, then bring the hand to the mouth; three times.")),
      std::nullopt);
  add(6.0, false, text(QT_TR_NOOP("Arm out and across")),
      text(QT_TR_NOOP("Lift the arm out to the side, then bring it back across; three times.")),
      std::nullopt);
  add(2.0, false, text(QT_TR_NOOP("Back to the start pose")), startText, start);
  add(3.0, true, startPose, holdStill, start);
  return p;
}
}  // namespace

QString CalibrationPhase::shownTitle() const {
  return QCoreApplication::translate(kContext, title.toUtf8().constData());
}

QString CalibrationPhase::shownInstruction() const {
  return QCoreApplication::translate(kContext, instruction.toUtf8().constData());
}

const std::vector<CalibrationPhase>& calibrationPhases() {
  static const std::vector<CalibrationPhase> phases = Guide::makePhases();
  return phases;
}

double protocolSeconds() {
  return calibrationPhases().back().endS;
}

const CalibrationPhase& phaseAt(double t) {
  for (const CalibrationPhase& p : calibrationPhases())
    if (t < p.endS) return p;
  return calibrationPhases().back();
}

}  // namespace armtrack::app::gui
