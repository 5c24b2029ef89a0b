// The trunk in the live session screen (docs/gui.md, "Live session"): the trunk's angles when a
// trunk sensor measures them, a note when the trunk moved with nothing to measure it (the shoulder
// angles then include the lean), and, when the protocol sets a trunk limit, the cue "Keep your
// back against the chair" and the count of repetitions made with compensation
// (core/metrics/TrunkLimitCue). Its labels are laid out by the screen.
#pragma once

#include <QCoreApplication>
#include <QString>
#include <optional>
#include <vector>

#include "core/metrics/RepetitionCounter.h"
#include "core/metrics/TrunkLimitCue.h"
#include "core/session/Session.h"

class QLabel;
class QWidget;

namespace armtrack::app::gui {

class LiveTrunkFeedback {
  Q_DECLARE_TR_FUNCTIONS(armtrack::app::gui::LiveTrunkFeedback)
 public:
  /// limitDeg: the protocol's trunk limit (deg), or empty (no cue, no count). The labels are
  /// made as parent's children, hidden until they have something to say.
  LiveTrunkFeedback(std::optional<double> limitDeg, QWidget* parent);

  /// The big cue, the line of trunk angles and the trunk-moved note, the compensation count.
  QLabel* cueLabel() const { return m_cue; }
  QLabel* anglesLabel() const { return m_angles; }
  QLabel* countLabel() const { return m_count; }

  /// One estimate, before the repetition counter is given it.
  void add(const session::EstimateRow& row);
  /// After the counter was given the row: judges the repetitions it has counted since.
  void judgeRepetitions(const RepetitionCounter& counter);
  /// Shows what the rows added so far say (once per batch).
  void refresh();
  void reset();
  void retranslate();

  /// The cue, when the protocol sets a limit.
  const TrunkLimitCue* cue() const { return m_limit ? &*m_limit : nullptr; }
  bool cueShown() const { return m_limit && m_limit->cueShown(); }
  /// Repetitions made with compensation (0 without a limit).
  std::size_t compensated() const { return m_limit ? m_limit->compensated() : 0; }
  /// The line the session's notes keep, e.g. "Trunk limit 15°: 3 of 10 repetitions with
  /// compensation"; empty without a limit.
  QString notesLine() const;

 private:
  std::optional<TrunkLimitCue> m_limit;
  std::size_t m_judged = 0;                // the counter's repetitions judged so far
  std::optional<Eigen::Vector3d> m_trunk;  // newest trunk angles (rad)
  double m_trunkT = -1e9, m_lastT = 0;
  bool m_moved = false;
  double m_movedT = -1e9;
  QLabel* m_cue;
  QLabel* m_angles;
  QLabel* m_count;
};

}  // namespace armtrack::app::gui
