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
    r.name->installEventFilter(this);  // its height follows its wrapping (eventFilter())
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

QString AngleReadouts::noteText(int angle) const {
  return m_readouts[static_cast<std::size_t>(angle)].note->text();
}

void AngleReadouts::refresh() {
  m_dirty = false;
  for (std::size_t a = 0; a < kAngleCount; ++a) {
    Readout& r = m_readouts[a];
    const double v = m_sample ? m_sample->deg[a] : std::nan("");
    // In doubt: the confidence and the reason in words (not by colour alone).
    const AngleDoubt doubt = m_sample && std::isfinite(v)
                                 ? angleDoubt(*m_sample, static_cast<int>(a), m_uncertainAbove)
                                 : AngleDoubt::None;
    const bool uncertain = doubt != AngleDoubt::None;
    r.value->setText(formatDegrees(v, 0));
    QString note;
    if (std::isfinite(v)) {
      note = confidenceText(m_sample->sigmaDeg[a]);
      if (uncertain) note = tr("%1, %2").arg(note, doubtText(doubt));
    }
    r.note->setText(note);
    r.note->setToolTip(
        tr("The angle lies within this range of the value shown, with about 95 % "
           "probability."));
    r.value->setAccessibleDescription(uncertain ? doubtText(doubt) : QString());
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
      text = dark ? QColor(0xff, 0xe0, 0xa0) : QColor(0x5a, 0x3a, 0x00);
      p.setColor(QPalette::Window, dark ? QColor(0x4a, 0x3b, 0x12) : QColor(0xff, 0xf1, 0xc7));
    }
    p.setColor(QPalette::WindowText, text);
    r.box->setPalette(p);
  }
}

bool AngleReadouts::eventFilter(QObject* watched, QEvent* event) {
  // A name that wraps onto a second line (narrow boxes, large fonts, German) gets the height
  // of both lines: an outer layout that ignores height-for-width would cut it to one.
  if (event->type() == QEvent::Resize)
    if (auto* label = qobject_cast<QLabel*>(watched)) {
      const int need = label->heightForWidth(label->width());
      if (need > 0 && need != label->minimumHeight()) label->setMinimumHeight(need);
    }
  return QWidget::eventFilter(watched, event);
}

void AngleReadouts::changeEvent(QEvent* event) {
  if (event->type() == QEvent::PaletteChange) applyColours();
  if (event->type() == QEvent::FontChange) applyFonts();
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QWidget::changeEvent(event);
}

}  // namespace armtrack::ui
