#include "core/rays.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace octocap::internal {

ViewRay make_view_ray(const Camera& cam, int view, const Eigen::Vector2d& pixel, double confidence) {
  ViewRay r;
  r.view = view;
  r.pixel = pixel;
  r.normalized = cam.pixel_to_normalized(pixel);
  r.origin = cam.center();
  r.direction = (cam.R.transpose() * Eigen::Vector3d(r.normalized.x(), r.normalized.y(), 1.0)).normalized();
  r.confidence = confidence;
  return r;
}

bool triangulate_dlt(const Calibration& calib, const std::vector<ViewRay>& rays, uint64_t mask, bool weighted,
                     Eigen::Vector3d& out) {
  // Normal equations of the homogeneous system: sum of per-view 2x4 blocks, smallest eigenvector.
  Eigen::Matrix4d AtA = Eigen::Matrix4d::Zero();
  int n = 0;
  for (const ViewRay& r : rays) {
    if (!(mask >> r.view & 1u)) continue;
    const Camera& c = calib[r.view];
    Eigen::Matrix<double, 3, 4> P;
    P << c.R, c.t;
    const double w = weighted ? r.confidence : 1.0;
    const Eigen::Matrix<double, 1, 4> row1 = w * (r.normalized.x() * P.row(2) - P.row(0));
    const Eigen::Matrix<double, 1, 4> row2 = w * (r.normalized.y() * P.row(2) - P.row(1));
    AtA += row1.transpose() * row1 + row2.transpose() * row2;
    ++n;
  }
  if (n < 2) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(AtA);
  const Eigen::Vector4d h = es.eigenvectors().col(0);
  if (std::abs(h.w()) < 1e-12) return false;
  out = h.head<3>() / h.w();
  return out.allFinite();
}

}  // namespace octocap::internal
