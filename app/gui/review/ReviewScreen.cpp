#include "app/gui/review/ReviewScreen.h"

#include <QComboBox>
#include <QHeaderView>
#include <QJsonDocument>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>

#include "app/gui/common/AngleNames.h"
#include "app/gui/common/Forms.h"
#include "app/gui/common/JobProgress.h"
#include "app/gui/common/SessionTableModel.h"
#include "app/gui/review/TrunkPanel.h"
#include "app/gui/services/AppSettings.h"
#include "app/gui/services/RecordsService.h"
#include "ui/AnglePlotPanel.h"
#include "ui/ArmView.h"
#include "ui/Retranslate.h"

namespace armtrack::gui {

namespace {

/// The estimates as plot samples, their times in recording time (less origin).
std::vector<ui::AngleSample> samplesOf(const storage::StoredAnalysis& a, double origin) {
  std::vector<ui::AngleSample> out;
  out.reserve(a.t.size());
  const bool trunk = a.trunk.size() == a.t.size() && a.trunkSd.size() == a.t.size();
  for (std::size_t i = 0; i < a.t.size(); ++i) {
    out.push_back(ui::angleSample(recordingTime(a.t[i], origin), a.joints[i], a.sd[i]));
    if (trunk) ui::setTrunk(out.back(), a.trunk[i], a.trunkSd[i]);  // the trunk's plot
  }
  return out;
}

QString clock(double s) {
  const int tenths = static_cast<int>(std::max(0.0, s) * 10 + 0.5);
  return QStringLiteral("%1:%2%3%4")
      .arg(tenths / 600)
      .arg((tenths / 10) % 60, 2, 10, QLatin1Char('0'))
      .arg(QLocale().decimalPoint())
      .arg(tenths % 10);
}

QString howMade(const storage::StoredAnalysis& a, int versions) {
  const QJsonObject p = QJsonDocument::fromJson(a.paramsJson.toUtf8()).object();
  QString text = ReviewScreen::tr("version %1 of %2: %3, method %4")
                     .arg(a.version)
                     .arg(versions)
                     .arg(p["filter"].toString().toUpper(), p["method"].toString());
  text += p["optical_used"].toBool() ? ReviewScreen::tr(", optical data fused")
                                     : ReviewScreen::tr(", no optical data fused");
  if (p["calibration"].toBool()) text += ReviewScreen::tr(", calibrated");
  return text;
}

QString decimals(const QJsonValue& v, int digits) {
  return v.isDouble() ? QLocale().toString(v.toDouble(), 'f', digits) : QStringLiteral("-");
}

}  // namespace

ReviewScreen::ReviewScreen(RecordsService& records, const AppSettings& settings, qint64 sessionId,
                           QWidget* parent)
    : QWidget(parent), m_records(records), m_settings(settings), m_id(sessionId) {
  buildLayout();
  retranslateUi();
  m_play.setInterval(33);  // 30 Hz: the view and plots redraw from this timer only
  connect(&m_play, &QTimer::timeout, this, &ReviewScreen::tick);
  reload();
}

ReviewScreen::~ReviewScreen() {
  keepDraft();
}

void ReviewScreen::buildLayout() {
  auto* layout = new QVBoxLayout(this);
  auto* top = new QHBoxLayout;
  m_title = heading(QString(), this);
  m_back = new QPushButton(this);
  m_back->setShortcut(QKeySequence::Back);
  top->addWidget(m_title, 1);
  top->addWidget(m_back);
  layout->addLayout(top);
  m_message = new MessageLine(this);
  layout->addWidget(m_message);

  auto* vertical = new QSplitter(Qt::Vertical, this);
  auto* horizontal = new QSplitter(Qt::Horizontal, vertical);
  m_arm = new ui::ArmView(horizontal);
  m_arm->setMinimumSize(320, 280);
  m_plots = new ui::AnglePlotPanel(horizontal);
  m_plots->setMode(ui::AnglePlotPanel::Mode::Review);
  horizontal->setStretchFactor(0, 2);
  horizontal->setStretchFactor(1, 3);

  auto* lower = new QWidget(vertical);
  auto* lowerLayout = new QVBoxLayout(lower);
  lowerLayout->setContentsMargins(0, 0, 0, 0);
  auto* transport = new QHBoxLayout;
  m_playButton = new QPushButton(lower);
  m_playButton->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Space));
  m_slider = new QSlider(Qt::Horizontal, lower);
  m_slider->setSingleStep(100);  // 0.1 s per arrow key
  m_slider->setPageStep(5000);
  m_time = new QLabel(lower);
  m_speed = new QComboBox(lower);
  for (double s : {0.25, 0.5, 1.0, 2.0, 4.0}) m_speed->addItem(QString(), s);
  m_speed->setCurrentIndex(2);
  transport->addWidget(m_playButton);
  transport->addWidget(m_slider, 1);
  transport->addWidget(m_time);
  transport->addWidget(m_speed);
  lowerLayout->addLayout(transport);

  m_tabs = new QTabWidget(lower);
  m_repsTab = new QWidget;
  auto* repsLayout = new QVBoxLayout(m_repsTab);
  m_repSummary = new QLabel(m_repsTab);
  m_repSummary->setWordWrap(true);
  repsLayout->addWidget(m_repSummary);
  m_reps = new RepetitionTableModel(this);
  m_reps->setRadians(m_settings.units == AppSettings::AngleUnit::Radians);
  m_repTable = new QTableView(m_repsTab);
  m_repTable->setModel(m_reps);
  m_repTable->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_repTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_repTable->setTabKeyNavigation(false);
  m_repTable->verticalHeader()->hide();
  m_repTable->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  auto* repsRow = new QHBoxLayout;
  repsRow->addWidget(m_repTable, 1);
  m_trunk = new TrunkPanel(m_repsTab);
  repsRow->addWidget(m_trunk, 0, Qt::AlignTop);
  repsLayout->addLayout(repsRow);
  m_tabs->addTab(m_repsTab, QString());

  m_compareTab = new QWidget;
  auto* compareLayout = new QVBoxLayout(m_compareTab);
  m_compare = new QComboBox(m_compareTab);
  m_compare->addItem(QString(), qint64{0});  // none
  m_compareNote = new QLabel(m_compareTab);
  compareLayout->addWidget(m_compareNote);
  compareLayout->addWidget(m_compare);
  compareLayout->addStretch();
  m_tabs->addTab(m_compareTab, QString());

  m_notesTab = new QWidget;
  auto* notesLayout = new QVBoxLayout(m_notesTab);
  m_notes = new QPlainTextEdit(m_notesTab);
  m_notes->setTabChangesFocus(true);
  m_saveNotes = new QPushButton(m_notesTab);
  m_saveNotes->setShortcut(QKeySequence::Save);
  notesLayout->addWidget(m_notes);
  notesLayout->addWidget(m_saveNotes, 0, Qt::AlignRight);
  m_tabs->addTab(m_notesTab, QString());

  m_reestimate = new ReestimatePanel(m_settings);
  m_tabs->addTab(m_reestimate, QString());
  m_outputs = new OutputsPanel;
  m_tabs->addTab(m_outputs, QString());
  lowerLayout->addWidget(m_tabs, 1);
  vertical->setStretchFactor(0, 3);
  vertical->setStretchFactor(1, 2);
  layout->addWidget(vertical, 1);

  connect(m_back, &QPushButton::clicked, this,
          [this] { emit backRequested(m_data.info.patientCode); });
  connect(m_playButton, &QPushButton::clicked, this, [this] { playing() ? pause() : play(); });
  connect(m_slider, &QSlider::valueChanged, this, [this](int ms) {
    if (std::abs(ms - static_cast<int>(std::lround(m_cursor * 1000))) > 1) setCursor(ms / 1000.0);
  });
  connect(m_plots, &ui::AnglePlotPanel::cursorRequested, this, &ReviewScreen::setCursor);
  connect(m_repTable, &QTableView::activated, this, [this](const QModelIndex& i) {
    setCursor(i.data(RepetitionTableModel::StartRole).toDouble());
  });
  connect(m_compare, &QComboBox::activated, this,
          [this] { compareWith(m_compare->currentData().toLongLong()); });
  connect(m_notes, &QPlainTextEdit::textChanged, this, &ReviewScreen::keepDraft);
  connect(m_saveNotes, &QPushButton::clicked, this, &ReviewScreen::saveNotes);
  connect(m_reestimate, &ReestimatePanel::reestimateRequested, this, &ReviewScreen::reestimate);
  connect(m_outputs, &OutputsPanel::reportRequested, this, &ReviewScreen::askReport);
  connect(m_outputs, &OutputsPanel::exportRequested, this, &ReviewScreen::askExport);
  setTabOrder(m_back, m_playButton);
  setTabOrder(m_playButton, m_slider);
  setTabOrder(m_slider, m_speed);
  setTabOrder(m_speed, m_tabs);
  setFocusProxy(m_playButton);
}

