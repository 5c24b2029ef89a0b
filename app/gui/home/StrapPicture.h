// A picture of the arm with its two sensors, drawn by the program: how they are worn now (as the
// sensor check found them) beside how they should be, so a wrong strap or swapped sensors are
// shown, not only said.
#pragma once

#include <QImage>
#include <QWidget>

#include "core/calibration/SensorCheck.h"
#include "core/kinematics/Side.h"

namespace armtrack::gui::home {

class StrapPicture : public QWidget {
  Q_OBJECT
 public:
  explicit StrapPicture(QWidget* parent = nullptr);

  /// The sensors as found: findings empty shows them worn right (one panel); otherwise two
  /// panels, "Now" and "How it should be".
  void setFindings(const std::vector<SensorFinding>& findings);
  const std::vector<SensorFinding>& findings() const { return m_findings; }
  /// The arm wearing the sensors: the captions name it ("your right arm").
  void setSide(Side side);
  Side side() const { return m_side; }
  /// The captions drawn (for the tests): one per panel.
  QStringList captions() const;
  /// Where the drawing goes in a panel of area: the figure (head to hand) and the caption's band,
  /// which do not overlap and stay inside area.
  static QRectF figureRect(const QRectF& area);
  static QRectF captionRect(const QRectF& area);
  /// The picture alone, at size (for the user guide and the tests).
  QImage image(const QSize& size) const;

  QSize sizeHint() const override { return {560, 380}; }
  bool hasHeightForWidth() const override { return true; }
  int heightForWidth(int w) const override { return w * 380 / 560; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  void paint(QPainter& p, const QRectF& area) const;
  void paintArm(QPainter& p, const QRectF& area, const std::vector<SensorFinding>& findings,
                const QString& caption, bool wrong) const;
  void describe();

  std::vector<SensorFinding> m_findings;
  Side m_side = Side::Right;
};

}  // namespace armtrack::gui::home
