// octocap-calibrate: intrinsics from checkerboard images, extrinsics from a person walking through the volume.
#include <cmath>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "octocap/octocap.hpp"

namespace fs = std::filesystem;

namespace {

std::string g_yaml;    // --yaml: also write OpenCV YAML
std::string g_boards;  // extrinsics --boards: image sets of a board instead of keypoints
std::string g_board;

int save(const octocap_calibration_t* calib, const std::string& output);

int fail(const std::string& what) {
  std::fprintf(stderr, "octocap-calibrate: error: %s: %s\n", what.c_str(), octocap_last_error());
  return 1;
}

void log_to_stderr(octocap_log_level_t level, const char* message, void*) {
  if (level >= OCTOCAP_LOG_INFO) std::fprintf(stderr, "  %s\n", message);
}

int run_intrinsics(const std::string& images, const std::string& board, const std::string& output,
                   const std::string& report_dir) {
  // One camera per sub-folder (sorted by name); a folder of images only is one camera.
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(images))
    if (e.is_directory()) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  if (dirs.empty()) dirs.push_back(images);
  std::vector<octocap_camera_t> cams;
  std::vector<float> rms;
  std::vector<uint32_t> used, rejected;
  for (size_t i = 0; i < dirs.size(); ++i) {
    std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, dirs.size(), dirs[i].string().c_str());
    octocap_camera_t c{};
    float r = 0;
    uint32_t u = 0, x = 0;
    std::string png;
    if (!report_dir.empty()) {
      fs::create_directories(report_dir);
      png = (fs::path(report_dir) / (dirs[i].filename().string() + "_fit.png")).string();
    }
    if (octocap_calibration_solve_intrinsics(dirs[i].c_str(), board.c_str(), &c, &r, &u, &x,
                                             png.empty() ? nullptr : png.c_str()) != OCTOCAP_OK)
      return fail(dirs[i].string());
    cams.push_back(c);
    rms.push_back(r);
    used.push_back(u);
    rejected.push_back(x);
  }
  octocap_calibration_t* calib = nullptr;
  if (octocap_calibration_create(cams.data(), static_cast<uint32_t>(cams.size()), &calib) != OCTOCAP_OK)
    return fail("building the calibration");
  const int saved = save(calib, output);
  octocap_calibration_destroy(calib);
  if (saved != 0) return saved;
  std::printf("%-16s %9s %9s %9s %7s %7s %9s\n", "camera", "fx", "fy", "k1", "images", "reject", "RMS px");
  for (size_t i = 0; i < cams.size(); ++i)
    std::printf("%-16s %9.1f %9.1f %9.4f %7u %7u %9.3f\n", cams[i].name, cams[i].matrix[0], cams[i].matrix[4],
                cams[i].distortion[0], used[i], rejected[i], rms[i]);
  std::printf("wrote %s (intrinsics; poses are identity until `octocap-calibrate extrinsics`)\n", output.c_str());
  return 0;
}

int run_extrinsics(const std::string& in, const std::string& keypoints, double height, const std::string& distance,
                   const std::string& up, const std::string& output, bool refine) {
  const octocap::Calibration intrinsics = octocap::Calibration::load(in);
  const octocap_calibration_t* intr = intrinsics.get();
  std::optional<octocap::Recording> recording;
  if (g_boards.empty()) recording.emplace(keypoints, OCTOCAP_LAYOUT_AUTO);
  octocap_recording_t* rec = recording ? recording->get() : nullptr;
  octocap_extrinsics_options_t opt;
  octocap_extrinsics_options_init(&opt);
  opt.person_height_m = static_cast<float>(height);
  opt.up_axis = up == "z" ? OCTOCAP_UP_Z : OCTOCAP_UP_Y;
  opt.refine = refine ? 1 : 0;
  if (!distance.empty()) {
    // CAM_A:CAM_B:METRES, cameras by index or name.
    const size_t c1 = distance.find(':'), c2 = distance.rfind(':');
    if (c1 == std::string::npos || c1 == c2) {
      std::fprintf(stderr, "octocap-calibrate: --camera-distance is CAM_A:CAM_B:METRES\n");
      return 2;
    }
    auto index_of = [&](const std::string& s) {
      uint32_t n = 0;
      octocap_calibration_camera_count(intr, &n);
      for (uint32_t i = 0; i < n; ++i) {
        octocap_camera_t c;
        octocap_calibration_get_camera(intr, i, &c);
        if (s == c.name || s == std::to_string(i)) return static_cast<int32_t>(i);
      }
      return -1;
    };
    opt.distance_camera_a = index_of(distance.substr(0, c1));
    opt.distance_camera_b = index_of(distance.substr(c1 + 1, c2 - c1 - 1));
    const std::string metres = distance.substr(c2 + 1);
    char* end = nullptr;
    const double d = std::strtod(metres.c_str(), &end);
    if (metres.empty() || *end != '\0' || !std::isfinite(d) || !(d > 0) || d > 1e4) {
      std::fprintf(stderr, "octocap-calibrate: --camera-distance: '%s' is not a distance in metres (CAM_A:CAM_B:METRES)\n",
                   metres.c_str());
      return 2;
    }
    if (opt.distance_camera_a < 0 || opt.distance_camera_b < 0) {
      std::fprintf(stderr, "octocap-calibrate: --camera-distance: no camera named '%s'\n",
                   (opt.distance_camera_a < 0 ? distance.substr(0, c1) : distance.substr(c1 + 1, c2 - c1 - 1)).c_str());
      return 2;
    }
    opt.camera_distance_m = static_cast<float>(d);
  }
  octocap_calibration_t* raw = nullptr;
  octocap_calibration_report_t rep;
  if (!g_boards.empty()) {
    std::fprintf(stderr, "solving extrinsics from boards in %s (PnP per view, bundle adjustment)...\n", g_boards.c_str());
    octocap::check(octocap_calibration_solve_extrinsics_boards(intr, g_boards.c_str(), g_board.c_str(), &opt, &raw, &rep),
                   "extrinsics");
  } else {
    std::fprintf(stderr, "solving extrinsics from %s (pairwise essential matrix, PnP, bundle adjustment)...\n",
                 keypoints.c_str());
    octocap::check(octocap_calibration_solve_extrinsics(intr, rec, &opt, &raw, &rep), "extrinsics");
  }
  const octocap::Calibration result(raw);
  const octocap_calibration_t* out = result.get();
  const int saved = save(out, output);
  std::printf("%-16s %12s %9s %24s\n", "camera", "observations", "RMS px", "centre (m)");
  for (uint32_t i = 0; i < rep.camera_count; ++i) {
    octocap_camera_t c;
    octocap_calibration_get_camera(out, i, &c);
    std::printf("%-16s %12u %9.2f %24s\n", c.name, rep.observations[i], rep.rms_px[i], "");
  }
  std::printf("bundle adjustment: %u points, %u iterations, RMS %.2f -> %.2f px\n", rep.points, rep.iterations,
              rep.initial_rms_px, rep.final_rms_px);
  if (saved != 0) return saved;
  std::printf("wrote %s\n", output.c_str());
  return 0;
}

