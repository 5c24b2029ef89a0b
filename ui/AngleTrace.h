// The clinical angles over time as the plots and tables show them: degrees at this boundary
// (the session and the records are SI), with each angle's 1-sigma uncertainty, and the
// decimation that turns thousands of samples into a couple of points per pixel column.
#pragma once

#include <QPointF>
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <vector>

#include "core/kinematics/ArmModel.h"

namespace armtrack::session {
struct EstimateRow;
}

namespace armtrack::ui {

inline constexpr int kAngleCount = 5;
/// Trunk flexion, lateral bending and axial rotation.
inline constexpr int kTrunkAngleCount = 3;
inline constexpr double kNoAngle = std::numeric_limits<double>::quiet_NaN();

/// The five clinical angles at one time, in the order and signs of clinicalAngleInfo().
struct AngleSample {
  double t = 0.0;                              ///< s
  std::array<double, kAngleCount> deg{};       ///< degrees; NaN where unknown
  std::array<double, kAngleCount> sigmaDeg{};  ///< 1-sigma (deg); 0 when not known
  /// No camera or Kinect for a while: the shoulder's heading rests on the start pose alone.
  bool headingFromStartPose = false;
  /// No new IMU data: the estimate is the filter's prediction (a sensor is lost).
  bool predicted = false;
  /// The trunk's flexion, lateral bending and axial rotation (degrees, patient terms,
  /// core/kinematics/Trunk.h) when a sternum sensor measures them; NaN otherwise.
  std::array<double, kTrunkAngleCount> trunkDeg{kNoAngle, kNoAngle, kNoAngle};
  std::array<double, kTrunkAngleCount> trunkSigmaDeg{};  ///< 1-sigma (deg); 0 when not known
  bool hasTrunk() const;
};

/// An estimate as clinical angles (degrees) with its uncertainty.
AngleSample angleSample(double t, const JointVector& thRad, const JointVector& thStdRad);
AngleSample angleSample(const session::EstimateRow& row);
/// Sets the sample's trunk angles from radians (NaN: not measured) and their 1-sigma (NaN: not
/// known).
void setTrunk(AngleSample& s, const Eigen::Vector3d& trunkRad, const Eigen::Vector3d& sdRad);

/// The samples of one series, in time order. Live: old samples beyond keepSeconds are dropped;
/// review: keepSeconds = infinity keeps everything. Samples out of time order or with a
/// non-finite time are refused and counted; a non-finite angle is kept as a gap in that angle.
class AngleTrace {
 public:
  explicit AngleTrace(double keepSeconds = std::numeric_limits<double>::infinity())
      : m_keep(keepSeconds) {}

  void setKeepSeconds(double s) { m_keep = s; }
  /// Samples kept by append() since construction (never decreases, also not on clear()): with
  /// clears(), how an incremental reader (ColumnDecimator) finds what is new.
  std::uint64_t appended() const { return m_appended; }
  std::uint64_t clears() const { return m_clears; }
  /// Appends in time order; returns how many were kept.
  std::size_t append(const std::vector<AngleSample>& rows);
  void clear();

  const std::deque<AngleSample>& samples() const { return m_rows; }
  bool empty() const { return m_rows.empty(); }
  double firstTime() const { return m_rows.empty() ? 0.0 : m_rows.front().t; }
  double lastTime() const { return m_rows.empty() ? 0.0 : m_rows.back().t; }
  /// The newest sample at or before t (the last one when t is past the end); nullptr if none.
  const AngleSample* at(double t) const;
  std::size_t refused() const { return m_refused; }

  /// Index of the first sample with time >= t.
  std::size_t lowerBound(double t) const;

 private:
  std::deque<AngleSample> m_rows;
  double m_keep;
  std::size_t m_refused = 0;
  std::uint64_t m_appended = 0, m_clears = 0;
};

/// One angle of a trace reduced for a plot of `columns` pixel columns spanning [t0, t1]: per
/// column, the smallest and largest value in the order they occur (so peaks survive), or the one
/// value there is. Non-finite values are skipped; values are clamped to +-limitDeg so that an
/// absurd one cannot wreck the axis. At most 2 x columns points; plus the last sample before t0
/// and the first after t1, so lines run to the plot's edges.
void decimateAngle(const AngleTrace& trace, int angle, double t0, double t1, int columns,
                   std::vector<QPointF>& out, double limitDeg = 720.0);

/// The +-k sigma envelope of one angle, one upper and one lower point per column (the column's
/// widest extent).
void decimateBand(const AngleTrace& trace, int angle, double t0, double t1, int columns, double k,
                  std::vector<QPointF>& upper, std::vector<QPointF>& lower,
                  double limitDeg = 720.0);

/// The live plots' decimation, kept from one redraw to the next. Its columns are anchored to
/// absolute time (column k spans [k w, (k + 1) w)), so a finished column never changes and a
/// redraw only folds in the samples appended since the last one, whatever the window's length.
/// Per column it keeps what decimateAngle() and decimateBand() keep: the smallest and largest
/// value in time order, and the widest +-k sigma extent at the column's mean sample time.
class ColumnDecimator {
 public:
  /// Folds in the trace's new samples of one angle. A different column width, band factor or
  /// limit, or a cleared trace, starts again from the trace's samples. Columns older than the
  /// trace's first sample are forgotten.
  void update(const AngleTrace& trace, int angle, double columnSeconds, double k,
              double limitDeg = 720.0);
  /// The points of the columns that reach into [t0, t1], plus the column before (so a line
  /// runs to the left edge), in time order: at most 2 per column for the line, 1 for each band.
  void points(double t0, double t1, std::vector<QPointF>& line, std::vector<QPointF>& upper,
              std::vector<QPointF>& lower) const;
  std::size_t columns() const { return m_columns.size(); }
  void clear();

 private:
  struct Column {
    std::int64_t index = 0;
    QPointF lo, hi;  // the line's extremes (count > 0)
    int count = 0;
    double bandHi = 0, bandLo = 0, tSum = 0;
    int bandCount = 0;
  };
  void fold(const AngleSample& s);
  std::deque<Column> m_columns;
  double m_width = 0, m_k = 0, m_limit = 0;
  int m_angle = -1;
  std::uint64_t m_seen = 0, m_clears = 0;
};

}  // namespace armtrack::ui
