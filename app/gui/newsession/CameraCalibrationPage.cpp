#include "app/gui/newsession/CameraCalibrationPage.h"

#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <memory>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "app/plugins/PluginRegistry.h"
#include "devices/api/Options.h"
#include "ui/Retranslate.h"

namespace armtrack::app::gui {

using devices::webcam::CalibrationError;
using devices::webcam::IntrinsicsResult;
using devices::webcam::NamedImage;

int Coverage::count() const {
  return static_cast<int>(std::count(covered.begin(), covered.end(), true));
}

int Coverage::add(const std::vector<cv::Point2f>& corners, cv::Size image) {
  if (image.width <= 0 || image.height <= 0) return 0;
  int added = 0;
  for (const cv::Point2f& p : corners) {
    const int c = std::clamp(static_cast<int>(p.x / image.width * columns), 0, columns - 1);
    const int r = std::clamp(static_cast<int>(p.y / image.height * rows), 0, rows - 1);
    auto cell = covered.begin() + r * columns + c;
    if (!*cell) {
      *cell = true;
      ++added;
    }
  }
  return added;
}

std::vector<CameraDevice> camerasAmong(const PluginRegistry& registry, const QStringList& specs) {
  std::vector<CameraDevice> cameras;
  for (const QString& spec : specs) {
    const qsizetype colon = spec.indexOf(u':');
    const QString name = spec.left(colon).trimmed();
    devices::DevicePlugin* plugin = registry.plugin(name);
    if (!plugin) continue;
    QString why;
    // Devices open nothing before start(): creating one only reads its options and streams.
    const std::unique_ptr<devices::Device> device =
        plugin->create(devices::Options::parse(colon < 0 ? QString() : spec.mid(colon + 1)), &why);
    if (!device) continue;
    const auto& streams = device->streams();
    if (std::none_of(streams.begin(), streams.end(),
                     [](const StreamInfo& s) { return s.role == StreamRole::Camera; }))
      continue;
    cameras.push_back({spec, name, name == QLatin1String("webcam")});
  }
  return cameras;
}

QString cameraStepText(const std::vector<CameraDevice>& cameras) {
  if (cameras.empty())
    return CameraCalibrationPage::tr(
        "No device among those chosen gives webcam images or marker pixels: nothing to "
        "calibrate here.");
  if (std::any_of(cameras.begin(), cameras.end(), [](const CameraDevice& c) { return c.images; }))
    return {};
  QStringList names;
  for (const CameraDevice& c : cameras) names << c.plugin;
  return CameraCalibrationPage::tr(
             "The webcam of %1 brings its own camera model (it is simulated or replayed), so "
             "there is no chessboard to show it: nothing to calibrate here.")
      .arg(names.join(QStringLiteral(", ")));
}

FrameProvider openWebcam(int index) {
  auto capture = std::make_shared<cv::VideoCapture>();
  auto opened = std::make_shared<bool>(false);
  return [capture, opened, index]() -> cv::Mat {
    if (!*opened) {
      *opened = true;
      capture->open(index, cv::CAP_ANY);
    }
    cv::Mat frame;
    if (capture->isOpened()) capture->read(frame);
    return frame;
  };
}

/// Lives in the page's thread: reads frames, finds the board, keeps views, calibrates.
class CameraCalibrationWorker : public QObject {
  Q_OBJECT
 public:
  CameraCalibrationWorker(FrameProvider provider, devices::webcam::ChessboardSpec board)
      : m_provider(std::move(provider)), m_board(board) {}

  void start() {
    if (!m_timer) {
      m_timer = new QTimer(this);
      connect(m_timer, &QTimer::timeout, this, &CameraCalibrationWorker::tick);
    }
    m_timer->start(66);  // about 15 frames a second: enough to aim the board
  }
  void stop() {
    if (m_timer) m_timer->stop();
  }
  void keep() {
    if (!m_lastFound) return;
    m_views.push_back({"view " + std::to_string(m_views.size() + 1), m_last.clone()});
  }
  void forget() { m_views.clear(); }
  void calibrate() {
    try {
      IntrinsicsResult r = devices::webcam::calibrateIntrinsics(m_views, m_board);
      emit calibrated(r, QString());
    } catch (const std::exception& e) {
      emit calibrated(IntrinsicsResult{}, QString::fromStdString(e.what()));
    }
  }