void ReviewScreen::retranslateUi() {
  ui::setButtonText(m_back, tr("&Back to the patient"));
  m_arm->setAccessibleName(tr("3D arm replay"));
  ui::setButtonText(m_playButton, playing() ? tr("&Pause") : tr("&Play"));
  m_playButton->setToolTip(tr("Play or pause the replay (%1)")
                               .arg(m_playButton->shortcut().toString(QKeySequence::NativeText)));
  m_slider->setAccessibleName(tr("Replay time"));
  m_time->setAccessibleName(tr("Replay time"));
  for (int i = 0; i < m_speed->count(); ++i)
    m_speed->setItemText(i, tr("%L1\u00d7").arg(m_speed->itemData(i).toDouble()));
  m_speed->setAccessibleName(tr("Replay speed"));
  m_repTable->setAccessibleName(tr("Repetitions"));
  m_tabs->setTabText(m_tabs->indexOf(m_repsTab), tr("&Repetitions"));
  m_compare->setAccessibleName(tr("Session to compare with"));
  m_compareNote->setText(
      tr("Another session of this patient, drawn dashed on the plots and as a translucent arm:"));
  m_tabs->setTabText(m_tabs->indexOf(m_compareTab), tr("Co&mpare"));
  m_notes->setAccessibleName(tr("Session notes"));
  ui::setButtonText(m_saveNotes, tr("Sa&ve notes"));
  m_tabs->setTabText(m_tabs->indexOf(m_notesTab), tr("&Notes"));
  m_tabs->setTabText(m_tabs->indexOf(m_reestimate), tr("Re-es&timate"));
  m_tabs->setTabText(m_tabs->indexOf(m_outputs), tr("Report and e&xport"));
  showDataTexts();
  updateTimeLabel();
}

