// The plots' data path: estimates to clinical degrees, the trace's window, and the decimation
// against a brute-force reduction of the same samples.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "core/kinematics/ClinicalAngles.h"
#include "core/session/Session.h"
#include "ui/AngleTableModel.h"
#include "ui/AngleTrace.h"

namespace armtrack::ui {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

TEST(AngleSample, IsTheClinicalAnglesInDegreesWithTheirUncertainty) {
  session::EstimateRow row;
  row.t = 1.5;
  row.th << 0.3, -0.2, 0.4, -1.2, 0.5;
  row.thStd << 0.01, 0.02, 0.5, 0.001, 0.003;
  const AngleSample s = angleSample(row);
  const auto expected = asArray(toClinical(row.th));
  for (int i = 0; i < kAngleCount; ++i) {
    EXPECT_DOUBLE_EQ(s.deg[i], expected[i]);
    EXPECT_NEAR(s.sigmaDeg[i], row.thStd(i) * 180.0 / std::numbers::pi, 1e-12);
  }
  EXPECT_NEAR(s.deg[3], 1.2 * 180 / std::numbers::pi, 1e-9);  // elbow flexion = -th4
  // One unknown joint leaves the others.
  row.th(2) = kNan;
  const AngleSample p = angleSample(row);
  EXPECT_TRUE(std::isnan(p.deg[2]));
  EXPECT_DOUBLE_EQ(p.deg[0], expected[0]);
  EXPECT_DOUBLE_EQ(p.deg[4], expected[4]);
}

TEST(AngleSample, NamesAreTheClinicalAngleNames) {
  for (int i = 0; i < kAngleCount; ++i)
    EXPECT_EQ(angleDisplayName(i).toStdString(), std::string(clinicalAngleInfo()[i].name));
  EXPECT_TRUE(angleDisplayName(5).isEmpty());
}

TEST(AngleTrace, KeepsItsWindowAndRefusesDisorder) {
  AngleTrace trace(10.0);
  std::vector<AngleSample> rows;
  for (int k = 0; k < 30000; ++k) rows.push_back({k * 1e-3, {1, 2, 3, 4, 5}, {}});
  EXPECT_EQ(trace.append(rows), rows.size());
  EXPECT_NEAR(trace.lastTime(), 29.999, 1e-9);
  EXPECT_LE(trace.firstTime(), 29.999 - 10.0);
  EXPECT_GT(trace.firstTime(), 29.999 - 10.01);
  AngleSample back{5.0, {}, {}}, inf{std::numeric_limits<double>::infinity(), {}, {}},
      nanT{kNan, {}, {}};
  EXPECT_EQ(trace.append({back, inf, nanT}), 0u);
  EXPECT_EQ(trace.refused(), 3u);
  EXPECT_EQ(trace.at(25.0)->t, 25.0);
  EXPECT_NEAR(trace.at(25.0005)->t, 25.0, 1e-12);
  EXPECT_EQ(trace.at(0.0), nullptr);
  EXPECT_NEAR(trace.at(1e9)->t, 29.999, 1e-9);
}

TEST(Decimation, KeepsEveryColumnsExtremesAndNoMoreThanTwoPointsPerColumn) {
  std::mt19937 rng(4);
  std::normal_distribution<double> noise(0, 20);
  AngleTrace trace;
  std::vector<AngleSample> rows;
  for (int k = 0; k < 20000; ++k) {
    AngleSample s;
    s.t = k * 1e-3;
    s.deg[1] = 50 * std::sin(s.t) + noise(rng);
    if (k % 977 == 0) s.deg[1] = kNan;
    if (k == 5000) s.deg[1] = 1e30;  // absurd: clamped
    s.sigmaDeg[1] = 2.0 + (k % 7);
    rows.push_back(s);
  }
  trace.append(rows);
  const double t0 = 3.0, t1 = 17.0;
  const int columns = 300;
  std::vector<QPointF> out;
  decimateAngle(trace, 1, t0, t1, columns, out, 720.0);
  EXPECT_LE(out.size(), 2u * columns + 2u);
  EXPECT_GT(out.size(), static_cast<std::size_t>(columns));
  for (std::size_t i = 1; i < out.size(); ++i) ASSERT_LE(out[i - 1].x(), out[i].x());
  for (const QPointF& p : out) ASSERT_TRUE(std::isfinite(p.y()) && std::abs(p.y()) <= 720.0);
  // Brute force: each column's min and max are among the points.
  std::vector<double> lo(columns, 1e300), hi(columns, -1e300);
  for (const AngleSample& s : rows) {
    if (s.t < t0 || s.t > t1 || !std::isfinite(s.deg[1])) continue;
    const int c = std::clamp(static_cast<int>((s.t - t0) / (t1 - t0) * columns), 0, columns - 1);
    const double v = std::clamp(s.deg[1], -720.0, 720.0);
    lo[c] = std::min(lo[c], v);
    hi[c] = std::max(hi[c], v);
  }
  for (int c = 0; c < columns; ++c) {
    bool foundLo = false, foundHi = false;
    for (const QPointF& p : out) {
      foundLo |= p.y() == lo[c];
      foundHi |= p.y() == hi[c];
    }
    ASSERT_TRUE(foundLo && foundHi) << "column " << c;
  }
  EXPECT_LT(out.front().x(), t0);  // runs to the left edge
  EXPECT_GT(out.back().x(), t1);

  std::vector<QPointF> upper, lower;
  decimateBand(trace, 1, t0, t1, columns, 2.0, upper, lower);
  ASSERT_EQ(upper.size(), lower.size());
  EXPECT_LE(upper.size(), static_cast<std::size_t>(columns));
  for (std::size_t i = 0; i < upper.size(); ++i) EXPECT_GE(upper[i].y() - lower[i].y(), 8.0);
}

TEST(Decimation, EmptyAndDegenerateInputs) {
  AngleTrace trace;
  std::vector<QPointF> out{{1, 1}};
  decimateAngle(trace, 0, 0, 10, 100, out);
  EXPECT_TRUE(out.empty());
  trace.append({{1.0, {kNan, kNan, kNan, kNan, kNan}, {}}});
  decimateAngle(trace, 0, 0, 10, 100, out);
  EXPECT_TRUE(out.empty());
  trace.append({{2.0, {5, 5, 5, 5, 5}, {}}});
  decimateAngle(trace, 0, 0, 10, 0, out);
  EXPECT_TRUE(out.empty());
  decimateAngle(trace, 0, 10, 10, 100, out);
  EXPECT_TRUE(out.empty());
  decimateAngle(trace, 0, 0, 10, 1, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0], QPointF(2.0, 5.0));
}

