// Calibration against ground truth the test makes (synthetic rigs and real CMU motion) and against a real
// lab calibration (Pose2Sim's demo: Qualisys-calibrated cameras, their checkerboard images and keypoints).
#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <random>

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/imgcodecs.hpp>

#include "calib/board_extrinsics.h"
#include "calib/extrinsics.h"
#include "calib/intrinsics.h"
#include "core/error.h"
#include "io/calibration_toml.h"
#include "octocap/octocap.h"
#include "pipeline/session.h"
#include "support/run_command.h"
#include "support/temp_dir.h"
#include "synth.h"

using namespace octocap::internal;
using Catch::Matchers::ContainsSubstring;

namespace {

using Frames = std::vector<std::vector<std::vector<Person2D>>>;

Frames observe_all(const Calibration& cams, const synth::Motion& m, const synth::NoiseOptions& noise, unsigned seed) {
  std::mt19937 rng(seed);
  Frames frames;
  for (const auto& f : m.frames) frames.push_back(synth::observe(cams, f, LayoutId::body25, noise, rng));
  return frames;
}

// The similarity (or rigid, scale = false) transform taking `got` camera centres onto `truth`'s.
Eigen::Matrix4d align(const Calibration& truth, const Calibration& got, bool scale) {
  Eigen::Matrix3Xd A(3, truth.size()), B(3, got.size());
  for (size_t i = 0; i < truth.size(); ++i) {
    A.col(i) = truth[i].center();
    B.col(i) = got[i].center();
  }
  return Eigen::umeyama(B, A, scale);
}

// `got` moved into truth's world frame by T (x_truth = s R x_got + t).
Calibration transformed(const Calibration& got, const Eigen::Matrix4d& T) {
  const double s = T.block<3, 3>(0, 0).col(0).norm();
  const Eigen::Matrix3d R = T.block<3, 3>(0, 0) / s;
  const Eigen::Vector3d t = T.block<3, 1>(0, 3);
  Calibration out = got;
  for (Camera& c : out) {
    // x_cam = R_c x_got + t_c, x_got = R^T (x_truth - t) / s  ->  metric camera frame scaled by s.
    c.R = got[&c - out.data()].R * R.transpose();
    c.t = s * got[&c - out.data()].t - c.R * t;
  }
  return out;
}

double mpjpe_with(const Calibration& calib, const synth::Motion& m, const Frames& frames) {
  SessionConfig cfg;
  cfg.filter = false;
  cfg.method = Method::triangulation;
  cfg.up = UpAxis::y;
  Session s(cfg, calib);
  double err = 0;
  size_t n = 0;
  for (size_t f = 0; f < frames.size(); ++f) {
    s.solve(frames[f], static_cast<int64_t>(f) * 33333);
    for (size_t k = 0; k < m.frames[f].size(); ++k)
      if (s.keypoints()[k].valid) err += (s.keypoints()[k].position - m.frames[f][k]).norm(), ++n;
  }
  return 1000 * err / n;
}

const std::string kDemo = std::string(OCTOCAP_REAL_DATA_DIR) + "/Demo";

}  // namespace

