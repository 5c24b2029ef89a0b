#include "app/gui/home/StrapPicture.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace armtrack::gui::home {

namespace {

const QColor kSkin(0xe8, 0xc0, 0x9c);
const QColor kOutline(0x10, 0x10, 0x10);
const QColor kUpperSensor(0x0b, 0x3d, 0x91);    // dark blue
const QColor kForearmSensor(0xb3, 0x4a, 0x00);  // dark orange
const QColor kWrong(0xc0, 0x00, 0x00);
const QColor kRight(0x00, 0x7a, 0x2e);

bool has(const std::vector<SensorFinding>& f, SensorFinding x) {
  return std::find(f.begin(), f.end(), x) != f.end();
}

// A sensor box on a segment from a to b: label, colour, turned end over end or tilted.
void paintSensor(QPainter& p, QPointF a, QPointF b, const QString& label, const QColor& colour,
                 bool upsideDown, bool tilted, double unit) {
  const QPointF centre = (a + b) / 2;
  const double along = std::atan2(b.y() - a.y(), b.x() - a.x()) * 180 / M_PI;
  p.save();
  p.translate(centre);
  p.rotate(along - 90 + (tilted ? 50 : 0) + (upsideDown ? 180 : 0));
  const QRectF box(-1.6 * unit, -2.2 * unit, 3.2 * unit, 4.4 * unit);
  p.setPen(QPen(kOutline, 0.25 * unit));
  p.setBrush(colour);
  p.drawRoundedRect(box, 0.5 * unit, 0.5 * unit);
  // The arrow printed on the sensor: it points to the shoulder when worn right.
  QPainterPath arrow;
  arrow.moveTo(0, 1.4 * unit);
  arrow.lineTo(0, -1.2 * unit);
  arrow.moveTo(-0.8 * unit, -0.3 * unit);
  arrow.lineTo(0, -1.4 * unit);
  arrow.lineTo(0.8 * unit, -0.3 * unit);
  p.setPen(QPen(Qt::white, 0.35 * unit, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  p.setBrush(Qt::NoBrush);
  p.drawPath(arrow);
  p.restore();
  // The label beside the box, always upright.
  QFont f = p.font();
  f.setPixelSize(std::max(8, static_cast<int>(1.3 * unit)));
  f.setBold(true);
  p.setFont(f);
  p.setPen(colour);
  p.drawText(QRectF(centre.x() + 2.4 * unit, centre.y() - unit, 14 * unit, 2 * unit),
             Qt::AlignLeft | Qt::AlignVCenter, label);
}

}  // namespace

StrapPicture::StrapPicture(QWidget* parent) : QWidget(parent) {
  setMinimumSize(280, 190);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  describe();
}

void StrapPicture::setFindings(const std::vector<SensorFinding>& findings) {
  m_findings = findings;
  describe();
  update();
}

QImage StrapPicture::image(const QSize& size) const {
  QImage img(size, QImage::Format_ARGB32_Premultiplied);
  img.fill(Qt::white);
  QPainter p(&img);
  paint(p, QRectF(QPointF(0, 0), QSizeF(size)));
  return img;
}

void StrapPicture::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), Qt::white);
  paint(p, rect());
}

void StrapPicture::setSide(Side side) {
  m_side = side;
  describe();
  update();
}

QStringList StrapPicture::captions() const {
  // "Right" would read as "correct" too: the arm is named, and "correctly" said so.
  if (m_findings.empty())
    return {m_side == Side::Left ? tr("Worn correctly on your left arm")
                                 : tr("Worn correctly on your right arm")};
  return {m_side == Side::Left ? tr("Now, on your left arm") : tr("Now, on your right arm"),
          tr("How it should be")};
}

// A panel is 28 units wide and 23 high: the caption's band on top (4 units, two lines at most),
// then the figure from the top of the head (1.4 units above its origin) to the bottom of
// the hand (17.1 units below it).
namespace {
constexpr double kPanelW = 28, kPanelH = 23, kCaptionH = 4, kHeadAbove = 1.6, kHandBelow = 17.1;
double unitOf(const QRectF& area) {
  return std::min(area.width() / kPanelW, area.height() / kPanelH);
}
}  // namespace

QRectF StrapPicture::captionRect(const QRectF& area) {
  const double unit = unitOf(area);
  return {area.left() + 0.5 * unit, area.top() + 0.2 * unit, area.width() - unit,
          kCaptionH * unit - 0.4 * unit};
}

QRectF StrapPicture::figureRect(const QRectF& area) {
  const double unit = unitOf(area);
  const QPointF origin(area.center().x() - 6 * unit,
                       area.top() + (kCaptionH + kHeadAbove + 0.2) * unit);
  // Head (left of the trunk) to the sensor labels on the right, head top to hand bottom.
  return {origin.x() - 3.8 * unit, origin.y() - kHeadAbove * unit, 20.6 * unit,
          (kHeadAbove + kHandBelow) * unit};
}

