#include "app/gui/newsession/CalibrationGuide.h"

#include <QCoreApplication>

namespace armtrack::app::gui {

namespace {
QString tr(const char* text) {
  return QCoreApplication::translate("armtrack::app::gui::CalibrationGuide", text);
}

std::vector<CalibrationPhase> makePhases() {
  using Pose = std::array<double, 5>;
  const Pose start{0, 0, 0, -90, 0};
  std::vector<CalibrationPhase> p;
  double t = 0;
  auto add = [&](double seconds, bool hold, const QString& title, const QString& text,
                 std::optional<Pose> pose) {
    p.push_back({t, t + seconds, hold, title, text, pose});
    t += seconds;
  };
  const QString startText =
      tr("Sit upright. Let the upper arm hang at the side, bend the elbow to a right angle, "
         "forearm pointing straight forward, thumb up. Keep still.");
  add(4.0, true, tr("Start pose"), startText, start);
  const struct {
    Pose pose;
    const char* title;
    const char* text;
  } poses[] = {
      {{90, 0, 0, -10, 0},
       QT_TRANSLATE_NOOP("armtrack::app::gui::CalibrationGuide", "Arm forward"),
       QT_TRANSLATE_NOOP("armtrack::app::gui::CalibrationGuide",
                         "Raise the arm forward to shoulder height, elbow almost straight.")},
      {{20, 60, 0, -10, 0},
       QT_TRANSLATE_NOOP("armtrack::app::gui::CalibrationGuide", "Arm to the side"),
       QT_TRANSLATE_NOOP("armtrack::app::gui::CalibrationGuide",
                         "Lift the arm out to the side, about 60 degrees, elbow almost "
                         "straight.")},
      {{45, 20, 45, -90, 60},
       QT_TRANSLATE_NOOP("armtrack::app::gui::CalibrationGuide", "Hand across"),
       QT_TRANSLATE_NOOP("armtrack::app::gui::CalibrationGuide",
                         "Bring the hand across the body, elbow at a right angle, palm down.")},
      {{0, 10, -30, -100, -60},
       QT_TRANSLATE_NOOP("armtrack::app::gui::CalibrationGuide", "Hand out"),
       QT_TRANSLATE_NOOP("armtrack::app::gui::CalibrationGuide",
                         "Take the hand out to the side, elbow bent, palm up.")},
  };
  for (const auto& s : poses) {
    add(2.0, false, tr(s.title), tr(s.text), s.pose);
    add(2.0, true, tr(s.title), tr("Hold still."), s.pose);
  }
  add(8.5, false, tr("Elbow bends"),
      tr("Bend and straighten the elbow four times, turning the palm down while straightening "
         "and up while bending."),
      std::nullopt);
  add(6.5, false, tr("Shoulder rotation"),
      tr("Elbow at a right angle: swing the hand in to the belly and out, three times."),
      std::nullopt);
  add(7.2, false, tr("Reach and mouth"),
      tr("Reach forward and up, then bring the hand to the mouth; three times."), std::nullopt);
  add(6.0, false, tr("Arm out and across"),
      tr("Lift the arm out to the side, then bring it back across; three times."), std::nullopt);
  add(2.0, false, tr("Back to the start pose"), startText, start);
  add(3.0, true, tr("Start pose"), tr("Hold still."), start);
  return p;
}
}  // namespace

const std::vector<CalibrationPhase>& calibrationPhases() {
  static const std::vector<CalibrationPhase> phases = makePhases();
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
