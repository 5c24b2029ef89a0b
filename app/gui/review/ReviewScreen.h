// Review of a stored session: the 3D arm and the joint-angle plots replayed in sync with a time
// slider; the repetitions and their metrics; another session of the patient overlaid; notes
// (a draft is kept until saved, so nothing typed is lost); re-estimation with another filter,
// method or calibration, and reports and exports, each in the job thread with progress and
// Cancel.
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>
#include <optional>

#include "app/clinical/Outputs.h"
#include "app/gui/review/ReviewPanels.h"
#include "app/gui/services/SessionReview.h"

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSlider;
class QTabWidget;
class QTableView;

namespace armtrack::ui {
class AnglePlotPanel;
class ArmView;
}  // namespace armtrack::ui

namespace armtrack::gui {

class MessageLine;
class TrunkPanel;
class RecordsService;
struct AppSettings;

class ReviewScreen : public QWidget {
  Q_OBJECT
 public:
  ReviewScreen(RecordsService& records, const AppSettings& settings, qint64 sessionId,
               QWidget* parent = nullptr);
  ~ReviewScreen() override;

  void reload();
  const ReviewData& data() const { return m_data; }
  qint64 sessionId() const { return m_id; }

  /// The replay's time: recording time (s since the first recorded row,
  /// core/metrics/SessionTime.h), the time base of the slider, the plots, the repetitions'
  /// table, the events and the report. The replay opens on the first estimate after the
  /// filter's start-up second.
  double cursor() const { return m_cursor; }
  /// Where recording time begins on the session clock (s).
  double timeOrigin() const { return m_origin; }
  /// The slider's range (recording time, s).
  std::pair<double, double> timeRange() const { return {m_t0, m_t1}; }
  /// The events drawn on the plots (recording time).
  const std::vector<EventMark>& events() const { return m_events; }
  /// The repetitions' table.
  const RepetitionTableModel* repetitions() const { return m_reps; }
  void setCursor(double t);
  void play();
  void pause();
  bool playing() const { return m_play.isActive(); }

  void reestimate(const ReestimateChoice& choice);
  void writeReport(const QString& pdf);
  void exportTo(clinical::ExportFormat format, const QString& path);
  /// Overlays another session of the patient (0 removes the overlay).
  void compareWith(qint64 otherSessionId);
  void saveNotes();
  QPlainTextEdit* notesEditor() const { return m_notes; }

  ui::ArmView* armView() const { return m_arm; }
  ui::AnglePlotPanel* plots() const { return m_plots; }
  QTableView* repetitionTable() const { return m_repTable; }
  TrunkPanel* trunkPanel() const { return m_trunk; }

 signals:
  void loaded();
  void backRequested(const QString& patientCode);
  /// A report or export finished: error is empty when path was written.
  void outputWritten(const QString& path, const QString& error);
  /// A re-estimation finished (version 0 and a message when it failed or was cancelled).
  void reestimated(int version, const QString& error);
  void notesSaved(const QString& error);
  void overlayShown(qint64 otherSessionId);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void buildLayout();
  void retranslateUi();
  void show(const ReviewData& d);
  /// The texts made from the session read (title, summary, the sessions to compare with).
  void showDataTexts();
  void tick();
  void updateTimeLabel();
  void showOverlay();
  void askReport();
  void askExport(clinical::ExportFormat format);
  void runOutput(const QString& what, const QString& path,
                 std::function<QString(storage::ClinicalStore&)> work);
  QString draftKey() const;
  void keepDraft();

  RecordsService& m_records;
  const AppSettings& m_settings;
  qint64 m_id;
  ReviewData m_data;
  std::optional<storage::StoredAnalysis> m_overlay;
  double m_cursor = 0, m_t0 = 0, m_t1 = 0;  // recording time (s)
  double m_origin = 0;                      // where it begins on the session clock (s)
  std::vector<EventMark> m_events;
  QTimer m_play;
  QElapsedTimer m_clock;
  bool m_busy = false;

  QLabel* m_title = nullptr;
  MessageLine* m_message = nullptr;
  ui::ArmView* m_arm = nullptr;
  ui::AnglePlotPanel* m_plots = nullptr;
  QPushButton* m_playButton = nullptr;
  QSlider* m_slider = nullptr;
  QLabel* m_time = nullptr;
  QComboBox* m_speed = nullptr;
  QTabWidget* m_tabs = nullptr;
  QWidget* m_repsTab = nullptr;
  QWidget* m_compareTab = nullptr;
  QWidget* m_notesTab = nullptr;
  QLabel* m_compareNote = nullptr;
  int m_skippedReps = 0;
  QLabel* m_repSummary = nullptr;
  RepetitionTableModel* m_reps = nullptr;
  QTableView* m_repTable = nullptr;
  TrunkPanel* m_trunk = nullptr;
  QComboBox* m_compare = nullptr;
  QPlainTextEdit* m_notes = nullptr;
  QPushButton* m_saveNotes = nullptr;
  ReestimatePanel* m_reestimate = nullptr;
  OutputsPanel* m_outputs = nullptr;
  QPushButton* m_back = nullptr;
};

}  // namespace armtrack::gui
