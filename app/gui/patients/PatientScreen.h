// One patient: details, measured segment lengths, home programme, sessions, and the range of
// motion per clinical angle over time. From here a therapist starts a new session, reviews a
// stored one, edits the patient or writes a progress report.
#pragma once

#include <QWidget>

#include "app/gui/services/PatientRecords.h"

class QGroupBox;
class QLabel;
class QPushButton;
class QSortFilterProxyModel;
class QStandardItemModel;
class QTableView;

namespace armtrack::gui {

class HomeDevicesBox;
class MessageLine;
class ProgressChart;
class RecordsService;
class SessionTableModel;
struct AppSettings;

class PatientScreen : public QWidget {
  Q_OBJECT
 public:
  PatientScreen(RecordsService& records, const AppSettings& settings, const QString& code,
                QWidget* parent = nullptr);

  void reload();
  const QString& code() const { return m_code; }
  /// The loaded record (valid after loaded()).
  const PatientOverview& overview() const { return m_overview; }
  ProgressChart* progressChart() const { return m_chart; }
  /// The patient's home devices (administrators and therapists), or nullptr.
  HomeDevicesBox* homeDevices() const { return m_homeDevices; }
  /// The selected session's id, or 0.
  qint64 selectedSession() const;
  /// Writes the progress report of every session to pdf (a job with progress).
  void writeProgressReport(const QString& pdf);
  /// Asks whether to delete the selected session (administrators), then deletes it.
  void deleteSession();

 signals:
  void loaded();
  void backRequested();
  void newSessionRequested(const QString& code);
  void reviewRequested(qint64 sessionId);
  /// A progress report was written (or failed: message non-empty).
  void reportWritten(const QString& pdf, const QString& message);

 protected:
  void changeEvent(QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  /// The heading: the name elided to the width (whole in the tooltip), the code always shown.
  void updateTitle();
  void retranslateUi();
  /// Shows what was read; again: the same record in words of a new language (the chart's
  /// angle and the session chosen stay).
  void show(const PatientOverview& o, bool again = false);
  void editPatient();
  void askProgressReport();
  void updateButtons();

  RecordsService& m_records;
  const AppSettings& m_settings;
  QString m_code;
  PatientOverview m_overview;
  bool m_canWrite;
  bool m_canDelete;  ///< administrators: the store lets only them remove sessions

  bool m_loaded = false;
  QLabel* m_title;
  std::vector<QLabel*> m_detailNames, m_detailValues;  // code, born, sex, side, diagnosis, notes
  std::vector<QLabel*> m_lengthNames, m_lengthValues;  // upper arm, forearm, both IMUs
  QLabel* m_lengthsNote = nullptr;
  QGroupBox* m_detailsBox;
  QGroupBox* m_lengthsBox;
  QGroupBox* m_programmeBox;
  QGroupBox* m_progressBox;
  QGroupBox* m_sessionsBox;
  QTableView* m_programmeTable;
  HomeDevicesBox* m_homeDevices = nullptr;
  QStandardItemModel* m_programme;
  ProgressChart* m_chart;
  SessionTableModel* m_sessions;
  QSortFilterProxyModel* m_sessionsSorted;
  QTableView* m_sessionTable;
  MessageLine* m_message;
  QPushButton* m_newSession;
  QPushButton* m_review;
  QPushButton* m_delete;
  QPushButton* m_report;
  QPushButton* m_edit;
  QPushButton* m_back;
};

}  // namespace armtrack::gui
