#include "calib/extrinsics.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <opencv2/calib3d.hpp>
#include <set>

#include "calib/bundle_adjustment.h"
#include "core/error.h"
#include "core/log.h"
#include "core/stats.h"
#include "core/rays.h"

namespace octocap::internal {
namespace {

struct Obs {
  int camera;
  int point;                  // frame * K + keypoint
  Eigen::Vector2d pixel, normalized;
};

// The most prominent person of a view: biggest box times mean confidence (bystanders are usually far away).
int prominent(const std::vector<Person2D>& people, double min_conf) {
  int best = -1;
  double score = 0;
  for (size_t p = 0; p < people.size(); ++p) {
    Eigen::AlignedBox2d box;
    double conf = 0;
    int n = 0;
    for (const auto& k : people[p])
      if (k.confidence >= min_conf) {
        box.extend(Eigen::Vector2d(k.x, k.y));
        conf += k.confidence;
        ++n;
      }
    if (n < 4) continue;
    const double s = box.diagonal().norm() * conf / n;
    if (s > score) {
      score = s;
      best = static_cast<int>(p);
    }
  }
  return best;
}

std::string camera_list(const Calibration& calib, const std::vector<int>& idx) {
  std::string s;
  for (int i : idx) s += (s.empty() ? "" : ", ") + calib[i].name;
  return s;
}

double median(std::vector<double> v) { return median_in_place(v, 0); }

// Triangulates every point seen by >= 2 placed cameras that is not yet known; keeps it when it lies in front of
// them and reprojects within max_px.
void triangulate_new(const Calibration& calib, const std::vector<bool>& placed, const std::vector<std::vector<Obs>>& by_point,
                     std::vector<Eigen::Vector3d>& points, std::vector<bool>& known, double max_px) {
  std::vector<ViewRay> rays;
  for (size_t p = 0; p < by_point.size(); ++p) {
    if (known[p]) continue;
    rays.clear();
    uint64_t mask = 0;
    for (const Obs& o : by_point[p]) {
      if (!placed[o.camera]) continue;
      rays.push_back(make_view_ray(calib[o.camera], o.camera, o.pixel, 1.0));
      mask |= uint64_t{1} << o.camera;
    }
    if (rays.size() < 2) continue;
    Eigen::Vector3d X;
    if (!triangulate_dlt(calib, rays, mask, false, X)) continue;
    bool ok = true;
    for (const ViewRay& r : rays) {
      const Eigen::Vector2d px = calib[r.view].project(X);
      ok = ok && px.allFinite() && (px - r.pixel).norm() < max_px;
    }
    if (!ok) continue;
    points[p] = X;
    known[p] = true;
  }
}

// Observations within 3x the median reprojection error (at least 5 px): wrong detections and left/right
// swaps lie far out.
std::vector<BaObservation> inlier_observations(const Calibration& calib, const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<BaObservation>& obs) {
  std::vector<double> errs;
  for (const auto& o : obs) {
    const Eigen::Vector2d p = calib[o.camera].project(points[o.point]);
    errs.push_back(p.allFinite() ? (p - o.pixel).norm() : 1e9);
  }
  const double limit = std::max(5.0, 3 * median(errs));
  std::vector<BaObservation> out;
  for (size_t i = 0; i < obs.size(); ++i)
    if (errs[i] < limit) out.push_back(obs[i]);
  return out;
}

// Refinement: every camera starts where the given calibration has it. Bundle adjustment moves them all; the
// result is then put back into the original frame by the similarity that best maps the new camera centres
// onto the old ones, leaving out the camera that moved most (the nudged one) when there are 4 or more.
Calibration refine_extrinsics(const Calibration& given, const std::vector<std::vector<Obs>>& by_point,
                              ExtrinsicsReport* report) {
  const int V = static_cast<int>(given.size());
  Calibration calib = given;
  std::vector<bool> placed(V, true), known(by_point.size(), false);
  std::vector<Eigen::Vector3d> points(by_point.size(), Eigen::Vector3d::Zero());
  // Generous: the nudged camera disagrees with the others until the adjustment has moved it.
  triangulate_new(calib, placed, by_point, points, known, 200.0);
  std::vector<BaObservation> obs;
  for (const auto& po : by_point)
    for (const Obs& o : po)
      if (known[o.point]) obs.push_back({o.camera, o.point, o.pixel});
  if (obs.size() < 50)
    throw Error(Errc::invalid_argument, "too few keypoints agree with the given calibration to refine it");
  std::vector<bool> adjust(V, true);
  const BaResult r1 = bundle_adjust(calib, adjust, -1, points, obs, 2.0, 100);
  const std::vector<BaObservation> inl = inlier_observations(calib, points, obs);
  const BaResult r2 = bundle_adjust(calib, adjust, -1, points, inl, 2.0, 100);

  auto similarity = [&](int skip) {
    const int n = V - (skip >= 0 ? 1 : 0);
    Eigen::Matrix3Xd A(3, n), B(3, n);
    for (int v = 0, i = 0; v < V; ++v) {
      if (v == skip) continue;
      A.col(i) = given[v].center();
      B.col(i++) = calib[v].center();
    }
    return Eigen::Matrix4d(Eigen::umeyama(B, A, true));
  };
  Eigen::Matrix4d T = similarity(-1);
  if (V >= 4) {
    int worst = 0;
    double worst_d = -1;
    for (int v = 0; v < V; ++v) {
      const double d = ((T * calib[v].center().homogeneous()).head<3>() - given[v].center()).norm();
      if (d > worst_d) worst_d = d, worst = v;
    }
    T = similarity(worst);
  }
  const double s = T.block<3, 3>(0, 0).col(0).norm();
  const Eigen::Matrix3d R = T.block<3, 3>(0, 0) / s;
  const Eigen::Vector3d t = T.block<3, 1>(0, 3);
  for (Camera& c : calib) {
    c.R = c.R * R.transpose();
    c.t = s * c.t - c.R * t;
  }
  std::vector<Eigen::Vector3d> world(points.size());
  for (size_t p = 0; p < points.size(); ++p) world[p] = s * R * points[p] + t;
  fill_extrinsics_report(calib, world, inl, static_cast<size_t>(std::count(known.begin(), known.end(), true)), r1, r2,
                         report);
  return calib;
}

}  // namespace

void fill_extrinsics_report(const Calibration& calib, const std::vector<Eigen::Vector3d>& world_points,
                            const std::vector<BaObservation>& observations, size_t point_count,
                            const BaResult& first_pass, const BaResult& last_pass, ExtrinsicsReport* report) {
  if (!report) return;
  const size_t V = calib.size();
  report->rms_px.assign(V, 0);
  report->observations.assign(V, 0);
  std::vector<double> sum(V, 0);
  for (const auto& o : observations) {
    const Eigen::Vector2d p = calib[o.camera].project(world_points[o.point]);
    sum[o.camera] += (p - o.pixel).squaredNorm();
    ++report->observations[o.camera];
  }
  for (size_t v = 0; v < V; ++v)
    report->rms_px[v] = report->observations[v] ? std::sqrt(sum[v] / report->observations[v]) : 0;
  report->points = point_count;
  report->iterations = first_pass.iterations + (&first_pass == &last_pass ? 0 : last_pass.iterations);
  report->initial_rms_px = first_pass.initial_rms_px;
  report->final_rms_px = last_pass.final_rms_px;
}

Calibration calibrate_extrinsics(const Calibration& intrinsics,
                                 const std::vector<std::vector<std::vector<Person2D>>>& frames, LayoutId layout_id,
                                 const ExtrinsicsOptions& opt, ExtrinsicsReport* report) {
  const int V = static_cast<int>(intrinsics.size());
  if (V < 2) throw Error(Errc::not_enough_views, "extrinsics need at least 2 cameras, the calibration has " + std::to_string(V));
  const bool by_distance = opt.camera_distance_m > 0;
  if (!opt.refine && !(opt.person_height_m > 0) && !by_distance)
    throw Error(Errc::invalid_argument, "the scale of the scene cannot be seen in images: give the person's height or a camera distance");
  if (by_distance && (opt.distance_camera_a < 0 || opt.distance_camera_b < 0 || opt.distance_camera_a >= V ||
                      opt.distance_camera_b >= V || opt.distance_camera_a == opt.distance_camera_b))
    throw Error(Errc::invalid_argument, "camera distance: two different cameras of the calibration are needed");
  const KeypointLayout& lay = layout(layout_id);
  const int K = static_cast<int>(lay.keypoints.size());

  // Observations, frames subsampled evenly to max_frames.
  const size_t F = frames.size();
  const size_t step = std::max<size_t>(1, (F + opt.max_frames - 1) / std::max<size_t>(1, opt.max_frames));
  std::vector<std::vector<Obs>> by_point;
  std::vector<std::vector<Obs>> by_camera(V);
  for (size_t f = 0; f < F; f += step) {
    if (frames[f].size() != static_cast<size_t>(V))
      throw Error(Errc::camera_mismatch, "frame " + std::to_string(f) + " has " + std::to_string(frames[f].size()) +
                                             " views, the calibration has " + std::to_string(V) + " cameras");
    const int base = static_cast<int>(by_point.size());
    by_point.resize(by_point.size() + K);
    for (int v = 0; v < V; ++v) {
      const int p = prominent(frames[f][v], opt.min_confidence);
      if (p < 0) continue;
      for (int k = 0; k < K; ++k) {
        const Keypoint2D& kp = frames[f][v][p][k];
        if (kp.confidence < opt.min_confidence) continue;
        const Eigen::Vector2d px(kp.x, kp.y);
        Obs o{v, base + k, px, intrinsics[v].pixel_to_normalized(px)};
        by_point[base + k].push_back(o);
        by_camera[v].push_back(o);
      }
    }
  }
  for (int v = 0; v < V; ++v)
    if (by_camera[v].size() < 20)
      throw Error(Errc::not_enough_views, "camera " + intrinsics[v].name + " saw the person in too few frames (" +
                                              std::to_string(by_camera[v].size()) + " keypoints)");

  // Pairs that share points; their graph must be connected.
  std::vector<std::vector<int>> common(V, std::vector<int>(V, 0));
  for (const auto& obs : by_point)
    for (size_t a = 0; a < obs.size(); ++a)
      for (size_t b = a + 1; b < obs.size(); ++b) {
        ++common[obs[a].camera][obs[b].camera];
        ++common[obs[b].camera][obs[a].camera];
      }
  constexpr int kMinCommon = 40;
  {
    std::vector<int> group(V, -1);
    int groups = 0;
    for (int s = 0; s < V; ++s) {
      if (group[s] >= 0) continue;
      std::vector<int> stack{s};
      group[s] = groups;
      while (!stack.empty()) {
        const int c = stack.back();
        stack.pop_back();
        for (int d = 0; d < V; ++d)
          if (group[d] < 0 && common[c][d] >= kMinCommon) {
            group[d] = groups;
            stack.push_back(d);
          }
      }
      ++groups;
    }
    if (groups > 1) {
      std::string msg = "the cameras form " + std::to_string(groups) + " groups that see no common keypoints:";
      for (int g = 0; g < groups; ++g) {
        std::vector<int> members;
        for (int v = 0; v < V; ++v)
          if (group[v] == g) members.push_back(v);
        msg += " [" + camera_list(intrinsics, members) + "]";
      }
      throw Error(Errc::not_enough_views, msg + "; walk where both groups see the person");
    }
  }

  if (opt.refine) return refine_extrinsics(intrinsics, by_point, report);

  // Initial pair: the one sharing the most points. Essential matrix on undistorted normalised points.
  int a = 0, b = 1;
  for (int i = 0; i < V; ++i)
    for (int j = i + 1; j < V; ++j)
      if (common[i][j] > common[a][b]) a = i, b = j;
  std::vector<cv::Point2d> pa, pb;
  for (const auto& obs : by_point) {
    const Obs *oa = nullptr, *ob = nullptr;
    for (const Obs& o : obs) {
      if (o.camera == a) oa = &o;
      if (o.camera == b) ob = &o;
    }
    if (oa && ob) {
      pa.emplace_back(oa->normalized.x(), oa->normalized.y());
      pb.emplace_back(ob->normalized.x(), ob->normalized.y());
    }
  }
  // The common points must spread over the images: keypoints that all sit in one spot (a person who never
  // moves, a mislabelled recording) determine no relative pose.
  for (const auto* pts : {&pa, &pb}) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& p : *pts) mean += Eigen::Vector2d(p.x, p.y);
    mean /= static_cast<double>(pts->size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const auto& p : *pts) {
      const Eigen::Vector2d d = Eigen::Vector2d(p.x, p.y) - mean;
      cov += d * d.transpose();
    }
    cov /= static_cast<double>(pts->size());
    if (std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov).eigenvalues()(0))) < 0.02)
      throw Error(Errc::invalid_argument, "degenerate motion: the keypoints seen by " + intrinsics[a].name + " and " +
                                              intrinsics[b].name + " barely spread over the image (the person must move through the volume)");
  }
  const double focal = 0.5 * (intrinsics[a].focal() + intrinsics[b].focal());
  cv::Mat inliers;
  const cv::Mat E = cv::findEssentialMat(pa, pb, cv::Mat::eye(3, 3, CV_64F), cv::RANSAC, 0.999, 3.0 / focal, inliers);
  if (E.rows != 3 || E.cols != 3)
    throw Error(Errc::invalid_argument, "degenerate motion: no essential matrix between " + intrinsics[a].name +
                                            " and " + intrinsics[b].name + " (the person must move through the volume)");
  cv::Mat R, t;
  const int good = cv::recoverPose(E, pa, pb, cv::Mat::eye(3, 3, CV_64F), R, t, inliers);
  if (good < kMinCommon / 2)
    throw Error(Errc::invalid_argument, "degenerate motion: only " + std::to_string(good) +
                                            " consistent points between " + intrinsics[a].name + " and " + intrinsics[b].name);

  Calibration calib = intrinsics;
  std::vector<bool> placed(V, false);
  calib[a].R.setIdentity();
  calib[a].t.setZero();
  for (int i = 0; i < 9; ++i) calib[b].R(i / 3, i % 3) = R.at<double>(i / 3, i % 3);
  calib[b].t = Eigen::Vector3d(t.at<double>(0), t.at<double>(1), t.at<double>(2));
  placed[a] = placed[b] = true;
  std::vector<Eigen::Vector3d> points(by_point.size(), Eigen::Vector3d::Zero());
  std::vector<bool> known(by_point.size(), false);
  triangulate_new(calib, placed, by_point, points, known, 12.0);

  // Add the others by PnP on the points already known, best-connected first.
  for (int added = 2; added < V; ++added) {
    int next = -1;
    size_t best = 0;
    for (int v = 0; v < V; ++v) {
      if (placed[v]) continue;
      size_t n = 0;
      for (const Obs& o : by_camera[v]) n += known[o.point];
      if (n > best) best = n, next = v;
    }
    if (next < 0 || best < 12)
      throw Error(Errc::invalid_argument, "degenerate motion: camera " + (next < 0 ? std::string("?") : intrinsics[next].name) +
                                              " sees too few of the reconstructed points to be placed");
    std::vector<cv::Point3d> obj;
    std::vector<cv::Point2d> img;
    for (const Obs& o : by_camera[next])
      if (known[o.point]) {
        obj.emplace_back(points[o.point].x(), points[o.point].y(), points[o.point].z());
        img.emplace_back(o.normalized.x(), o.normalized.y());
      }
    cv::Mat rvec, tvec;
    std::vector<int> pnp_inliers;
    if (!cv::solvePnPRansac(obj, img, cv::Mat::eye(3, 3, CV_64F), cv::noArray(), rvec, tvec, false, 200,
                            4.0 / intrinsics[next].focal(), 0.999, pnp_inliers) ||
        pnp_inliers.size() < 8)
      throw Error(Errc::invalid_argument, "degenerate motion: camera " + intrinsics[next].name + " could not be placed");
    calib[next].R = rodrigues_to_matrix({rvec.at<double>(0), rvec.at<double>(1), rvec.at<double>(2)});
    calib[next].t = Eigen::Vector3d(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
    placed[next] = true;
    triangulate_new(calib, placed, by_point, points, known, 12.0);
  }

  // Bundle adjustment, twice: the second time without the observations the first found to be wrong.
  std::vector<BaObservation> obs;
  for (const auto& po : by_point)
    for (const Obs& o : po)
      if (known[o.point]) obs.push_back({o.camera, o.point, o.pixel});
  std::vector<bool> adjust(V, true);
  BaResult r1 = bundle_adjust(calib, adjust, a, points, obs, 2.0, 100);
  const std::vector<BaObservation> inl = inlier_observations(calib, points, obs);
  BaResult r2 = bundle_adjust(calib, adjust, a, points, inl, 2.0, 100);

  // A skeleton joint of frame f from the reconstructed keypoints, by the layout's definition.
  auto joint = [&](size_t f, int j, Eigen::Vector3d& out) {
    const std::vector<int>* alt = first_present_alternative(lay.joint_sources[j], [&](int k) { return known[f * K + k]; });
    if (!alt) return false;
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (int k : *alt) s += points[f * K + k];
    out = s / static_cast<double>(alt->size());
    return true;
  };

  // Scale.
  double scale = 1;
  if (by_distance) {
    const double d = (calib[opt.distance_camera_a].center() - calib[opt.distance_camera_b].center()).norm();
    scale = opt.camera_distance_m / d;
  } else {
    std::vector<double> paths;
    const size_t frames_used = by_point.size() / K;
    for (size_t f = 0; f < frames_used; ++f) {
      Eigen::Vector3d J[kJointCount];
      bool ok = true;
      for (int j : {kLFoot, kLKnee, kLHip, kRFoot, kRKnee, kRHip, kNeck, kHead}) ok = ok && joint(f, j, J[j]);
      if (!ok) continue;
      const double legs = 0.5 * ((J[kLFoot] - J[kLKnee]).norm() + (J[kLKnee] - J[kLHip]).norm() +
                                 (J[kRFoot] - J[kRKnee]).norm() + (J[kRKnee] - J[kRHip]).norm());
      const Eigen::Vector3d hip = 0.5 * (J[kLHip] + J[kRHip]);
      paths.push_back(legs + (J[kNeck] - hip).norm() + (J[kHead] - J[kNeck]).norm());
    }
    if (paths.size() < 5) throw Error(Errc::invalid_argument, "too few frames show the whole person to measure the scale");
    scale = opt.person_height_m * kKeypointPathOfHeight / median(paths);
  }

  // World frame: up = the person's mean up (feet -> neck); origin = mean floor contact below the ankles.
  Eigen::Vector3d up = Eigen::Vector3d::Zero(), ankles = Eigen::Vector3d::Zero();
  size_t n_up = 0, n_ank = 0;
  std::vector<Eigen::Vector3d> ankle_points;
  for (size_t f = 0; f < by_point.size() / K; ++f) {
    Eigen::Vector3d neck, la, ra;
    const bool has_l = joint(f, kLFoot, la), has_r = joint(f, kRFoot, ra);
    if (has_l) ankle_points.push_back(la);
    if (has_r) ankle_points.push_back(ra);
    if (has_l && has_r && joint(f, kNeck, neck)) {
      up += (neck - 0.5 * (la + ra)).normalized();
      ++n_up;
    }
  }
  if (n_up < 5 || ankle_points.empty()) throw Error(Errc::invalid_argument, "too few frames show the person upright to find the floor");
  up.normalize();
  for (const auto& p : ankle_points) ankles += p, ++n_ank;
  ankles /= static_cast<double>(n_ank);
  std::vector<double> heights;
  for (const auto& p : ankle_points) heights.push_back(p.dot(up));
  std::sort(heights.begin(), heights.end());
  const double floor_h = heights[heights.size() / 10];  // low ankles: feet on the floor; ankle height above it
  const double ankle_above_floor = 0.039 * (opt.person_height_m > 0 ? opt.person_height_m : 1.7) / scale;
  const Eigen::Vector3d origin = ankles - (ankles.dot(up) - floor_h + ankle_above_floor) * up;
  // Horizontal axes: toward the first camera is "forward" (+Z in a Y-up world).
  Eigen::Vector3d fwd = calib[0].center() - origin;
  fwd -= fwd.dot(up) * up;
  if (fwd.norm() < 1e-9) fwd = up.unitOrthogonal();
  fwd.normalize();
  const Eigen::Vector3d side = up.cross(fwd);  // Y x Z = X
  Eigen::Matrix3d Q;                             // rows: world axes in the reconstruction frame
  if (opt.z_up) {
    Q.row(0) = side;
    Q.row(1) = fwd;
    Q.row(2) = up;
    Q.row(1) = up.cross(side);  // right-handed: Z x X = Y
  } else {
    Q.row(0) = side;
    Q.row(1) = up;
    Q.row(2) = fwd;
  }
  for (Camera& c : calib) {
    const Eigen::Matrix3d R0 = c.R;
    const Eigen::Vector3d t0 = c.t;
    c.R = R0 * Q.transpose();
    c.t = scale * (R0 * origin + t0);
  }

  std::vector<Eigen::Vector3d> world(points.size());
  for (size_t p = 0; p < points.size(); ++p) world[p] = scale * Q * (points[p] - origin);
  fill_extrinsics_report(calib, world, inl, static_cast<size_t>(std::count(known.begin(), known.end(), true)), r1, r2,
                         report);
  log(LogLevel::info, "extrinsics: bundle adjustment " + std::to_string(r1.initial_rms_px) + " -> " +
                          std::to_string(r2.final_rms_px) + " px RMS");
  return calib;
}

}  // namespace octocap::internal
