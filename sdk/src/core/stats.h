// Order statistics of samples, for the robust costs and the latency figures.
#pragma once
#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace octocap::internal {

// Element floor(p * n) of the sorted samples (p in [0, 1]), found by partial reordering of `v`; `empty` when v holds
// none.
inline double quantile_in_place(std::vector<double>& v, double p, double empty) {
  if (v.empty()) return empty;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

inline double median_in_place(std::vector<double>& v, double empty) { return quantile_in_place(v, 0.5, empty); }

// The cost of what cannot be measured (no pairs, no views): worse than any measured one.
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// The median, or kInf when there is nothing to take it of.
inline double median_or_inf(std::vector<double>& v) { return median_in_place(v, kInf); }

}  // namespace octocap::internal