void ReviewScreen::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

void ReviewScreen::showDataTexts() {
  const ReviewData& d = m_data;
  m_compare->setItemText(0, tr("(none)"));
  if (d.info.id == 0) {  // not read yet
    setWindowTitle(tr("Review of session %1").arg(m_id));
    setHeading(m_title, tr("Session %1").arg(m_id));
    return;
  }
  const QString side = d.meta.side == Side::Left ? tr("left arm") : tr("right arm");
  const QString started = SessionTableModel::localTime(d.info.startedAt);
  setHeading(m_title, tr("%1: session of %2, %3").arg(d.patient.name, started, side));
  setWindowTitle(tr("Review: %1, %2").arg(d.patient.name, started));
  m_reestimate->setCurrent(d.analysis && !d.analysis->t.empty() ? howMade(*d.analysis, d.versions)
                                                                : tr("not analysed yet"));
  if (d.metrics) {
    const QJsonObject r = (*d.metrics)["repetitions"].toObject();
    m_repSummary->setText(
        tr("%n repetition(s) on %1 (%2 full, %3 partial). Smoothness: SPARC %4, LDLJ %5.", nullptr,
           r["count"].toInt())
            .arg(angleName(angleIndex(r["primary_angle"].toString())))
            .arg(r["full"].toInt())
            .arg(r["partial"].toInt())
            .arg(decimals((*d.metrics)["sparc"], 2), decimals((*d.metrics)["ldlj"], 2)) +
        (m_skippedReps > 0
             ? u' ' + tr("%n repetition(s) could not be read.", nullptr, m_skippedReps)
             : QString()));
  } else {
    m_repSummary->setText(tr("No metrics yet."));
  }
  for (int i = 1; i < m_compare->count(); ++i) {
    const qint64 id = m_compare->itemData(i).toLongLong();
    for (const storage::SessionInfo& o : d.others)
      if (o.id == id)
        m_compare->setItemText(
            i, tr("%1 %2").arg(SessionTableModel::localTime(o.startedAt), o.protocolName));
  }
}