TEST_CASE("extrinsics from a person: cameras recovered from noisy, partly wrong keypoints", "[calib]") {
  synth::RigOptions rig;
  rig.cameras = GENERATE(4, 6);
  const Calibration truth = synth::make_camera_ring(rig);
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 350, 6);
  const Frames frames = observe_all(truth, motion, {1.0, 0.03, 0.02, 0.01}, 5);
  ExtrinsicsOptions opt;
  opt.distance_camera_a = 0;
  opt.distance_camera_b = rig.cameras / 2;
  opt.camera_distance_m = (truth[0].center() - truth[rig.cameras / 2].center()).norm();
  ExtrinsicsReport rep;
  const Calibration got = calibrate_extrinsics(truth, frames, LayoutId::body25, opt, &rep);
  INFO(rig.cameras << " cameras, BA RMS " << rep.initial_rms_px << " -> " << rep.final_rms_px);
  // The scale is fixed by the distance, so only a rigid motion separates the two worlds.
  const Eigen::Matrix4d T = align(truth, got, false);
  const Calibration moved = transformed(got, T);
  double worst_centre = 0, worst_angle = 0;
  for (size_t i = 0; i < truth.size(); ++i) {
    worst_centre = std::max(worst_centre, (moved[i].center() - truth[i].center()).norm());
    worst_angle = std::max(worst_angle, Eigen::AngleAxisd(moved[i].R * truth[i].R.transpose()).angle());
  }
  INFO("worst centre " << worst_centre * 1000 << " mm, worst rotation " << worst_angle * 180 / M_PI << " deg");
  CHECK(worst_centre < 0.01);                // 10 mm in a ~8 m wide rig
  CHECK(worst_angle * 180 / M_PI < 0.2);
  for (double r : rep.rms_px) CHECK(r < 3.0);  // inliers: pixel noise is 1 px
  // What matters: 3D accuracy with the recovered calibration equals that with the true one.
  const double with_truth = mpjpe_with(truth, motion, frames), with_got = mpjpe_with(moved, motion, frames);
  INFO("MPJPE " << with_truth << " mm (true calibration) vs " << with_got << " mm (recovered)");
  CHECK(with_got < with_truth + 1.0);
  // Up and floor: the person stands on y = 0 in the recovered world, up along +Y.
  Eigen::Vector3d up = T.block<3, 3>(0, 0).transpose() * Eigen::Vector3d::UnitY();
  CHECK(up.y() > 0.99);
}

TEST_CASE("extrinsics from a board seen by several cameras at once", "[calib]") {
  const Calibration truth = synth::make_camera_ring({});
  const BoardSpec board{9, 6, 0.1};
  std::mt19937 rng(21);
  std::normal_distribution<double> noise(0, 0.3);
  std::uniform_real_distribution<double> u(-1, 1);
  BoardViews views;
  for (int s = 0; s < 12; ++s) {
    // The first board lies on the floor at the origin, its columns along +X, its rows along +Z; the others
    // stand around the volume, turned and tilted.
    Eigen::Matrix3d R = (Eigen::Matrix3d() << 1, 0, 0, 0, 0, -1, 0, 1, 0).finished().transpose();
    R.col(2) = R.col(0).cross(R.col(1));
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
    if (s > 0) {
      R = Eigen::AngleAxisd(u(rng) * M_PI, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(M_PI / 2 + 0.4 * u(rng), Eigen::Vector3d::UnitX());
      t = Eigen::Vector3d(0.8 * u(rng), 1.0 + 0.3 * u(rng), 0.8 * u(rng));
    }
    std::vector<std::vector<Eigen::Vector2d>> set(truth.size());
    for (size_t v = 0; v < truth.size(); ++v) {
      const Eigen::Vector3d normal = R.col(2);
      if (std::abs(normal.dot((truth[v].center() - t).normalized())) < 0.3) continue;  // seen too edge-on
      std::vector<Eigen::Vector2d> px;
      for (int i = 0; i < board.cols * board.rows; ++i) {
        const Eigen::Vector3d p = R * Eigen::Vector3d((i % board.cols) * board.square_m, (i / board.cols) * board.square_m, 0) + t;
        px.push_back(truth[v].project(p) + Eigen::Vector2d(noise(rng), noise(rng)));
      }
      set[v] = px;
    }
    views.push_back(set);
  }
  ExtrinsicsReport rep;
  const Calibration got = calibrate_extrinsics_from_boards(truth, views, board, false, &rep);
  for (size_t i = 0; i < truth.size(); ++i) {
    INFO("camera " << i << " centre off by " << (got[i].center() - truth[i].center()).norm() * 1000 << " mm, RMS " << rep.rms_px[i]);
    CHECK((got[i].center() - truth[i].center()).norm() < 0.01);  // the same world: the floor board defines it
    CHECK(Eigen::AngleAxisd(got[i].R * truth[i].R.transpose()).angle() * 180 / M_PI < 0.2);
    CHECK(rep.rms_px[i] < 1.0);
  }
  // A camera that never sees the board with the others is named.
  BoardViews alone = views;
  for (auto& set : alone) set[4].clear();
  REQUIRE_THROWS_WITH(calibrate_extrinsics_from_boards(truth, alone, board, false, nullptr), ContainsSubstring("cam_5"));
}

TEST_CASE("extrinsics: the scale from the person's height", "[calib]") {
  const Calibration truth = synth::make_camera_ring({});
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 300, 6);
  // The height whose keypoint path (ankle-knee-hip-neck-head) the anthropometric ratio expects.
  std::vector<double> paths;
  const auto& lay = layout(LayoutId::body25);
  auto joint = [&](const std::vector<Eigen::Vector3d>& f, int j) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (int k : lay.joint_sources[j].front()) s += f[k];
    return Eigen::Vector3d(s / static_cast<double>(lay.joint_sources[j].front().size()));
  };
  for (const auto& f : motion.frames) {
    const double legs = 0.5 * ((joint(f, kLFoot) - joint(f, kLKnee)).norm() + (joint(f, kLKnee) - joint(f, kLHip)).norm() +
                               (joint(f, kRFoot) - joint(f, kRKnee)).norm() + (joint(f, kRKnee) - joint(f, kRHip)).norm());
    paths.push_back(legs + (joint(f, kNeck) - 0.5 * (joint(f, kLHip) + joint(f, kRHip))).norm() +
                    (joint(f, kHead) - joint(f, kNeck)).norm());
  }
  std::nth_element(paths.begin(), paths.begin() + paths.size() / 2, paths.end());
  ExtrinsicsOptions opt;
  opt.person_height_m = paths[paths.size() / 2] / kKeypointPathOfHeight;
  const Calibration got = calibrate_extrinsics(truth, observe_all(truth, motion, {1.0, 0, 0, 0}, 8), LayoutId::body25, opt, nullptr);
  const Eigen::Matrix4d T = align(truth, got, true);
  const double scale = T.block<3, 3>(0, 0).col(0).norm();
  CHECK(std::abs(scale - 1.0) < 0.02);
}

