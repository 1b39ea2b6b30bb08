// Several people at once: association across views and identities over time, against real motion placed in one
// volume (the truth is the test's own: known cameras, known motions, known who-is-who).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "crowd.h"
#include "io/calibration_toml.h"
#include "octocap/octocap.h"
#include "pipeline/session.h"
#include "temp_dir.h"

using namespace octocap::internal;

namespace {

// What a take of several people came to, judged against the truth.
struct Judged {
  std::vector<double> mpjpe_mm;     // per true person
  std::vector<double> coverage;     // per true person: frames it was solved in / frames it was there
  std::vector<int> switches;        // per true person: how often the id that follows it changed
  size_t extra = 0;                 // solved people matching nobody (a bystander, a chimera)
  std::set<uint32_t> ids;
};

// Each solved person is the true person its keypoints are nearest (mean distance under 0.25 m).
int nearest_truth(const PersonResult& p, const std::vector<std::vector<Eigen::Vector3d>>& truth, double* mean_m) {
  int best = -1;
  double best_d = 0.25;
  for (size_t t = 0; t < truth.size(); ++t) {
    if (truth[t].empty()) continue;
    double sum = 0;
    int n = 0;
    for (size_t k = 0; k < p.keypoints.size(); ++k)
      if (p.keypoints[k].valid && truth[t][k].allFinite()) sum += (p.keypoints[k].position - truth[t][k]).norm(), ++n;
    if (n >= 3 && sum / n < best_d) best_d = sum / n, best = static_cast<int>(t);
  }
  if (mean_m) *mean_m = best_d;
  return best;
}

struct Take {
  Calibration calib;
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> truth;  // [person][frame], BODY_25; empty frame: absent
};

Take crowd_take(size_t people, size_t frames, int cameras, unsigned seed = 3) {
  synth::RigOptions rig;
  rig.cameras = cameras;
  rig.seed = seed;
  return {synth::make_camera_ring(rig), synth::make_crowd(people, frames)};
}

SessionConfig several(uint32_t max_people = 0) {
  SessionConfig c;
  c.layout = LayoutId::body25;
  c.max_people = max_people;
  c.threads = 1;
  return c;
}

Judged run(Session& session, const Take& take, const synth::CrowdNoise& noise, unsigned seed,
           const std::vector<Eigen::Vector3d>* bystander = nullptr) {
  const size_t P = take.truth.size(), F = take.truth[0].size();
  std::mt19937 rng(seed);
  Judged j;
  j.mpjpe_mm.assign(P, 0);
  j.coverage.assign(P, 0);
  j.switches.assign(P, 0);
  std::vector<double> err_sum(P, 0), err_n(P, 0), present(P, 0), solved(P, 0);
  std::vector<uint32_t> last_id(P, 0);
  for (size_t f = 0; f < F; ++f) {
    std::vector<std::vector<Eigen::Vector3d>> now;
    for (size_t p = 0; p < P; ++p) now.push_back(take.truth[p][f]);
    std::vector<std::vector<Eigen::Vector3d>> observed = now;
    if (bystander) observed.push_back(*bystander);
    const synth::CrowdObservation obs = synth::observe_crowd(take.calib, observed, LayoutId::body25, noise, rng);
    session.solve(obs.views, static_cast<int64_t>(f) * 33333);
    for (size_t p = 0; p < P; ++p) present[p] += !now[p].empty();
    for (const PersonResult& person : session.result().people) {
      j.ids.insert(person.id);
      const int t = nearest_truth(person, now, nullptr);
      if (t < 0) {
        ++j.extra;
        continue;
      }
      solved[t] += 1;
      if (last_id[t] != 0 && last_id[t] != person.id) ++j.switches[t];
      last_id[t] = person.id;
      for (size_t k = 0; k < person.keypoints.size(); ++k)
        if (person.keypoints[k].valid) err_sum[t] += (person.keypoints[k].position - now[t][k]).norm(), err_n[t] += 1;
    }
  }
  for (size_t p = 0; p < P; ++p) {
    j.mpjpe_mm[p] = err_n[p] ? 1000 * err_sum[p] / err_n[p] : INFINITY;
    j.coverage[p] = present[p] ? solved[p] / present[p] : 1;
  }
  return j;
}

}  // namespace