void ReviewScreen::reload() {
  m_message->showMessage([] { return tr("Reading the session..."); }, MessageLine::Kind::Notice);
  m_records.call(
      this, [id = m_id](storage::ClinicalStore& s) { return loadReview(s, id); },
      [this](const ReviewData& d) {
        m_message->clear();
        show(d);
        emit loaded();
      },
      [this](const RecordsFailure& f) {
        m_message->showMessage(
            [why = f.message] { return tr("This session could not be read: %1").arg(why); });
      });
}

void ReviewScreen::show(const ReviewData& d) {
  const bool first = m_data.info.id == 0;
  m_data = d;
  m_arm->setArm(d.meta.geometry, d.meta.side, d.meta.up, d.meta.camera);
  m_arm->setSternumImu(d.meta.trunk);  // present when the session had a sternum IMU
  if (d.protocol) {
    const int a = angleIndex(d.protocol->angleKey);
    if (a >= 0) m_plots->setTarget(a, d.protocol->targetMinDeg, d.protocol->targetMaxDeg);
  } else {
    m_plots->clearTarget();
  }
  // One time base on the slider, the plots, the table and the events: recording time, the
  // seconds since the first recorded row (core/metrics/SessionTime.h), as the report prints it.
  m_origin = d.timeOrigin();
  m_plots->clear();  // the events of an earlier load
  m_events = d.events();
  double opensAt = 0;
  if (d.analysis && !d.analysis->t.empty()) {
    m_plots->setSession(samplesOf(*d.analysis, m_origin));
    m_t0 = recordingTime(d.analysis->t.front(), m_origin);
    m_t1 = recordingTime(d.analysis->t.back(), m_origin);
    // The first estimates are the filter's start-up (kStartupSeconds), far off while it
    // converges: the review opens after them, as the metrics begin.
    opensAt = recordingTime(firstConvergedTime(d.analysis->t, kStartupSeconds), m_origin);
    for (const EventMark& e : m_events)
      m_plots->addEvent(e.recordingS, QString::fromStdString(e.label));
    if (m_overlay) showOverlay();
  } else {
    m_plots->setSession({});
    m_t0 = m_t1 = 0;
    // Say why, from the session's analysis state: waiting for its turn, failed, or cut short.
    const QString state = d.info.analysis, note = d.info.analysisNote;
    m_message->showMessage([state, note] {
      if (state == QLatin1String(storage::kAnalysisPending))
        return tr(
            "This session is waiting for its analysis, which ArmTrack runs in the "
            "background while a therapist is signed in: open the review again in a "
            "moment, or open \"Re-estimate\" to analyse it now.");
      if (state == QLatin1String(storage::kAnalysisFailed))
        return tr("This session could not be analysed: %1. Open \"Re-estimate\" to try "
                  "again, for example with other filter settings.")
            .arg(note.isEmpty() ? tr("no reason was stored") : note);
      return tr(
          "This recording was cut short, so it was not analysed. Open \"Re-estimate\" "
          "to estimate its joint angles from what was recorded.");
    });
    m_tabs->setCurrentWidget(m_reestimate);
  }
  m_slider->setRange(static_cast<int>(std::lround(m_t0 * 1000)),
                     static_cast<int>(std::lround(m_t1 * 1000)));
  // A re-estimate keeps the cursor where it was, unless that is in the new start-up.
  setCursor(first || m_cursor < opensAt ? opensAt : std::clamp(m_cursor, m_t0, m_t1));

  m_skippedReps = 0;
  const std::vector<RepetitionRow> reps = d.metrics
                                              ? repetitionRows(*d.metrics, &m_skippedReps, m_origin)
                                              : std::vector<RepetitionRow>{};
  m_reps->setRows(reps);
  for (int c = RepetitionTableModel::TrunkFlexion; c < RepetitionTableModel::ColumnCount; ++c)
    m_repTable->setColumnHidden(c, !m_reps->hasValues(c));
  m_trunk->setMetrics(d.metrics, m_settings.units == AppSettings::AngleUnit::Radians);

  while (m_compare->count() > 1) m_compare->removeItem(1);
  for (const storage::SessionInfo& o : d.others) m_compare->addItem(QString(), o.id);
  showDataTexts();

  // The stored notes, unless a draft typed earlier was never saved.
  const QString draft = QSettings().value(draftKey()).toString();
  const QSignalBlocker block(m_notes);
  if (!draft.isEmpty() && draft != d.info.notes) {
    m_notes->setPlainText(draft);
    m_message->showMessage(
        [] {
          return tr(
              "Notes typed earlier were not saved; they are back in the Notes tab. Save "
              "them or edit them.");
        },
        MessageLine::Kind::Notice);
  } else if (first || m_notes->toPlainText() == d.info.notes || draft.isEmpty()) {
    m_notes->setPlainText(d.info.notes);
  }
}

