// Large readouts of the current clinical angles, for reading across the room, each with its
// confidence ("±3°"). An angle not to be trusted (a wide confidence, a lost sensor, the
// shoulder's heading resting on the start pose without a camera) is shown on amber with the
// reason in words, so the mark does not rest on colour alone.
#pragma once

#include <QTimer>
#include <QWidget>
#include <array>
#include <optional>

#include "ui/AngleTrace.h"

class QLabel;

namespace armtrack::ui {

class AngleReadouts : public QWidget {
  Q_OBJECT
 public:
  explicit AngleReadouts(QWidget* parent = nullptr);

  /// The newest values; shown at the next refresh (at most refreshRate() a second, default 10,
  /// so the digits can be read). nullptr clears them.
  void setSample(const AngleSample* sample);
  /// An angle is marked uncertain when its confidence (2-sigma half-width) exceeds this (deg,
  /// default 10) or its sensor is lost (angleDoubt()).
  void setUncertainAboveDeg(double deg) { m_uncertainAbove = deg; }
  /// 0: only refresh() or refreshIfChanged() redraw.
  void setRefreshRate(double hz);
  void refreshIfChanged() {
    if (m_dirty) refresh();
  }
  /// Lays the readouts out in one row (wide) or a grid (narrow).
  void setColumns(int columns);

  /// For tests: the text shown and whether the angle is marked uncertain.
  QString valueText(int angle) const;
  /// The line under the value: its confidence and, in doubt, why.
  QString noteText(int angle) const;
  bool isUncertain(int angle) const { return m_uncertain[static_cast<std::size_t>(angle)]; }

 public slots:
  void refresh();

 protected:
  void changeEvent(QEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  struct Readout {
    QWidget* box = nullptr;
    QLabel* name = nullptr;
    QLabel* value = nullptr;
    QLabel* note = nullptr;
  };
  void applyFonts();
  void applyColours();
  void retranslateUi();

  std::array<Readout, kAngleCount> m_readouts;
  std::array<bool, kAngleCount> m_uncertain{};
  std::optional<AngleSample> m_sample;
  bool m_dirty = true;
  double m_uncertainAbove = 10.0;
  int m_columns = kAngleCount;
  QTimer m_timer;
};

}  // namespace armtrack::ui
