/**
 * @file octocap.hpp
 * @brief Header-only C++17 wrapper over octocap.h: RAII handles, exceptions for errors, statuses as values.
 *
 * Nothing here adds behaviour: every method is one C call (see octocap.h for what it does, its errors and its
 * thread rules). Errors (negative results) throw octocap::Error carrying the code and octocap_last_error()'s
 * message; normal outcomes come back as values (a solve's status, an empty std::optional on a timeout).
 * @code
 * octocap::Calibration calib = octocap::Calibration::load("calibration.toml");
 * octocap_session_config_t cfg; octocap_session_config_init(&cfg); cfg.layout = OCTOCAP_LAYOUT_COCO_17;
 * octocap::Session session(cfg, calib);
 * if (session.solve_keypoints(keypoints.data(), nullptr, views, t_us) == OCTOCAP_OK)
 *   for (const octocap_bone_pose_t& b : session.frame().bones(0, OCTOCAP_FRAME_UNITY)) ...
 * @endcode
 */
#ifndef OCTOCAP_OCTOCAP_HPP
#define OCTOCAP_OCTOCAP_HPP

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "octocap/octocap.h"

namespace octocap {

/** A failed call: the result code and the library's message. */
class Error : public std::runtime_error {
 public:
  Error(octocap_result_t code, const std::string& message) : std::runtime_error(message), code_(code) {}
  octocap_result_t code() const noexcept { return code_; }

 private:
  octocap_result_t code_;
};

/** Throws Error for an error result (`what` prefixes the message); returns OK and statuses unchanged. */
inline octocap_result_t check(octocap_result_t r, const std::string& what = "") {
  if (OCTOCAP_FAILED(r))
    throw Error(r, (what.empty() ? "" : what + ": ") + octocap_last_error() + " (" + octocap_result_name(r) + ")");
  return r;
}

namespace detail {
template <class T, void (*Destroy)(T*)>
struct Deleter {
  void operator()(T* p) const noexcept { Destroy(p); }
};
template <class T, void (*Destroy)(T*)>
using Owned = std::unique_ptr<T, Deleter<T, Destroy>>;

// The two-call pattern: ask for the count, then fill.
template <class T, class Call>
std::vector<T> read_array(Call&& call, const char* what) {
  uint32_t n = 0;
  check(call(static_cast<T*>(nullptr), 0u, &n), what);
  std::vector<T> out(n);
  if (n) check(call(out.data(), n, &n), what);
  return out;
}
}  // namespace detail

/** An immutable solved frame (octocap_frame_*). */
class Frame {
 public:
  explicit Frame(octocap_frame_t* f) : f_(f) {}
  const octocap_frame_t* get() const { return f_.get(); }
  octocap_frame_summary_t summary() const {
    octocap_frame_summary_t s{};
    s.struct_size = sizeof s;
    check(octocap_frame_get_summary(f_.get(), &s), "frame summary");
    return s;
  }
  uint32_t person_count() const { return summary().person_count; }
  octocap_person_t person(uint32_t i) const {
    octocap_person_t p{};
    p.struct_size = sizeof p;
    check(octocap_frame_get_person(f_.get(), i, &p), "frame person");
    return p;
  }
  std::vector<octocap_joint_t> keypoints3d(uint32_t person) const {
    return detail::read_array<octocap_joint_t>(
        [&](octocap_joint_t* o, uint32_t c, uint32_t* n) { return octocap_frame_get_keypoints3d(f_.get(), person, o, c, n); },
        "frame keypoints");
  }
  std::vector<octocap_joint_t> joints(uint32_t person) const {
    return detail::read_array<octocap_joint_t>(
        [&](octocap_joint_t* o, uint32_t c, uint32_t* n) { return octocap_frame_get_joints(f_.get(), person, o, c, n); },
        "frame joints");
  }
  std::vector<octocap_bone_pose_t> bones(uint32_t person, octocap_coord_frame_t frame = OCTOCAP_FRAME_RIG) const {
    return detail::read_array<octocap_bone_pose_t>(
        [&](octocap_bone_pose_t* o, uint32_t c, uint32_t* n) {
          return octocap_frame_get_bones(f_.get(), person, frame, o, c, n);
        },
        "frame bones");
  }
  std::vector<int32_t> person_views(uint32_t person) const {
    return detail::read_array<int32_t>(
        [&](int32_t* o, uint32_t c, uint32_t* n) { return octocap_frame_get_person_views(f_.get(), person, o, c, n); },
        "frame person views");
  }

