// The live engine's rate governor on simulated hosts: sets whose cost per rung is known (and a load that multiplies
// it), so that where it settles, how fast and how often it changes are checked against what each host allows.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <functional>
#include <random>
#include <vector>

#include "core/error.h"
#include "pipeline/rate_governor.h"

using namespace octocap::internal;
using Catch::Matchers::WithinAbs;

namespace {

// Four cameras, the named model and its lighter one: Thunder on 4, 3, 2, 1 views, then Lightning on 1.
std::vector<QualityRung> four_views() { return quality_ladder(4, 0, 2); }

struct Run {
  std::vector<size_t> rungs;  // the rung of each set
  int changes = 0;
  int64_t end_us = 0;
};

// Sets as a camera at `fps` delivers them to an engine that solves one at a time: the next set starts when the
// camera has one and the last solve ended. cost(rung, t_us) is what a set costs on that host at that time.
Run simulate(RateGovernor& g, double fps, double seconds, const std::function<double(size_t, int64_t)>& cost,
             int64_t start_us = 1) {
  Run run;
  const double period_us = 1e6 / fps;
  int64_t t = start_us;
  while (t < start_us + static_cast<int64_t>(seconds * 1e6)) {
    const double c = cost(g.rung_index(), t);
    run.rungs.push_back(g.rung_index());
    t += static_cast<int64_t>(c * 1000);
    if (g.observe(c, 15, t)) ++run.changes;
    t = std::max(t, start_us + static_cast<int64_t>(std::ceil((t - start_us) / period_us) * period_us));
  }
  run.end_us = t;
  return run;
}

}  // namespace

TEST_CASE("the quality ladder goes from every view with the named model to one view with the lighter one") {
  const std::vector<QualityRung> l = quality_ladder(4, 0, 2);
  REQUIRE(l.size() == 5);
  for (int i = 0; i < 4; ++i) CHECK((l[i].network == 0 && l[i].views == 4 - i));
  CHECK((l[4].network == 1 && l[4].views == 1));
  // A detector config that asks for two views a set caps the top; one network: no lighter rung.
  const std::vector<QualityRung> capped = quality_ladder(4, 2, 1);
  REQUIRE(capped.size() == 2);
  CHECK((capped[0].views == 2 && capped[1].views == 1));
  CHECK(quality_ladder(1, 0, 1).size() == 1);
  CHECK_THROWS_AS(quality_ladder(0, 0, 1), Error);
  CHECK_THROWS_AS(RateGovernor({}, {}), Error);
  CHECK_THROWS_AS(RateGovernor(four_views(), {0, 100}), Error);
}

TEST_CASE("a host with headroom keeps every view detected with the best model") {
  RateGovernor g(four_views(), {30, 100});
  const Run run = simulate(g, 30, 20, [](size_t r, int64_t) { return r == 0 ? 20.0 : 10.0; });
  CHECK(run.changes == 0);
  CHECK(g.rung_index() == 0);
  CHECK(g.budget_used() < 0.8);
}

TEST_CASE("an overloaded host steps down within a few sets, to the first rung that fits, and stays there") {
  // Measured-like costs on two cores (ms): Thunder on 4, 3, 2, 1 views, Lightning on 1. Only the last fits 30 sets/s.
  const std::vector<double> cost = {120, 95, 70, 40, 22};
  RateGovernor g(four_views(), {30, 100});
  const Run run = simulate(g, 30, 60, [&](size_t r, int64_t) { return cost[r]; });
  const auto first_fit = std::find(run.rungs.begin(), run.rungs.end(), size_t{4});
  REQUIRE(first_fit != run.rungs.end());
  CHECK(first_fit - run.rungs.begin() <= 8);  // about a quarter of a second of sets
  CHECK(g.rung_index() == 4);
  // After the descent, a probe up now and then at most: Thunder on one view was measured too dear.
  CHECK(run.changes <= 4 + 2);
  const size_t settled = static_cast<size_t>(first_fit - run.rungs.begin());
  const size_t at_floor = static_cast<size_t>(std::count(run.rungs.begin() + settled, run.rungs.end(), size_t{4}));
  CHECK(at_floor >= (run.rungs.size() - settled) * 98 / 100);
}

TEST_CASE("a load that passes gives the best rung back, slowly") {
  const std::vector<double> cost = {25, 20, 15, 10, 6};
  RateGovernor g(four_views(), {30, 100});
  // Three times the cost for 10 s (another process took the cores), then the host is free again.
  auto host = [&](size_t r, int64_t t) { return cost[r] * (t < 10000000 ? 3.0 : 1.0); };
  const Run busy = simulate(g, 30, 10, host);
  CHECK(g.rung_index() >= 3);  // 3 x 10 ms does not fit 30 ms; 3 x 6 does
  CHECK(busy.changes <= 10);
  const Run free = simulate(g, 30, 40, host, busy.end_us);
  CHECK(g.rung_index() == 0);
  CHECK(free.changes <= 6);
  // Up one rung at a time, each after a hold: not at once.
  CHECK(std::count(free.rungs.begin(), free.rungs.begin() + 30, size_t{0}) == 0);
}

TEST_CASE("a host at the edge of a rung does not see-saw: a probe that fails waits longer before the next") {
  // Thunder on 3 views just does not fit (31.5 ms of 30), on 2 it does with room; jitter of +-10 %.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(0.9, 1.1);
  const std::vector<double> cost = {42, 31.5, 22, 14, 8};
  RateGovernor g(four_views(), {30, 100});
  const Run run = simulate(g, 30, 120, [&](size_t r, int64_t) { return cost[r] * jitter(rng); });
  CHECK(run.changes <= 14);  // the descent, then probes 2, 4, 8, 16, 30 s apart
  const size_t at_two = static_cast<size_t>(std::count(run.rungs.begin(), run.rungs.end(), size_t{2}));
  CHECK(at_two >= run.rungs.size() * 85 / 100);
}

TEST_CASE("what a set may cost: 90 % of the target period, less where collection ate the latency budget") {
  RateGovernor g(four_views(), {30, 100});
  CHECK_THAT(g.budget_ms(), WithinAbs(30, 1e-9));
  g.set_target_fps(15);
  CHECK_THAT(g.budget_ms(), WithinAbs(60, 1e-9));
  g.set_target_fps(-1);  // ignored: the rate is not known yet
  CHECK_THAT(g.budget_ms(), WithinAbs(60, 1e-9));
  g.set_target_fps(30);
  g.observe(10, 80, 1000);  // pictures that waited 80 ms leave 20 of the 100
  CHECK_THAT(g.budget_ms(), WithinAbs(20, 1e-9));
  g.observe(10, 1e9, 2000);  // never under a third of the period, whatever collection took
  CHECK_THAT(g.budget_ms(), WithinAbs(1000.0 / 90, 1e-9));
  CHECK_FALSE(g.observe(std::numeric_limits<double>::quiet_NaN(), 0, 3000));
}
