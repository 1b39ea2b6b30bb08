#include "pipeline/session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/axes.h"
#include "core/error.h"
#include "core/log.h"
#ifdef OCTOCAP_HAVE_DDS
#include "stream/dds_publisher.h"
#include "stream/vmc_sender.h"
#endif
#include "solve/association.h"
#include "solve/person_select.h"
#include "solve/subdivision.h"
#include "solve/triangulation.h"
#include "solve/view_order.h"
#include "solve/volume.h"

namespace octocap::internal {
namespace {

// Cameras are mounted roughly upright: each one's image-down axis (+y in the camera) points to world down.
bool guess_z_up(const Calibration& calib) {
  Eigen::Vector3d down = Eigen::Vector3d::Zero();
  for (const Camera& c : calib) down += c.R.transpose() * Eigen::Vector3d::UnitY();
  return std::abs(down.z()) > std::abs(down.y());
}


// NaN/inf, zero confidence or OpenPose's (0, 0) placeholder is "not detected", not an error: detectors emit them.
Keypoint2D clean(const Keypoint2D& k) {
  const bool ok = std::isfinite(k.x) && std::isfinite(k.y) && std::isfinite(k.confidence) && k.confidence > 0 &&
                  !(k.x == 0 && k.y == 0);
  return ok ? k : Keypoint2D{};
}

}  // namespace

void SessionConfig::validate(int cameras) const {
  if (layout == LayoutId::automatic || std::find(all_layouts().begin(), all_layouts().end(), layout) == all_layouts().end())
    throw Error(Errc::invalid_argument, "config.layout must be a concrete layout (not AUTO)");
  if (method != Method::subdivision && method != Method::triangulation && method != Method::automatic)
    throw Error(Errc::invalid_argument, "config.method is not a known method");
  if (up != UpAxis::y && up != UpAxis::z && up != UpAxis::automatic)
    throw Error(Errc::invalid_argument, "config.up_axis must be Y, Z or AUTO");
  const double values[] = {delta, pixel_tolerance, min_confidence, outlier_threshold_px, filter_min_cutoff,
                           filter_beta};
  for (double v : values)
    if (!std::isfinite(v)) throw Error(Errc::invalid_argument, "a config value is NaN or infinite");
  if (!volume_min.allFinite() || !volume_max.allFinite())
    throw Error(Errc::invalid_argument, "config.volume_min/volume_max must be finite");
  // Subdivision visits about max_candidates * 8 cubes per level and log2(volume / delta) levels: a 1 mm floor and a
  // cap of 4096 candidates keep a frame in milliseconds whatever the volume.
  if (!(delta >= 0.001)) throw Error(Errc::invalid_argument, "config.delta_m must be >= 0.001 (1 mm)");
  if (pixel_tolerance < 0) throw Error(Errc::invalid_argument, "config.pixel_tolerance must be >= 0");
  if (max_candidates < 1 || max_candidates > 4096)
    throw Error(Errc::invalid_argument, "config.max_candidates must be 1..4096");
  if (!(outlier_threshold_px > 0)) throw Error(Errc::invalid_argument, "config.outlier_threshold_px must be > 0");
  if (!(filter_min_cutoff > 0) || filter_beta < 0)
    throw Error(Errc::invalid_argument, "config.filter_min_cutoff_hz must be > 0 and filter_beta >= 0");
  // Frame numbers count up from here; leaving room below INT64_MAX keeps every increment defined.
  if (first_frame_index < 0 || first_frame_index > (int64_t{1} << 62))
    throw Error(Errc::invalid_argument, "config.first_frame_index must be 0 .. 2^62");
  if (volume_min != volume_max && (volume_max.array() <= volume_min.array()).any())
    throw Error(Errc::invalid_argument, "config.volume_max must exceed volume_min on every axis");
  if (max_people > kMaxPeople)
    throw Error(Errc::invalid_argument, "config.max_people must be 0 (all) .. " + std::to_string(kMaxPeople) + ", is " +
                                            std::to_string(max_people));
  if (min_views < 2 || min_views > cameras)
    throw Error(Errc::invalid_argument, "min_views must be between 2 and the camera count (" +
                                            std::to_string(cameras) + "), is " + std::to_string(min_views));
  if (sigma > cameras)
    throw Error(Errc::invalid_argument, "sigma (" + std::to_string(sigma) + ") exceeds the camera count (" +
                                            std::to_string(cameras) + ")");
  if (vmc_port && vmc_host.empty()) throw Error(Errc::invalid_argument, "config.vmc_host must name a host");
  detector.validate();
}

Session::Session(const SessionConfig& config, Calibration calib)
    : config_(config), calib_(std::move(calib)), layout_(nullptr) {
  const int cams = static_cast<int>(calib_.size());
  if (cams < 2) throw Error(Errc::not_enough_views, "a session needs at least 2 cameras, the calibration has " +
                                                        std::to_string(cams));
  if (cams > 64) throw Error(Errc::invalid_argument, "at most 64 cameras are supported");
  config_.validate(cams);
  layout_ = &layout(config_.layout);
  auto keypoint = [&](const char* name) {
    for (size_t k = 0; k < layout_->keypoints.size(); ++k)
      if (std::string(layout_->keypoints[k]) == name) return static_cast<int>(k);
    return -1;
  };
  nose_ = keypoint("Nose"), l_eye_ = keypoint("LEye"), r_eye_ = keypoint("REye");
  l_ear_ = keypoint("LEar"), r_ear_ = keypoint("REar");
  r_index_ = keypoint("RIndex"), r_pinky_ = keypoint("RPinky"), l_index_ = keypoint("LIndex"), l_pinky_ = keypoint("LPinky");
  sigma_ = config_.sigma > 0 ? config_.sigma : std::max(2, cams - 1);
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
  view_order_ = std::make_unique<ViewOrderCheck>(calib_, config_.min_confidence, config_.outlier_threshold_px);
  const size_t K = layout_->keypoints.size();
  single_ = new_person_state();
  if (config_.max_people != 1) tracks_ = std::make_unique<PersonTracks>(*layout_);
  frame_.blank.keypoints.assign(K, PointResult{});
  frame_.layout = config_.layout;
  frame_.view_count = static_cast<uint32_t>(cams);
  frame_.definition_counter = next_definition_counter();
  frame_.info.frame_index = config_.first_frame_index - 1;
  if (config_.publish) {
#ifdef OCTOCAP_HAVE_DDS
    StreamConfig stream = config_.stream;
    stream.several_people = config_.max_people != 1;
    sinks_.push_back(std::make_unique<DdsPublisher>(stream, config_.layout, frame_.definition_counter));
#else
    throw Error(Errc::unsupported, "this build of octocap has no DDS streaming (OCTOCAP_WITH_DDS=OFF)");
#endif
  }
  if (config_.vmc_port != 0) {
#ifdef OCTOCAP_HAVE_DDS
    // A receiver per person: ports vmc_port .. vmc_port + max_people - 1.
    const uint32_t slots = config_.max_people == 0 ? kMaxPeople : config_.max_people;
    sinks_.push_back(std::make_unique<VmcSender>(config_.vmc_host, config_.vmc_port, slots));
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

Session::PersonState Session::new_person_state() const {
  PersonState st;
  st.filters.assign(layout_->keypoints.size(), OneEuroFilter3(config_.filter_min_cutoff, config_.filter_beta));
  st.noise_px.assign(layout_->keypoints.size(), 0.0);
  return st;
}

void Session::reset() {
  single_ = new_person_state();
  if (tracks_) tracks_->reset();
  states_.clear();
  last_timestamp_us_ = 0;
  has_timestamp_ = false;
  solved_any_ = false;
  whole_people_.clear();
  const int64_t last = frame_.info.frame_index;
  frame_.info = FrameInfo{};
  frame_.info.frame_index = last;  // numbering goes on: a stream's readers must not see a restart
  clear_frame();
}

void Session::clear_frame() {
  frame_.people.clear();
  frame_.blank = PersonResult{};
  frame_.blank.keypoints.assign(layout_->keypoints.size(), PointResult{});
  frame_.blank.selected.assign(calib_.size(), -1);
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
  // Once per session, over its first frames with people: said as a warning, the solve goes on as told.
  if (view_order_->add(usable) && !view_order_->verdict().empty()) log(LogLevel::warning, view_order_->verdict());
  // In double: the difference of two extreme int64 timestamps overflows int64.
  const double dt = has_timestamp_
                        ? (static_cast<double>(timestamp_us) - static_cast<double>(last_timestamp_us_)) * 1e-6
                        : 0.0;
  has_timestamp_ = true;
  ++frame_.info.frame_index;
  solved_any_ = true;
  frame_.info.timestamp_us = timestamp_us;
  last_timestamp_us_ = timestamp_us;
  frame_.info.keypoints_total = static_cast<uint32_t>(K);
  clear_frame();
  if (config_.max_people == 1)
    solve_one(usable, original, dt);
  else
    solve_several(usable, original, dt, timestamp_us);

  // The frame as a whole: every person's keypoints; the views that hold anyone (the blank person keeps a one-person
  // selection that solved nobody).
  uint32_t solved = 0;
  double err = 0;
  std::vector<bool> seen(V, false);
  auto mark_views = [&](const PersonResult& p) {
    for (size_t v = 0; v < p.selected.size() && v < V; ++v)
      if (p.selected[v] >= 0) seen[v] = true;
  };
  mark_views(frame_.blank);
  for (const PersonResult& p : frame_.people) {
    solved += p.keypoints_solved;
    err += p.mean_reprojection_error_px * p.keypoints_solved;
    mark_views(p);
  }
  frame_.info.keypoints_solved = solved;
  frame_.info.mean_reprojection_error_px = solved ? err / solved : 0;
  frame_.info.views_with_person = static_cast<uint32_t>(std::count(seen.begin(), seen.end(), true));
  frame_.info.solve_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  publish();
  return frame_.has_person();
}

void Session::solve_one(const std::vector<std::vector<Person2D>>& usable, const std::vector<std::vector<int>>& original,
                        double dt) {
  const size_t V = calib_.size();
  const std::vector<int> choice =
      select_people(calib_, usable, single_.raw_previous, {config_.min_confidence, 2 * config_.outlier_threshold_px});
  PersonResult& blank = frame_.blank;
  uint32_t with_person = 0;
  for (size_t v = 0; v < V; ++v) {
    with_person += choice[v] >= 0;
    blank.selected[v] = choice[v] >= 0 ? original[v][choice[v]] : -1;  // indices into the caller's list
  }
  blank.views_with_person = with_person;
  if (with_person < static_cast<uint32_t>(config_.min_views)) {
    single_.raw_previous.clear();
    for (auto& f : single_.filters) f.reset();
    single_.feet.reset();
    return;
  }
  PersonResult person = blank;
  person.keypoints = solve_points(usable, choice);
  finish_person(person, single_, dt);
  if (person.has_pose()) frame_.people.push_back(std::move(person));
}

void Session::solve_several(const std::vector<std::vector<Person2D>>& usable,
                            const std::vector<std::vector<int>>& original, double dt, int64_t timestamp_us) {
  const size_t V = calib_.size();
  AssociationParams params;
  params.min_confidence = config_.min_confidence;
  params.threshold_px = 2 * config_.outlier_threshold_px;
  params.min_views = config_.min_views;
  params.birth_views = std::min(3, static_cast<int>(V));
  params.max_people = config_.max_people == 0 ? kMaxPeople : config_.max_people;
  params.volume = volume_;
  const std::vector<PersonCluster> clusters = associate_people(calib_, usable, tracks_->priors(timestamp_us), params);

  std::vector<PersonResult> people;
  std::vector<std::vector<Eigen::Vector3d>> raw;
  std::vector<int> prior_of;
  for (const PersonCluster& c : clusters) {
    PersonResult p;
    p.keypoints = solve_points(usable, c.choice);
    std::vector<Eigen::Vector3d> pose = raw_pose(p.keypoints);
    const auto solved = std::count_if(pose.begin(), pose.end(), [](const Eigen::Vector3d& x) { return x.allFinite(); });
    if (solved < 3) continue;  // the views agreed on too little of a body to call it a person
    p.selected.assign(V, -1);
    for (size_t v = 0; v < V; ++v)
      if (c.choice[v] >= 0) p.selected[v] = original[v][c.choice[v]], ++p.views_with_person;
    people.push_back(std::move(p));
    raw.push_back(std::move(pose));
    prior_of.push_back(c.prior);
  }
  const std::vector<uint32_t> ids = tracks_->update(raw, prior_of, timestamp_us);
  for (uint32_t gone : tracks_->forgotten()) states_.erase(gone);
  for (size_t i = 0; i < people.size(); ++i) {
    people[i].id = ids[i];
    auto [it, fresh] = states_.try_emplace(ids[i]);
    if (fresh) it->second = new_person_state();
    finish_person(people[i], it->second, dt);
  }
  // Tracks not seen this frame: their filters start again when they come back (as the one person's do).
  for (auto& [id, state] : states_)
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) {
      for (auto& f : state.filters) f.reset();
      state.feet.reset();
    }
  std::sort(people.begin(), people.end(), [](const PersonResult& a, const PersonResult& b) { return a.id < b.id; });
  frame_.people = std::move(people);
}

std::vector<PointResult> Session::solve_points(const std::vector<std::vector<Person2D>>& usable,
                                               const std::vector<int>& choice) const {
  const size_t V = calib_.size(), K = layout_->keypoints.size();
  std::vector<PointResult> points(K);
  pool_->parallel_for(K, [&](size_t k) {
    std::vector<ViewRay> rays;
    rays.reserve(V);
    for (size_t v = 0; v < V; ++v) {
      if (choice[v] < 0) continue;
      const Keypoint2D& kp = usable[v][choice[v]][k];
      if (!(kp.confidence >= config_.min_confidence) || !std::isfinite(kp.x) || !std::isfinite(kp.y)) continue;
      rays.push_back(make_view_ray(calib_[v], static_cast<int>(v), {kp.x, kp.y}, kp.confidence));
    }
    PointResult r = solve_keypoint(rays);
    // Never a NaN marked valid: a degenerate camera (an absurd rotation in a calibration) makes the point missing.
    if (r.valid && (!r.position.allFinite() || !std::isfinite(r.reprojection_error_px) ||
                    r.position.cwiseAbs().maxCoeff() > 1e6))
      r = PointResult{};
    points[k] = r;
  });
  return points;
}

std::vector<Eigen::Vector3d> Session::raw_pose(const std::vector<PointResult>& keypoints) {
  std::vector<Eigen::Vector3d> pose(keypoints.size(), Eigen::Vector3d::Constant(std::nan("")));
  for (size_t k = 0; k < pose.size(); ++k)
    if (keypoints[k].valid) pose[k] = keypoints[k].position;
  return pose;
}

namespace {

// The adaptive filter: the noise a keypoint's reprojection error shows at the fixed filter's tuning point (3 px of
// detection noise on 4 views), how fast the estimate follows, and the cutoff's range. The cutoff goes as the 4th power
// of (tuned / measured) noise: 1 / noise (a steady-state Kalman filter's law) and its square still lagged at 1 px
// (5.6 and 4.6 mm against 3.2 unfiltered, octocap_bench_solve --filter). Never below the fixed cutoff: reprojection
// error also carries the views' disagreement, which is no jitter.
constexpr double kTunedNoisePx = 3.0, kNoiseFollow = 0.1, kMinScale = 1, kMaxScale = 100;

}  // namespace

double Session::noise_cutoff_scale(const PointResult& r, double& noise_px) const {
  if (!config_.filter_adaptive) return 1.0;
  const double e = std::max(r.reprojection_error_px, 0.05);
  noise_px = noise_px > 0 ? noise_px + kNoiseFollow * (e - noise_px) : e;
  const double ratio = kTunedNoisePx / noise_px;
  return std::clamp(ratio * ratio * ratio * ratio, kMinScale, kMaxScale);
}

void Session::finish_person(PersonResult& person, PersonState& state, double dt) const {
  const size_t K = person.keypoints.size();
  state.raw_previous = raw_pose(person.keypoints);
  uint32_t solved = 0;
  double err = 0;
  for (size_t k = 0; k < K; ++k) {
    PointResult& r = person.keypoints[k];
    if (!r.valid) {
      state.filters[k].reset();
      continue;
    }
    ++solved;
    err += r.reprojection_error_px;
    if (config_.filter) r.position = state.filters[k].filter(r.position, dt, noise_cutoff_scale(r, state.noise_px[k]));
  }
  person.keypoints_solved = solved;
  person.mean_reprojection_error_px = solved ? err / solved : 0;

  std::array<const std::vector<int>*, kJointCount> sources{};  // the keypoints each joint was made of
  for (int j = 0; j < kJointCount; ++j) {
    const std::vector<int>* alternative = first_present_alternative(
        layout_->joint_sources[j], [&](int k) { return person.keypoints[k].valid; });
    if (!alternative) continue;
    sources[j] = alternative;
    PointResult out;
    out.valid = true;
    out.confidence = 1e9;
    out.views_used = 1u << 31;
    for (int k : *alternative) {
      const PointResult& r = person.keypoints[k];
      out.position += r.position / static_cast<double>(alternative->size());
      out.reprojection_error_px += r.reprojection_error_px / static_cast<double>(alternative->size());
      out.confidence = std::min(out.confidence, r.confidence);
      out.views_used = std::min(out.views_used, r.views_used);
      out.view_mask |= r.view_mask;
    }
    person.joints[j] = out;
  }
  SkeletonJoints rig_joints;
  for (int j = 0; j < kJointCount; ++j) {
    if (!person.joints[j].valid) {
      rig_joints[j] = Eigen::Vector3d::Constant(std::nan(""));
      continue;
    }
    rig_joints[j] = z_up_ ? zup_to_yup(person.joints[j].position) : person.joints[j].position;
  }
  auto rig_point = [&](int k) -> Eigen::Vector3d {
    if (k < 0 || !person.keypoints[k].valid) return Eigen::Vector3d::Constant(std::nan(""));
    return z_up_ ? zup_to_yup(person.keypoints[k].position) : person.keypoints[k].position;
  };
  BodyCues cues;
  cues.head_across = rig_point(l_ear_) - rig_point(r_ear_);
  if (!cues.head_across.allFinite()) cues.head_across = rig_point(l_eye_) - rig_point(r_eye_);
  cues.head_forward = rig_point(nose_) - rig_joints[kHead];
  cues.r_palm_across = rig_point(r_index_) - rig_point(r_pinky_);
  cues.l_palm_across = rig_point(l_index_) - rig_point(l_pinky_);
  // Feet: contacts always (engines run their own IK on them); with foot_lock, the planted ankles, their knees and
  // feet go back into the joints, the keypoints they were made of (what TRC and CSV carry) and the bones.
  SkeletonJoints locked = rig_joints;
  const FootContacts contacts = state.feet.apply(locked, dt);
  person.foot_contact = {contacts.right, contacts.left};
  state.lock_shift.clear();
  if (config_.foot_lock) {
    std::vector<bool> moved(K, false);
    for (int j = 0; j < kJointCount; ++j) {
      if (!person.joints[j].valid || locked[j] == rig_joints[j]) continue;
      const Eigen::Vector3d delta = z_up_ ? yup_to_zup(locked[j] - rig_joints[j]) : Eigen::Vector3d(locked[j] - rig_joints[j]);
      person.joints[j].position += delta;
      for (int k : *sources[j]) {
        if (moved[k]) continue;
        person.keypoints[k].position += delta, moved[k] = true;
        if (state.lock_shift.empty()) state.lock_shift.assign(K, Eigen::Vector3d::Zero());
        state.lock_shift[k] = delta;
      }
    }
    rig_joints = locked;
  }
  person.bones = state.bone_solver.solve(rig_joints, cues);
}

void Session::publish() {
  for (auto& sink : sinks_) sink->publish(frame_);
}

}  // namespace octocap::internal
