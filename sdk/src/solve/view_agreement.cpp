#include "solve/view_agreement.h"

#include <cmath>
#include <limits>

#include "core/stats.h"
#include "solve/triangulation.h"

namespace octocap::internal {

double distance_to_pose(const Camera& cam, const Person2D& person, const std::vector<Eigen::Vector3d>& pose,
                        double min_conf) {
  std::vector<double> d;
  for (size_t k = 0; k < person.size() && k < pose.size(); ++k) {
    if (person[k].confidence < min_conf || !pose[k].allFinite()) continue;
    const Eigen::Vector2d p = cam.project(pose[k]);
    if (p.allFinite()) d.push_back((p - Eigen::Vector2d(person[k].x, person[k].y)).norm());
  }
  return d.size() >= 3 ? median_or_inf(d) : kInf;
}

std::vector<double> combination_errors(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                                       const std::vector<int>& choice, double min_conf,
                                       std::vector<Eigen::Vector3d>* pose) {
  const size_t V = calib.size();
  size_t K = 0;
  for (size_t v = 0; v < V; ++v)
    if (choice[v] >= 0) K = people[v][choice[v]].size();
  std::vector<std::vector<double>> errs(V);
  std::vector<ViewRay> rays;
  if (pose) pose->assign(K, Eigen::Vector3d::Constant(std::nan("")));
  for (size_t k = 0; k < K; ++k) {
    rays.clear();
    uint64_t mask = 0;
    for (size_t v = 0; v < V; ++v) {
      if (choice[v] < 0) continue;
      const Keypoint2D& kp = people[v][choice[v]][k];
      if (kp.confidence < min_conf) continue;
      rays.push_back(make_view_ray(calib[v], static_cast<int>(v), {kp.x, kp.y}, kp.confidence));
      mask |= uint64_t{1} << v;
    }
    if (rays.size() < 2) continue;
    Eigen::Vector3d X;
    if (!triangulate_dlt(calib, rays, mask, true, X)) continue;
    if (pose) (*pose)[k] = X;
    for (const ViewRay& r : rays) {
      const Eigen::Vector2d p = calib[r.view].project(X);
      errs[r.view].push_back(p.allFinite() ? (p - r.pixel).norm() : 1e6);
    }
  }
  std::vector<double> out(V, kInf);
  for (size_t v = 0; v < V; ++v)
    if (errs[v].size() >= 3) out[v] = median_or_inf(errs[v]);
  return out;
}

void grow_by_nearest(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                     const std::vector<std::vector<int>>& cands, double min_conf, double max_px,
                     std::vector<int>& choice) {
  std::vector<Eigen::Vector3d> pose;
  combination_errors(calib, people, choice, min_conf, &pose);
  for (size_t v = 0; v < choice.size(); ++v) {
    if (choice[v] >= 0) continue;
    double nearest = kInf;
    for (int p : cands[v]) {
      const double d = distance_to_pose(calib[v], people[v][p], pose, min_conf);
      if (d < nearest) nearest = d, choice[v] = p;
    }
    if (!(nearest <= max_px)) choice[v] = -1;
  }
}

}  // namespace octocap::internal
