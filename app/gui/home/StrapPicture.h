// A picture of the arm with its two sensors, drawn by the program: how they are worn now (as the
// sensor check found them) beside how they should be, so a wrong strap or swapped sensors are
// shown, not only said.
#pragma once

#include <QImage>
#include <QWidget>

#include "core/calibration/SensorCheck.h"

namespace armtrack::gui::home {

class StrapPicture : public QWidget {
  Q_OBJECT
 public:
  explicit StrapPicture(QWidget* parent = nullptr);

  /// The sensors as found: findings empty shows them worn right (one panel); otherwise two
  /// panels, "Now" and "How it should be".
  void setFindings(const std::vector<SensorFinding>& findings);
  const std::vector<SensorFinding>& findings() const { return m_findings; }
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
};

}  // namespace armtrack::gui::home