 signals:
  void frame(const QImage& preview, const std::vector<cv::Point2f>& corners, bool found,
             cv::Size size);
  void cameraProblem(const QString& message);
  void calibrated(const devices::webcam::IntrinsicsResult& result, const QString& error);

 private:
  void tick() {
    cv::Mat f;
    try {
      f = m_provider();
    } catch (const std::exception& e) {
      emit cameraProblem(QString::fromStdString(e.what()));
      return;
    }
    if (f.empty()) {
      if (++m_empty == 30) emit cameraProblem(tr("No picture from the camera."));
      return;
    }
    m_empty = 0;
    cv::Mat gray;
    if (f.channels() == 3)
      cv::cvtColor(f, gray, cv::COLOR_BGR2GRAY);
    else if (f.channels() == 4)
      cv::cvtColor(f, gray, cv::COLOR_BGRA2GRAY);
    else
      gray = f;
    if (gray.depth() != CV_8U) return;
    std::vector<cv::Point2f> corners;
    const bool found = cv::findChessboardCorners(
        gray, m_board.innerCorners, corners,
        cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK);
    m_last = f;
    m_lastFound = found;
    QImage preview(gray.data, gray.cols, gray.rows, static_cast<qsizetype>(gray.step),
                   QImage::Format_Grayscale8);
    emit frame(preview.copy(), found ? corners : std::vector<cv::Point2f>{}, found, gray.size());
  }