// The live plots' incremental decimation, fed in uneven batches through a trace that drops its
// oldest samples, against a brute-force reduction of the samples into the same time-anchored
// columns.
TEST(ColumnDecimator, FedInBatchesKeepsEachColumnsExtremesAndBand) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0, 15);
  std::uniform_int_distribution<int> batch(1, 90);
  AngleTrace trace(21.0);
  ColumnDecimator decimator;
  std::vector<AngleSample> all;
  const double width = 20.0 / 317;  // an awkward column width
  int k = 0;
  while (k < 40000) {
    std::vector<AngleSample> rows;
    for (int n = batch(rng); n > 0; --n, ++k) {
      AngleSample s;
      s.t = k * 1e-3;
      s.deg[2] = 60 * std::sin(0.7 * s.t) + noise(rng);
      if (k % 613 == 0) s.deg[2] = kNan;  // a gap
      if (k == 33333) s.deg[2] = -1e30;   // absurd
      s.sigmaDeg[2] = k % 101 == 0 ? std::numeric_limits<double>::infinity() : 1.0 + k % 5;
      rows.push_back(s);
      all.push_back(s);
    }
    trace.append(rows);
    decimator.update(trace, 2, width, 2.0, 720.0);
  }
  const double t1 = trace.lastTime(), t0 = t1 - 20.0;
  std::vector<QPointF> line, upper, lower;
  decimator.points(t0, t1, line, upper, lower);
  // Brute force over the same columns, from every sample ever appended.
  struct Col {
    double lo = 1e300, hi = -1e300, bandHi = -1e300, bandLo = 1e300, tSum = 0;
    int n = 0, bandN = 0;
  };
  std::map<std::int64_t, Col> cols;
  const auto first = static_cast<std::int64_t>(std::floor(t0 / width)) - 1;
  for (const AngleSample& s : all) {
    const auto c = static_cast<std::int64_t>(std::floor(s.t / width));
    if (c < first || !std::isfinite(s.deg[2])) continue;
    Col& col = cols[c];
    const double v = std::clamp(s.deg[2], -720.0, 720.0);
    col.lo = std::min(col.lo, v);
    col.hi = std::max(col.hi, v);
    ++col.n;
    if (!std::isfinite(s.sigmaDeg[2])) continue;
    col.bandHi = std::max(col.bandHi, s.deg[2] + 2 * s.sigmaDeg[2]);
    col.bandLo = std::min(col.bandLo, s.deg[2] - 2 * s.sigmaDeg[2]);
    col.tSum += s.t;
    ++col.bandN;
  }
  ASSERT_GT(cols.size(), 300u);
  EXPECT_LE(line.size(), 2 * cols.size());
  for (std::size_t i = 1; i < line.size(); ++i) ASSERT_LE(line[i - 1].x(), line[i].x());
  std::size_t bandColumns = 0;
  for (const auto& [c, col] : cols) {
    bool foundLo = false, foundHi = false;
    for (const QPointF& p : line) {
      if (static_cast<std::int64_t>(std::floor(p.x() / width)) != c) continue;
      foundLo |= p.y() == col.lo;
      foundHi |= p.y() == col.hi;
    }
    ASSERT_TRUE(foundLo && foundHi) << "column " << c;
    if (col.bandN > 0) ++bandColumns;
  }
  ASSERT_EQ(upper.size(), bandColumns);
  ASSERT_EQ(lower.size(), bandColumns);
  std::size_t i = 0;
  for (const auto& [c, col] : cols) {
    if (col.bandN == 0) continue;
    EXPECT_NEAR(upper[i].x(), col.tSum / col.bandN, 1e-9);
    EXPECT_DOUBLE_EQ(upper[i].y(), std::clamp(col.bandHi, -720.0, 720.0)) << "column " << c;
    EXPECT_DOUBLE_EQ(lower[i].y(), std::clamp(col.bandLo, -720.0, 720.0)) << "column " << c;
    ++i;
  }
  EXPECT_LE(line.front().x(), t0);  // runs to the left edge
  // It keeps only what the trace keeps (plus a column).
  EXPECT_LE(decimator.columns(), static_cast<std::size_t>(21.0 / width) + 3);
}

