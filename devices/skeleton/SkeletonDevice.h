// The skeleton device: elbow, wrist and shoulder positions from an external body tracker, one JSON
// object per UDP datagram. See docs/devices/skeleton-udp.md, "Using the plugin".
#pragma once

#include <Eigen/Core>
#include <QByteArray>
#include <QString>
#include <QVariantMap>
#include <cstdint>
#include <memory>
#include <optional>

#include "core/io/Recording.h"
#include "devices/api/Device.h"
#include "devices/api/ProblemLimiter.h"
#include "devices/skeleton/SkeletonParser.h"
#include "devices/skeleton/StartOrigin.h"

class QTimer;
class QUdpSocket;

namespace armtrack::devices::skeleton {

/// Where the published positions are measured from.
enum class Origin {
  Shoulder,  ///< elbow and wrist minus the tracked shoulder; frames need a shoulder
  /// The world frame: minus where the tracked shoulder was in the first second (StartOrigin),
  /// fixed; the shoulder is published too, so a leaning trunk moves it.
  Start,
  Camera,  ///< as sent: the tracker's own frame (with camera=, the registered frame)
};

/// What the plugin's options select.
struct SkeletonSettings {
  std::uint16_t port = 9870;      ///< local UDP port the tracker sends to
  Origin origin = Origin::Start;  ///< see Origin
  double timeoutSeconds = 3.0;    ///< s without a frame: back to Connecting
  /// From camera=FILE: the tracker camera, whose pose (p_camera = R p_shoulder + t, m) turns
  /// tracker axes into shoulder-frame axes; only R and t are used. Empty with axes=shoulder,
  /// when the tracker already sends shoulder-frame axes.
  std::optional<CameraParams> pose;
};

/// Reads `port`, `origin` (shoulder, start or camera), `timeout` and the registration:
/// `camera=FILE` (a camera file with its pose, from armtrack-cli camera-register) or
/// `axes=shoulder`; one of the two is required, since published positions must be in the shoulder
/// frame. Empty, with *error saying what to change, when an option is malformed, unknown or
/// missing. Any thread.
std::optional<SkeletonSettings> readSkeletonSettings(const QVariantMap& options, QString* error);

/// An external tracker as one Optical stream (OpticalPositions, m). Listens on the UDP port on all
/// addresses; Connecting until the first frame, then Streaming; no frame for `timeoutSeconds`
/// sets Connecting ("no data") and frames coming back count as a reconnect. A port already in
/// use is an Error. Device time is the frame's "t" (s); gaps in "frame" count as dropped.
/// Positions are published in the registered axes: with a pose, elbow and wrist become
/// R^T (p - shoulder) (origin shoulder), R^T (p - s0) (origin start, s0 the shoulder's start
/// position) or R^T (p - t) (origin camera). With origin start or camera the positions are in the
/// world frame (docs/recording-format.md, "Trunk") and the shoulder is published as well, in the
/// same frame; with origin shoulder it is not (it would always be zero). Frames without elbow and
/// wrist, with origin shoulder without a shoulder, or with origin start before any shoulder was
/// seen, publish nothing and are reported, rate-limited.
/// Threads: construct anywhere, then use only from the device's thread (see Device).
class SkeletonDevice final : public Device {
  Q_OBJECT
 public:
  explicit SkeletonDevice(const SkeletonSettings& settings, QObject* parent = nullptr);
  ~SkeletonDevice() override;

 public slots:
  void start() override;
  void stop() override;

 private:
  void onReadyRead();
  void onSilence();
  void fail(const QString& reason);
  /// A tracker-axes vector in shoulder-frame axes (R^T v with a pose, else v).
  Eigen::Vector3d toShoulderAxes(const Eigen::Vector3d& v) const;

  const SkeletonSettings m_settings;
  QUdpSocket* m_socket = nullptr;  // children, created in start()
  QTimer* m_silenceTimer = nullptr;
  std::unique_ptr<ProblemLimiter> m_problems;  // one problem message per second at most
  bool m_running = false;

  SkeletonParser m_parser;
  QByteArray m_datagram;  // reused between reads
  StartOrigin m_start;    // origin=start: the world origin, found again at each start()
  std::uint64_t m_errorsSeen = 0;
  std::uint64_t m_droppedSeen = 0;
  std::uint64_t m_reorderedSeen = 0;
  std::uint64_t m_duplicatesSeen = 0;
  bool m_streaming = false;
  bool m_everStreamed = false;  // a later Streaming counts as a reconnect
};

}  // namespace armtrack::devices::skeleton
