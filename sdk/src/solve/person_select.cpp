#include "solve/person_select.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/stats.h"
#include "solve/view_agreement.h"

namespace octocap::internal {
namespace {

double mean_confidence(const Person2D& p) {
  double s = 0;
  for (const auto& k : p) s += k.confidence;
  return p.empty() ? 0 : s / p.size();
}

// Keeps the enumeration bounded: at most `keep` most confident people per view.
std::vector<std::vector<int>> candidates_per_view(const std::vector<std::vector<Person2D>>& people, size_t keep) {
  std::vector<std::vector<int>> out(people.size());
  for (size_t v = 0; v < people.size(); ++v) {
    for (size_t p = 0; p < people[v].size(); ++p) out[v].push_back(static_cast<int>(p));
    std::stable_sort(out[v].begin(), out[v].end(), [&](int a, int b) {
      return mean_confidence(people[v][a]) > mean_confidence(people[v][b]);
    });
    if (out[v].size() > keep) out[v].resize(keep);
  }
  return out;
}

// Search spaces above this are not enumerated: past ~12 views "person or nobody" per view is 2^V combinations.
constexpr double kMaxCombinations = 4096;

// What a choice costs: an empty view the threshold, a chosen person its reprojection error capped at twice that
// (so agreeing views beat empty ones, and one bad view cannot dominate).
double choice_cost(const std::vector<int>& choice, const std::vector<double>& errs, double threshold) {
  double cost = 0;
  for (size_t v = 0; v < choice.size(); ++v) cost += choice[v] < 0 ? threshold : std::min(errs[v], 2 * threshold);
  return cost;
}

// Bounded search for many views, where "person or nobody" per view is 2^V combinations: every pair of views
// whose people agree seeds a pose; each other view takes its person nearest that pose's reprojection; views
// that then disagree are dropped; the cheapest expansion wins. Seeds already inside an expansion are skipped, so
// about one expansion is made per distinct person. O(V^2 * keep^2) two-view triangulations, whatever V.
std::vector<int> greedy_combination(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                                    const std::vector<int>& fixed, const std::vector<std::vector<int>>& cands,
                                    const PersonSelectParams& params) {
  const size_t V = calib.size();
  const double thr = params.association_threshold_px;
  auto options = [&](size_t v) { return fixed[v] >= 0 ? std::vector<int>{fixed[v]} : cands[v]; };
  struct Seed {
    double cost;
    std::vector<int> choice;
  };
  std::vector<Seed> seeds;
  size_t seeded = 0;
  for (int f : fixed) seeded += f >= 0;
  if (seeded >= 2) {
    seeds.push_back({0, fixed});
  } else {
    for (size_t a = 0; a < V; ++a)
      for (size_t b = a + 1; b < V; ++b)
        for (int pa : options(a))
          for (int pb : options(b)) {
            std::vector<int> trial(V, -1);
            trial[a] = pa;
            trial[b] = pb;
            const auto errs = combination_errors(calib, people, trial, params.min_confidence);
            const double cost = std::max(errs[a], errs[b]);
            if (cost <= thr) seeds.push_back({cost, trial});
          }
    std::sort(seeds.begin(), seeds.end(), [](const Seed& x, const Seed& y) { return x.cost < y.cost; });
  }
  constexpr size_t kMaxExpansions = 16;
  std::vector<std::vector<int>> expanded;
  std::vector<int> best(V, -1);
  double best_cost = kInf;
  for (const Seed& seed : seeds) {
    if (expanded.size() >= kMaxExpansions) break;
    bool inside = false;
    for (const auto& e : expanded) {
      bool all = true;
      for (size_t v = 0; v < V; ++v)
        if (seed.choice[v] >= 0 && e[v] != seed.choice[v]) all = false;
      inside = inside || all;
    }
    if (inside) continue;
    std::vector<int> choice = seed.choice;
    grow_by_nearest(calib, people, cands, params.min_confidence, 2 * thr, choice);
    const auto errs = combination_errors(calib, people, choice, params.min_confidence);
    for (size_t v = 0; v < V; ++v)
      if (choice[v] >= 0 && fixed[v] < 0 && errs[v] > thr) choice[v] = -1;
    expanded.push_back(choice);
    const double cost = choice_cost(choice, combination_errors(calib, people, choice, params.min_confidence), thr);
    if (cost < best_cost) best_cost = cost, best = choice;
  }
  return best;
}

// Exhaustive search over "one person or nobody" per view for the views not yet fixed. A view left empty
// costs the threshold; a chosen person costs its reprojection error (capped at twice the threshold), so
// agreeing views are preferred to empty ones and a disagreeing one is dropped afterwards.
std::vector<int> best_combination(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                                  std::vector<int> fixed, const PersonSelectParams& params) {
  const size_t V = calib.size();
  size_t keep = 4;
  auto cands = candidates_per_view(people, keep);
  auto combos = [&] {
    double n = 1;
    for (size_t v = 0; v < V; ++v)
      if (fixed[v] < 0) n *= static_cast<double>(cands[v].size() + 1);
    return n;
  };
  while (combos() > kMaxCombinations && keep > 1) cands = candidates_per_view(people, --keep);
  if (combos() > kMaxCombinations)
    return greedy_combination(calib, people, fixed, candidates_per_view(people, 2), params);

  std::vector<int> choice = fixed, best = fixed;
  double best_cost = kInf;
  std::vector<size_t> digit(V, 0);
  for (;;) {
    int chosen = 0;
    for (size_t v = 0; v < V; ++v) {
      if (fixed[v] >= 0) {
        choice[v] = fixed[v];
      } else {
        choice[v] = digit[v] < cands[v].size() ? cands[v][digit[v]] : -1;
      }
      if (choice[v] >= 0) ++chosen;
    }
    if (chosen >= 2) {
      const double cost = choice_cost(choice, combination_errors(calib, people, choice, params.min_confidence),
                                      params.association_threshold_px);
      if (cost < best_cost) {
        best_cost = cost;
        best = choice;
      }
    }
    size_t v = 0;  // next combination (mixed-radix counter over the free views)
    for (; v < V; ++v) {
      if (fixed[v] >= 0) continue;
      if (++digit[v] <= cands[v].size()) break;
      digit[v] = 0;
    }
    if (v == V) break;
  }
  if (best_cost == kInf) return std::vector<int>(V, -1);
  const auto errs = combination_errors(calib, people, best, params.min_confidence);
  for (size_t v = 0; v < V; ++v)
    if (best[v] >= 0 && fixed[v] < 0 && errs[v] > params.association_threshold_px) best[v] = -1;
  return best;
}

}  // namespace

std::vector<int> select_people(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                               const std::vector<Eigen::Vector3d>& previous, const PersonSelectParams& params) {
  const size_t V = calib.size();
  std::vector<int> fixed(V, -1);
  bool any_multi = false;
  for (size_t v = 0; v < V; ++v)
    if (people[v].size() > 1) any_multi = true;
  if (!any_multi) {
    // One candidate per view: nothing to choose. A wrong lone detection is rejected per keypoint by the
    // 3D solvers (sigma, outlier views), which is cheaper than judging the whole person here.
    for (size_t v = 0; v < V; ++v) fixed[v] = people[v].empty() ? -1 : 0;
    return fixed;
  }
  if (!previous.empty()) {
    size_t matched = 0;
    std::vector<int> tracked(V, -1);
    for (size_t v = 0; v < V; ++v) {
      double best = kInf;
      for (size_t p = 0; p < people[v].size(); ++p) {
        const double d = distance_to_pose(calib[v], people[v][p], previous, params.min_confidence);
        if (d < best) {
          best = d;
          tracked[v] = static_cast<int>(p);
        }
      }
      // Between two frames a person moves; allow more than the association threshold.
      if (best > 3 * params.association_threshold_px) tracked[v] = -1;
      if (tracked[v] >= 0) ++matched;
    }
    if (matched >= 2) {
      // The tracked people must still agree with each other; a free view may join them.
      std::vector<int> check = tracked;
      const auto errs = combination_errors(calib, people, check, params.min_confidence);
      size_t agreeing = 0;
      for (size_t v = 0; v < V; ++v) {
        if (check[v] >= 0 && errs[v] > params.association_threshold_px) check[v] = -1;
        if (check[v] >= 0) ++agreeing;
      }
      if (agreeing >= 2) {
        bool free_views = false;
        for (size_t v = 0; v < V; ++v)
          if (check[v] < 0 && !people[v].empty()) free_views = true;
        return free_views ? best_combination(calib, people, check, params) : check;
      }
    }
  }
  return best_combination(calib, people, std::vector<int>(V, -1), params);
}

}  // namespace octocap::internal
