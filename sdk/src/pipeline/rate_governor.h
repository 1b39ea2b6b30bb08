// The live engine's rate governor: it holds a target set rate within a latency budget by choosing, set by set, how
// much detection a set gets. The choices form a quality ladder, best first: the named model on every view, on one
// view fewer, ... on one view, then the card's lighter model on one view (the views not detected follow their people
// by optical flow). It steps down fast when sets cost more than the budget and back up slowly, probing: a step up is
// tried only when the rung above is predicted to fit, and a probe that had to be undone waits twice as long before
// the next one (up to half a minute), so that a host at its limit does not see-saw.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace octocap::internal {

struct QualityRung {
  int network = 0;  // 0: the model named; 1: its card's lighter model
  int views = 1;    // views running the network a set (as many as there are cameras: every view)
};

// Best to cheapest, for `views` cameras: the named model on `top_views` views (0: every view), then one view fewer
// each rung down to one, then each further network on one view. `networks` >= 1.
std::vector<QualityRung> quality_ladder(int views, int top_views, int networks);

struct GovernorOptions {
  double target_fps = 30;          // sets a second to hold
  double latency_budget_ms = 100;  // grab of a set's oldest picture to its frame, at the 99th percentile
};

class RateGovernor {
 public:
  RateGovernor(std::vector<QualityRung> ladder, GovernorOptions options);

  // One set: `cost_ms` from its solve's start to its frame (detection, 3D, outputs), `wait_ms` how long its oldest
  // picture waited before that (collection: beyond the governor's reach, but it eats the latency budget).
  // True when the rung changed.
  bool observe(double cost_ms, double wait_ms, int64_t now_us);
  // The cameras' rate can be learnt only once they deliver; a new target keeps the rung.
  void set_target_fps(double fps);

  size_t rung_index() const { return rung_; }
  const QualityRung& rung() const { return ladder_[rung_]; }
  size_t rungs() const { return ladder_.size(); }
  // What a set may cost now: 90 % of the target period, less where the latency budget is tighter.
  double budget_ms() const;
  // Smoothed cost of the last sets over budget_ms() (1 = exactly the budget).
  double budget_used() const;

 private:
  void move_to(size_t rung, int64_t now_us);
  // What rung `upper` costs over the rung below it: as the two last measured one after the other (the ratio holds
  // when the load changes, the costs do not), else a guess for going `up` or down.
  double ratio(size_t upper, bool up) const;
  // The cost rung `target` would have now, from this rung's.
  double predicted_cost(size_t target) const;

  std::vector<QualityRung> ladder_;
  GovernorOptions options_;
  size_t rung_ = 0;
  double cost_ms_ = 0;                // smoothed, at the current rung
  double wait_ms_ = 0;                // smoothed
  std::vector<double> step_ratio_;    // per rung, its cost over the next one's (0: not measured)
  size_t left_rung_ = 0;              // the rung before this one, and its cost when it was left
  double left_cost_ms_ = 0;
  int sets_at_rung_ = 0;
  int sets_over_ = 0;                 // consecutive sets over budget
  int64_t changed_us_ = 0;            // when the rung last changed
  int64_t hold_us_;                   // how long to stay before probing up
  bool probing_ = false;              // the last change was a step up, not yet confirmed
};

}  // namespace octocap::internal
