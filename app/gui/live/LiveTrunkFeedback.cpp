#include "app/gui/live/LiveTrunkFeedback.h"

#include <QLabel>
#include <QLocale>
#include <QPalette>
#include <cmath>
#include <numbers>

#include "ui/Fonts.h"

namespace armtrack::app::gui {

namespace {
constexpr double kShownSeconds = 1.0;  // angles and the note vanish when no longer measured
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

QString degrees(double deg) {
  const double whole = std::round(deg);
  return QLocale().toString(whole == 0 ? 0.0 : whole, 'f', 0) + QChar(0x00b0);  // never "-0"
}
}  // namespace

LiveTrunkFeedback::LiveTrunkFeedback(std::optional<double> limitDeg, QWidget* parent)
    : m_cue(new QLabel(parent)), m_angles(new QLabel(parent)), m_count(new QLabel(parent)) {
  if (limitDeg) {
    TrunkLimitCueParams p;
    p.limitDeg = *limitDeg;
    m_limit.emplace(p);
  }
  ui::setScaledFont(m_cue, 1.6);
  QFont bold = m_cue->font();
  bold.setBold(true);
  m_cue->setFont(bold);
  m_cue->setAlignment(Qt::AlignCenter);
  m_cue->setWordWrap(true);
  m_cue->setAutoFillBackground(true);
  m_cue->setMargin(8);
  // Amber, dark text: seen from across the room, and not the red of a device problem.
  QPalette pal = m_cue->palette();
  pal.setColor(QPalette::Window, QColor(0xff, 0xc1, 0x07));
  pal.setColor(QPalette::WindowText, QColor(0x20, 0x18, 0x00));
  m_cue->setPalette(pal);
  m_cue->hide();
  m_angles->setWordWrap(true);
  m_angles->hide();
  m_count->setWordWrap(true);
  m_count->setVisible(m_limit.has_value());
  retranslate();
}

void LiveTrunkFeedback::add(const session::EstimateRow& row) {
  m_lastT = row.t;
  if (row.trunk && row.trunk->allFinite()) {
    m_trunk = row.trunk;
    m_trunkT = row.t;
  }
  if (row.trunkMoved) m_movedT = row.t;
  if (m_limit)
    m_limit->add(row.t, row.trunk ? std::optional((*row.trunk)(0)) : std::nullopt, row.trunkMoved);
}

void LiveTrunkFeedback::judgeRepetitions(const RepetitionCounter& counter) {
  const auto& reps = counter.repetitions();
  for (; m_judged < reps.size(); ++m_judged)
    if (m_limit) m_limit->addRepetition(reps[m_judged].enterS, reps[m_judged].exitS);
}

void LiveTrunkFeedback::refresh() {
  m_cue->setVisible(cueShown());
  const bool angles = m_trunk && m_lastT - m_trunkT <= kShownSeconds;
  m_moved = m_lastT - m_movedT <= kShownSeconds;
  QStringList lines;
  if (angles)
    lines << tr("Trunk: flexion %1, lateral bending %2, axial rotation %3")
                 .arg(degrees((*m_trunk)(0) * kRadToDeg), degrees((*m_trunk)(1) * kRadToDeg),
                      degrees((*m_trunk)(2) * kRadToDeg));
  if (m_moved) lines << tr("The trunk moved: shoulder angles include the lean.");
  m_angles->setText(lines.join(u'\n'));
  m_angles->setVisible(!lines.isEmpty());
  if (m_limit)
    m_count->setText(tr("%n repetition(s) with compensation", nullptr,
                        static_cast<int>(m_limit->compensated())) +
                     u' ' + tr("(trunk limit %1)").arg(degrees(m_limit->params().limitDeg)));
}

void LiveTrunkFeedback::reset() {
  if (m_limit) m_limit->reset();
  m_judged = 0;
  m_trunk.reset();
  m_trunkT = m_movedT = -1e9;
  m_lastT = 0;
  refresh();
}

void LiveTrunkFeedback::retranslate() {
  m_cue->setText(tr("Keep your back against the chair"));
  m_cue->setAccessibleName(tr("Trunk cue"));
  m_angles->setAccessibleName(tr("Trunk"));
  m_count->setAccessibleName(tr("Repetitions with compensation"));
  refresh();
}

QString LiveTrunkFeedback::notesLine() const {
  if (!m_limit) return {};
  return tr("Trunk limit %1: %2 of %3 repetitions with compensation")
      .arg(degrees(m_limit->params().limitDeg))
      .arg(m_limit->compensated())
      .arg(m_limit->repetitions());
}

}  // namespace armtrack::app::gui