 private:
  detail::Owned<octocap_frame_t, octocap_frame_release> f_;
};

class Calibration {
 public:
  static Calibration load(const std::string& path) {
    octocap_calibration_t* c = nullptr;
    check(octocap_calibration_load(path.c_str(), &c), "loading " + path);
    return Calibration(c);
  }
  explicit Calibration(octocap_calibration_t* c) : c_(c) {}
  const octocap_calibration_t* get() const { return c_.get(); }
  uint32_t camera_count() const {
    uint32_t n = 0;
    check(octocap_calibration_camera_count(c_.get(), &n), "camera count");
    return n;
  }
  octocap_camera_t camera(uint32_t i) const {
    octocap_camera_t cam{};
    check(octocap_calibration_get_camera(c_.get(), i, &cam), "camera");
    return cam;
  }

 private:
  detail::Owned<octocap_calibration_t, octocap_calibration_destroy> c_;
};

class Session {
 public:
  Session(const octocap_session_config_t& cfg, const Calibration& calib) {
    octocap_session_t* s = nullptr;
    check(octocap_session_create(&cfg, calib.get(), &s), "creating the session");
    s_.reset(s);
  }
  octocap_session_t* get() const { return s_.get(); }
  void set_detector(const octocap_detector_config_t& cfg) {
    check(octocap_session_set_detector(s_.get(), &cfg), "setting the detector");
  }
  /** ::OCTOCAP_OK or ::OCTOCAP_STATUS_NO_PERSON; throws for errors. */
  octocap_result_t solve_keypoints(const octocap_keypoint2d_t* keypoints, const uint32_t* people_per_view,
                                   uint32_t views, int64_t timestamp_us) {
    return check(octocap_session_solve_keypoints(s_.get(), keypoints, people_per_view, views, timestamp_us), "solving");
  }
  octocap_result_t solve_images(const octocap_image_t* images, uint32_t views, int64_t timestamp_us) {
    return check(octocap_session_solve_images(s_.get(), images, views, timestamp_us), "solving from images");
  }
  Frame frame() const {
    octocap_frame_t* f = nullptr;
    check(octocap_session_get_frame(s_.get(), &f), "session frame");
    return Frame(f);
  }
  std::vector<octocap_keypoint2d_t> detections(uint32_t view) const {
    return detail::read_array<octocap_keypoint2d_t>(
        [&](octocap_keypoint2d_t* o, uint32_t c, uint32_t* n) { return octocap_session_detections(s_.get(), view, o, c, n); },
        "detections");
  }
  octocap_detect_info_t detect_info() const {
    octocap_detect_info_t d{};
    d.struct_size = sizeof d;
    check(octocap_session_detect_info(s_.get(), &d), "detect info");
    return d;
  }
  octocap_method_t method() const {
    octocap_method_t m = OCTOCAP_METHOD_AUTO;
    check(octocap_session_method(s_.get(), &m), "method");
    return m;
  }
  octocap_up_axis_t up_axis() const {
    octocap_up_axis_t u = OCTOCAP_UP_Y;
    check(octocap_session_up_axis(s_.get(), &u), "up axis");
    return u;
  }
  uint32_t stream_subscribers() const {
    uint32_t n = 0;
    check(octocap_session_stream_subscribers(s_.get(), &n), "stream subscribers");
    return n;
  }
  void flush_stream() { check(octocap_session_flush_stream(s_.get()), "flushing the stream"); }
  void reset() { check(octocap_session_reset(s_.get()), "resetting"); }

