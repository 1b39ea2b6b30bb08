// octocap: the command line. `octocap solve` turns a multi-camera 2D keypoint recording into 3D.
#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>
#include <string>

#include "octocap/octocap.h"
#include "detect_command.h"
#include "option_typos.h"
#include "live_command.h"
#include "security_command.h"
#include "sync_command.h"
#include "solve_command.h"

namespace {

void add_detector_options(CLI::App* app, DetectorOptions& d) {
  app->add_option("--model", d.model, "Pose model: a shipped name (movenet-thunder, movenet-lightning, movenet-multipose) or an .onnx with its card")->capture_default_str();
  app->add_option("--detect-mode", d.mode, "per-view, mosaic (the paper's merged image) or crop (around the last pose)")->check(CLI::IsMember({"per-view", "mosaic", "crop"}))->capture_default_str();
  app->add_option("--pick", d.pick, "People per view passed on: all, largest, most-confident, nearest")->check(CLI::IsMember({"all", "largest", "most-confident", "nearest"}))->capture_default_str();
  app->add_option("--detect-threads", d.threads, "Inference threads per view (0: all cores, shared by parallel views)")->capture_default_str();
  app->add_option("--mosaic-tile", d.mosaic_tile, "Mosaic: tile height in pixels")->capture_default_str();
  app->add_option("--max-people", d.max_people, "People kept per view")->check(CLI::Range(1, 64))->capture_default_str();
  app->add_option("--parallel-views", d.parallel_views, "Views inferred at once (0: one per core)")->check(CLI::Range(0, 256))->capture_default_str();
  app->add_option("--views-per-frame", d.views_per_frame, "Views detected each frame, the others followed by optical flow (0: every view; docs/benchmarks.md \"Real time\")")->check(CLI::Range(0, 256))->capture_default_str();
  app->add_option("--runtime", d.runtime, "Inference back end: auto (OpenVINO on the CPU where built in, else ONNX Runtime), onnxruntime or openvino")->check(CLI::IsMember({"auto", "onnxruntime", "openvino"}))->capture_default_str();
  app->add_option("--precision", d.precision, "Network arithmetic: auto (f32 today: bf16 was measured to move keypoints), f32 or reduced (bf16 where the CPU has it; OpenVINO)")->check(CLI::IsMember({"auto", "f32", "reduced"}))->capture_default_str();
  app->add_option("--device", d.device, "Where the network runs: cpu, auto (the GPU when there is one, else the CPU) or cuda (the GPU or an error)")->check(CLI::IsMember({"cpu", "auto", "cuda"}))->capture_default_str();
}

void add_output_options(CLI::App* app, OutputOptions& o) {
  app->add_flag("--publish", o.publish, "Stream every frame over DDS (solve: paced at --rate)");
  app->add_option("--publish-qos", o.publish_qos, "live (best effort, newest only) or record (reliable, late joiners get history)")
      ->check(CLI::IsMember({"live", "record"}))->capture_default_str();
  app->add_option("--domain", o.domain, "DDS domain id")->check(CLI::Range(0, 232))->capture_default_str();
  app->add_option("--topic", o.topic, "DDS topic base name")->capture_default_str();
  app->add_option("--source-id", o.source_id, "This rig's id on the topic")->capture_default_str();
  app->add_option("--vmc-port", o.vmc_port, "Also send VMC protocol (OSC/UDP) to this port (VMC's usual: 39539)")
      ->check(CLI::Range(0, 65535));
  app->add_option("--vmc-host", o.vmc_host, "VMC receiver host")->capture_default_str();
  app->add_option("--dds-security", o.dds_security, "DDS Security: this participant's identity folder, KEYSTORE/NAME (octocap security add; role hub); the stream and the capture nodes' keypoints then go over an authenticated, encrypted network (docs/security.md)");
}

}  // namespace

void add_people_option(CLI::App* app, std::string& people) {
  app->add_option("--people", people, "People to solve: 1 (the one the views agree on), N (up to N, tracked with ids), or auto (everyone in the volume, up to 16); with several, OUT.trc becomes OUT_person<ID>.trc (BVH too) and the CSV has a person column")
      ->check(CLI::IsMember({"auto"}) | CLI::Range(1, 16))->capture_default_str();
}