  FrameProvider m_provider;
  devices::webcam::ChessboardSpec m_board;
  QTimer* m_timer = nullptr;
  cv::Mat m_last;
  bool m_lastFound = false;
  int m_empty = 0;
  std::vector<NamedImage> m_views;
};

CameraCalibrationPage::CameraCalibrationPage(FrameProvider provider,
                                             devices::webcam::ChessboardSpec board, QWidget* parent)
    : QWidget(parent),
      m_worker(new CameraCalibrationWorker(std::move(provider), board)),
      m_board(board) {
  qRegisterMetaType<std::vector<cv::Point2f>>("std::vector<cv::Point2f>");
  qRegisterMetaType<cv::Size>("cv::Size");
  qRegisterMetaType<devices::webcam::IntrinsicsResult>("devices::webcam::IntrinsicsResult");
  auto* root = new QHBoxLayout(this);
  m_preview = new QLabel(this);
  m_previewText = [] { return tr("Starting the camera\u2026"); };
  m_preview->setMinimumSize(160, 120);
  m_preview->setAlignment(Qt::AlignCenter);
  root->addWidget(m_preview, 3);
  auto* side = new QVBoxLayout;
  m_help = new QLabel(this);
  m_help->setWordWrap(true);
  m_auto = new QCheckBox(this);
  m_auto->setChecked(true);
  m_capture = new QPushButton(this);
  m_capture->setShortcut(QKeySequence(Qt::Key_Space));
  m_calibrate = new QPushButton(this);
  m_reset = new QPushButton(this);
  m_coverageLabel = new QLabel(this);
  m_coverageLabel->setWordWrap(true);
  m_verdict = new QLabel(this);
  m_verdict->setWordWrap(true);
  side->addWidget(m_help);
  side->addWidget(m_auto);
  side->addWidget(m_capture);
  side->addWidget(m_calibrate);
  side->addWidget(m_reset);
  side->addWidget(m_coverageLabel);
  side->addWidget(m_verdict);
  side->addStretch(1);
  root->addLayout(side, 2);

  m_worker->moveToThread(&m_thread);
  connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
  m_thread.setObjectName(QStringLiteral("armtrack-camera"));
  m_thread.start();
  connect(m_worker, &CameraCalibrationWorker::frame, this, &CameraCalibrationPage::showFrame);
  connect(m_worker, &CameraCalibrationWorker::cameraProblem, this, [this](const QString& why) {
    m_previewText = [why] {
      return why + QLatin1Char(' ') +
             tr("Check that the camera is plugged in and not used by another program.");
    };
    m_preview->setText(m_previewText());
  });
  connect(m_worker, &CameraCalibrationWorker::calibrated, this,
          [this](const IntrinsicsResult& r, const QString& error) {
            m_calibrate->setEnabled(true);
            if (!error.isEmpty()) {
              showVerdict([error] { return tr("Could not calibrate: %1").arg(error); });
              emit calibrated(false);
              emit completeChanged();
              return;
            }
            m_result = r;
            const double rms = r.intrinsics.rmsPx;
            const double covered = m_coverage.fraction();
            showVerdict([r, rms, covered] {
              const QString numbers =
                  tr("Reprojection error %L1 px over %2 views; fx %L3, fy %L4 px.")
                      .arg(rms, 0, 'f', 2)
                      .arg(r.intrinsics.boards)
                      .arg(r.intrinsics.fx, 0, 'f', 1)
                      .arg(r.intrinsics.fy, 0, 'f', 1);
              QString verdict;
              if (rms < 0.5)
                verdict = tr("Good.");
              else if (rms < 1.0)
                verdict = tr("Usable; more views, sharper and better lit, would improve it.");
              else
                verdict = tr("Poor: capture the views again, holding the board still and flat.");
              if (covered < 0.6)
                verdict += QLatin1Char(' ') + tr("The boards covered only %1 % of the picture; "
                                                 "views near the edges help most.")
                                                  .arg(std::lround(100 * covered));
              return numbers + QLatin1Char(' ') + verdict;
            });
            emit calibrated(rms < 1.0);
            emit completeChanged();
          });
  connect(m_capture, &QPushButton::clicked, this, &CameraCalibrationPage::capture);
  connect(m_calibrate, &QPushButton::clicked, this, &CameraCalibrationPage::calibrate);
  connect(m_reset, &QPushButton::clicked, this, &CameraCalibrationPage::reset);
  retranslateUi();
}

void CameraCalibrationPage::retranslateUi() {
  setAccessibleName(tr("Camera calibration"));
  if (m_preview->pixmap().isNull()) m_preview->setText(m_previewText());
  m_preview->setAccessibleName(tr("Camera picture"));
  m_help->setText(
      tr("Hold the printed chessboard (%1 x %2 inner corners) in front of the camera. Capture "
         "views with the board in every part of the picture, near and far, tilted a little.")
          .arg(m_board.innerCorners.width)
          .arg(m_board.innerCorners.height));
  m_auto->setText(tr("Capture &automatically when the board covers new ground"));
  ui::setButtonText(m_capture, tr("&Capture view"));
  m_calibrate->setText(tr("Ca&librate"));
  m_reset->setText(tr("&Start over"));
  m_coverageLabel->setAccessibleName(tr("Coverage"));
  m_verdict->setAccessibleName(tr("Camera calibration verdict"));
  if (m_verdictText) m_verdict->setText(m_verdictText());
  updateCoverageText();
}

void CameraCalibrationPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QWidget::changeEvent(event);
}

void CameraCalibrationPage::showVerdict(std::function<QString()> text) {
  m_verdictText = std::move(text);
  m_verdict->setText(m_verdictText ? m_verdictText() : QString());
}

CameraCalibrationPage::~CameraCalibrationPage() {
  QMetaObject::invokeMethod(m_worker, &CameraCalibrationWorker::stop);
  m_thread.quit();
  m_thread.wait();
}

void CameraCalibrationPage::startCamera() {
  QMetaObject::invokeMethod(m_worker, &CameraCalibrationWorker::start);
}

void CameraCalibrationPage::stopCamera() {
  QMetaObject::invokeMethod(m_worker, &CameraCalibrationWorker::stop);
}

