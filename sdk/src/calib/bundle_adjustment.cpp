#include "calib/bundle_adjustment.h"

#include <ceres/ceres.h>
#include <ceres/rotation.h>
#include <glog/logging.h>

#include <array>
#include <cmath>

namespace octocap::internal {
namespace {

// Pixel residual of one observation: world point -> camera (angle-axis, translation) -> OpenCV standard
// distortion -> pixel. Templated for Ceres' automatic derivatives; mirrors Camera::project.
struct ReprojectionCost {
  ReprojectionCost(const Camera& cam, const Eigen::Vector2d& px) : c(cam), observed(px) {}

  template <class T>
  bool operator()(const T* pose, const T* point, T* residual) const {
    T p[3];
    ceres::AngleAxisRotatePoint(pose, point, p);
    p[0] += pose[3];
    p[1] += pose[4];
    p[2] += pose[5];
    if (p[2] <= T(1e-9)) return false;  // behind the camera: Ceres rejects the step
    const T x = p[0] / p[2], y = p[1] / p[2];
    const T r2 = x * x + y * y;
    const double k1 = c.dist[0], k2 = c.dist[1], p1 = c.dist[2], p2 = c.dist[3], k3 = c.dist[4];
    const T radial = T(1) + r2 * (T(k1) + r2 * (T(k2) + r2 * T(k3)));
    const T xd = x * radial + T(2 * p1) * x * y + T(p2) * (r2 + T(2) * x * x);
    const T yd = y * radial + T(p1) * (r2 + T(2) * y * y) + T(2 * p2) * x * y;
    residual[0] = T(c.K(0, 0)) * xd + T(c.K(0, 1)) * yd + T(c.K(0, 2)) - T(observed.x());
    residual[1] = T(c.K(1, 1)) * yd + T(c.K(1, 2)) - T(observed.y());
    return true;
  }

  Camera c;
  Eigen::Vector2d observed;
};

double rms(const Calibration& calib, const std::vector<Eigen::Vector3d>& points, const std::vector<BaObservation>& obs) {
  double s = 0;
  size_t n = 0;
  for (const BaObservation& o : obs) {
    const Eigen::Vector2d p = calib[o.camera].project(points[o.point]);
    if (!p.allFinite()) continue;
    s += (p - o.pixel).squaredNorm();
    ++n;
  }
  return n ? std::sqrt(s / n) : 0;
}

}  // namespace

BaResult bundle_adjust(Calibration& calib, const std::vector<bool>& adjust, int fixed_camera,
                       std::vector<Eigen::Vector3d>& points, const std::vector<BaObservation>& observations,
                       double huber_px, int max_iterations) {
  BaResult result;
  result.initial_rms_px = rms(calib, points, observations);
  std::vector<std::array<double, 6>> poses(calib.size());
  for (size_t c = 0; c < calib.size(); ++c) {
    const Eigen::Vector3d r = matrix_to_rodrigues(calib[c].R);
    poses[c] = {r.x(), r.y(), r.z(), calib[c].t.x(), calib[c].t.y(), calib[c].t.z()};
  }
  // Ceres reports through glog to stderr; a library prints nothing, so only fatal messages pass.
  FLAGS_minloglevel = google::GLOG_FATAL;
  ceres::Problem problem;
  for (const BaObservation& o : observations) {
    if (!adjust[o.camera] && o.camera != fixed_camera) continue;
    // A point behind a camera would fail the very first evaluation and stop the solver: leave it out.
    if (calib[o.camera].to_camera(points[o.point]).z() <= 1e-6) continue;
    auto* cost = new ceres::AutoDiffCostFunction<ReprojectionCost, 2, 6, 3>(
        new ReprojectionCost(calib[o.camera], o.pixel));
    problem.AddResidualBlock(cost, new ceres::HuberLoss(huber_px), poses[o.camera].data(), points[o.point].data());
  }
  if (fixed_camera >= 0 && problem.HasParameterBlock(poses[fixed_camera].data()))
    problem.SetParameterBlockConstant(poses[fixed_camera].data());
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_SCHUR;  // few cameras, many points: the reduced camera system is small
  options.max_num_iterations = max_iterations;
  options.num_threads = 2;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  result.iterations = static_cast<int>(summary.iterations.size());
  for (size_t c = 0; c < calib.size(); ++c) {
    calib[c].R = rodrigues_to_matrix({poses[c][0], poses[c][1], poses[c][2]});
    calib[c].t = {poses[c][3], poses[c][4], poses[c][5]};
  }
  result.final_rms_px = rms(calib, points, observations);
  return result;
}

}  // namespace octocap::internal
