// Surface-statistics accumulators: Ra, Rq, Rsk, Rku, Rp, Rv, Rz and the bearing-area ratio of a
// set of summit heights. Mergeable, so per-rank partial results combine by an element-wise sum
// (MPI_SUM) of a small fixed-size array, plus MPI_MIN / MPI_MAX for the extremes.
//
// Two passes (the compute runin/roughness design):
//   1. HeightRange: count, sum, min, max           -> mean plane height and the highest summit;
//   2. HeightMoments about a reference height (the pass-1 mean) and the highest summit:
//      power sums of d = z - reference (S1..S4), sum |d|, and one summit count per bearing depth.
// The central moments are recovered exactly from the raw sums about the reference
// (delta = S1/n corrects a reference that is off the mean by round-off), so the result is
// well conditioned whenever the reference is close to the mean, whatever the absolute heights.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace runin::tribo {

// Pass 1: count, sum, min and max of the heights.
struct HeightRange {
  double count = 0.0;
  double sum = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();

  void add(double z);
  void merge(const HeightRange &other);
  bool empty() const { return count <= 0.0; }
  double mean() const;    // 0 when empty
};

// Pass 2: power sums about a reference height and bearing counts below the highest summit.
class HeightMoments {
 public:
  enum Sum { N = 0, S1, SABS, S2, S3, S4, NFIXED };

  // reference: the height the sums are taken about (the mean from pass 1);
  // top: the highest summit (HeightRange::max); depths: bearing depths below top, each >= 0
  // (throws std::invalid_argument otherwise).
  HeightMoments(double reference, double top, std::vector<double> depths = {});

  void add(double z);
  void merge(const HeightMoments &other);    // throws if reference, top or depths differ

  // The sums as one array of NFIXED + depths().size() values, combinable by element-wise sum.
  const std::vector<double> &sums() const { return sums_; }
  std::vector<double> &sums() { return sums_; }    // e.g. the target of MPI_Allreduce
  std::size_t size() const { return sums_.size(); }

  double reference() const { return reference_; }
  double top() const { return top_; }
  const std::vector<double> &depths() const { return depths_; }

 private:
  double reference_, top_;
  std::vector<double> depths_;
  std::vector<double> sums_;
};

struct RoughnessStatistics {
  double count = 0.0;
  double mean = 0.0;    // mean plane height
  double Ra = 0.0;      // mean |z - reference| (reference = the mean in the two-pass design)
  double Rq = 0.0;      // RMS of z - mean
  double Rsk = 0.0;     // skewness mu3 / Rq^3 (0 when Rq == 0)
  double Rku = 0.0;     // kurtosis mu4 / Rq^4 (0 when Rq == 0)
  double Rp = 0.0;      // highest peak above the mean
  double Rv = 0.0;      // deepest valley below the mean (positive)
  double Rz = 0.0;      // Rp + Rv
  std::vector<double> bearing;    // fraction of summits with z >= top - depth, one per depth
  bool valid() const { return count > 0.0; }
};

// Statistics from the two passes; all zero (valid() false) when there are no heights.
RoughnessStatistics roughness(const HeightRange &range, const HeightMoments &moments);

// Convenience for a whole set held in memory: both passes over heights.
RoughnessStatistics roughness(const std::vector<double> &heights, const std::vector<double> &depths = {});

}    // namespace runin::tribo