void StrapPicture::paint(QPainter& p, const QRectF& area) const {
  p.setRenderHint(QPainter::Antialiasing);
  const QStringList c = captions();
  if (m_findings.empty()) {
    paintArm(p, area, {}, c[0], false);
    return;
  }
  const QRectF left(area.left(), area.top(), area.width() / 2, area.height());
  const QRectF right(area.center().x(), area.top(), area.width() / 2, area.height());
  paintArm(p, left, m_findings, c[0], true);
  paintArm(p, right, {}, c[1], false);
  p.setPen(QPen(QColor(0x90, 0x90, 0x90), 2));
  p.drawLine(QPointF(area.center().x(), area.top() + 8),
             QPointF(area.center().x(), area.bottom() - 8));
}

void StrapPicture::paintArm(QPainter& p, const QRectF& area, const std::vector<SensorFinding>& f,
                            const QString& caption, bool wrong) const {
  const double unit = unitOf(area);
  const QPointF origin = figureRect(area).topLeft() + QPointF(3.8 * unit, kHeadAbove * unit);
  const auto at = [&](double x, double y) { return origin + QPointF(x * unit, y * unit); };
  // The body from the side: head, trunk; the arm hanging straight, as in the check.
  p.setPen(QPen(kOutline, 0.2 * unit));
  p.setBrush(QColor(0xf4, 0xf4, 0xf4));
  p.drawEllipse(at(-1.4, 0.6), 1.8 * unit, 2.0 * unit);
  p.drawRoundedRect(QRectF(at(-3.6, 2.8), at(0.8, 15.5)), unit, unit);
  const QPointF shoulder = at(0, 4), elbow = at(0.6, 9.6), wrist = at(1.2, 14.6);
  p.setPen(QPen(kOutline, 2.6 * unit, Qt::SolidLine, Qt::RoundCap));
  p.drawLine(shoulder, elbow);
  p.drawLine(elbow, wrist);
  p.setPen(QPen(kSkin, 2.1 * unit, Qt::SolidLine, Qt::RoundCap));
  p.drawLine(shoulder, elbow);
  p.drawLine(elbow, wrist);
  p.setBrush(kSkin);
  p.setPen(QPen(kOutline, 0.2 * unit));
  p.drawEllipse(at(1.3, 15.8), 1.0 * unit, 1.3 * unit);

  const bool swapped = has(f, SensorFinding::Swapped);
  const QString upperLabel = tr("upper-arm sensor"), foreLabel = tr("forearm sensor");
  // What sits on each segment (after a swap, each sensor is on the other's segment).
  paintSensor(p, shoulder, elbow, swapped ? foreLabel : upperLabel,
              swapped ? kForearmSensor : kUpperSensor, has(f, SensorFinding::UpperArmUpsideDown),
              has(f, SensorFinding::UpperArmTilted), unit);
  paintSensor(p, elbow, wrist, swapped ? upperLabel : foreLabel,
              swapped ? kUpperSensor : kForearmSensor, has(f, SensorFinding::ForearmUpsideDown),
              has(f, SensorFinding::ForearmTilted), unit);
  // Caption with a cross or a tick, so it does not rest on colour alone.
  QFont font = p.font();
  font.setPixelSize(std::max(9, static_cast<int>(1.5 * unit)));
  font.setBold(true);
  p.setFont(font);
  p.setPen(wrong ? kWrong : kRight);
  p.drawText(captionRect(area), Qt::AlignCenter | Qt::TextWordWrap,
             (wrong ? QStringLiteral("\u2717 ") : QStringLiteral("\u2713 ")) + caption);
}

void StrapPicture::describe() {
  QStringList parts;
  if (m_findings.empty())
    parts << tr(
        "The upper-arm sensor on the upper arm and the forearm "
        "sensor on the forearm, both with their arrow pointing up "
        "towards the shoulder.");
  for (SensorFinding f : m_findings) {
    switch (f) {
      case SensorFinding::Swapped:
        parts << tr("Now the two sensors are on each other's place.");
        break;
      case SensorFinding::UpperArmUpsideDown:
        parts << tr("Now the sensor on the upper arm has its arrow pointing down.");
        break;
      case SensorFinding::ForearmUpsideDown:
        parts << tr("Now the sensor on the forearm has its arrow pointing down.");
        break;
      case SensorFinding::UpperArmTilted:
        parts << tr("Now the sensor on the upper arm sits crooked.");
        break;
      case SensorFinding::ForearmTilted:
        parts << tr("Now the sensor on the forearm sits crooked.");
        break;
      case SensorFinding::TrunkUpsideDown:
      case SensorFinding::TrunkTurned:
        break;  // the chest sensor is not in the arm's picture; the text says what to do
    }
  }
  parts.prepend(m_side == Side::Left ? tr("Your left arm, seen from the side.")
                                     : tr("Your right arm, seen from the side."));
  setAccessibleName(tr("Picture of the sensors on the arm"));
  setAccessibleDescription(parts.join(u' '));
}

}  // namespace armtrack::gui::home