TEST_CASE("several people: each solved with its own id, accurately, with occlusion and shuffled detections",
          "[people]") {
  struct Case {
    size_t people;
    int cameras;
    double mpjpe_mm, coverage;
  };
  // Occluded keypoints are hidden or detected on the nearer body; 5 % of people missed per view.
  for (const Case c : {Case{2, 4, 20, 0.97}, Case{3, 6, 20, 0.97}, Case{5, 8, 20, 0.95}}) {
    DYNAMIC_SECTION(c.people << " people, " << c.cameras << " cameras") {
      const Take take = crowd_take(c.people, 90, c.cameras);
      Session session(several(), take.calib);
      const Judged j = run(session, take, {}, 21);
      for (size_t p = 0; p < c.people; ++p) {
        INFO("person " << p << ": MPJPE " << j.mpjpe_mm[p] << " mm, coverage " << j.coverage[p] << ", switches "
                       << j.switches[p]);
        CHECK(j.mpjpe_mm[p] < c.mpjpe_mm);
        CHECK(j.coverage[p] >= c.coverage);
        CHECK(j.switches[p] == 0);
      }
      CHECK(j.extra == 0);
      CHECK(j.ids.size() == c.people);  // one id per person for the whole take
    }
  }
}

TEST_CASE("several people: max_people keeps the best-seen ones; one person behaves as the single-person solve",
          "[people]") {
  const Take take = crowd_take(3, 30, 6);
  Session capped(several(2), take.calib);
  std::mt19937 rng(4);
  for (size_t f = 0; f < 30; ++f) {
    std::vector<std::vector<Eigen::Vector3d>> now{take.truth[0][f], take.truth[1][f], take.truth[2][f]};
    capped.solve(synth::observe_crowd(take.calib, now, LayoutId::body25, {}, rng).views, f * 33333);
    CHECK(capped.result().person_count() <= 2);
  }
  CHECK(capped.result().person_count() == 2);

  // Alone in the volume, the several-people path solves the person as the one-person path does.
  const Take alone = crowd_take(1, 30, 5);
  SessionConfig one = several(1), many = several(0);
  one.filter = many.filter = false;
  Session a(one, alone.calib), b(many, alone.calib);
  synth::CrowdNoise noise;
  noise.noise.outlier = noise.noise.swap = 0;
  noise.missed = 0;
  for (size_t f = 0; f < 30; ++f) {
    const synth::CrowdObservation obs = synth::observe_crowd(alone.calib, {alone.truth[0][f]}, LayoutId::body25, noise, rng);
    a.solve(obs.views, f * 33333);
    b.solve(obs.views, f * 33333);
    REQUIRE(a.result().person_count() == 1);
    REQUIRE(b.result().person_count() == 1);
    CHECK(b.result().people[0].id == 1);
    for (size_t k = 0; k < 25; ++k) {
      REQUIRE(a.keypoints()[k].valid == b.keypoints()[k].valid);
      if (a.keypoints()[k].valid) CHECK((a.keypoints()[k].position - b.keypoints()[k].position).norm() < 1e-9);
    }
  }
}

TEST_CASE("several people: a bystander outside the capture volume is not a person", "[people]") {
  const Take take = crowd_take(2, 45, 6);
  SessionConfig c = several();
  c.volume_min = Eigen::Vector3d(-2.5, -0.5, -2.5);
  c.volume_max = Eigen::Vector3d(2.5, 2.5, 2.5);
  Session session(c, take.calib);
  // A real pose, 6.5 m from the middle: behind the cameras on one side, in view of those across.
  std::vector<Eigen::Vector3d> bystander = take.truth[0][0];
  for (auto& k : bystander) k += Eigen::Vector3d(0.3, 0, 6.5);
  const Judged j = run(session, take, {}, 8, &bystander);
  CHECK(j.extra == 0);
  CHECK(j.ids.size() == 2);
  for (size_t p = 0; p < 2; ++p) CHECK(j.coverage[p] >= 0.97);
}