void CameraCalibrationPage::showFrame(const QImage& preview,
                                      const std::vector<cv::Point2f>& corners, bool found,
                                      cv::Size size) {
  ++m_frames;
  m_found = found;
  m_lastCorners = corners;
  m_lastSize = size;
  QImage shown = preview.convertToFormat(QImage::Format_RGB32);
  {
    QPainter p(&shown);
    p.setRenderHint(QPainter::Antialiasing);
    // The coverage grid: covered cells tinted green.
    const double cw = double(shown.width()) / m_coverage.columns;
    const double ch = double(shown.height()) / m_coverage.rows;
    for (int r = 0; r < m_coverage.rows; ++r)
      for (int c = 0; c < m_coverage.columns; ++c)
        if (m_coverage.covered[static_cast<std::size_t>(r * m_coverage.columns + c)])
          p.fillRect(QRectF(c * cw, r * ch, cw, ch), QColor(40, 200, 80, 60));
    p.setPen(QPen(QColor(255, 255, 255, 90), 1));
    for (int c = 1; c < m_coverage.columns; ++c)
      p.drawLine(QPointF(c * cw, 0), QPointF(c * cw, shown.height()));
    for (int r = 1; r < m_coverage.rows; ++r)
      p.drawLine(QPointF(0, r * ch), QPointF(shown.width(), r * ch));
    p.setPen(QPen(found ? QColor(40, 220, 90) : QColor(230, 60, 60), 2));
    for (const cv::Point2f& pt : corners) p.drawEllipse(QPointF(pt.x, pt.y), 3, 3);
  }
  m_preview->setPixmap(QPixmap::fromImage(shown).scaled(m_preview->size(), Qt::KeepAspectRatio,
                                                        Qt::SmoothTransformation));
  m_capture->setEnabled(found);
  if (found && m_auto->isChecked()) {
    // Automatic: keep a view that covers new cells, or whose board sits away from every kept one.
    Coverage probe = m_coverage;
    const bool adds = probe.add(corners, size) > 0;
    cv::Point2f centre(0, 0);
    for (const cv::Point2f& c : corners) centre += c;
    centre *= 1.0f / static_cast<float>(corners.size());
    bool far = true;
    for (const cv::Point2f& c : m_lastCentres)
      far = far && cv::norm(c - centre) > 0.12 * std::max(size.width, size.height);
    if (adds || (far && m_views < 20)) capture();
  }
}

void CameraCalibrationPage::capture() {
  if (!m_found || m_lastCorners.empty()) return;
  QMetaObject::invokeMethod(m_worker, &CameraCalibrationWorker::keep);
  m_coverage.add(m_lastCorners, m_lastSize);
  cv::Point2f centre(0, 0);
  for (const cv::Point2f& c : m_lastCorners) centre += c;
  m_lastCentres.push_back(centre * (1.0f / static_cast<float>(m_lastCorners.size())));
  ++m_views;
  updateCoverageText();
}

void CameraCalibrationPage::calibrate() {
  if (m_views < 4) {
    showVerdict([views = m_views] {
      return tr("Capture at least 4 views first (%1 so far); 10 or more spread over the picture "
                "give a good calibration.")
          .arg(views);
    });
    return;
  }
  m_calibrate->setEnabled(false);
  showVerdict([] { return tr("Calibrating\u2026"); });
  QMetaObject::invokeMethod(m_worker, &CameraCalibrationWorker::calibrate);
}

void CameraCalibrationPage::reset() {
  QMetaObject::invokeMethod(m_worker, &CameraCalibrationWorker::forget);
  m_coverage = Coverage{};
  m_views = 0;
  m_lastCentres.clear();
  m_result.reset();
  showVerdict({});
  updateCoverageText();
  emit completeChanged();
}

void CameraCalibrationPage::updateCoverageText() {
  m_coverageLabel->setText(tr("%1 views kept; the boards cover %2 % of the picture.")
                               .arg(m_views)
                               .arg(std::lround(100 * m_coverage.fraction())));
}

QString CameraCalibrationPage::verdictText() const {
  return m_verdict->text();
}

bool CameraCalibrationPage::isComplete() const {
  return m_result && m_result->intrinsics.rmsPx < 1.0;
}

}  // namespace armtrack::app::gui

#include "CameraCalibrationPage.moc"
