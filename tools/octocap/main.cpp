// octocap: the command line. `octocap solve` turns a multi-camera 2D keypoint recording into 3D.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "octocap/octocap.h"
#include "solve_command.h"

int main(int argc, char** argv) {
  CLI::App app{"octocap: markerless multi-camera motion capture"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("octocap ") + octocap_version());

  SolveOptions solve;
  CLI::App* sc = app.add_subcommand("solve", "Solve a recording of 2D keypoints (OpenPose JSON) into 3D (TRC/CSV)");
  sc->add_option("--calibration", solve.calibration, "Calibration TOML (anipose / Pose2Sim)")->required()->check(CLI::ExistingFile);
  sc->add_option("--keypoints", solve.keypoints, "Folder with one OpenPose JSON sub-folder per camera")->required()->check(CLI::ExistingDirectory);
  sc->add_option("--output", solve.output, "Output TRC file")->required();
  sc->add_option("--csv", solve.csv, "Also write a CSV (calibration world frame)");
  sc->add_option("--bvh", solve.bvh, "Also write the bone animation as BVH (Y up, centimetres)");
  sc->add_option("--method", solve.method, "3D method (auto: subdivision with 5+ cameras, else triangulation)")->check(CLI::IsMember({"auto", "subdivision", "triangulation"}))->capture_default_str();
  sc->add_option("--sigma", solve.sigma, "Views a cube must be supported by (0: cameras - 1)")->capture_default_str();
  sc->add_option("--delta-mm", solve.delta_mm, "Smallest cube edge, mm")->check(CLI::PositiveNumber)->capture_default_str();
  sc->add_option("--filter", solve.filter, "Temporal filter")->check(CLI::IsMember({"none", "oneeuro"}))->capture_default_str();
  sc->add_option("--layout", solve.layout, "Keypoint layout: auto, BODY_25, BODY_25B, COCO_17, HALPE_26")->capture_default_str();
  sc->add_option("--up", solve.up, "World up axis of the calibration")->check(CLI::IsMember({"auto", "y", "z"}))->capture_default_str();
  sc->add_option("--rate", solve.rate_hz, "Frame rate of the recording, Hz")->check(CLI::PositiveNumber)->capture_default_str();
  sc->add_option("--threads", solve.threads, "Worker threads (0: all cores)")->capture_default_str();
  sc->add_option("--ground-truth", solve.ground_truth, "CSV of true 3D keypoints: report the error against it")->check(CLI::ExistingFile);
  sc->add_flag("--quiet", solve.quiet, "No progress on stderr");
  sc->add_flag("--publish", solve.publish, "Stream every frame over DDS, paced at --rate");
  sc->add_option("--publish-qos", solve.publish_qos, "live (best effort, newest only) or record (reliable, late joiners get history)")
      ->check(CLI::IsMember({"live", "record"}))->capture_default_str();
  sc->add_option("--domain", solve.domain, "DDS domain id")->check(CLI::Range(0, 232))->capture_default_str();
  sc->add_option("--topic", solve.topic, "DDS topic base name")->capture_default_str();
  sc->add_option("--source-id", solve.source_id, "This rig's id on the topic")->capture_default_str();
  sc->add_option("--start-frame", solve.start_frame, "Skip the recording's first frames (numbering keeps their index)")->capture_default_str();
  sc->add_option("--wait-subscribers", solve.wait_subscribers, "With --publish: wait (up to 10 s) for this many subscribers before the first frame")->capture_default_str();
  sc->add_option("--vmc-port", solve.vmc_port, "Also send VMC protocol (OSC/UDP) to this port (VMC's usual: 39539); paced at --rate")
      ->check(CLI::Range(0, 65535));
  sc->add_option("--vmc-host", solve.vmc_host, "VMC receiver host")->capture_default_str();
  sc->add_option("--linger-s", solve.linger_s, "With --publish: stay on the network this long after the last frame")->capture_default_str();

  CLI::App* lc = app.add_subcommand("layouts", "List the keypoint layouts and their keypoints");

  CLI11_PARSE(app, argc, argv);
  if (sc->parsed()) return run_solve(solve);
  if (lc->parsed()) return run_layouts();
  return 0;
}