void ReviewScreen::setCursor(double t) {
  m_cursor = std::clamp(t, m_t0, m_t1);
  if (m_data.analysis && !m_data.analysis->t.empty()) {
    const std::size_t i = rowAt(m_data.analysis->t, m_cursor + m_origin);
    m_arm->setPose(m_data.analysis->joints[i]);
    // The stored trunk angles lean and turn the figure; upright where none were measured.
    const std::vector<Eigen::Vector3d>& trunk = m_data.analysis->trunk;
    m_arm->setTrunk(i < trunk.size() && trunk[i].allFinite() ? std::optional(trunk[i])
                                                             : std::nullopt);
  }
  if (m_overlay && !m_overlay->t.empty()) {
    // The other session at the same time since its own start.
    const double since = m_cursor - m_t0 + m_overlay->t.front();
    m_arm->setTargetPose(m_overlay->joints[rowAt(m_overlay->t, since)]);
  }
  m_plots->setCursor(m_cursor);
  const QSignalBlocker block(m_slider);
  m_slider->setValue(static_cast<int>(std::lround(m_cursor * 1000)));
  updateTimeLabel();
}

void ReviewScreen::updateTimeLabel() {
  m_time->setText(tr("%1 / %2").arg(clock(m_cursor), clock(m_t1)));
}

void ReviewScreen::play() {
  if (m_t1 <= m_t0) return;
  if (m_cursor >= m_t1) setCursor(m_t0);
  m_clock.start();
  m_play.start();
  ui::setButtonText(m_playButton, tr("&Pause"));
}

void ReviewScreen::pause() {
  m_play.stop();
  ui::setButtonText(m_playButton, tr("&Play"));
}

void ReviewScreen::tick() {
  const double dt = m_clock.restart() / 1000.0;
  setCursor(m_cursor + dt * m_speed->currentData().toDouble());
  if (m_cursor >= m_t1) pause();
}

void ReviewScreen::compareWith(qint64 other) {
  if (other == 0) {
    m_overlay.reset();
    m_plots->clearOverlay();
    m_arm->setTargetPose(std::nullopt);
    emit overlayShown(0);
    return;
  }
  m_records.call(
      this, [other](storage::ClinicalStore& s) { return storage::latestAnalysis(s, other); },
      [this, other](const std::optional<storage::StoredAnalysis>& a) {
        if (!a || a->t.empty()) {
          m_message->showMessage([other] {
            return tr("Session %1 has no analysis to compare with. Review it and re-estimate it "
                      "first.")
                .arg(other);
          });
          return;
        }
        m_overlay = a;
        showOverlay();
        setCursor(m_cursor);
        emit overlayShown(other);
      },
      [this](const RecordsFailure& f) {
        m_message->showMessage(
            [why = f.message] { return tr("That session could not be read: %1").arg(why); });
      });
}