TEST(ColumnDecimator, StartsAgainOnAClearedTraceOrANewWidth) {
  AngleTrace trace;
  ColumnDecimator d;
  std::vector<QPointF> line, upper, lower;
  trace.append({{1.0, {10, 0, 0, 0, 0}, {1, 0, 0, 0, 0}}, {1.5, {20, 0, 0, 0, 0}, {}}});
  d.update(trace, 0, 1.0, 2.0);
  d.points(0, 2, line, upper, lower);
  ASSERT_EQ(line.size(), 2u);
  EXPECT_EQ(line[1], QPointF(1.5, 20));
  trace.clear();
  trace.append({{0.2, {-5, 0, 0, 0, 0}, {}}});
  d.update(trace, 0, 1.0, 2.0);
  d.points(0, 2, line, upper, lower);
  ASSERT_EQ(line.size(), 1u);  // the cleared samples are gone
  EXPECT_EQ(line[0], QPointF(0.2, -5));
  trace.append({{0.7, {7, 0, 0, 0, 0}, {}}});
  d.update(trace, 0, 0.5, 2.0);  // a new width: both samples in columns of their own
  d.points(0, 2, line, upper, lower);
  ASSERT_EQ(line.size(), 2u);
  d.update(trace, 0, 0.0, 2.0);  // a width of zero draws nothing
  d.points(0, 2, line, upper, lower);
  EXPECT_TRUE(line.empty());
  d.update(trace, 0, std::numeric_limits<double>::quiet_NaN(), 2.0);
  d.points(0, 2, line, upper, lower);
  EXPECT_TRUE(line.empty());
}

}  // namespace
}  // namespace armtrack::ui
