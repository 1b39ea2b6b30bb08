#include "solve_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "check.h"
#include "debug_draw.h"
#include "ground_truth.h"
#include "image_source.h"
#include "octocap/octocap.h"

namespace {

template <class T, void (*Destroy)(T*)>
struct Deleter {
  void operator()(T* p) const { Destroy(p); }
};
using CalibPtr = std::unique_ptr<octocap_calibration_t, Deleter<octocap_calibration_t, octocap_calibration_destroy>>;
using SessionPtr = std::unique_ptr<octocap_session_t, Deleter<octocap_session_t, octocap_session_destroy>>;
using RecordingPtr = std::unique_ptr<octocap_recording_t, Deleter<octocap_recording_t, octocap_recording_destroy>>;

// Closing writes the file, and can fail: done explicitly on success; on an error path it only frees.
void discard_writer(octocap_motion_writer_t* w) { octocap_motion_writer_close(w); }
using WriterPtr = std::unique_ptr<octocap_motion_writer_t, Deleter<octocap_motion_writer_t, discard_writer>>;

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

struct Accuracy {
  double sum_mm = 0;
  size_t count = 0;
  std::vector<double> per_keypoint_sum, per_keypoint_n;
};

void log_to_stderr(octocap_log_level_t level, const char* message, void*) {
  static const char* names[] = {"debug", "info", "warning", "error"};
  std::fprintf(stderr, "octocap %s: %s\n", names[level], message);
}

// Each view with what the detector found and where the solved 3D keypoints reproject.
void write_debug_images(octocap_session_t* session, const octocap_calibration_t* calib, std::vector<cv::Mat>& images,
                        octocap_layout_t layout, uint32_t K, bool solved, const std::string& dir, uint32_t frame) {
  std::vector<octocap_joint_t> joints(K);
  uint32_t count = 0;
  if (solved) check(octocap_session_get_keypoints3d(session, joints.data(), K, &count), "keypoints");
  for (uint32_t v = 0; v < images.size(); ++v) {
    uint32_t n = 0;
    check(octocap_session_detections(session, v, nullptr, 0, &n), "detections");
    std::vector<octocap_keypoint2d_t> people(n);
    if (n) check(octocap_session_detections(session, v, people.data(), n, &n), "detections");
    draw_detections(images[v], people, K, layout, 0.3f);
    std::vector<cv::Point2d> reprojected;
    for (uint32_t k = 0; solved && k < K; ++k) {
      if (!joints[k].valid) continue;
      const double world[3] = {joints[k].position[0], joints[k].position[1], joints[k].position[2]};
      double px[2];
      if (octocap_calibration_project(calib, v, world, px) == OCTOCAP_OK) reprojected.emplace_back(px[0], px[1]);
    }
    draw_reprojection(images[v], reprojected);
    octocap_camera_t cam;
    check(octocap_calibration_get_camera(calib, v, &cam), "camera");
    cv::imwrite(debug_image_path(dir, cam.name, frame), images[v]);
  }
}

int solve(const SolveOptions& o) {
  octocap_set_log_callback(log_to_stderr, OCTOCAP_LOG_WARNING, nullptr);
  octocap_calibration_t* calib_raw = nullptr;
  check(octocap_calibration_load(o.calibration.c_str(), &calib_raw), "loading the calibration");
  CalibPtr calib(calib_raw);
  uint32_t cameras = 0;
  check(octocap_calibration_camera_count(calib.get(), &cameras), "camera count");

  octocap_layout_t layout = OCTOCAP_LAYOUT_AUTO;
  if (o.layout != "auto") check(octocap_layout_from_name(o.layout.c_str(), &layout), "--layout");
  RecordingPtr rec;
  std::unique_ptr<ImageSource> source;
  uint32_t views = 0, frames = 0;
  if (!o.images.empty()) {
    source = std::make_unique<ImageSource>(o.images);
    views = static_cast<uint32_t>(source->camera_count());
    frames = static_cast<uint32_t>(source->frame_count());
    if (layout == OCTOCAP_LAYOUT_AUTO) layout = OCTOCAP_LAYOUT_COCO_17;  // the shipped models' layout
  } else {
    octocap_recording_t* rec_raw = nullptr;
    check(octocap_recording_open(o.keypoints.c_str(), layout, &rec_raw), "opening the keypoints");
    rec.reset(rec_raw);
    check(octocap_recording_view_count(rec.get(), &views), "view count");
    check(octocap_recording_frame_count(rec.get(), &frames), "frame count");
    check(octocap_recording_layout(rec.get(), &layout), "layout");
  }
  if (o.max_frames) frames = std::min(frames, o.start_frame + o.max_frames);
  const std::string input = o.images.empty() ? o.keypoints : o.images;
  if (views != cameras)
    throw std::runtime_error(input + " has " + std::to_string(views) + (source ? " cameras, " : " camera folders, ") + o.calibration +
                             " has " + std::to_string(cameras) + " cameras");

  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.layout = layout;
  cfg.method = o.method == "triangulation" ? OCTOCAP_METHOD_TRIANGULATION
               : o.method == "subdivision"  ? OCTOCAP_METHOD_SUBDIVISION
                                            : OCTOCAP_METHOD_AUTO;
  cfg.filter = o.filter == "none" ? OCTOCAP_FILTER_NONE : OCTOCAP_FILTER_ONE_EURO;
  cfg.up_axis = o.up == "y" ? OCTOCAP_UP_Y : o.up == "z" ? OCTOCAP_UP_Z : OCTOCAP_UP_AUTO;
  cfg.sigma = o.sigma;
  cfg.delta_m = static_cast<float>(o.delta_mm / 1000.0);
  cfg.worker_threads = o.threads;
  cfg.first_frame_index = o.start_frame;
  cfg.vmc_port = o.vmc_port;
  std::snprintf(cfg.vmc_host, sizeof cfg.vmc_host, "%s", o.vmc_host.c_str());
  if (o.publish) {
    cfg.stream_enable = 1;
    cfg.stream_domain_id = o.domain;
    cfg.stream_qos = o.publish_qos == "record" ? OCTOCAP_QOS_RECORD : OCTOCAP_QOS_LIVE;
    cfg.stream_source_id = o.source_id;
    std::snprintf(cfg.stream_topic, sizeof cfg.stream_topic, "%s", o.topic.c_str());
  }
  cfg.detector = o.detector.config();
  if (!o.debug_images.empty()) std::filesystem::create_directories(o.debug_images);
  octocap_session_t* session_raw = nullptr;
  check(octocap_session_create(&cfg, calib.get(), &session_raw), "creating the session");
  SessionPtr session(session_raw);
  octocap_up_axis_t up = OCTOCAP_UP_Y;
  check(octocap_session_up_axis(session.get(), &up), "up axis");
  octocap_method_t method = OCTOCAP_METHOD_AUTO;
  check(octocap_session_method(session.get(), &method), "method");
  const std::string method_name = method == OCTOCAP_METHOD_TRIANGULATION ? "triangulation" : "subdivision";

  octocap_motion_writer_t* raw = nullptr;
  check(octocap_motion_writer_create(o.output.c_str(), OCTOCAP_MOTION_TRC, layout, up, o.rate_hz, &raw), "--output");
  WriterPtr trc(raw);
  raw = nullptr;
  if (!o.csv.empty())
    check(octocap_motion_writer_create(o.csv.c_str(), OCTOCAP_MOTION_CSV, layout, up, o.rate_hz, &raw), "--csv");
  WriterPtr csv(raw);
  raw = nullptr;
  if (!o.bvh.empty())
    check(octocap_motion_writer_create(o.bvh.c_str(), OCTOCAP_MOTION_BVH, layout, up, o.rate_hz, &raw), "--bvh");
  WriterPtr bvh(raw);
  auto add_frame = [&](bool solved) {
    for (octocap_motion_writer_t* w : {trc.get(), csv.get(), bvh.get()}) {
      if (!w) continue;
      check(solved ? octocap_motion_writer_add_frame(w, session.get()) : octocap_motion_writer_add_empty_frame(w),
            "writing a frame");
    }
  };

  const uint32_t K = octocap_layout_keypoint_count(layout);
  GroundTruth gt;
  std::vector<int> gt_index(K, -1);
  if (!o.ground_truth.empty()) {
    gt = read_ground_truth_csv(o.ground_truth);
    for (uint32_t k = 0; k < K; ++k)
      for (size_t g = 0; g < gt.names.size(); ++g)
        if (gt.names[g] == octocap_layout_keypoint_name(layout, k)) gt_index[k] = static_cast<int>(g);
  }

  std::vector<octocap_keypoint2d_t> buffer(static_cast<size_t>(K) * views * 4);
  std::vector<uint32_t> people(views);
  std::vector<octocap_joint_t> joints(K);
  std::vector<double> errors;
  size_t solved_keypoints = 0, frames_with_result = 0, frames_multi = 0;
  double solve_ms = 0, detect_ms = 0;
  std::string detect_model;
  Accuracy acc;
  acc.per_keypoint_sum.assign(K, 0);
  acc.per_keypoint_n.assign(K, 0);
  if (o.publish && o.wait_subscribers > 0) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    uint32_t readers = 0;
    while (check(octocap_session_stream_subscribers(session.get(), &readers), "stream subscribers"),
           readers < o.wait_subscribers && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (readers < o.wait_subscribers)
      std::fprintf(stderr, "octocap solve: only %u of %u subscribers after 10 s; streaming anyway\n", readers,
                   o.wait_subscribers);
  }
  const auto start = std::chrono::steady_clock::now();
  for (uint32_t f = o.start_frame; f < frames; ++f) {
    if (o.publish || o.vmc_port) {
      // Stream at the recording's own rate, as a live rig would.
      const auto due = start + std::chrono::microseconds(static_cast<int64_t>((f - o.start_frame) * 1e6 / o.rate_hz));
      std::this_thread::sleep_until(due);
    }
    const int64_t t_us = static_cast<int64_t>(std::llround(f * 1e6 / o.rate_hz));
    octocap_result_t r = OCTOCAP_OK;
    std::vector<cv::Mat> images;
    if (source) {
      images = source->read(f);
      std::vector<octocap_image_t> views_c;
      for (const cv::Mat& m : images) views_c.push_back(as_image(m));
      r = octocap_session_solve_images(session.get(), views_c.data(), views, t_us);
      if (r != OCTOCAP_OK && r != OCTOCAP_ERROR_NOT_ENOUGH_VIEWS) check(r, "solving a frame from images");
      octocap_detect_info_t dinfo{};
      dinfo.struct_size = sizeof dinfo;
      check(octocap_session_detect_info(session.get(), &dinfo), "detect info");
      detect_ms += dinfo.total_ms;
      detect_model = dinfo.model;
      bool several = false;
      for (uint32_t v = 0; v < views; ++v) {
        uint32_t n = 0;
        check(octocap_session_detections(session.get(), v, nullptr, 0, &n), "detections");
        several = several || n > K;
      }
      frames_multi += several;
    } else {
      uint32_t needed = 0;
      r = octocap_recording_read_frame(rec.get(), f, buffer.data(), static_cast<uint32_t>(buffer.size()), &needed,
                                       people.data(), views);
      if (r == OCTOCAP_ERROR_BUFFER_TOO_SMALL) {
        buffer.resize(needed);
        r = octocap_recording_read_frame(rec.get(), f, buffer.data(), needed, &needed, people.data(), views);
      }
      check(r, "reading a frame");
      if (std::any_of(people.begin(), people.end(), [](uint32_t n) { return n > 1; })) ++frames_multi;
      r = octocap_session_solve_keypoints(session.get(), buffer.data(), people.data(), views, t_us);
    }
    if (!o.debug_images.empty() && source)
      write_debug_images(session.get(), calib.get(), images, layout, K, r == OCTOCAP_OK, o.debug_images, f);
    octocap_frame_info_t info;
    check(octocap_session_get_frame_info(session.get(), &info), "frame info");
    solve_ms += info.solve_ms;
    if (r == OCTOCAP_ERROR_NOT_ENOUGH_VIEWS) {
      add_frame(false);
    } else {
      check(r, "solving a frame");
      ++frames_with_result;
      uint32_t count = 0;
      check(octocap_session_get_keypoints3d(session.get(), joints.data(), K, &count), "keypoints");
      for (uint32_t k = 0; k < K; ++k) {
        if (!joints[k].valid) continue;
        ++solved_keypoints;
        errors.push_back(joints[k].reprojection_error_px);
        if (gt_index[k] >= 0 && f < gt.frames.size()) {
          const auto& g = gt.frames[f][gt_index[k]];
          if (std::isnan(g[0])) continue;
          const double d = std::sqrt(std::pow(joints[k].position[0] - g[0], 2) +
                                     std::pow(joints[k].position[1] - g[1], 2) +
                                     std::pow(joints[k].position[2] - g[2], 2)) * 1000.0;
          acc.sum_mm += d;
          ++acc.count;
          acc.per_keypoint_sum[k] += d;
          acc.per_keypoint_n[k] += 1;
        }
      }
      add_frame(true);
    }
    if (!o.quiet && frames >= 50 && (f + 1) % std::max(1u, frames / 10) == 0)
      std::fprintf(stderr, "\r  frame %u / %u", f + 1, frames);
  }
  if (!o.quiet && frames >= 50) std::fprintf(stderr, "\n");
  if (o.publish) {
    check(octocap_session_flush_stream(session.get()), "flushing the stream");
    std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<int64_t>(o.linger_s * 1000)));
  }
  const double total_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  check(octocap_motion_writer_close(trc.release()), "writing the TRC");
  if (csv) check(octocap_motion_writer_close(csv.release()), "writing the CSV");
  if (bvh) check(octocap_motion_writer_close(bvh.release()), "writing the BVH");

  const uint32_t done = frames > o.start_frame ? frames - o.start_frame : 0;  // frames this run solved
  double mean_err = 0;
  for (double e : errors) mean_err += e;
  mean_err = errors.empty() ? NAN : mean_err / errors.size();
  std::printf("octocap solve: %u frames x %u cameras, layout %s (%u keypoints), method %s, filter %s, up %s\n",
              frames, views, octocap_layout_name(layout), K, method_name.c_str(), o.filter.c_str(),
              up == OCTOCAP_UP_Z ? "Z" : "Y");
  std::printf("  frames solved:        %zu / %u (%zu with several people in a view)\n", frames_with_result, done,
              frames_multi);
  std::printf("  keypoints solved:     %zu / %zu (%.1f%%)\n", solved_keypoints, static_cast<size_t>(done) * K,
              done ? 100.0 * solved_keypoints / (static_cast<double>(done) * K) : 0.0);
  std::printf("  reprojection error:   mean %.2f px, median %.2f px\n", mean_err, median(errors));
  std::printf("  3D solve time:        %.3f ms/frame; end to end (JSON parsing included) %.2f ms/frame, %.0f frames/s%s\n",
              done ? solve_ms / done : 0.0, done ? total_ms / done : 0.0,
              total_ms > 0 ? done * 1000.0 / total_ms : 0.0,
              o.publish || o.vmc_port ? " (paced at --rate for streaming)" : "");
  if (source)
    std::printf("  2D detection:         %.1f ms/frame, model %s, mode %s (ONNX Runtime %s)\n",
                done ? detect_ms / done : 0.0, detect_model.c_str(), o.detector.mode.c_str(),
                octocap_onnxruntime_version());
  if (!o.ground_truth.empty()) {
    std::printf("  accuracy vs %s: MPJPE %.1f mm over %zu keypoint observations\n", o.ground_truth.c_str(),
                acc.count ? acc.sum_mm / acc.count : NAN, acc.count);
    double worst = 0;
    int worst_k = -1;
    for (uint32_t k = 0; k < K; ++k)
      if (acc.per_keypoint_n[k] > 0 && acc.per_keypoint_sum[k] / acc.per_keypoint_n[k] > worst) {
        worst = acc.per_keypoint_sum[k] / acc.per_keypoint_n[k];
        worst_k = static_cast<int>(k);
      }
    if (worst_k >= 0)
      std::printf("  worst keypoint:       %s, %.1f mm mean\n", octocap_layout_keypoint_name(layout, worst_k), worst);
  }
  std::printf("  wrote %s%s%s%s%s\n", o.output.c_str(), o.csv.empty() ? "" : ", ", o.csv.c_str(),
              o.bvh.empty() ? "" : ", ", o.bvh.c_str());
  return 0;
}

}  // namespace

int run_solve(const SolveOptions& options) {
  try {
    return solve(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "octocap solve: error: %s\n", e.what());
    return 1;
  }
}

int run_layouts() {
  for (octocap_layout_t l : {OCTOCAP_LAYOUT_BODY_25, OCTOCAP_LAYOUT_BODY_25B, OCTOCAP_LAYOUT_COCO_17,
                             OCTOCAP_LAYOUT_HALPE_26}) {
    std::printf("%s (%u keypoints):", octocap_layout_name(l), octocap_layout_keypoint_count(l));
    for (uint32_t k = 0; k < octocap_layout_keypoint_count(l); ++k) std::printf(" %s", octocap_layout_keypoint_name(l, k));
    std::printf("\n");
  }
  return 0;
}