TEST_CASE("refining a calibration puts a nudged camera back and keeps the world frame", "[calib]") {
  const Calibration truth = synth::make_camera_ring({});
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 250, 6);
  const Frames frames = observe_all(truth, motion, {1.0, 0.03, 0.02, 0}, 12);
  Calibration nudged = truth;
  const Eigen::Vector3d centre = nudged[2].center() + Eigen::Vector3d(0.06, -0.03, 0.04);
  nudged[2].R = Eigen::AngleAxisd(2.0 * M_PI / 180, Eigen::Vector3d(0.3, 1, 0.2).normalized()).toRotationMatrix() * nudged[2].R;
  nudged[2].t = -nudged[2].R * centre;
  ExtrinsicsOptions opt;
  opt.refine = true;
  const Calibration got = calibrate_extrinsics(nudged, frames, LayoutId::body25, opt, nullptr);
  for (size_t i = 0; i < truth.size(); ++i) {
    INFO("camera " << i << ": centre off by " << (got[i].center() - truth[i].center()).norm() * 1000 << " mm");
    CHECK((got[i].center() - truth[i].center()).norm() < 0.01);
    CHECK(Eigen::AngleAxisd(got[i].R * truth[i].R.transpose()).angle() * 180 / M_PI < 0.2);
  }
}

