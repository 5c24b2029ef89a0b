// The first screen: today's exercises from the therapist, which of them can be measured with
// this set-up, how the patient presses (keyboard, or a single switch), Start and Sign out.
#pragma once

#include "app/gui/home/HomeScreen.h"
#include "app/gui/home/SwitchAccess.h"
#include "app/gui/services/HomeRecords.h"

class QLabel;
class QPushButton;

namespace armtrack::gui::home {

class HomeStartScreen : public HomeScreen {
  Q_OBJECT
 public:
  /// withClinic: offer "Connect to the clinic" (the install syncs with a clinic).
  HomeStartScreen(const HomePlan& plan, bool opticalConfigured, AccessMode mode,
                  QWidget* parent = nullptr, bool withClinic = false);
  QPushButton* clinicButton() const { return m_clinic; }

  QList<QAbstractButton*> choices() const override;
  QAbstractButton* defaultChoice() const override;
  /// The programme as shown, one line per exercise (for tests and screen readers).
  QStringList exerciseLines() const { return m_lines; }
  QString measurementNote() const;

 signals:
  void startRequested();
  void signOutRequested();
  /// The patient wants to enter the clinic's address and code (only when the install syncs).
  void clinicRequested();
  void accessModeChosen(armtrack::gui::home::AccessMode mode);

 protected:
  void retranslate() override;

 private:
  void showMode();

  HomePlan m_plan;
  bool m_optical;
  AccessMode m_mode;
  QStringList m_lines;
  QLabel* m_hello;
  QLabel* m_intro;
  QList<QLabel*> m_lineLabels;
  QLabel* m_note;
  QPushButton* m_start;
  QPushButton* m_access;
  QPushButton* m_signOut;
  QPushButton* m_clinic;
};

/// "Elbow flexion: 2 sets of 5 repetitions, 20 s rest" (translated).
QString exerciseLine(const HomeExercise& e);
/// The patient's first name, for a greeting.
QString firstName(const QString& name);

}  // namespace armtrack::gui::home
