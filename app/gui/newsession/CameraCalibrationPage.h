// New session, camera calibration: the webcam's intrinsics from chessboard views. Frames come
// from the camera in a worker thread, which finds the board in each (the preview shows it),
// keeps the views the user captures (or that add coverage, in automatic mode) and calibrates
// them (devices/webcam's calibrateIntrinsics, as armtrack-cli camera-calibrate does). The page
// shows which parts of the image the captured boards cover and the reprojection error.
#pragma once

#include <QImage>
#include <QThread>
#include <QWidget>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "devices/vision/CameraCalibration.h"

class QCheckBox;
class QLabel;
class QPushButton;

namespace armtrack::app {
class PluginRegistry;
}

namespace armtrack::app::gui {

/// Where frames come from: called in the worker thread, returns the next frame (8-bit BGR or
/// gray) or an empty Mat when none is ready. openWebcam() opens a camera with OpenCV.
using FrameProvider = std::function<cv::Mat()>;
/// A webcam by index (0 = the first) or a video file; the provider reports an empty Mat when the
/// camera cannot be read. Opened in the thread that first calls it.
FrameProvider openWebcam(int index);

/// A device among a session's that gives webcam marker pixels (a stream of StreamRole::Camera as
/// its plugin creates it, not started).
struct CameraDevice {
  QString spec;    ///< "plugin:options" as chosen
  QString plugin;  ///< the plugin's name
  /// It reads a real camera's images (the webcam plugin), so a chessboard can calibrate it; the
  /// others (the virtual arm's simulated webcam, a replay) bring their camera model along.
  bool images = false;
};

/// The devices among specs that give webcam marker pixels, in order. A spec whose plugin is not
/// loaded or refuses its options is left out (the devices step says why).
std::vector<CameraDevice> camerasAmong(const PluginRegistry& registry, const QStringList& specs);

/// What the camera step says when none of cameras reads a real camera's images (empty when one
/// does: the chessboard page is shown).
QString cameraStepText(const std::vector<CameraDevice>& cameras);

/// The grid cells (columns x rows over the image) that corners of the boards fall in.
struct Coverage {
  int columns = 6, rows = 4;
  std::vector<bool> covered = std::vector<bool>(24, false);
  int count() const;
  double fraction() const { return covered.empty() ? 0.0 : double(count()) / covered.size(); }
  /// Marks the cells of these corners; returns how many were new.
  int add(const std::vector<cv::Point2f>& corners, cv::Size image);
};

class CameraCalibrationWorker;

class CameraCalibrationPage : public QWidget {
  Q_OBJECT
 public:
  /// provider: the camera (openWebcam) or a test's frames. board: the printed chessboard.
  CameraCalibrationPage(FrameProvider provider, devices::webcam::ChessboardSpec board,
                        QWidget* parent = nullptr);
  ~CameraCalibrationPage() override;

  /// Starts showing frames (the camera is opened in the worker thread).
  void startCamera();
  void stopCamera();

  int capturedViews() const { return m_views; }
  const Coverage& coverage() const { return m_coverage; }
  bool boardInView() const { return m_found; }
  std::uint64_t framesSeen() const { return m_frames; }
  /// The calibration, once made.
  const std::optional<devices::webcam::IntrinsicsResult>& result() const { return m_result; }
  QString verdictText() const;
  /// Calibrated with a reprojection error under 1 pixel.
  bool isComplete() const;
  QCheckBox* automaticBox() const { return m_auto; }

 public slots:
  /// Keeps the current view if the board is found in it.
  void capture();
  /// Calibrates from the views kept (in the worker thread).
  void calibrate();
  /// Forgets the views and the result.
  void reset();

 signals:
  void completeChanged();
  void calibrated(bool good);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void showFrame(const QImage& preview, const std::vector<cv::Point2f>& corners, bool found,
                 cv::Size size);
  void updateCoverageText();
  /// Shows the verdict, made again when the language changes.
  void showVerdict(std::function<QString()> text);

  QThread m_thread;
  CameraCalibrationWorker* m_worker;
  devices::webcam::ChessboardSpec m_board;
  QLabel* m_preview;
  QLabel* m_help;
  std::function<QString()> m_verdictText, m_previewText;
  QLabel* m_coverageLabel;
  QLabel* m_verdict;
  QPushButton* m_capture;
  QPushButton* m_calibrate;
  QPushButton* m_reset;
  QCheckBox* m_auto;
  Coverage m_coverage;
  int m_views = 0;
  bool m_found = false;
  std::uint64_t m_frames = 0;
  std::optional<devices::webcam::IntrinsicsResult> m_result;
  std::vector<cv::Point2f> m_lastCorners;
  cv::Size m_lastSize;
  std::vector<cv::Point2f> m_lastCentres;  // board centres of the views kept
};

}  // namespace armtrack::app::gui
