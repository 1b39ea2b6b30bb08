#include "pipeline/rate_governor.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace octocap::internal {
namespace {

constexpr double kSmoothing = 0.3;         // weight of a new set's cost
constexpr int kSettleSets = 3;             // sets at a new rung before its cost counts
constexpr double kUpMargin = 0.85;         // a step up only when the rung above is predicted under 85 % of budget
constexpr int64_t kMinHoldUs = 2000000;    // first probe up 2 s after a change
constexpr int64_t kMaxHoldUs = 30000000;   // a host at its limit probes twice a minute at most
constexpr int64_t kConfirmUs = 5000000;    // a probe that held 5 s was right
constexpr double kNetworkGuess = 1.8;      // a model over its lighter one (Thunder 256² over Lightning 192²)

}  // namespace

std::vector<QualityRung> quality_ladder(int views, int top_views, int networks) {
  if (views < 1 || networks < 1 || top_views < 0)
    throw Error(Errc::invalid_argument, "a quality ladder needs at least one view and one network");
  const int top = top_views == 0 || top_views >= views ? views : top_views;
  std::vector<QualityRung> ladder;
  for (int v = top; v >= 1; --v) ladder.push_back({0, v});
  for (int n = 1; n < networks; ++n) ladder.push_back({n, 1});
  return ladder;
}

RateGovernor::RateGovernor(std::vector<QualityRung> ladder, GovernorOptions options)
    : ladder_(std::move(ladder)), options_(options), hold_us_(kMinHoldUs) {
  if (ladder_.empty()) throw Error(Errc::invalid_argument, "the rate governor needs at least one rung");
  if (!(options_.target_fps > 0) || !(options_.latency_budget_ms > 0))
    throw Error(Errc::invalid_argument, "the rate governor needs a positive target rate and latency budget");
  step_ratio_.assign(ladder_.size(), 0);
}

void RateGovernor::set_target_fps(double fps) {
  if (fps > 0 && std::isfinite(fps)) options_.target_fps = fps;
}

double RateGovernor::budget_ms() const {
  const double period = 1000.0 / options_.target_fps;
  // The latency budget is for the whole path: what collection already took is not the solve's to spend. Never under
  // a third of the period, or a slow collection (a camera's late pictures) would drive the ladder to its floor.
  return std::max(std::min(0.9 * period, options_.latency_budget_ms - wait_ms_), period / 3);
}

double RateGovernor::budget_used() const { return cost_ms_ / budget_ms(); }

double RateGovernor::ratio(size_t upper, bool up) const {
  if (step_ratio_[upper] > 0) return step_ratio_[upper];
  // Not measured: going up, try it (the step measures it, and a wrong one is undone within a few sets and waits
  // longer); going down, assume the worst the views allow (views detected at once on several cores cost less).
  if (up) return 1.0;
  const QualityRung& a = ladder_[upper];
  const QualityRung& b = ladder_[upper + 1];
  if (a.network != b.network) return kNetworkGuess;
  return static_cast<double>(a.views) / std::max(1, b.views);
}

double RateGovernor::predicted_cost(size_t target) const {
  double cost = cost_ms_;
  for (size_t r = rung_; r > target; --r) cost *= ratio(r - 1, true);
  for (size_t r = rung_; r < target; ++r) cost /= ratio(r, false);
  return cost;
}

void RateGovernor::move_to(size_t rung, int64_t now_us) {
  left_rung_ = rung_;
  left_cost_ms_ = cost_ms_;
  rung_ = rung;
  sets_at_rung_ = 0;
  sets_over_ = 0;
  changed_us_ = now_us;
}

bool RateGovernor::observe(double cost_ms, double wait_ms, int64_t now_us) {
  if (!std::isfinite(cost_ms) || cost_ms < 0) return false;
  if (changed_us_ == 0) changed_us_ = now_us;
  if (std::isfinite(wait_ms) && wait_ms >= 0) wait_ms_ = wait_ms_ == 0 ? wait_ms : 0.9 * wait_ms_ + 0.1 * wait_ms;
  cost_ms_ = sets_at_rung_ == 0 ? cost_ms : (1 - kSmoothing) * cost_ms_ + kSmoothing * cost_ms;
  ++sets_at_rung_;
  const double budget = budget_ms();
  sets_over_ = cost_ms > budget ? sets_over_ + 1 : 0;
  // Two neighbouring rungs measured one after the other, under the same load: what one costs over the other.
  if (sets_at_rung_ == kSettleSets && (left_rung_ + 1 == rung_ || rung_ + 1 == left_rung_) && cost_ms_ > 0) {
    const size_t upper = std::min(left_rung_, rung_);
    const double r = upper == rung_ ? cost_ms_ / left_cost_ms_ : left_cost_ms_ / cost_ms_;
    step_ratio_[upper] = std::clamp(r, 1.0, 4.0);
  }
  if (probing_ && now_us - changed_us_ >= kConfirmUs) {
    probing_ = false;
    hold_us_ = kMinHoldUs;
  }
  // Down, fast: two sets in a row over budget, and the smoothed cost too; as far down as is predicted to fit.
  if (rung_ + 1 < ladder_.size() && sets_over_ >= 2 && cost_ms_ > budget) {
    size_t target = rung_ + 1;
    while (target + 1 < ladder_.size() && predicted_cost(target) > budget) ++target;
    if (probing_) hold_us_ = std::min(2 * hold_us_, kMaxHoldUs);  // the probe was wrong: wait longer next time
    probing_ = false;
    move_to(target, now_us);
    return true;
  }
  // Up, slowly: settled, held long enough, and the rung above predicted to fit with a margin.
  if (rung_ > 0 && sets_at_rung_ >= 10 && now_us - changed_us_ >= hold_us_ &&
      predicted_cost(rung_ - 1) < kUpMargin * budget) {
    move_to(rung_ - 1, now_us);
    probing_ = true;
    return true;
  }
  return false;
}

}  // namespace octocap::internal
