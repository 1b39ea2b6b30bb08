#include "pipeline/session.h"

#include <chrono>
#include <cmath>
#include <string>

#include "core/error.h"
#include "io/motion_files.h"
#ifdef OCTOCAP_HAVE_DDS
#include "stream/dds_publisher.h"
#include "stream/vmc_sender.h"
#endif
#include "solve/person_select.h"
#include "solve/subdivision.h"
#include "solve/triangulation.h"
#include "solve/volume.h"

namespace octocap {
namespace {

// Cameras are mounted roughly upright: each one's image-down axis (+y in the camera) points to world down.
bool guess_z_up(const Calibration& calib) {
  Eigen::Vector3d down = Eigen::Vector3d::Zero();
  for (const Camera& c : calib) down += c.R.transpose() * Eigen::Vector3d::UnitY();
  return std::abs(down.z()) > std::abs(down.y());
}


// Every value checked, and every per-frame cost bounded: a config that could take seconds a frame is refused.
void validate(const SessionConfig& c) {
  const double values[] = {c.delta, c.pixel_tolerance, c.min_confidence, c.outlier_threshold_px, c.filter_min_cutoff,
                           c.filter_beta};
  for (double v : values)
    if (!std::isfinite(v)) throw Error(Errc::invalid_argument, "a config value is NaN or infinite");
  if (!c.volume_min.allFinite() || !c.volume_max.allFinite())
    throw Error(Errc::invalid_argument, "config.volume_min/volume_max must be finite");
  // Subdivision visits about max_candidates * 8 cubes per level and log2(volume / delta) levels: a 1 mm floor and a
  // cap of 4096 candidates keep a frame in milliseconds whatever the volume.
  if (!(c.delta >= 0.001)) throw Error(Errc::invalid_argument, "config.delta_m must be >= 0.001 (1 mm)");
  if (c.pixel_tolerance < 0) throw Error(Errc::invalid_argument, "config.pixel_tolerance must be >= 0");
  if (c.max_candidates < 1 || c.max_candidates > 4096)
    throw Error(Errc::invalid_argument, "config.max_candidates must be 1..4096");
  if (!(c.outlier_threshold_px > 0)) throw Error(Errc::invalid_argument, "config.outlier_threshold_px must be > 0");
  if (!(c.filter_min_cutoff > 0) || c.filter_beta < 0)
    throw Error(Errc::invalid_argument, "config.filter_min_cutoff_hz must be > 0 and filter_beta >= 0");
  // Frame numbers count up from here; leaving room below INT64_MAX keeps every increment defined.
  if (c.first_frame_index < 0 || c.first_frame_index > (int64_t{1} << 62))
    throw Error(Errc::invalid_argument, "config.first_frame_index must be 0 .. 2^62");
  if (c.volume_min != c.volume_max && (c.volume_max.array() <= c.volume_min.array()).any())
    throw Error(Errc::invalid_argument, "config.volume_max must exceed volume_min on every axis");
}

// NaN/inf, zero confidence or OpenPose's (0, 0) placeholder is "not detected", not an error: detectors emit them.
Keypoint2D clean(const Keypoint2D& k) {
  const bool ok = std::isfinite(k.x) && std::isfinite(k.y) && std::isfinite(k.confidence) && k.confidence > 0 &&
                  !(k.x == 0 && k.y == 0);
  return ok ? k : Keypoint2D{};
}

}  // namespace

Session::Session(const SessionConfig& config, Calibration calib)
    : config_(config), calib_(std::move(calib)), layout_(&layout(config.layout)) {
  validate(config_);
  auto keypoint = [&](const char* name) {
    for (size_t k = 0; k < layout_->keypoints.size(); ++k)
      if (std::string(layout_->keypoints[k]) == name) return static_cast<int>(k);
    return -1;
  };
  nose_ = keypoint("Nose"), l_eye_ = keypoint("LEye"), r_eye_ = keypoint("REye");
  l_ear_ = keypoint("LEar"), r_ear_ = keypoint("REar");
  const int cams = static_cast<int>(calib_.size());
  if (cams < 2) throw Error(Errc::not_enough_views, "a session needs at least 2 cameras, the calibration has " +
                                                        std::to_string(cams));
  if (cams > 64) throw Error(Errc::invalid_argument, "at most 64 cameras are supported");
  if (config_.min_views < 2 || config_.min_views > cams)
    throw Error(Errc::invalid_argument, "min_views must be between 2 and the camera count (" +
                                            std::to_string(cams) + "), is " + std::to_string(config_.min_views));
  sigma_ = config_.sigma > 0 ? config_.sigma : std::max(2, cams - 1);
  if (sigma_ > cams)
    throw Error(Errc::invalid_argument, "sigma (" + std::to_string(sigma_) + ") exceeds the camera count (" +
                                            std::to_string(cams) + ")");
  // min == max: no volume given, it is derived from the calibration.
  if (config_.volume_min != config_.volume_max) volume_ = Eigen::AlignedBox3d(config_.volume_min, config_.volume_max);
  if (volume_.isEmpty() || volume_.volume() <= 0) {
    volume_ = derive_capture_volume(calib_);
    if (volume_.isEmpty())
      throw Error(Errc::invalid_argument, "the cameras share no field of view; give the capture volume explicitly");
  }
  // Measured (bench/, README): subdivision is the more accurate with 5+ views, triangulation with fewer.
  method_ = config_.method != Method::automatic ? config_.method
            : cams >= 5                         ? Method::subdivision
                                                : Method::triangulation;
  z_up_ = config_.up == UpAxis::automatic ? guess_z_up(calib_) : config_.up == UpAxis::z;
  pool_ = std::make_unique<WorkerPool>(config_.threads);
  const size_t K = layout_->keypoints.size();
  filters_.assign(K, OneEuroFilter3(config_.filter_min_cutoff, config_.filter_beta));
  frame_.keypoints.assign(K, PointResult{});
  frame_.layout = config_.layout;
  frame_.view_count = static_cast<uint32_t>(cams);
  frame_.definition_counter = next_definition_counter();
  frame_.info.frame_index = config_.first_frame_index - 1;
  if (config_.publish) {
#ifdef OCTOCAP_HAVE_DDS
    sinks_.push_back(std::make_unique<DdsPublisher>(config_.stream, config_.layout, frame_.definition_counter));
#else
    throw Error(Errc::unsupported, "this build of octocap has no DDS streaming (OCTOCAP_WITH_DDS=OFF)");
#endif
  }
  if (config_.vmc_port != 0) {
#ifdef OCTOCAP_HAVE_DDS
    sinks_.push_back(std::make_unique<VmcSender>(config_.vmc_host, config_.vmc_port));
#else
    throw Error(Errc::unsupported, "this build of octocap has no VMC output (OCTOCAP_WITH_DDS=OFF)");
#endif
  }
}

Session::~Session() = default;

void Session::flush_stream() {
  for (auto& sink : sinks_) sink->flush();
}

uint32_t Session::stream_readers() const {
  uint32_t n = 0;
  for (const auto& sink : sinks_) n += sink->receivers();
  return n;
}

void Session::reset() {
  for (auto& f : filters_) f.reset();
  bone_solver_.reset();
  raw_previous_.clear();
  last_timestamp_us_ = 0;
  has_timestamp_ = false;
  solved_any_ = false;
  const int64_t last = frame_.info.frame_index;
  frame_.info = FrameInfo{};
  frame_.info.frame_index = last;  // numbering goes on: a stream's readers must not see a restart
  clear_frame();
}

void Session::clear_frame() {
  frame_.keypoints.assign(layout_->keypoints.size(), PointResult{});
  frame_.joints.fill(PointResult{});
  frame_.bones = SkeletonPose{};
}

PointResult Session::solve_keypoint(const std::vector<ViewRay>& rays) const {
  if (method_ == Method::triangulation) {
    return solve_triangulation(calib_, rays, {config_.min_views, config_.outlier_threshold_px});
  }
  SubdivisionParams p;
  p.sigma = sigma_;
  p.min_views = config_.min_views;
  p.delta = config_.delta;
  p.pixel_tolerance = config_.pixel_tolerance;
  p.max_candidates = config_.max_candidates;
  p.volume = volume_;
  p.max_reprojection_error_px = config_.outlier_threshold_px;
  return solve_subdivision(calib_, rays, p);
}

bool Session::solve(const std::vector<std::vector<Person2D>>& people, int64_t timestamp_us) {
  const auto t0 = std::chrono::steady_clock::now();
  const size_t V = calib_.size(), K = layout_->keypoints.size();
  if (people.size() != V)
    throw Error(Errc::camera_mismatch, "got " + std::to_string(people.size()) + " views, the calibration has " +
                                           std::to_string(V) + " cameras");
  for (size_t v = 0; v < V; ++v)
    for (const Person2D& p : people[v])
      if (p.size() != K)
        throw Error(Errc::invalid_argument, "view " + std::to_string(v) + " has a person with " +
                                                std::to_string(p.size()) + " keypoints, layout " + layout_->name +
                                                " has " + std::to_string(K));

  // A "person" without three confident keypoints (all NaN, all below min_confidence) is nobody: it must
  // not count as a view that saw someone.
  if (people.size() > 0)
    for (size_t v = 0; v < V; ++v)
      if (people[v].size() > kMaxPeoplePerView)
        throw Error(Errc::invalid_argument, "view " + std::to_string(v) + " has more than " +
                                                std::to_string(kMaxPeoplePerView) + " people");
  std::vector<std::vector<Person2D>> usable(V);
  std::vector<std::vector<int>> original(V);
  for (size_t v = 0; v < V; ++v)
    for (size_t p = 0; p < people[v].size(); ++p) {
      Person2D person(K);
      int confident = 0;
      for (size_t k = 0; k < K; ++k) {
        person[k] = clean(people[v][p][k]);
        confident += person[k].confidence >= config_.min_confidence;
      }
      if (confident < 3) continue;
      usable[v].push_back(std::move(person));
      original[v].push_back(static_cast<int>(p));
    }
  frame_.selected = select_people(calib_, usable, raw_previous_, {config_.min_confidence, 2 * config_.outlier_threshold_px});
  uint32_t with_person = 0;
  for (int s : frame_.selected) with_person += s >= 0;
  std::vector<int> selected_usable = frame_.selected;
  for (size_t v = 0; v < V; ++v)
    if (frame_.selected[v] >= 0) frame_.selected[v] = original[v][frame_.selected[v]];  // report indices into the caller's list

  // In double: the difference of two extreme int64 timestamps overflows int64.
  const double dt = has_timestamp_
                        ? (static_cast<double>(timestamp_us) - static_cast<double>(last_timestamp_us_)) * 1e-6
                        : 0.0;
  has_timestamp_ = true;
  ++frame_.info.frame_index;
  solved_any_ = true;
  frame_.info.timestamp_us = timestamp_us;
  last_timestamp_us_ = timestamp_us;
  frame_.info.views_with_person = with_person;
  frame_.info.keypoints_total = static_cast<uint32_t>(K);
  clear_frame();

  if (with_person < static_cast<uint32_t>(config_.min_views)) {
    frame_.info.keypoints_solved = 0;
    frame_.info.mean_reprojection_error_px = 0;
    frame_.info.solve_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    raw_previous_.clear();
    for (auto& f : filters_) f.reset();
    publish();
    return false;
  }

  pool_->parallel_for(K, [&](size_t k) {
    std::vector<ViewRay> rays;
    rays.reserve(V);
    for (size_t v = 0; v < V; ++v) {
      if (selected_usable[v] < 0) continue;
      const Keypoint2D& kp = usable[v][selected_usable[v]][k];
      if (!(kp.confidence >= config_.min_confidence) || !std::isfinite(kp.x) || !std::isfinite(kp.y)) continue;
      rays.push_back(make_view_ray(calib_[v], static_cast<int>(v), {kp.x, kp.y}, kp.confidence));
    }
    PointResult r = solve_keypoint(rays);
    // Never a NaN marked valid: a degenerate camera (an absurd rotation in a calibration) makes the point missing.
    if (r.valid && (!r.position.allFinite() || !std::isfinite(r.reprojection_error_px) ||
                    r.position.cwiseAbs().maxCoeff() > 1e6))
      r = PointResult{};
    frame_.keypoints[k] = r;
  });

  raw_previous_.assign(K, Eigen::Vector3d::Constant(std::nan("")));
  uint32_t solved = 0;
  double err = 0;
  for (size_t k = 0; k < K; ++k) {
    PointResult& r = frame_.keypoints[k];
    if (!r.valid) {
      filters_[k].reset();
      continue;
    }
    raw_previous_[k] = r.position;
    ++solved;
    err += r.reprojection_error_px;
    if (config_.filter) r.position = filters_[k].filter(r.position, dt);
  }
  frame_.info.keypoints_solved = solved;
  frame_.info.mean_reprojection_error_px = solved ? err / solved : 0;
  derive_skeleton();
  frame_.info.solve_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  publish();
  return frame_.has_person();
}

void Session::publish() {
  for (auto& sink : sinks_) sink->publish(frame_);
}

void Session::derive_skeleton() {
  for (int j = 0; j < kJointCount; ++j) {
    for (const auto& alternative : layout_->joint_sources[j]) {
      bool all = true;
      for (int k : alternative) all = all && frame_.keypoints[k].valid;
      if (!all) continue;
      PointResult out;
      out.valid = true;
      out.confidence = 1e9;
      out.views_used = 1u << 31;
      for (int k : alternative) {
        const PointResult& r = frame_.keypoints[k];
        out.position += r.position / static_cast<double>(alternative.size());
        out.reprojection_error_px += r.reprojection_error_px / static_cast<double>(alternative.size());
        out.confidence = std::min(out.confidence, r.confidence);
        out.views_used = std::min(out.views_used, r.views_used);
        out.view_mask |= r.view_mask;
      }
      frame_.joints[j] = out;
      break;
    }
  }
  SkeletonJoints rig_joints;
  for (int j = 0; j < kJointCount; ++j) {
    if (!frame_.joints[j].valid) {
      rig_joints[j] = Eigen::Vector3d::Constant(std::nan(""));
      continue;
    }
    rig_joints[j] = z_up_ ? zup_to_yup(frame_.joints[j].position) : frame_.joints[j].position;
  }
  auto rig_point = [&](int k) -> Eigen::Vector3d {
    if (k < 0 || !frame_.keypoints[k].valid) return Eigen::Vector3d::Constant(std::nan(""));
    return z_up_ ? zup_to_yup(frame_.keypoints[k].position) : frame_.keypoints[k].position;
  };
  BodyCues cues;
  cues.head_across = rig_point(l_ear_) - rig_point(r_ear_);
  if (!cues.head_across.allFinite()) cues.head_across = rig_point(l_eye_) - rig_point(r_eye_);
  cues.head_forward = rig_point(nose_) - rig_joints[kHead];
  frame_.bones = bone_solver_.solve(rig_joints, cues);
}

}  // namespace octocap