TEST_CASE("extrinsics: clear errors", "[calib]") {
  const Calibration truth = synth::make_camera_ring({});
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 120, 6);
  Frames frames = observe_all(truth, motion, {1.0, 0, 0, 0}, 9);
  ExtrinsicsOptions opt;
  SECTION("no scale") {
    REQUIRE_THROWS_WITH(calibrate_extrinsics(truth, frames, LayoutId::body25, opt, nullptr),
                        ContainsSubstring("height") && ContainsSubstring("distance"));
  }
  opt.person_height_m = 1.7;
  SECTION("one camera") {
    REQUIRE_THROWS_WITH(calibrate_extrinsics({truth[0]}, frames, LayoutId::body25, opt, nullptr),
                        ContainsSubstring("at least 2 cameras"));
  }
  SECTION("a camera that never sees the person") {
    for (auto& f : frames) f[3].clear();
    REQUIRE_THROWS_WITH(calibrate_extrinsics(truth, frames, LayoutId::body25, opt, nullptr),
                        ContainsSubstring("cam_4") && ContainsSubstring("too few"));
  }
  SECTION("two groups of cameras that never see the person at the same time: named") {
    for (size_t f = 0; f < frames.size(); ++f)
      for (size_t v = 0; v < frames[f].size(); ++v)
        if ((v < 2) == (f % 2 == 0)) frames[f][v].clear();
    REQUIRE_THROWS_WITH(calibrate_extrinsics(truth, frames, LayoutId::body25, opt, nullptr),
                        ContainsSubstring("[cam_1, cam_2]") && ContainsSubstring("[cam_3, cam_4, cam_5]"));
  }
  SECTION("degenerate motion: every keypoint at one spot") {
    std::mt19937 rng(1);
    Frames flat;
    for (size_t f = 0; f < 60; ++f) {
      std::vector<Eigen::Vector3d> same(25, Eigen::Vector3d(0.1, 1.0, 0.2));
      flat.push_back(synth::observe(truth, same, LayoutId::body25, {0.5, 0, 0, 0}, rng));
    }
    REQUIRE_THROWS_WITH(calibrate_extrinsics(truth, flat, LayoutId::body25, opt, nullptr), ContainsSubstring("degenerate"));
  }
}

TEST_CASE("OpenCV YAML export reads back in OpenCV", "[calib][formats]") {
  testing::TempDir dir;
  const Calibration truth = synth::make_camera_ring({});
  octocap_calibration_t* c = nullptr;
  write_calibration_toml(truth, dir.file("c.toml"));
  REQUIRE(octocap_calibration_load(dir.file("c.toml").c_str(), &c) == OCTOCAP_OK);
  REQUIRE(octocap_calibration_save_opencv_yaml(c, dir.file("c.yml").c_str()) == OCTOCAP_OK);
  octocap_calibration_destroy(c);
  cv::FileStorage fs(dir.file("c.yml"), cv::FileStorage::READ);
  REQUIRE(fs.isOpened());
  REQUIRE(static_cast<int>(fs["camera_count"]) == 5);
  cv::Mat K, R, t, d;
  fs["cam_3"]["camera_matrix"] >> K;
  fs["cam_3"]["rotation_matrix"] >> R;
  fs["cam_3"]["tvec"] >> t;
  fs["cam_3"]["distortion_coefficients"] >> d;
  for (int i = 0; i < 9; ++i) {
    CHECK(std::abs(K.at<double>(i / 3, i % 3) - truth[2].K(i / 3, i % 3)) < 1e-9);
    CHECK(std::abs(R.at<double>(i / 3, i % 3) - truth[2].R(i / 3, i % 3)) < 1e-9);
  }
  CHECK(std::abs(t.at<double>(2) - truth[2].t.z()) < 1e-12);
  CHECK(std::abs(d.at<double>(0) - truth[2].dist[0]) < 1e-12);
  CHECK(static_cast<std::string>(fs["cam_3"]["name"]) == "cam_3");
}

TEST_CASE("intrinsics: errors for bad boards, unreadable and too few images", "[calib]") {
  testing::TempDir dir;
  REQUIRE_THROWS_WITH(parse_board("checkerboard:9x6"), ContainsSubstring("COLSxROWS:SQUARE_M"));
  REQUIRE(parse_board("charuco:5x7:0.04:0.03").charuco);
  REQUIRE_THROWS_WITH(parse_board("charuco:5x7:0.04:0.05"), ContainsSubstring("marker < square"));
  REQUIRE_THROWS_WITH(parse_board("charuco:5x7:0.04:0.03:DICT_9X9_1"), ContainsSubstring("DICT_9X9_1"));
  REQUIRE_THROWS_WITH(calibrate_intrinsics(dir.file("none"), parse_board("checkerboard:9x6:0.025"), nullptr),
                      ContainsSubstring("not a directory"));
  dir.write("imgs/a.png", "not an image");
  dir.write("imgs/b.jpg", "neither");
  IntrinsicsReport rep;
  REQUIRE_THROWS_WITH(calibrate_intrinsics(dir.file("imgs"), parse_board("checkerboard:9x6:0.025"), &rep),
                      ContainsSubstring("at least 3"));
  REQUIRE(rep.rejected.size() == 2);
  REQUIRE_THAT(rep.rejected[0], ContainsSubstring("unreadable"));
}