int save(const octocap_calibration_t* calib, const std::string& output) {
  if (octocap_calibration_save(calib, output.c_str()) != OCTOCAP_OK) return fail(output);
  if (!g_yaml.empty() && octocap_calibration_save_opencv_yaml(calib, g_yaml.c_str()) != OCTOCAP_OK) return fail(g_yaml);
  if (!g_yaml.empty()) std::printf("wrote %s (OpenCV YAML)\n", g_yaml.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"octocap-calibrate: camera intrinsics from checkerboard images, extrinsics from a person"};
  app.require_subcommand(1);
  octocap_set_log_callback(log_to_stderr, OCTOCAP_LOG_INFO, nullptr);
  std::string images, board, output, in, keypoints, distance, up = "y";
  double height = 0;
  CLI::App* intr = app.add_subcommand("intrinsics", "Intrinsics and distortion from checkerboard images");
  intr->add_option("--images", images, "Folder of images, or of one sub-folder per camera")->required()->check(CLI::ExistingDirectory);
  intr->add_option("--board", board, "checkerboard:COLSxROWS:SQUARE_M (inner corners) or charuco:COLSxROWS:SQUARE_M:MARKER_M[:DICT_6X6_250] (squares)")->required();
  intr->add_option("--output", output, "Calibration TOML to write")->required();
  std::string report_dir;
  intr->add_option("--report", report_dir, "Folder for one PNG per camera: detected vs reprojected corners");
  CLI::App* extr = app.add_subcommand("extrinsics", "All camera poses from a person moving through the volume");
  extr->add_option("--calibration", in, "Calibration TOML with the cameras' intrinsics")->required()->check(CLI::ExistingFile);
  CLI::Option* kp = extr->add_option("--keypoints", keypoints, "One OpenPose JSON folder per camera (as `octocap solve` reads)")->check(CLI::ExistingDirectory);
  CLI::Option* bd = extr->add_option("--boards", g_boards, "Or: one image folder per camera, same file name = same moment, a board seen by several")->check(CLI::ExistingDirectory);
  extr->add_option("--board", g_board, "With --boards: checkerboard:COLSxROWS:SQUARE_M");
  kp->excludes(bd);
  extr->add_option("--person-height", height, "The person's height in metres (sets the scale)");
  extr->add_option("--camera-distance", distance, "CAM_A:CAM_B:METRES, a measured distance (sets the scale exactly)");
  extr->add_option("--up", up, "Up axis of the written world frame")->check(CLI::IsMember({"y", "z"}))->capture_default_str();
  extr->add_option("--output", output, "Calibration TOML to write")->required();
  CLI::App* refine = app.add_subcommand("refine", "Refine an existing calibration from new keypoints (a camera was nudged)");
  refine->add_option("--calibration", in, "The calibration to refine")->required()->check(CLI::ExistingFile);
  refine->add_option("--keypoints", keypoints, "One OpenPose JSON folder per camera")->required()->check(CLI::ExistingDirectory);
  refine->add_option("--output", output, "Calibration TOML to write")->required();
  for (CLI::App* sub : {intr, extr, refine}) sub->add_option("--yaml", g_yaml, "Also write the calibration as OpenCV YAML");
  CLI11_PARSE(app, argc, argv);
  // Whatever the file system says (a --report path that is a file, a full disk) is an error message, never an abort.
  try {
    if (intr->parsed()) return run_intrinsics(images, board, output, report_dir);
    if (extr->parsed() && keypoints.empty() && g_boards.empty()) {
      std::fprintf(stderr, "octocap-calibrate extrinsics: give --keypoints DIR (a person) or --boards DIR --board SPEC\n");
      return 2;
    }
    return run_extrinsics(in, keypoints, height, distance, up, output, refine->parsed());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "octocap-calibrate: error: %s\n", e.what());
    return 1;
  }
}