TEST_CASE("several people: a person who leaves and comes back keeps the id; a newcomer gets a new one", "[people]") {
  Take take = crowd_take(2, 150, 6);
  // Person 1 is away for frames 40..79 (1.3 s); person 0 leaves at frame 100, and from frame 120 (0.7 s later)
  // someone of another build (15 % taller) stands where person 0 stood.
  for (size_t f = 40; f < 80; ++f) take.truth[1][f].clear();
  for (size_t f = 100; f < 120; ++f) take.truth[0][f].clear();
  std::vector<std::vector<Eigen::Vector3d>> newcomer(150);
  for (size_t f = 120; f < 150; ++f) {
    const Eigen::Vector3d feet(take.truth[0][f][8].x(), 0, take.truth[0][f][8].z());
    for (const auto& k : take.truth[0][f]) newcomer[f].push_back(feet + 1.15 * (k - feet));
    take.truth[0][f].clear();
  }
  take.truth.push_back(newcomer);
  Session session(several(), take.calib);
  std::mt19937 rng(12);
  std::map<size_t, std::set<uint32_t>> ids_of;  // true person -> ids that followed it
  for (size_t f = 0; f < 150; ++f) {
    std::vector<std::vector<Eigen::Vector3d>> now{take.truth[0][f], take.truth[1][f], take.truth[2][f]};
    session.solve(synth::observe_crowd(take.calib, now, LayoutId::body25, {}, rng).views, f * 33333);
    for (const PersonResult& p : session.result().people) {
      const int t = nearest_truth(p, now, nullptr);
      REQUIRE(t >= 0);
      ids_of[t].insert(p.id);
    }
  }
  INFO("ids: person 0 " << ids_of[0].size() << ", person 1 " << ids_of[1].size() << ", newcomer " << ids_of[2].size());
  REQUIRE(ids_of[0].size() == 1);
  REQUIRE(ids_of[1].size() == 1);  // back after 1.3 s at its place with its build: the same id
  REQUIRE(ids_of[2].size() == 1);
  CHECK(*ids_of[2].begin() != *ids_of[0].begin());  // someone else where person 0 was: not person 0's id
  CHECK(*ids_of[2].begin() != *ids_of[1].begin());
  CHECK(*ids_of[2].begin() > *ids_of[1].begin());  // ids are never reused: the newcomer's is new

  // After a reset the numbering goes on: an id never names two people in one session.
  session.reset();
  std::vector<std::vector<Eigen::Vector3d>> now{take.truth[1][0]};
  session.solve(synth::observe_crowd(take.calib, now, LayoutId::body25, {}, rng).views, 0);
  REQUIRE(session.result().person_count() == 1);
  CHECK(session.result().people[0].id > *ids_of[2].begin());
}

