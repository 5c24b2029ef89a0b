#include "app/gui/home/HomeSummaryScreen.h"

#include <QCoreApplication>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "app/gui/home/HomeStartScreen.h"
#include "app/gui/home/HomeStyle.h"
#include "app/gui/home/HomeSummaryChart.h"
#include "ui/Fonts.h"
#include "ui/Retranslate.h"

namespace armtrack::gui::home {

namespace {
constexpr int kMaxCommentChars = 2000;  // what the records keep (ClinicalStore::saveHomeOutcome)
}

QString HomeSummaryScreen::line(const HomeExerciseResult& r,
                                const std::vector<HomeHistoryEntry>& history) {
  const auto tr = [](const char* s) {
    return QCoreApplication::translate("armtrack::gui::home::HomeSummaryScreen", s);
  };
  QString text =
      tr("%1: %L2 of %L3 repetitions").arg(r.exercise).arg(r.repetitions).arg(r.repetitionsPlanned);
  if (!r.measured) {
    text = tr("%1: %L2 of %L3 sets done (not measured without the camera)")
               .arg(r.exercise)
               .arg(r.setsDone)
               .arg(r.setsPlanned);
  } else if (r.rangeMaxDeg) {
    text += QStringLiteral("; ") + tr("you reached %L1\u00b0, the target is %L2\u00b0")
                                       .arg(*r.rangeMaxDeg, 0, 'f', 0)
                                       .arg(r.targetMaxDeg, 0, 'f', 0);
  }
  if (!history.empty() && history.back().result.rangeMaxDeg)
    text += QStringLiteral("; ") +
            tr("last time %L1\u00b0").arg(*history.back().result.rangeMaxDeg, 0, 'f', 0);
  if (r.trunkCompensation > 0)
    text +=
        QStringLiteral("; ") + QCoreApplication::translate("armtrack::gui::home::HomeSummaryScreen",
                                                           "%n repetition(s) leaning too far",
                                                           nullptr, r.trunkCompensation);
  if (r.stoppedEarly) text += QStringLiteral("; ") + tr("stopped early");
  return text + u'.';
}

HomeSummaryScreen::HomeSummaryScreen(const HomePlan& plan,
                                     const std::vector<HomeExerciseResult>& results,
                                     QWidget* parent)
    : HomeScreen(parent),
      m_plan(plan),
      m_results(results),
      m_chart(new HomeSummaryChart(this)),
      m_heading(heading({}, this)),
      m_painQuestion(bodyText({}, this)),
      m_commentQuestion(bodyText({}, this)),
      m_painValue(new QLabel(this)),
      m_status(bodyText({}, this)),
      m_comment(new QPlainTextEdit(this)),
      m_less(bigButton(QStringLiteral("\u2212"), this)),
      m_more(bigButton(QStringLiteral("+"), this)),
      m_save(bigButton({}, this, true)),
      m_close(bigButton({}, this, true)) {
  auto* root = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  left->addWidget(m_heading);
  for (std::size_t i = 0; i < results.size(); ++i) {
    m_lineLabels << bodyText({}, this);
    left->addWidget(m_lineLabels.back());
  }
  left->addWidget(m_chart, 1);
  root->addLayout(left, 3);

  auto* right = new QVBoxLayout;
  right->addWidget(m_painQuestion);
  auto* pain = new QHBoxLayout;
  setHomeFont(m_painValue, 2.0, true);
  m_painValue->setAlignment(Qt::AlignCenter);
  pain->addWidget(m_less);
  pain->addWidget(m_painValue, 1);
  pain->addWidget(m_more);
  right->addLayout(pain);
  right->addWidget(m_commentQuestion);
  setHomeFont(m_comment);
  m_comment->setTabChangesFocus(true);
  right->addWidget(m_comment, 1);
  m_status->hide();
  right->addWidget(m_status);
  right->addWidget(m_save);
  right->addWidget(m_close);
  m_close->hide();
  root->addLayout(right, 2);
  retranslate();

  // From "no answer", the first More pain says 1 and the first Less pain says 0 (none); Less
  // pain below 0 takes the answer back.
  connect(m_less, &QPushButton::clicked, this, [this] {
    m_pain = m_pain < 0 ? 0 : m_pain - 1;
    showPain();
  });
  connect(m_more, &QPushButton::clicked, this, [this] {
    m_pain = m_pain < 0 ? 1 : std::min(10, m_pain + 1);
    showPain();
  });
  connect(m_comment, &QPlainTextEdit::textChanged, this, [this] {
    // The records keep 2000 characters; the box does not take more.
    if (m_comment->toPlainText().size() > kMaxCommentChars) {
      QString t = m_comment->toPlainText().left(kMaxCommentChars);
      m_comment->setPlainText(t);
      m_comment->moveCursor(QTextCursor::End);
    }
  });
  connect(m_save, &QPushButton::clicked, this, [this] {
    m_save->setEnabled(false);
    setBanner(m_status, tr("Saving\u2026"), Tone::Neutral);
    emit saveRequested(painScore(), comment());
  });
  connect(m_close, &QPushButton::clicked, this, &HomeSummaryScreen::closeRequested);
}

void HomeSummaryScreen::retranslate() {
  setAccessibleName(tr("Summary"));
  m_heading->setText(tr("Well done, %1!").arg(firstName(m_plan.patient.name)));
  m_lines.clear();
  for (std::size_t i = 0; i < m_results.size(); ++i) {
    const auto& h = i < m_plan.history.size() ? m_plan.history[i] : std::vector<HomeHistoryEntry>{};
    m_lines << line(m_results[i], h);
    m_lineLabels[static_cast<qsizetype>(i)]->setText(m_lines.back());
  }
  m_chart->setResults(m_results, m_plan.history);
  m_painQuestion->setText(tr("How much pain did you have? 0 is none, 10 the worst."));
  m_commentQuestion->setText(tr("Anything to tell your therapist? (You may leave it empty.)"));
  m_less->setAccessibleName(tr("Less pain"));
  m_more->setAccessibleName(tr("More pain"));
  m_painValue->setAccessibleName(tr("Pain score"));
  m_painValue->setMinimumWidth(m_painValue->fontMetrics().horizontalAdvance(tr("no answer")));
  m_comment->setAccessibleName(tr("Your comment"));
  m_status->setAccessibleName(tr("Saved"));
  ui::setButtonText(m_save, tr("&Save and finish"));
  ui::setButtonText(m_close, tr("&Close"));
  for (QPushButton* b : {m_save, m_close}) b->setAccessibleName(QString(b->text()).remove(u'&'));
  showPain();
}

void HomeSummaryScreen::showPain() {
  m_painValue->setText(m_pain < 0 ? tr("no answer") : QLocale().toString(m_pain));
  m_less->setEnabled(!m_saved);
  m_more->setEnabled(m_pain < 10 && !m_saved);
}

std::optional<int> HomeSummaryScreen::painScore() const {
  return m_pain < 0 ? std::nullopt : std::optional<int>(m_pain);
}

void HomeSummaryScreen::setPainScore(std::optional<int> score) {
  m_pain = score ? std::clamp(*score, 0, 10) : -1;
  showPain();
}

QString HomeSummaryScreen::comment() const {
  return m_comment->toPlainText().trimmed();
}

void HomeSummaryScreen::setComment(const QString& text) {
  m_comment->setPlainText(text);
}

void HomeSummaryScreen::showSaved(bool ok, const QString& message) {
  m_saved = ok;
  if (ok) {
    setBanner(m_status, tr("Saved. Your therapist will see it. Thank you!"), Tone::Good);
    m_save->hide();
    m_close->show();
    m_comment->setReadOnly(true);
  } else {
    setBanner(m_status, tr("It could not be saved: %1. Press Save to try again.").arg(message),
              Tone::Problem);
    m_save->setEnabled(true);
  }
  showPain();
  if (QAbstractButton* main = defaultChoice()) main->setFocus(Qt::OtherFocusReason);
  emit choicesChanged();
}

QString HomeSummaryScreen::status() const {
  return m_status->isHidden() ? QString() : m_status->text();
}

QList<QAbstractButton*> HomeSummaryScreen::choices() const {
  return {m_less, m_more, m_save, m_close};
}

QAbstractButton* HomeSummaryScreen::defaultChoice() const {
  return m_saved ? m_close : m_save;
}

}  // namespace armtrack::gui::home