TEST_CASE("ChArUco intrinsics from rendered views of a printed board recover the camera", "[calib]") {
  // Print the board (OpenCV draws it), then photograph it with a known pinhole camera from several poses.
  const BoardSpec spec = parse_board("charuco:7x5:0.04:0.03");
  cv::Mat printed;
  cv::aruco::CharucoBoard::create(7, 5, 0.04f, 0.03f, cv::aruco::getPredefinedDictionary(cv::aruco::DICT_6X6_250))
      ->draw(cv::Size(1400, 1000), printed, 40, 1);
  const double metres_per_px = 0.04 * 7 / (1400 - 80);  // drawn squares span the size minus margins
  const double f = 900, cx = 650, cy = 470;
  cv::Mat K = (cv::Mat_<double>(3, 3) << f, 0, cx, 0, f, cy, 0, 0, 1);
  testing::TempDir dir;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int v = 0; v < 8; ++v) {
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.5 * u(rng), Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(0.5 * u(rng), Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(0.3 * u(rng), Eigen::Vector3d::UnitZ())).toRotationMatrix();
    const Eigen::Vector3d centre(0.15 * u(rng), 0.1 * u(rng), 0.55 + 0.1 * u(rng));
    // Board pixel (a, b) -> plane point ((a - w/2) s, (b - h/2) s, 0) -> camera.
    cv::Mat H(3, 3, CV_64F);
    Eigen::Matrix3d M;
    M.col(0) = R.col(0) * metres_per_px;
    M.col(1) = R.col(1) * metres_per_px;
    M.col(2) = centre - R.col(0) * metres_per_px * printed.cols / 2 - R.col(1) * metres_per_px * printed.rows / 2;
    for (int i = 0; i < 9; ++i) H.at<double>(i / 3, i % 3) = M(i / 3, i % 3);
    cv::Mat photo;
    cv::warpPerspective(printed, photo, K * H, cv::Size(1300, 940), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(90));
    cv::imwrite(dir.file("view" + std::to_string(v) + ".png"), photo);
  }
  IntrinsicsReport rep;
  const Camera cam = calibrate_intrinsics(dir.path().string(), spec, &rep, dir.file("fit.png"));
  INFO("fx " << cam.K(0, 0) << " fy " << cam.K(1, 1) << " cx " << cam.K(0, 2) << " cy " << cam.K(1, 2) << ", RMS "
             << rep.rms_px << ", used " << rep.used.size());
  CHECK(std::abs(cam.K(0, 0) / f - 1) < 0.01);
  CHECK(std::abs(cam.K(1, 1) / f - 1) < 0.01);
  CHECK(std::abs(cam.K(0, 2) - cx) < 10);
  CHECK(std::abs(cam.K(1, 2) - cy) < 10);
  CHECK(rep.used.size() >= 6);
  CHECK(std::filesystem::exists(dir.file("fit.png")));
}

TEST_CASE("real checkerboard images give the lab's focal length within 1%", "[calib][real]") {
  INFO("real data missing: run scripts/fetch-real-data.sh (scripts/test.sh does)");
  REQUIRE(std::filesystem::exists(kDemo + "/calibration/intrinsics/int_cam2_img"));
  const Calibration lab = read_calibration_toml(kDemo + "/calibration/Calib_qualisys.toml");
  IntrinsicsReport rep;
  testing::TempDir dir;
  const Camera cam = calibrate_intrinsics(kDemo + "/calibration/intrinsics/int_cam2_img",
                                          parse_board("checkerboard:4x7:0.06"), &rep, dir.file("fit.png"));
  const cv::Mat overlay = cv::imread(dir.file("fit.png"));
  REQUIRE(overlay.cols == 1088);
  REQUIRE(overlay.rows == 1920);
  INFO("fx " << cam.K(0, 0) << " vs lab " << lab[1].K(0, 0) << ", RMS " << rep.rms_px << " px, used " << rep.used.size());
  CHECK(std::abs(cam.K(0, 0) / lab[1].K(0, 0) - 1) < 0.01);
  CHECK(std::abs(cam.K(1, 1) / lab[1].K(1, 1) - 1) < 0.01);
  CHECK(std::abs(cam.K(0, 2) - lab[1].K(0, 2)) < 30);
  CHECK(rep.rms_px < 1.0);
  CHECK(rep.used.size() >= 3);
}