// Solve and live alike: --output is always TRC, so a name that says another format is a mistake, not a request (the
// file would hold TRC under a .csv or .bvh name).
const CLI::Validator kTrcName(
    [](std::string& name) -> std::string {
      const auto dot = name.rfind('.');
      std::string ext = dot == std::string::npos ? "" : name.substr(dot);
      for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (ext == ".csv") return "--output writes TRC; for CSV give --csv " + name;
      if (ext == ".bvh") return "--output writes TRC; for BVH give --bvh " + name;
      return "";
    },
    "TRC", "TRC file name");

void add_foot_lock_flag(CLI::App* app, bool& foot_lock) {
  app->add_flag("--foot-lock,!--no-foot-lock", foot_lock, "Hold planted feet still (the default): a foot on the floor keeps its place while the solve's noise would make it skate (its ankle, knee and foot; contacts are reported either way); --no-foot-lock: joints as solved");
}

int main(int argc, char** argv) {
  CLI::App app{"octocap: markerless multi-camera motion capture"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("octocap ") + octocap_version());

  SolveOptions solve;
  CLI::App* sc = app.add_subcommand("solve", "Solve a recording of 2D keypoints (OpenPose JSON) into 3D (TRC/CSV)");
  sc->add_option("--calibration", solve.calibration, "Calibration TOML (anipose / Pose2Sim)")->required()->check(CLI::ExistingFile);
  auto* kp = sc->add_option("--keypoints", solve.keypoints, "Folder with one OpenPose JSON sub-folder per camera")->check(CLI::ExistingDirectory);
  auto* im = sc->add_option("--images", solve.images, "Folder with one video or picture sub-folder per camera (calibration order): detect 2D keypoints first")->check(CLI::ExistingDirectory);
  kp->excludes(im);
  sc->add_option("--frames", solve.max_frames, "Solve at most this many frames (0: all)")->capture_default_str();
  sc->add_option("--debug-images", solve.debug_images, "With --images: write each view with detections and reprojected 3D keypoints as PNG");
  add_detector_options(sc, solve.detector);
  sc->add_option("--output", solve.output, "Output TRC file")->required()->check(kTrcName);
  sc->add_option("--csv", solve.csv, "Also write a CSV (calibration world frame)");
  sc->add_option("--bvh", solve.bvh, "Also write the bone animation as BVH (Y up, centimetres)");
  sc->add_option("--method", solve.method, "3D method (auto: subdivision with 5+ cameras, else triangulation)")->check(CLI::IsMember({"auto", "subdivision", "triangulation"}))->capture_default_str();
  sc->add_option("--sigma", solve.sigma, "Views a cube must be supported by (0: cameras - 1)")->capture_default_str();
  sc->add_option("--delta-mm", solve.delta_mm, "Smallest cube edge, mm")->check(CLI::PositiveNumber)->capture_default_str();
  sc->add_option("--filter", solve.filter, "Temporal filter (oneeuro: its cutoff follows the measured noise; "
                 "oneeuro-fixed: before 1.4's)")->check(CLI::IsMember({"none", "oneeuro", "oneeuro-fixed"}))->capture_default_str();
  sc->add_option("--layout", solve.layout, "Keypoint layout: auto, BODY_25, BODY_25B, COCO_17, HALPE_26, BLAZEPOSE_33")->capture_default_str();
  sc->add_option("--up", solve.up, "World up axis of the calibration")->check(CLI::IsMember({"auto", "y", "z"}))->capture_default_str();
  sc->add_option("--rate", solve.rate_hz, "Frame rate of the recording, Hz (default: with --images the videos' own, else 30)")->check(CLI::PositiveNumber);
  sc->add_option("--threads", solve.threads, "Worker threads (0: all cores)")->capture_default_str();
  add_people_option(sc, solve.people);
  add_foot_lock_flag(sc, solve.foot_lock);
  sc->add_option("--sync", solve.sync, "Sync TOML (octocap sync): each camera's keypoints taken at its own time offset")->check(CLI::ExistingFile);
  sc->add_option("--ground-truth", solve.ground_truth, "CSV of true 3D keypoints: report the error against it")->check(CLI::ExistingFile);
  sc->add_flag("--quiet", solve.quiet, "No progress on stderr");
  add_output_options(sc, solve.out);
  sc->add_option("--start-frame", solve.start_frame, "Skip the recording's first frames (numbering keeps their index)")->capture_default_str();
  sc->add_option("--wait-subscribers", solve.wait_subscribers, "With --publish: wait (up to 10 s) for this many subscribers before the first frame")->capture_default_str();
  sc->add_option("--linger-s", solve.linger_s, "With --publish: stay on the network this long after the last frame")->capture_default_str();

  DetectOptions detect;
  CLI::App* dc = app.add_subcommand("detect", "Detect 2D keypoints in camera images or videos and write OpenPose JSON");
  auto* dimages = dc->add_option("--images", detect.images, "Folder with one video or picture sub-folder per camera")->check(CLI::ExistingDirectory);
  auto* doutput = dc->add_option("--output", detect.output, "Folder for the OpenPose JSON (one <camera>_json sub-folder per camera)");
  auto* dlive = dc->add_flag("--live", detect.live, "A capture node: detect live cameras and publish their keypoints (with --publish-keypoints) for a hub's `octocap live --camera dds://NODE/CAMERA`");
  dimages->excludes(dlive);
  doutput->excludes(dlive);
  dc->add_option("--camera", detect.cameras, "--live: a camera (as for octocap live), once per camera")->needs(dlive);
  dc->add_option("--cameras", detect.camera_file, "--live: cameras from a TOML file readable by its owner only ([[camera]] url = \"...\", name = \"cam01\"), after any --camera: passwords kept off the command line (docs/security.md)")->needs(dlive)->check(CLI::ExistingFile);
  dc->add_option("--camera-name", detect.camera_names, "--live: the CAMERA of dds://NODE/CAMERA, once per camera (default cam01, cam02, ...)")->needs(dlive);
  dc->add_flag("--publish-keypoints", detect.publish_keypoints, "--live: publish each camera's 2D keypoints over DDS (\"<topic>_keypoints2d\")")->needs(dlive);
  dc->add_option("--node", detect.node, "--live: this node's name, the NODE of dds://NODE/CAMERA")->capture_default_str();
  dc->add_option("--domain", detect.domain, "--live: DDS domain id")->check(CLI::Range(0, 232))->capture_default_str();
  dc->add_option("--topic", detect.topic, "--live: DDS topic base name")->capture_default_str();
  dc->add_option("--dds-security", detect.dds_security, "--live: DDS Security identity folder, KEYSTORE/NAME (octocap security add; role node): the keypoints go to hubs of that keystore only (docs/security.md)")->needs(dlive);
  dc->add_option("--duration", detect.duration_s, "--live: stop after this many seconds (0: when the cameras end, or Ctrl-C)")->capture_default_str();
  dc->add_option("--detect-rate", detect.detect_rate_hz, "--live: detections per second and camera, at wall-clock ticks all nodes share (0: the fastest of 60, 30, 20, 15, 12, 10, ... the detector keeps up with); give every node the same")->check(CLI::Range(0.0, 1000.0))->capture_default_str();
  dc->add_option("--picture-rate", detect.picture_rate_hz, "--live: rate of picture-folder cameras")->check(CLI::PositiveNumber)->capture_default_str();
  dc->add_option("--frames", detect.max_frames, "Detect at most this many frames (0: all)")->capture_default_str();
  dc->add_option("--debug-images", detect.debug_images, "Write each view with its detections drawn as PNG");
  dc->add_flag("--quiet", detect.quiet, "No progress on stderr");
  add_detector_options(dc, detect.detector);

  LiveOptions live;
  CLI::App* lv = app.add_subcommand("live", "Capture live from cameras (devices, rtsp://, http://, videos or picture folders as cameras) into 3D");
  lv->add_option("--camera", live.cameras, "A camera, once per camera in calibration order: /dev/videoN or N, rtsp://..., http://... (MJPEG), a video file, a picture folder, or dds://NODE/CAMERA (a capture node's keypoints, on --domain/--topic); ${NAME} in it is taken from the environment (a password kept out of ps)");
  lv->add_option("--cameras", live.camera_file, "Cameras from a TOML file readable by its owner only ([[camera]] url = \"...\"), after any --camera, in calibration order: passwords kept off the command line (docs/security.md)")->check(CLI::ExistingFile);
  lv->add_option("--calibration", live.calibration, "Calibration TOML (anipose / Pose2Sim)")->required()->check(CLI::ExistingFile);
  lv->add_option("--duration", live.duration_s, "Stop after this many seconds (0: when the cameras end, or Ctrl-C)")->capture_default_str();
  lv->add_option("--picture-rate", live.picture_rate_hz, "Rate of picture-folder cameras")->check(CLI::PositiveNumber)->capture_default_str();
  lv->add_option("--rate", live.rate_hz, "TRC and BVH rows at this fixed rate, Hz, the sets resampled onto it (default: the take's own mean set rate); the CSV keeps each set's time")->check(CLI::PositiveNumber);
  lv->add_option("--output", live.output, "Write the take as TRC")->check(kTrcName);
  lv->add_option("--csv", live.csv, "Also write a CSV (calibration world frame)");
  lv->add_option("--bvh", live.bvh, "Also write the bone animation as BVH");
  lv->add_option("--record", live.record, "Record the take into this new folder: calibration.toml, images/ (pictures), keypoints/ (OpenPose JSON), timestamps.csv; solve it again with octocap solve --keypoints DIR/keypoints");
  lv->add_option("--method", live.method, "3D method")->check(CLI::IsMember({"auto", "subdivision", "triangulation"}))->capture_default_str();
  lv->add_option("--filter", live.filter, "Temporal filter")->check(CLI::IsMember({"none", "oneeuro", "oneeuro-fixed"}))->capture_default_str();
  add_output_options(lv, live.out);
  lv->add_flag("--quiet", live.quiet, "No status line on stderr");
  add_people_option(lv, live.people);
  add_foot_lock_flag(lv, live.foot_lock);
  add_detector_options(lv, live.detector);
  lv->add_option("--quality", live.quality, "governed: hold --target-fps within --latency-budget, choosing each set how many views the network runs on and which model (docs/benchmarks.md \"Real time\"); max: every view with the model named, whatever the rate")->check(CLI::IsMember({"governed", "max"}))->capture_default_str();
  lv->add_option("--target-fps", live.target_fps, "Sets a second the governor holds (0: the slowest camera's rate)")->check(CLI::Range(0.0, 1000.0))->capture_default_str();
  lv->add_option("--latency-budget", live.latency_budget_ms, "Grab to frame, ms, that the governor keeps sets within")->check(CLI::Range(10, 10000))->capture_default_str();

  SyncOptions sync;
  CLI::App* sy = app.add_subcommand("sync", "Estimate each camera's time offset from the person's motion (unsynchronised cameras)");
  sy->add_option("--calibration", sync.calibration, "Calibration TOML (anipose / Pose2Sim)")->required()->check(CLI::ExistingFile);
  sy->add_option("--keypoints", sync.keypoints, "Folder with one OpenPose JSON sub-folder per camera")->required()->check(CLI::ExistingDirectory);
  sy->add_option("--rate", sync.rate_hz, "Frame rate of the recording, Hz")->check(CLI::PositiveNumber)->capture_default_str();
  sy->add_option("--max-offset-s", sync.max_offset_s, "Offsets searched on either side, seconds")->check(CLI::PositiveNumber)->capture_default_str();
  sy->add_option("--output", sync.output, "Sync TOML to write (for octocap solve --sync)")->required();

  CLI::App* lc = app.add_subcommand("layouts", "List the keypoint layouts and their keypoints");

  SecurityOptions security;
  CLI::App* sec = add_security_commands(app, security);

  if (const int status = report_unknown_options(app, argc, argv)) return status;
  CLI11_PARSE(app, argc, argv);
  if (sc->parsed() && solve.keypoints.empty() && solve.images.empty()) {
    std::fprintf(stderr, "octocap solve: give --keypoints or --images\n");
    return 2;
  }
  if (lv->parsed() && live.cameras.empty() && live.camera_file.empty()) {
    std::fprintf(stderr, "octocap live: give --camera (once per camera) or --cameras FILE\n");
    return 2;
  }
  if (sc->parsed()) return run_solve(solve);
  if (dc->parsed()) return run_detect(detect);
  if (lv->parsed()) return run_live(live);
  if (sy->parsed()) return run_sync(sync);
  if (lc->parsed()) return run_layouts();
  if (sec->parsed()) return run_security(security);
  return 0;
}
