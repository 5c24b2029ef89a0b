#include "core/storage/ChunkLattice.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace armtrack::storage::detail {

namespace {

// A distance of more than this many doubles counts the value as off the lattice when a step is
// judged (it is still stored exactly, only whole).
constexpr std::uint64_t kNear = 64;

// The count of v on step q, or nothing when v is not finite or too far out for a count.
std::optional<std::int64_t> countOf(double v, double q) {
  const double r = v / q;
  if (!(std::fabs(r) <= kMaxLatticeCount)) return std::nullopt;  // also NaN and infinities
  return static_cast<std::int64_t>(std::nearbyint(r));
}

// The wrapping distance, in doubles, from n * q to v: v = fromOrderedBits(orderedBits(n * q) + d).
std::uint64_t distance(double v, std::int64_t n, double q) {
  return orderedBits(v) - orderedBits(static_cast<double>(n) * q);
}

struct Fit {
  std::size_t exact = 0;  // values that are n * q to the bit
  std::size_t off = 0;    // values more than kNear doubles away (or not finite)
};

Fit fit(const std::vector<double>& values, double q, std::size_t count) {
  Fit f;
  for (std::size_t i = 0; i < count; ++i) {
    const double v = values[i];
    const auto n = countOf(v, q);
    const std::uint64_t z = n ? zigzagWord(distance(v, *n, q)) : ~0ull;
    f.exact += z == 0 ? 1 : 0;
    f.off += z > 2 * kNear ? 1 : 0;
  }
  return f;
}

// How many values are off the lattice of q and stay off on each of the two neighbouring doubles
// each way that polish() tries: a value's distance moves by at most a few doubles when q moves by
// two (n x q moves by n x 2 ulp(q), under 4 ulp(n x q), plus rounding), so one more than kNear +
// 32 doubles away on q is off on all of them; one that is not finite is off on any step. A value
// whose count is out of range is left out: a neighbour might just bring it in range.
std::size_t surelyOff(const std::vector<double>& values, double q) {
  std::size_t off = 0;
  for (const double v : values) {
    if (!std::isfinite(v)) {
      ++off;
      continue;
    }
    const auto n = countOf(v, q);
    if (n && zigzagWord(distance(v, *n, q)) > 2 * (kNear + 32)) ++off;
  }
  return off;
}

// The neighbouring double of q (up to two each way) that puts the most values on n * q exactly:
// the plugin's operations round differently from n * q. f becomes that step's fit.
double polish(const std::vector<double>& values, double q, Fit& f) {
  const double centre = q;
  f = fit(values, q, values.size());
  for (int step = -2; step <= 2; ++step) {
    double c = centre;
    for (int s = 0; s < std::abs(step); ++s) c = std::nextafter(c, step < 0 ? 0.0 : INFINITY);
    if (step == 0 || !std::isnormal(c)) continue;
    const Fit g = fit(values, c, values.size());
    if (g.exact > f.exact) {
      f = g;
      q = c;
    }
  }
  return q;
}

// q refined on the largest value that lies on it: v / round(v / q) has v's relative precision.
double refine(const std::vector<double>& values, double q) {
  double best = 0.0, m = 0.0;
  for (const double v : values) {
    const double a = std::fabs(v), r = a / q;
    if (!(r <= kMaxLatticeCount) || a <= best) continue;
    const double n = std::nearbyint(r);
    if (n >= 1.0 && std::fabs(r - n) < 0.05) {
      best = a;
      m = n;
    }
  }
  return best > 0.0 ? best / m : q;
}

// The step of a short column, from its smallest gap between distinct values (or a fraction of
// it, up to 1/kFractions, when no two values are neighbours), refined on ever larger values.
std::optional<double> searchStep(const std::vector<double>& values) {
  constexpr int kFractions = 16;
  std::vector<double> magnitudes;
  magnitudes.reserve(values.size());
  for (const double v : values)
    if (std::isfinite(v) && v != 0.0) magnitudes.push_back(std::fabs(v));
  std::vector<double> distinct;
  distinct.reserve(values.size());
  for (const double v : values)
    if (std::isfinite(v)) distinct.push_back(v);
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() < 2 || magnitudes.empty()) return std::nullopt;
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < distinct.size(); ++i)
    gap = std::min(gap, distinct[i] - distinct[i - 1]);
  std::sort(magnitudes.begin(), magnitudes.end());

  std::optional<double> best;
  Fit bestFit;
  for (int k = 1; k <= kFractions; ++k) {
    double q = gap / k;
    if (!std::isnormal(q)) break;
    // Refine on ever larger values that lie on the step, so that each step's count is sure.
    for (const double v : magnitudes) {
      const double r = v / q;
      if (r > kMaxLatticeCount) break;
      const double m = std::nearbyint(r);
      if (m >= 1.0 && std::fabs(r - m) < 0.05) q = v / m;
    }
    if (!std::isnormal(q)) continue;
    // A step that leaves more than an eighth of the values off whatever polish does would be
    // refused below, and cannot win over one that is not (it has more values off): skip the five
    // fits. For a column of full-precision noise (most of a simulation's) this is every step.
    if (surelyOff(values, q) * 8 > values.size()) continue;
    Fit f;
    q = polish(values, q, f);
    if (!best || f.off < bestFit.off || (f.off == bestFit.off && f.exact > bestFit.exact)) {
      best = q;
      bestFit = f;
    }
    if (f.off == 0) break;
  }
  // A few values off the lattice (a spike, NaN) are stored whole; most must lie on it.
  if (!best || bestFit.off * 8 > values.size()) return std::nullopt;
  return best;
}

}  // namespace