namespace {

// Extrinsics from a recording of a person, aligned onto the lab's Qualisys cameras by a similarity: the worst
// camera-centre distance (metres).
double worst_centre_vs_lab(const std::string& keypoints, octocap_calibration_report_t& rep) {
  octocap_calibration_t* lab = nullptr;
  REQUIRE(octocap_calibration_load((kDemo + "/calibration/Calib_qualisys.toml").c_str(), &lab) == OCTOCAP_OK);
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open(keypoints.c_str(), OCTOCAP_LAYOUT_AUTO, &rec) == OCTOCAP_OK);
  octocap_extrinsics_options_t opt;
  octocap_extrinsics_options_init(&opt);
  opt.person_height_m = 1.7f;
  opt.up_axis = OCTOCAP_UP_Z;
  octocap_calibration_t* got = nullptr;
  const octocap_result_t r = octocap_calibration_solve_extrinsics(lab, rec, &opt, &got, &rep);
  INFO(octocap_last_error());
  REQUIRE(r == OCTOCAP_OK);
  Calibration a, b;
  for (uint32_t i = 0; i < 4; ++i) {
    octocap_camera_t c;
    octocap_calibration_get_camera(lab, i, &c);
    Camera ca;
    ca.R = rodrigues_to_matrix({c.rotation[0], c.rotation[1], c.rotation[2]});
    ca.t = {c.translation[0], c.translation[1], c.translation[2]};
    a.push_back(ca);
    octocap_calibration_get_camera(got, i, &c);
    Camera cb;
    cb.R = rodrigues_to_matrix({c.rotation[0], c.rotation[1], c.rotation[2]});
    cb.t = {c.translation[0], c.translation[1], c.translation[2]};
    b.push_back(cb);
  }
  const Eigen::Matrix4d T = align(a, b, true);
  double worst = 0;
  for (size_t i = 0; i < 4; ++i)
    worst = std::max(worst, ((T * b[i].center().homogeneous()).head<3>() - a[i].center()).norm());
  octocap_calibration_destroy(got);
  octocap_recording_destroy(rec);
  octocap_calibration_destroy(lab);
  return worst;
}

}  // namespace

TEST_CASE("real keypoints of a person give the lab's camera layout", "[calib][real]") {
  REQUIRE(std::filesystem::exists(kDemo + "/pose"));
  octocap_calibration_report_t rep;
  const double worst = worst_centre_vs_lab(kDemo + "/pose", rep);
  INFO("worst camera centre vs Qualisys " << worst * 1000 << " mm; BA RMS " << rep.final_rms_px << " px");
  CHECK(worst < 0.10);
  CHECK(rep.points > 1000);
}

#ifdef OCTOCAP_HAVE_ONNXRUNTIME  // needs the detector
TEST_CASE("markerless end to end: the lab's cameras from their own videos, through octocap's detector", "[calib][real]") {
  // Pose2Sim's 4 videos -> octocap detect (MoveNet, crops) -> extrinsics from the person -> the Qualisys layout.
  testing::TempDir dir;
  const std::string videos = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos";
  const testing::Run r = testing::run_command(std::string(OCTOCAP_CLI_PATH) + " detect --images " + videos +
                                              " --output " + dir.file("kp") + " --detect-threads 1 --quiet");
  INFO(r.output);
  REQUIRE(r.status == 0);
  octocap_calibration_report_t rep;
  const double worst = worst_centre_vs_lab(dir.file("kp"), rep);
  INFO("worst camera centre vs Qualisys " << worst * 1000 << " mm; BA RMS " << rep.final_rms_px << " px");
  CHECK(worst < 0.15);
  CHECK(rep.final_rms_px < 10);
}
#endif