void ReviewScreen::showOverlay() {
  // The other session from the same start as this one's first estimate.
  m_plots->setOverlay(samplesOf(*m_overlay, m_overlay->t.front() - m_t0));
}

QString ReviewScreen::draftKey() const {
  const QString where = m_records.signedIn() ? m_records.url().display() : QString();
  return QStringLiteral("drafts/notes/%1/%2").arg(qHash(where)).arg(m_id);
}

void ReviewScreen::keepDraft() {
  if (!m_notes || m_data.info.id == 0) return;
  QSettings settings;
  if (m_notes->toPlainText() == m_data.info.notes)
    settings.remove(draftKey());
  else
    settings.setValue(draftKey(), m_notes->toPlainText());
}

void ReviewScreen::saveNotes() {
  const QString text = m_notes->toPlainText();
  m_saveNotes->setEnabled(false);
  m_records.call(
      this, [id = m_id, text](storage::ClinicalStore& s) { s.updateSessionNotes(id, text); },
      [this, text] {
        m_saveNotes->setEnabled(true);
        m_data.info.notes = text;
        keepDraft();  // the draft is no longer needed
        m_message->showMessage([] { return tr("Notes saved."); }, MessageLine::Kind::Notice);
        emit notesSaved({});
      },
      [this](const RecordsFailure& f) {
        m_saveNotes->setEnabled(true);
        const auto text = [why = f.message] {
          return tr("The notes could not be saved: %1. They stay here and in a draft; try again.")
              .arg(why);
        };
        m_message->showMessage(text);
        emit notesSaved(text());
      });
}

void ReviewScreen::reestimate(const ReestimateChoice& choice) {
  if (m_busy) return;
  m_busy = true;
  m_reestimate->setBusy(true);
  m_message->showMessage([] { return tr("Estimating the joint angles again..."); },
                         MessageLine::Kind::Notice);
  RecordsJob* job = m_records.startJob(
      this,
      [id = m_id, choice](JobContext& c) {
        storage::AnalysisOptions o;
        o.filter = choice.filter;
        o.model = choice.model;
        o.noOptical = !choice.optical;
        if (!choice.calibrationFile.isEmpty())
          o.calibration = readCalibration(choice.calibrationFile.toStdString());
        o.progress = [&c](int p) { c.progress(p); };
        o.cancel = c.cancelFlag();
        const storage::AnalysisResult r = storage::analyseSession(c.store(), id, o);
        return r.cancelled ? 0 : r.estimateVersion;
      },
      [this](int version) {
        m_busy = false;
        m_reestimate->setBusy(false);
        if (version == 0) {
          m_message->showMessage([] { return tr("Re-estimation cancelled; nothing was stored."); },
                                 MessageLine::Kind::Notice);
          emit reestimated(0, tr("cancelled"));
          return;
        }
        m_message->showMessage(
            [version] { return tr("New estimates stored as version %1.").arg(version); },
            MessageLine::Kind::Notice);
        connect(
            this, &ReviewScreen::loaded, this, [this, version] { emit reestimated(version, {}); },
            Qt::SingleShotConnection);
        reload();
      },
      [this](const RecordsFailure& f) {
        m_busy = false;
        m_reestimate->setBusy(false);
        const auto text = [why = f.message] {
          return tr("The session could not be estimated again: %1. The earlier estimates are "
                    "kept.")
              .arg(why);
        };
        m_message->showMessage(text);
        emit reestimated(0, text());
      });
  showJobProgress(this, job, tr("Estimating the joint angles again..."));
}

}  // namespace armtrack::gui