std::optional<double> findLatticeStep(const std::vector<double>& values) {
  // The step is looked for among the first values (cheap to sort, and most columns, of
  // full-precision noise, lie on no lattice), then refined on the whole column's largest value
  // on it and judged on every value.
  constexpr std::size_t kHead = 64;
  if (values.size() <= 2 * kHead) return searchStep(values);
  const auto head = searchStep(std::vector<double>(values.begin(), values.begin() + kHead));
  if (!head) return std::nullopt;
  // The rest may need half or a quarter of the head's step (float32 readings that cross a power
  // of two: below it their spacing halves).
  for (const double fraction : {1.0, 0.5, 0.25}) {
    const double q = refine(values, *head * fraction);
    if (!std::isnormal(q)) continue;
    Fit f;
    const double polished = polish(values, q, f);
    if (f.off * 8 <= values.size()) return polished;
  }
  return std::nullopt;
}

void appendLatticeColumn(std::string& raw, BitWriter& bits, const std::vector<double>& values,
                         double q) {
  const std::uint64_t qBits = std::bit_cast<std::uint64_t>(q);
  for (int b = 0; b < 8; ++b) raw.push_back(static_cast<char>((qBits >> (8 * b)) & 0xff));
  std::vector<std::uint64_t> counts(values.size()), escaped;
  std::string marks(values.size(), '\0');
  std::int64_t previous = 0;  // a value off the lattice repeats the count before it
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::int64_t n = countOf(values[i], q).value_or(previous);
    counts[i] = static_cast<std::uint64_t>(n);
    previous = n;
    const std::uint64_t z = zigzagWord(distance(values[i], n, q));
    if (z >= kEscape) {
      marks[i] = static_cast<char>(kEscape);
      escaped.push_back(z);
    } else {
      marks[i] = static_cast<char>(z);
    }
  }
  appendPredictiveIntegers(raw, bits, counts);
  raw += marks;
  appendEscaped(raw, escaped);
}

std::vector<double> readLatticeColumn(const std::string& raw, std::size_t& pos, BitReader& bits,
                                      std::size_t count) {
  if (raw.size() - pos < 8) throw std::runtime_error("chunk content ends early");
  std::uint64_t qBits = 0;
  for (int b = 0; b < 8; ++b)
    qBits |= static_cast<std::uint64_t>(static_cast<unsigned char>(raw[pos + b])) << (8 * b);
  pos += 8;
  const double q = std::bit_cast<double>(qBits);
  if (!std::isnormal(q) || q < 0.0)
    throw std::runtime_error("lattice step " + std::to_string(q) + " (bits " +
                             std::to_string(qBits) + ") is not a positive normal double");
  const std::vector<std::uint64_t> counts = readPredictiveIntegers(raw, pos, bits, count);
  if (raw.size() - pos < count) throw std::runtime_error("chunk content ends early");
  const char* marks = raw.data() + pos;
  pos += count;
  const EscapedWords escaped = readEscaped(raw, pos, marks, count);
  std::vector<double> values(count);
  std::size_t e = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const auto n = static_cast<std::int64_t>(counts[i]);
    if (n > static_cast<std::int64_t>(kMaxLatticeCount) ||
        n < -static_cast<std::int64_t>(kMaxLatticeCount))
      throw std::runtime_error("lattice count " + std::to_string(n) + " out of range");
    const unsigned mark = static_cast<unsigned char>(marks[i]);
    const std::uint64_t z = mark == kEscape ? escaped.word(e++) : mark;
    values[i] = fromOrderedBits(orderedBits(static_cast<double>(n) * q) + unzigzagWord(z));
  }
  return values;
}

}  // namespace armtrack::storage::detail