TEST_CASE("several people through the C ABI: frames with people, per-person queries, misuse", "[people][capi]") {
  const Take take = crowd_take(3, 10, 6);
  octocap_calibration_t* calib = nullptr;
  {
    // The calibration goes through a file, as a user's would.
    testing::TempDir dir;
    const std::string path = dir.file("calibration.toml");
    write_calibration_toml(take.calib, path);
    REQUIRE(octocap_calibration_load(path.c_str(), &calib) == OCTOCAP_OK);
  }
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  CHECK(cfg.max_people == 1);  // today's behaviour unless asked
  cfg.max_people = OCTOCAP_MAX_PEOPLE + 1;
  octocap_session_t* s = nullptr;
  CHECK(octocap_session_create(&cfg, calib, &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK_THAT(octocap_last_error(), Catch::Matchers::ContainsSubstring("max_people"));
  cfg.max_people = 0;
  REQUIRE(octocap_session_create(&cfg, calib, &s) == OCTOCAP_OK);
  std::mt19937 rng(2);
  std::set<uint32_t> ids;
  for (size_t f = 0; f < 10; ++f) {
    std::vector<std::vector<Eigen::Vector3d>> now{take.truth[0][f], take.truth[1][f], take.truth[2][f]};
    const synth::FlatFrame flat = synth::flatten(synth::observe_crowd(take.calib, now, LayoutId::body25, {}, rng).views);
    REQUIRE(octocap_session_solve_keypoints(s, reinterpret_cast<const octocap_keypoint2d_t*>(flat.xyc.data()),
                                            flat.people_per_view.data(), 6, static_cast<int64_t>(f) * 33333) == OCTOCAP_OK);
    octocap_frame_t* frame = nullptr;
    REQUIRE(octocap_session_get_frame(s, &frame) == OCTOCAP_OK);
    octocap_frame_summary_t sum{};
    sum.struct_size = sizeof sum;
    REQUIRE(octocap_frame_get_summary(frame, &sum) == OCTOCAP_OK);
    CHECK(sum.person_count == 3);
    for (uint32_t i = 0; i < sum.person_count; ++i) {
      octocap_person_t p{};
      p.struct_size = sizeof p;
      REQUIRE(octocap_frame_get_person(frame, i, &p) == OCTOCAP_OK);
      ids.insert(p.id);
      CHECK(p.keypoints_solved >= 20);
      CHECK(p.views_with_person >= 4);
      octocap_joint_t kp[25];
      uint32_t n = 0;
      REQUIRE(octocap_frame_get_keypoints3d(frame, i, kp, 25, &n) == OCTOCAP_OK);
      std::vector<Eigen::Vector3d> pose;
      for (const auto& k : kp) pose.push_back(k.valid ? Eigen::Vector3d(k.position[0], k.position[1], k.position[2])
                                                      : Eigen::Vector3d::Constant(NAN));
      // Each person is one of the true people, within centimetres.
      double best = INFINITY;
      for (const auto& t : now) {
        double sum_d = 0;
        int m = 0;
        for (size_t k = 0; k < 25; ++k)
          if (pose[k].allFinite()) sum_d += (pose[k] - t[k]).norm(), ++m;
        best = std::min(best, sum_d / m);
      }
      CHECK(best < 0.03);
      int32_t views[6];
      REQUIRE(octocap_frame_get_person_views(frame, i, views, 6, &n) == OCTOCAP_OK);
      CHECK(n == 6);
    }
    // A person index past the frame's people is a clear error, never a read past the end.
    octocap_person_t p{};
    p.struct_size = sizeof p;
    CHECK(octocap_frame_get_person(frame, 3, &p) == OCTOCAP_ERROR_INVALID_ARGUMENT);
    CHECK_THAT(octocap_last_error(), Catch::Matchers::ContainsSubstring("out of range"));
    octocap_joint_t kp[25];
    uint32_t n = 0;
    CHECK(octocap_frame_get_joints(frame, 7, kp, 25, &n) == OCTOCAP_ERROR_INVALID_ARGUMENT);
    octocap_frame_release(frame);
  }
  CHECK(ids.size() == 3);  // ten frames, three people, three ids
  octocap_session_destroy(s);
  octocap_calibration_destroy(calib);
}

TEST_CASE("several people: a crowd of detections in many views is solved in bounded work, at most max_people",
          "[people][hardening]") {
  synth::RigOptions rig;
  rig.cameras = 20;
  const Calibration calib = synth::make_camera_ring(rig);
  const auto crowd = synth::make_crowd(3, 2);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<Person2D>> views(calib.size());
  for (size_t v = 0; v < calib.size(); ++v) {
    // The three real people, then 61 phantoms scattered over the picture (a detector gone wrong, less sure of them).
    views[v] = synth::observe_crowd(Calibration{calib[v]}, {crowd[0][0], crowd[1][0], crowd[2][0]}, LayoutId::body25,
                                    {}, rng).views[0];
    while (views[v].size() < kMaxPeoplePerView) {
      Person2D p(25);
      for (auto& k : p) k = {u(rng) * 1280, u(rng) * 720, 0.35};
      views[v].push_back(p);
    }
  }
  Session session(several(0), calib);
  session.solve(views, 0);
  CHECK(session.result().person_count() <= kMaxPeople);
  CHECK(session.result().person_count() >= 3);  // the real people, at least
}