 private:
  detail::Owned<octocap_session_t, octocap_session_destroy> s_;
};

class Subscriber {
 public:
  explicit Subscriber(const octocap_subscriber_config_t& cfg) {
    octocap_subscriber_t* s = nullptr;
    check(octocap_subscriber_create(&cfg, &s), "subscribing");
    s_.reset(s);
  }
  /** The next frame, or nothing when none arrived within `timeout_ms`. */
  std::optional<Frame> take(int32_t timeout_ms) {
    octocap_frame_t* f = nullptr;
    if (check(octocap_subscriber_take_frame(s_.get(), timeout_ms, &f), "taking a frame") == OCTOCAP_STATUS_TIMEOUT)
      return std::nullopt;
    return Frame(f);
  }
  octocap_stream_info_t stream_info() const {
    octocap_stream_info_t i{};
    check(octocap_subscriber_get_stream_info(s_.get(), &i), "stream info");
    return i;
  }

 private:
  detail::Owned<octocap_subscriber_t, octocap_subscriber_destroy> s_;
};

/** A live capture (octocap_live_*): cameras in, frames out on library threads. */
class Live {
 public:
  Live(const octocap_live_config_t& cfg, const octocap_session_config_t& session_cfg, const Calibration& calib,
       const std::vector<std::string>& cameras) {
    std::vector<const char*> specs;
    for (const std::string& c : cameras) specs.push_back(c.c_str());
    octocap_live_t* l = nullptr;
    check(octocap_live_create(&cfg, &session_cfg, calib.get(), specs.data(), static_cast<uint32_t>(specs.size()), &l),
          "creating the live capture");
    l_.reset(l);
  }
  octocap_live_t* get() const { return l_.get(); }
  void set_detector(const octocap_detector_config_t& cfg) { check(octocap_live_set_detector(l_.get(), &cfg), "detector"); }
  /** Records the next run into `directory` (octocap_live_set_recording); "" turns it off. */
  void set_recording(const std::string& directory) {
    check(octocap_live_set_recording(l_.get(), directory.c_str()), "recording");
  }
  void start() { check(octocap_live_start(l_.get()), "starting the live capture"); }
  void stop() { check(octocap_live_stop(l_.get()), "stopping the live capture"); }
  /** The next solved frame, or nothing within `timeout_ms`. */
  std::optional<Frame> take(int32_t timeout_ms) {
    octocap_frame_t* f = nullptr;
    if (check(octocap_live_take_frame(l_.get(), timeout_ms, &f), "taking a frame") == OCTOCAP_STATUS_TIMEOUT)
      return std::nullopt;
    return Frame(f);
  }
  octocap_live_stats_t stats() const {
    octocap_live_stats_t s{};
    s.struct_size = sizeof s;
    check(octocap_live_get_stats(l_.get(), &s), "live stats");
    return s;
  }
  octocap_camera_status_t camera(uint32_t index) const {
    octocap_camera_status_t c{};
    c.struct_size = sizeof c;
    check(octocap_live_get_camera_status(l_.get(), index, &c), "camera status");
    return c;
  }

