// Fonts scaled from the user's own (so large readouts and titles follow the system's font size
// and high-DPI settings rather than fixed point sizes).
#pragma once

#include <QFont>
#include <QWidget>

namespace armtrack::ui {

/// base scaled by scale, bold unless said otherwise.
inline QFont scaledFont(QFont base, double scale, bool bold = true) {
  base.setPointSizeF(base.pointSizeF() * scale);
  base.setBold(bold);
  return base;
}

/// Gives w its own font scaled by scale (bold unless said otherwise).
inline void setScaledFont(QWidget* w, double scale, bool bold = true) {
  w->setFont(scaledFont(w->font(), scale, bold));
}

}  // namespace armtrack::ui
