#include "ui/RepetitionCounterWidget.h"

#include <QEvent>
#include <QLabel>
#include <QProgressBar>
#include <QVBoxLayout>

#include "core/metrics/RepetitionCounter.h"
#include "ui/Fonts.h"

namespace armtrack::ui {

RepetitionCounterWidget::RepetitionCounterWidget(QWidget* parent) : QWidget(parent) {
  auto* v = new QVBoxLayout(this);
  v->setContentsMargins(4, 4, 4, 4);
  m_caption = new QLabel(this);
  m_count = new QLabel(this);
  setScaledFont(m_count, 2.6);
  m_detail = new QLabel(this);
  m_detail->setWordWrap(true);
  m_progress = new QProgressBar(this);
  m_progress->setTextVisible(false);
  v->addWidget(m_caption);
  v->addWidget(m_count);
  v->addWidget(m_detail);
  v->addWidget(m_progress);
  retranslateUi();
}

void RepetitionCounterWidget::retranslateUi() {
  setAccessibleName(tr("Repetitions"));
  m_progress->setAccessibleName(tr("Repetitions done of the target"));
  m_caption->setText(m_angleName.isEmpty() ? tr("Repetitions")
                                           : tr("Repetitions (%1)").arg(m_angleName));
  render();
}

void RepetitionCounterWidget::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QWidget::changeEvent(event);
}

void RepetitionCounterWidget::setTarget(std::optional<int> repetitions) {
  m_target = repetitions && *repetitions > 0 ? repetitions : std::nullopt;
  render();
}

void RepetitionCounterWidget::setAngleName(const QString& name) {
  m_angleName = name;
  m_caption->setText(name.isEmpty() ? tr("Repetitions") : tr("Repetitions (%1)").arg(name));
}

void RepetitionCounterWidget::showCount(const RepetitionCounter& counter) {
  if (counter.fullCount() == m_full && counter.partialCount() == m_partial &&
      counter.inRepetition() == m_inside)
    return;
  m_full = counter.fullCount();
  m_partial = counter.partialCount();
  m_inside = counter.inRepetition();
  render();
}

void RepetitionCounterWidget::render() {
  const auto done = static_cast<int>(m_full);
  m_count->setText(m_target ? tr("%1 of %2").arg(done).arg(*m_target) : QString::number(done));
  QStringList detail;
  if (m_partial > 0) detail << tr("%n partial", nullptr, static_cast<int>(m_partial));
  if (m_inside) detail << tr("moving");
  if (m_target && done >= *m_target) detail << tr("target reached");
  m_detail->setText(detail.join(QStringLiteral(", ")));
  m_progress->setVisible(m_target.has_value());
  m_progress->setRange(0, m_target.value_or(1));
  m_progress->setValue(std::min(done, m_target.value_or(1)));
  setAccessibleDescription(text());
}

QString RepetitionCounterWidget::text() const {
  const QString d = m_detail->text();
  return d.isEmpty() ? m_count->text() : m_count->text() + QStringLiteral(", ") + d;
}

}  // namespace armtrack::ui
