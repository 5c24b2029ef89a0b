// The new-session wizard's steps after "patient, protocol and arm": the device check, the
// guided sensor calibration and, with a webcam, its chessboard calibration (the pages of
// app/gui/newsession), each hosted in a QWizardPage that builds it when the step is entered, so
// it starts from the choices made before it.
#pragma once

#include <QWizardPage>
#include <functional>
#include <memory>
#include <optional>

#include "app/gui/common/Forms.h"
#include "core/calibration/Calibration.h"

class QCheckBox;
class QVBoxLayout;

namespace armtrack::gui {

/// A wizard step around a page widget with isComplete() and a completeChanged() signal.
class WidgetStep : public QWizardPage {
  Q_OBJECT
 public:
  using Make = std::function<QWidget*()>;
  using Check = std::function<bool(QWidget*)>;
  /// make builds the page when the step is entered; complete says whether it may be left;
  /// leave runs when Next is pressed (false keeps the step). skipText, when given, offers a check
  /// box that makes the step complete without its page. The texts follow a change of language.
  WidgetStep(TextFn title, TextFn subTitle, Make make, Check complete, Check leave = {},
             TextFn skipText = {}, QWidget* parent = nullptr);

  void initializePage() override;
  void cleanupPage() override;
  bool isComplete() const override;
  bool validatePage() override;
  QWidget* page() const { return m_page; }
  bool skipped() const;
  void setSkipped(bool skip);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();

  TextFn m_title, m_subTitle, m_skipText;
  Make m_make;
  Check m_complete, m_leave;
  QCheckBox* m_skip = nullptr;
  QVBoxLayout* m_layout;
  QWidget* m_page = nullptr;
};

/// What the steps decided, for the live session.
struct NewSessionChoices {
  QStringList devices;                     ///< "plugin:options" specs
  std::optional<Calibration> calibration;  ///< the sensor calibration made, if any
  QString calibrationFile;                 ///< where it was saved
  /// Its verdict ("good", "usable", "poor") and reason, stored with the session for the report.
  QString calibrationVerdict, calibrationReason;
};

/// The specs the virtual arm needs to play the calibration protocol (its other options kept);
/// other devices unchanged.
QStringList calibrationDevices(const QStringList& devices);

}  // namespace armtrack::gui
