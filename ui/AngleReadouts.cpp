#include "ui/AngleReadouts.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <cmath>

#include "ui/AngleTableModel.h"
#include "ui/Fonts.h"

namespace armtrack::ui {

AngleReadouts::AngleReadouts(QWidget* parent) : QWidget(parent) {
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(4, 4, 4, 4);
  grid->setSpacing(6);
  for (int a = 0; a < kAngleCount; ++a) {
    Readout& r = m_readouts[static_cast<std::size_t>(a)];
    r.box = new QWidget(this);
    r.box->setAutoFillBackground(true);
    auto* v = new QVBoxLayout(r.box);
    v->setContentsMargins(8, 4, 8, 4);
    v->setSpacing(0);
    r.name = new QLabel(r.box);
    r.name->setWordWrap(true);
    r.value = new QLabel(formatDegrees(std::nan("")), r.box);
    r.value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    r.note = new QLabel(r.box);
    r.note->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    v->addWidget(r.name);
    v->addWidget(r.value);
    v->addWidget(r.note);
  }
  retranslateUi();
  setColumns(kAngleCount);
  applyFonts();
  applyColours();
  connect(&m_timer, &QTimer::timeout, this, [this] {
    if (m_dirty) refresh();
  });
  setRefreshRate(10.0);
}

void AngleReadouts::retranslateUi() {
  setAccessibleName(tr("Current joint angles"));
  for (int a = 0; a < kAngleCount; ++a) {
    Readout& r = m_readouts[static_cast<std::size_t>(a)];
    r.name->setText(angleDisplayName(a));
    r.box->setAccessibleName(angleDisplayName(a));
    r.value->setAccessibleName(angleDisplayName(a));
  }
  m_dirty = true;  // the values' number format and the notes' words
}

void AngleReadouts::setColumns(int columns) {
  m_columns = std::clamp(columns, 1, kAngleCount);
  auto* grid = static_cast<QGridLayout*>(layout());
  for (int a = 0; a < kAngleCount; ++a) {
    QWidget* box = m_readouts[static_cast<std::size_t>(a)].box;
    grid->removeWidget(box);
    grid->addWidget(box, a / m_columns, a % m_columns);
  }
}

void AngleReadouts::setRefreshRate(double hz) {
  if (std::isfinite(hz) && hz > 0.0)
    m_timer.start(static_cast<int>(std::lround(1000.0 / std::min(hz, 60.0))));
  else
    m_timer.stop();
}

void AngleReadouts::setSample(const AngleSample* sample) {
  if (sample)
    m_sample = *sample;
  else
    m_sample.reset();
  m_dirty = true;
}

QString AngleReadouts::valueText(int angle) const {
  return m_readouts[static_cast<std::size_t>(angle)].value->text();
}

void AngleReadouts::refresh() {
  m_dirty = false;
  for (std::size_t a = 0; a < kAngleCount; ++a) {
    Readout& r = m_readouts[a];
    const double v = m_sample ? m_sample->deg[a] : std::nan("");
    const double twoSigma = m_sample ? 2.0 * m_sample->sigmaDeg[a] : 0.0;
    const bool uncertain =
        std::isfinite(v) && (!std::isfinite(twoSigma) || twoSigma > m_uncertainAbove);
    r.value->setText(formatDegrees(v, 0));
    QString note;
    if (std::isfinite(v)) {
      note = QStringLiteral("\u00b1") + formatDegrees(twoSigma, 0);
      if (uncertain) note = tr("uncertain (%1)").arg(note);
    }
    r.note->setText(note);
    r.value->setAccessibleDescription(uncertain ? tr("uncertain") : QString());
    if (uncertain != m_uncertain[a]) {
      m_uncertain[a] = uncertain;
      applyColours();
    }
  }
}

void AngleReadouts::applyFonts() {
  for (Readout& r : m_readouts) {
    r.value->setFont(scaledFont(font(), 2.6));
    r.note->setFont(scaledFont(font(), 0.9, false));
  }
}

void AngleReadouts::applyColours() {
  const QPalette base = palette();
  const bool dark = base.color(QPalette::Window).lightness() < 128;
  for (std::size_t a = 0; a < kAngleCount; ++a) {
    Readout& r = m_readouts[a];
    QPalette p = base;
    p.setColor(QPalette::Window, base.color(QPalette::Base));
    QColor text = base.color(QPalette::WindowText);
    if (m_uncertain[a]) {
      text = base.color(QPalette::PlaceholderText);
      p.setColor(QPalette::Window, dark ? QColor(0x4a, 0x3b, 0x12) : QColor(0xff, 0xf1, 0xc7));
    }
    p.setColor(QPalette::WindowText, text);
    r.box->setPalette(p);
  }
}

void AngleReadouts::changeEvent(QEvent* event) {
  if (event->type() == QEvent::PaletteChange) applyColours();
  if (event->type() == QEvent::FontChange) applyFonts();
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QWidget::changeEvent(event);
}

}  // namespace armtrack::ui
