#include "solve_command.h"

#include "command_main.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "debug_draw.h"
#include "ground_truth.h"
#include "take_writers.h"
#include "octocap/octocap.hpp"

namespace {

using octocap::check;

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

// Each view with what the detector found and where the solved 3D keypoints reproject.
void write_debug_images(const octocap::Session& session, const octocap_calibration_t* calib,
                        const std::vector<octocap_image_t>& images, octocap_layout_t layout, uint32_t K, const octocap::Frame& frame_3d,
                        const std::string& dir, uint32_t frame) {
  const bool solved = frame_3d.person_count() > 0;
  std::vector<octocap_joint_t> joints;
  if (solved) joints = frame_3d.keypoints3d(0);
  for (uint32_t v = 0; v < images.size(); ++v) {
    cv::Mat picture = drawable_copy(images[v]);
    draw_detections(picture, session.detections(v), K, layout, 0.3f);
    std::vector<cv::Point2d> reprojected;
    for (uint32_t k = 0; solved && k < K; ++k) {
      if (!joints[k].valid) continue;
      const double world[3] = {joints[k].position[0], joints[k].position[1], joints[k].position[2]};
      double px[2];
      if (octocap_calibration_project(calib, v, world, px) == OCTOCAP_OK) reprojected.emplace_back(px[0], px[1]);
    }
    draw_reprojection(picture, reprojected);
    octocap_camera_t cam;
    check(octocap_calibration_get_camera(calib, v, &cam), "camera");
    cv::imwrite(debug_image_path(dir, cam.name, frame), picture);
  }
}

int solve(const SolveOptions& o) {
  octocap_set_log_callback(print_library_log, OCTOCAP_LOG_WARNING, nullptr);
  check_rate_option(o.rate_hz, true);
  const octocap::Calibration calib = octocap::Calibration::load(o.calibration);
  const uint32_t cameras = calib.camera_count();

  octocap_layout_t layout = OCTOCAP_LAYOUT_AUTO;
  if (o.layout != "auto") check(octocap_layout_from_name(o.layout.c_str(), &layout), "--layout");
  std::optional<octocap::Recording> rec;
  std::unique_ptr<octocap::TakeReader> source;
  uint32_t views = 0, frames = 0;
  if (!o.images.empty()) {
    if (!o.sync.empty()) throw std::runtime_error("--sync applies to --keypoints (run octocap detect first)");
    source = std::make_unique<octocap::TakeReader>(o.images);
    views = source->camera_count();
    frames = source->frame_count();
    if (layout == OCTOCAP_LAYOUT_AUTO)  // the model's, from its card (the network is loaded once, by the session)
      octocap::check(octocap_model_layout(o.detector.config().model, &layout), "--model");
  } else {
    rec.emplace(o.keypoints, layout);
    if (!o.sync.empty()) {
      std::vector<double> offsets(cameras);
      octocap::check(octocap_sync_load(o.sync.c_str(), calib.get(), offsets.data(), cameras, nullptr), "--sync");
      octocap::check(octocap_recording_set_sync(rec->get(), offsets.data(), cameras), "--sync");
    }
    views = rec->view_count();
    frames = rec->frame_count();
    layout = rec->layout();
  }
  // The take's rate: --rate, else the videos' own (a 60 fps take written at 30 Hz plays twice as slow), else 30.
  const double rate_hz = o.rate_hz > 0 ? o.rate_hz : source && source->fps() > 0 ? source->fps() : 30.0;
  if (o.start_frame >= frames)
    throw std::runtime_error("--start-frame " + std::to_string(o.start_frame) + " is past the last frame (" +
                             std::to_string(frames) + " frames)");
  // 64-bit: a --start-frame + --frames that would wrap 32 bits is clamped to the take, not wrapped.
  if (o.max_frames) frames = static_cast<uint32_t>(std::min<uint64_t>(frames, uint64_t{o.start_frame} + o.max_frames));
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
  cfg.filter = o.filter == "none"            ? OCTOCAP_FILTER_NONE
                : o.filter == "oneeuro-fixed" ? OCTOCAP_FILTER_ONE_EURO_FIXED
                                              : OCTOCAP_FILTER_ONE_EURO;
  cfg.up_axis = o.up == "y" ? OCTOCAP_UP_Y : o.up == "z" ? OCTOCAP_UP_Z : OCTOCAP_UP_AUTO;
  cfg.sigma = o.sigma;
  cfg.delta_m = static_cast<float>(o.delta_mm / 1000.0);
  cfg.worker_threads = o.threads;
  cfg.first_frame_index = o.start_frame;
  cfg.max_people = max_people_of(o.people);
  cfg.foot_lock = o.foot_lock ? 1 : 0;
  const bool several = cfg.max_people != 1;
  apply_outputs(o.out, cfg);
  if (!o.debug_images.empty()) std::filesystem::create_directories(o.debug_images);
  octocap::Session session(cfg, calib);
  if (source) session.set_detector(o.detector.config());
  const octocap_up_axis_t up = session.up_axis();
  const std::string method_name = session.method() == OCTOCAP_METHOD_TRIANGULATION ? "triangulation" : "subdivision";

  // Each file is written when closed at the end; a take that fails on the way leaves none behind.
  TakeWriters writers(o.output, o.csv, o.bvh, layout, up, rate_hz, several);

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
  std::vector<size_t> people_histogram;               // frames with 0, 1, 2, ... people
  std::map<uint32_t, std::vector<double>> person_errors;  // per person id: reprojection errors
  size_t solved_keypoints = 0, frames_with_result = 0, frames_multi = 0;
  double solve_ms = 0, detect_ms = 0, read_ms = 0, inference_ms = 0, track_ms = 0;
  size_t inferences = 0, views_tracked = 0;
  std::string detect_model;
  octocap_detect_mode_t detect_mode = OCTOCAP_DETECT_CROP;
  std::string detect_runtime;
  Accuracy acc;
  acc.per_keypoint_sum.assign(K, 0);
  acc.per_keypoint_n.assign(K, 0);
  if (o.out.publish && o.wait_subscribers > 0) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    uint32_t readers = 0;
    while ((readers = session.stream_subscribers()) < o.wait_subscribers && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (readers < o.wait_subscribers)
      std::fprintf(stderr, "octocap solve: only %u of %u subscribers after 10 s; streaming anyway\n", readers,
                   o.wait_subscribers);
  }
  const auto start = std::chrono::steady_clock::now();
  for (uint32_t f = o.start_frame; f < frames; ++f) {
    if (o.out.publish || o.out.vmc_port) {
      // Stream at the recording's own rate, as a live rig would.
      const auto due = start + std::chrono::microseconds(static_cast<int64_t>((f - o.start_frame) * 1e6 / rate_hz));
      std::this_thread::sleep_until(due);
    }
    const int64_t t_us = static_cast<int64_t>(std::llround(f * 1e6 / rate_hz));
    octocap_result_t r = OCTOCAP_OK;  // or OCTOCAP_STATUS_NO_PERSON
    const std::vector<octocap_image_t>* images = nullptr;
    if (source) {
      const auto read_start = std::chrono::steady_clock::now();
      images = &source->read(f);
      read_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - read_start).count();
      r = session.solve_images(images->data(), views, t_us);
      const octocap_detect_info_t dinfo = session.detect_info();
      detect_ms += dinfo.total_ms;
      inference_ms += dinfo.inference_ms;
      track_ms += dinfo.track_ms;
      inferences += dinfo.inferences;
      views_tracked += dinfo.views_tracked;
      detect_model = dinfo.model;
      detect_mode = dinfo.mode;
      detect_runtime = runtime_description(dinfo);
      bool crowded = false;
      for (uint32_t v = 0; v < views; ++v) crowded = crowded || session.detections(v).size() > K;
      frames_multi += crowded;
    } else {
      rec->read_frame(f, buffer, people);
      if (std::any_of(people.begin(), people.end(), [](uint32_t n) { return n > 1; })) ++frames_multi;
      r = session.solve_keypoints(buffer.data(), people.data(), views, t_us);
    }
    const octocap::Frame frame = session.frame();
    if (!o.debug_images.empty() && source)
      write_debug_images(session, calib.get(), *images, layout, K, frame, o.debug_images, f);
    solve_ms += frame.summary().solve_ms;
    const uint32_t present = frame.person_count();
    writers.add(frame);
    if (present >= people_histogram.size()) people_histogram.resize(present + 1, 0);
    ++people_histogram[present];
    for (uint32_t i = 0; i < present; ++i) {
      joints = frame.keypoints3d(i);
      const uint32_t id = frame.person(i).id;
      for (uint32_t k = 0; k < K; ++k) {
        if (!joints[k].valid) continue;
        ++solved_keypoints;
        errors.push_back(joints[k].reprojection_error_px);
        person_errors[id].push_back(joints[k].reprojection_error_px);
      }
    }
    if (r == OCTOCAP_OK) {
      ++frames_with_result;
      joints = frame.keypoints3d(0);
      for (uint32_t k = 0; k < K; ++k) {
        if (!joints[k].valid) continue;
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
    }
    if (!o.quiet && frames >= 50 && (f + 1) % std::max(1u, frames / 10) == 0)
      std::fprintf(stderr, "\r  frame %u / %u", f + 1, frames);
  }
  if (!o.quiet && frames >= 50) std::fprintf(stderr, "\n");
  if (o.out.publish) {
    session.flush_stream();
    std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<int64_t>(o.linger_s * 1000)));
  }
  const double total_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  writers.close();

  const uint32_t done = frames > o.start_frame ? frames - o.start_frame : 0;  // frames this run solved
  double mean_err = 0;
  for (double e : errors) mean_err += e;
  mean_err = errors.empty() ? NAN : mean_err / errors.size();
  std::printf("octocap solve: %u frames x %u cameras, layout %s (%u keypoints), method %s, filter %s, up %s\n",
              frames, views, octocap_layout_name(layout), K, method_name.c_str(), o.filter.c_str(),
              up == OCTOCAP_UP_Z ? "Z" : "Y");
  std::printf("  frames solved:        %zu / %u (%zu with several people in a view)\n", frames_with_result, done,
              frames_multi);
  if (several) {
    std::printf("  people:               %zu tracked;", person_errors.size());
    for (size_t n = 0; n < people_histogram.size(); ++n)
      if (people_histogram[n]) std::printf(" %zu frames with %zu,", people_histogram[n], n);
    std::printf("\n");
    for (auto& [id, errs] : person_errors)
      std::printf("  person %-3u            %zu keypoints solved, reprojection error median %.2f px\n", id, errs.size(),
                  median(errs));
  }
  std::printf("  keypoints solved:     %zu / %zu (%.1f%%)%s\n", solved_keypoints, static_cast<size_t>(done) * K,
              done ? 100.0 * solved_keypoints / (static_cast<double>(done) * K) : 0.0,
              several ? " (all people together)" : "");
  if (errors.empty())
    std::printf("  reprojection error:   n/a (no keypoint solved)\n");
  else
    std::printf("  reprojection error:   mean %.2f px, median %.2f px\n", mean_err, median(errors));
  std::printf("  3D solve time:        %.3f ms/frame; end to end (%s included) %.2f ms/frame, %.0f frames/s%s\n",
              done ? solve_ms / done : 0.0, source ? "decoding and detection" : "JSON parsing",
              done ? total_ms / done : 0.0,
              total_ms > 0 ? done * 1000.0 / total_ms : 0.0,
              o.out.publish || o.out.vmc_port ? " (paced at --rate for streaming)" : "");
  if (source)
    std::printf("  2D detection:         %.1f ms/frame, model %s, mode %s (%s)\n",
                done ? detect_ms / done : 0.0, detect_model.c_str(),
                detect_mode == OCTOCAP_DETECT_PER_VIEW ? "per-view" : detect_mode == OCTOCAP_DETECT_MOSAIC ? "mosaic" : "crop",
                detect_runtime.c_str());
  if (source && done)
    std::printf("  per frame:            decoding waited for %.1f ms (the next frame decodes during this one's "
                "detection); %.2f inferences, %.1f ms in the network; %.2f views followed by optical flow, %.1f ms\n",
                read_ms / done, static_cast<double>(inferences) / done, inference_ms / done,
                static_cast<double>(views_tracked) / done, track_ms / done);
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
  std::printf("  wrote %s\n", writers.written().c_str());
  if (frames_with_result == 0) {
    std::fprintf(stderr, "octocap solve: no frame could be solved (no person seen by enough views)\n");
    return 3;
  }
  return 0;
}

}  // namespace

int run_solve(const SolveOptions& options) { return run_reporting_errors("solve", options, solve); }

int run_layouts() {
  for (octocap_layout_t l : {OCTOCAP_LAYOUT_BODY_25, OCTOCAP_LAYOUT_BODY_25B, OCTOCAP_LAYOUT_COCO_17,
                             OCTOCAP_LAYOUT_HALPE_26, OCTOCAP_LAYOUT_BLAZEPOSE_33}) {
    std::printf("%s (%u keypoints):", octocap_layout_name(l), octocap_layout_keypoint_count(l));
    for (uint32_t k = 0; k < octocap_layout_keypoint_count(l); ++k) std::printf(" %s", octocap_layout_keypoint_name(l, k));
    std::printf("\n");
  }
  return 0;
}