 private:
  detail::Owned<octocap_live_t, octocap_live_destroy> l_;
};

/** A capture node (octocap_node_*): its cameras' 2D keypoints published over DDS for a hub. */
class Node {
 public:
  Node(const octocap_node_config_t& cfg, const std::vector<std::string>& cameras,
       const std::vector<std::string>& names = {}) {
    std::vector<const char*> specs, ids;
    for (const std::string& c : cameras) specs.push_back(c.c_str());
    for (const std::string& n : names) ids.push_back(n.c_str());
    octocap_node_t* n = nullptr;
    check(octocap_node_create(&cfg, specs.data(), names.empty() ? nullptr : ids.data(),
                              static_cast<uint32_t>(specs.size()), &n),
          "creating the capture node");
    n_.reset(n);
  }
  void set_detector(const octocap_detector_config_t& cfg) { check(octocap_node_set_detector(n_.get(), &cfg), "detector"); }
  void start() { check(octocap_node_start(n_.get()), "starting the capture node"); }
  void stop() { check(octocap_node_stop(n_.get()), "stopping the capture node"); }
  octocap_node_stats_t stats() const {
    octocap_node_stats_t s{};
    s.struct_size = sizeof s;
    check(octocap_node_get_stats(n_.get(), &s), "node stats");
    return s;
  }
  octocap_camera_status_t camera(uint32_t index) const {
    octocap_camera_status_t c{};
    c.struct_size = sizeof c;
    check(octocap_node_get_camera_status(n_.get(), index, &c), "camera status");
    return c;
  }

 private:
  detail::Owned<octocap_node_t, octocap_node_destroy> n_;
};

class Recording {
 public:
  Recording(const std::string& dir, octocap_layout_t layout = OCTOCAP_LAYOUT_AUTO) {
    octocap_recording_t* r = nullptr;
    check(octocap_recording_open(dir.c_str(), layout, &r), "opening " + dir);
    r_.reset(r);
  }
  octocap_recording_t* get() const { return r_.get(); }
  uint32_t view_count() const {
    uint32_t n = 0;
    check(octocap_recording_view_count(r_.get(), &n), "view count");
    return n;
  }
  uint32_t frame_count() const {
    uint32_t n = 0;
    check(octocap_recording_frame_count(r_.get(), &n), "frame count");
    return n;
  }
  octocap_layout_t layout() const {
    octocap_layout_t l = OCTOCAP_LAYOUT_AUTO;
    check(octocap_recording_layout(r_.get(), &l), "layout");
    return l;
  }
  /** Frame `frame` into `keypoints` (grown as needed) and `people` (one count per view). */
  void read_frame(uint32_t frame, std::vector<octocap_keypoint2d_t>& keypoints, std::vector<uint32_t>& people) {
    people.resize(view_count());
    uint32_t needed = 0;
    octocap_result_t r = octocap_recording_read_frame(r_.get(), frame, keypoints.data(),
                                                      static_cast<uint32_t>(keypoints.size()), &needed, people.data(),
                                                      static_cast<uint32_t>(people.size()));
    if (r == OCTOCAP_ERROR_BUFFER_TOO_SMALL || (r == OCTOCAP_OK && keypoints.empty() && needed > 0)) {
      keypoints.resize(needed);
      r = octocap_recording_read_frame(r_.get(), frame, keypoints.data(), needed, &needed, people.data(),
                                       static_cast<uint32_t>(people.size()));
    }
    check(r, "reading frame " + std::to_string(frame));
  }

 private:
  detail::Owned<octocap_recording_t, octocap_recording_destroy> r_;
};

/** A file written on close(); destroyed without close() (an exception on the way) it writes nothing. */
class MotionWriter {
 public:
  MotionWriter(const std::string& path, octocap_motion_format_t format, octocap_layout_t layout, octocap_up_axis_t up,
               double rate_hz) {
    octocap_motion_writer_t* w = nullptr;
    check(octocap_motion_writer_create(path.c_str(), format, layout, up, rate_hz, &w), path);
    w_.reset(w);
  }
  void add(const Frame& frame, uint32_t person = 0) { check(octocap_motion_writer_add(w_.get(), frame.get(), person), "writing a frame"); }
  void add_empty() { check(octocap_motion_writer_add_empty_frame(w_.get()), "writing a frame"); }
  void add_empty(int64_t timestamp_us) {
    check(octocap_motion_writer_add_empty_frame_at(w_.get(), timestamp_us), "writing a frame");
  }
  void set_journal(const std::string& path) {
    check(octocap_motion_writer_set_journal(w_.get(), path.c_str()), "journal " + path);
  }
  void close() { check(octocap_motion_writer_close(w_.release()), "writing the file"); }

