#include "crowd.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Geometry>

#include <cstdio>
#include <filesystem>

#include "io/calibration_toml.h"
#include "io/openpose_json.h"

namespace octocap::internal::synth {

std::vector<std::vector<std::vector<Eigen::Vector3d>>> make_crowd(size_t people, size_t frames, double spread) {
  const std::string clips[] = {"/usr/share/assimp/models/BVH/01_01.bvh", "/usr/share/assimp/models/BVH/01_03.bvh"};
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> out;
  for (size_t p = 0; p < people; ++p) {
    // 120 Hz clips, every 4th frame: 30 Hz; each person from another moment of another clip.
    Motion m = load_cmu_motion(clips[p % 2], 200 + 700 * (p / 2) + 350 * (p % 2), frames, 4);
    const double angle = 2 * M_PI * static_cast<double>(p) / static_cast<double>(people) + 0.3;
    const Eigen::Vector3d spot = people == 1 ? Eigen::Vector3d::Zero()
                                             : Eigen::Vector3d(spread * std::sin(angle), 0, spread * std::cos(angle));
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(angle * 2.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
    for (auto& f : m.frames) {
      // Keep the body's own motion, shrink its travel (people at their spots do not walk through each other).
      const Eigen::Vector3d hips(f[8].x(), 0, f[8].z());
      for (auto& k : f) k = spot + turn * (k - hips + 0.25 * hips);
    }
    out.push_back(std::move(m.frames));
  }
  return out;
}

CrowdObservation observe_crowd(const Calibration& calib, const std::vector<std::vector<Eigen::Vector3d>>& truth,
                               LayoutId layout_id, const CrowdNoise& noise, std::mt19937& rng) {
  std::uniform_real_distribution<double> u01(0, 1);
  CrowdObservation obs;
  obs.views.resize(calib.size());
  obs.who.resize(calib.size());
  for (size_t v = 0; v < calib.size(); ++v) {
    const Camera& cam = calib[v];
    // Each person as this camera sees them (noise, misses, outliers, swaps), and how far they are.
    std::vector<Person2D> seen(truth.size());
    std::vector<std::vector<Eigen::Vector2d>> exact(truth.size());
    std::vector<double> depth(truth.size(), INFINITY), height_px(truth.size(), 0);
    for (size_t p = 0; p < truth.size(); ++p) {
      if (truth[p].empty()) continue;
      Calibration one{cam};
      std::vector<std::vector<Person2D>> single = observe(one, truth[p], layout_id, noise.noise, rng);
      if (single[0].empty()) continue;
      seen[p] = single[0][0];
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      int n = 0;
      double top = INFINITY, bottom = -INFINITY;
      for (const Eigen::Vector3d& k : truth[p]) {
        if (!k.allFinite()) {
          exact[p].emplace_back(NAN, NAN);
          continue;
        }
        centre += k, ++n;
        const Eigen::Vector2d px = cam.project(k);
        exact[p].push_back(px);
        top = std::min(top, px.y()), bottom = std::max(bottom, px.y());
      }
      depth[p] = (cam.R * (centre / n) + cam.t).z();
      height_px[p] = bottom - top;
    }
    // Occlusion: a keypoint near a nearer person's body is hidden, or detected on that body instead.
    for (size_t p = 0; p < truth.size(); ++p) {
      if (seen[p].empty()) continue;
      for (size_t k = 0; k < seen[p].size(); ++k) {
        if (!(k < exact[p].size()) || !exact[p][k].allFinite()) continue;
        for (size_t q = 0; q < truth.size(); ++q) {
          if (q == p || seen[q].empty() || !(depth[q] < depth[p])) continue;
          double nearest = INFINITY;
          size_t at = 0;
          for (size_t j = 0; j < exact[q].size(); ++j) {
            const double d = (exact[q][j] - exact[p][k]).norm();
            if (d < nearest) nearest = d, at = j;
          }
          if (!(nearest < noise.occlusion_px * height_px[q])) continue;
          if (u01(rng) < noise.hidden)
            seen[p][k] = Keypoint2D{};
          else if (noise.snap)
            seen[p][k] = {exact[q][at].x(), exact[q][at].y(), 0.4 + 0.3 * u01(rng)};
          break;
        }
      }
    }
    for (size_t p = 0; p < truth.size(); ++p) {
      if (seen[p].empty() || u01(rng) < noise.missed) continue;
      obs.views[v].push_back(seen[p]);
      obs.who[v].push_back(static_cast<int>(p));
    }
    // Detectors list people in no particular order.
    std::vector<size_t> order(obs.views[v].size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<Person2D> people;
    std::vector<int> who;
    for (size_t i : order) people.push_back(obs.views[v][i]), who.push_back(obs.who[v][i]);
    obs.views[v] = std::move(people);
    obs.who[v] = std::move(who);
  }
  return obs;
}

std::vector<std::vector<std::vector<Eigen::Vector3d>>> write_crowd_take(const Calibration& calib, size_t people,
                                                                        size_t frames, const std::string& dir,
                                                                        unsigned seed) {
  namespace fs = std::filesystem;
  write_calibration_toml(calib, (fs::path(dir) / "calibration.toml").string());
  const auto crowd = make_crowd(people, frames);
  std::mt19937 rng(seed);
  for (size_t f = 0; f < frames; ++f) {
    std::vector<std::vector<Eigen::Vector3d>> now;
    for (size_t p = 0; p < people; ++p) now.push_back(crowd[p][f]);
    const CrowdObservation obs = observe_crowd(calib, now, LayoutId::body25, {}, rng);
    for (size_t v = 0; v < calib.size(); ++v) {
      const fs::path folder = fs::path(dir) / "keypoints" / (calib[v].name + "_json");
      fs::create_directories(folder);
      char name[32];
      std::snprintf(name, sizeof name, "%06zu.json", f);
      write_openpose_file((folder / name).string(), obs.views[v]);
    }
  }
  return crowd;
}

}  // namespace octocap::internal::synth
