// Several people: the cost of associating 2D people across views and solving each, per frame, for 1..8 people and
// 4..16 views, on one core (real CMU motion placed side by side, occlusion and shuffled detections as in the tests).
// Not a test: it prints figures to compare.
#include <chrono>
#include <cstdio>
#include <random>

#include "crowd.h"
#include "pipeline/session.h"
#include "solve/association.h"

using namespace octocap::internal;
using Clock = std::chrono::steady_clock;

namespace {

struct Row {
  double associate_ms, frame_ms;
  double people_found;
};

// One pass of a fresh session over the frames: ms per frame, people per frame.
std::pair<double, double> solve_all(const Calibration& calib, const std::vector<std::vector<std::vector<Person2D>>>& observed,
                                    uint32_t max_people, Method method) {
  SessionConfig cfg;
  cfg.max_people = max_people;
  cfg.threads = 1;
  cfg.method = method;
  Session session(cfg, calib);
  double found = 0;
  const auto t0 = Clock::now();
  for (size_t f = 0; f < observed.size(); ++f) {
    session.solve(observed[f], static_cast<int64_t>(f) * 33333);
    found += static_cast<double>(session.result().person_count());
  }
  const double n = static_cast<double>(observed.size());
  return {std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / n, found / n};
}

Row measure(size_t people, int views, uint32_t max_people, size_t frames, Method method = Method::automatic) {
  synth::RigOptions rig;
  rig.cameras = views;
  const Calibration calib = synth::make_camera_ring(rig);
  const auto crowd = synth::make_crowd(people, frames, people > 5 ? 2.0 : 1.5);
  std::mt19937 rng(1);
  std::vector<std::vector<std::vector<Person2D>>> observed;
  for (size_t f = 0; f < frames; ++f) {
    std::vector<std::vector<Eigen::Vector3d>> now;
    for (size_t p = 0; p < people; ++p) now.push_back(crowd[p][f]);
    observed.push_back(synth::observe_crowd(calib, now, LayoutId::body25, {}, rng).views);
  }
  solve_all(calib, observed, max_people, method);  // warm: the timed pass below runs on warm caches
  const auto [frame_ms, found] = solve_all(calib, observed, max_people, method);
  // The association alone, with the truth of the previous frame as priors (what a running session has).
  AssociationParams params;
  params.threshold_px = 30;
  params.max_people = max_people ? max_people : kMaxPeople;
  const auto t1 = Clock::now();
  for (size_t f = 1; f < frames; ++f) {
    std::vector<std::vector<Eigen::Vector3d>> priors;
    for (size_t p = 0; p < people && max_people != 1; ++p) priors.push_back(crowd[p][f - 1]);
    associate_people(calib, observed[f], priors, params);
  }
  const double assoc_ms = std::chrono::duration<double, std::milli>(Clock::now() - t1).count() / (frames - 1);
  return {assoc_ms, frame_ms, found};
}

}  // namespace

int main() {
  const size_t frames = 90;
  std::printf("Several people (max_people = 0), one core, %zu frames of real CMU motion, BODY_25, occlusion and 5 %% "
              "missed detections; 3D by triangulation, and by the method auto picks (subdivision from 5 views):\n\n",
              frames);
  std::printf("| people | views | association ms/frame | + 3D, filter, rig: triangulation | + 3D, filter, rig: auto | people found/frame |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (size_t people : {1, 2, 3, 5, 8})
    for (int views : {4, 8, 16}) {
      const Row tri = measure(people, views, 0, frames, Method::triangulation);
      const Row automatic = measure(people, views, 0, frames);
      std::printf("| %zu | %d | %.3f | %.3f | %.3f | %.2f |\n", people, views, tri.associate_ms, tri.frame_ms,
                  automatic.frame_ms, automatic.people_found);
      std::fflush(stdout);
    }
  std::printf("\nOne person: max_people = 1 (the single-person path) against max_people = 0 (method auto):\n\n");
  std::printf("| views | max_people 1: ms/frame | max_people 0: ms/frame |\n|---|---|---|\n");
  for (int views : {4, 8, 16}) {
    const Row one = measure(1, views, 1, frames), all = measure(1, views, 0, frames);
    std::printf("| %d | %.3f | %.3f |\n", views, one.frame_ms, all.frame_ms);
  }
  return 0;
}
