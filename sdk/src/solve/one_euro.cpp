#include "solve/one_euro.h"

#include <cmath>

namespace octocap::internal {
namespace {

double alpha(double cutoff_hz, double dt) {
  const double tau = 1.0 / (2.0 * M_PI * cutoff_hz);
  return 1.0 / (1.0 + tau / dt);
}

}  // namespace

Eigen::Vector3d OneEuroFilter3::filter(const Eigen::Vector3d& x, double dt, double cutoff_scale) {
  if (!initialised_ || !(dt > 0)) {
    initialised_ = true;
    x_prev_ = x;
    dx_prev_.setZero();
    return x;
  }
  const Eigen::Vector3d dx = (x - x_prev_) / dt;
  const double ad = alpha(d_cutoff_, dt);
  dx_prev_ = ad * dx + (1 - ad) * dx_prev_;
  // One cutoff for the whole point (from its speed), so the three axes stay in step.
  const double cutoff = min_cutoff_ * cutoff_scale + beta_ * dx_prev_.norm();
  const double a = alpha(cutoff, dt);
  x_prev_ = a * x + (1 - a) * x_prev_;
  return x_prev_;
}

}  // namespace octocap::internal