 private:
  detail::Owned<octocap_motion_writer_t, octocap_motion_writer_discard> w_;
};

class Motion {
 public:
  explicit Motion(const std::string& path) {
    octocap_motion_t* m = nullptr;
    check(octocap_motion_open(path.c_str(), &m), "opening " + path);
    m_.reset(m);
  }
  uint32_t frame_count() const {
    uint32_t n = 0;
    check(octocap_motion_info(m_.get(), &n, nullptr), "motion info");
    return n;
  }
  double rate_hz() const {
    double r = 0;
    check(octocap_motion_info(m_.get(), nullptr, &r), "motion info");
    return r;
  }
  Frame frame(uint32_t index) const {
    octocap_frame_t* f = nullptr;
    check(octocap_motion_get_frame(m_.get(), index, &f), "motion frame");
    return Frame(f);
  }

 private:
  detail::Owned<octocap_motion_t, octocap_motion_destroy> m_;
};

class Detector {
 public:
  explicit Detector(const octocap_detector_config_t& cfg) {
    octocap_detector_t* d = nullptr;
    check(octocap_detector_create(&cfg, &d), "loading the detector");
    d_.reset(d);
  }
  void run(const octocap_image_t* images, uint32_t count) { check(octocap_detector_run(d_.get(), images, count), "detecting"); }
  uint32_t people(uint32_t view) const {
    uint32_t n = 0;
    check(octocap_detector_people(d_.get(), view, &n), "people");
    return n;
  }
  std::vector<octocap_keypoint2d_t> keypoints(uint32_t view, uint32_t person) const {
    return detail::read_array<octocap_keypoint2d_t>(
        [&](octocap_keypoint2d_t* o, uint32_t c, uint32_t* n) { return octocap_detector_keypoints(d_.get(), view, person, o, c, n); },
        "keypoints");
  }
  octocap_detect_info_t info() const {
    octocap_detect_info_t i{};
    i.struct_size = sizeof i;
    check(octocap_detector_info(d_.get(), &i), "detector info");
    return i;
  }

 private:
  detail::Owned<octocap_detector_t, octocap_detector_destroy> d_;
};

// A recorded take's pictures (a folder of videos, or of picture folders, one per camera), frame by frame.
class TakeReader {
 public:
  explicit TakeReader(const std::string& folder) {
    octocap_take_reader_t* r = nullptr;
    check(octocap_take_reader_open(folder.c_str(), &r), "opening the take");
    r_.reset(r);
    info_.struct_size = sizeof info_;
    check(octocap_take_reader_info(r_.get(), &info_), "take info");
  }
  uint32_t camera_count() const { return info_.camera_count; }
  uint32_t frame_count() const { return info_.frame_count; }
  double fps() const { return info_.frames_per_second; }
  std::string camera_name(uint32_t camera) const {
    const char* name = nullptr;
    check(octocap_take_reader_camera_name(r_.get(), camera, &name), "camera name");
    return name;
  }
  // Every camera's picture of `frame`, borrowed from the reader until the next read().
  const std::vector<octocap_image_t>& read(uint32_t frame) {
    images_.resize(info_.camera_count);
    uint32_t n = 0;
    check(octocap_take_reader_read(r_.get(), frame, images_.data(), static_cast<uint32_t>(images_.size()), &n),
          "reading the take");
    return images_;
  }

 private:
  detail::Owned<octocap_take_reader_t, octocap_take_reader_destroy> r_;
  octocap_take_info_t info_{};
  std::vector<octocap_image_t> images_;
};

}  // namespace octocap

#endif  // OCTOCAP_OCTOCAP_HPP
