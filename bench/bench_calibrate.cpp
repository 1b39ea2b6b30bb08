// Calibration benchmark: the whole extrinsics solve (pairwise essential matrix, PnP, two rounds of Ceres bundle
// adjustment) from person keypoints, for 4 and 8 cameras and 500 / 5000 frames of CMU motion (1 px noise,
// 3 % missed, 2 % wrong detections).
#include <chrono>
#include <cstdio>
#include <random>

#include "calib/extrinsics.h"
#include "synth.h"

using namespace octocap::internal;

int main() {
  std::printf("extrinsics from person keypoints (25 per frame), 2 cores\n\n");
  std::printf("%7s %7s | %9s %9s %10s %10s\n", "cameras", "frames", "time s", "points", "RMS px", "BA iters");
  const synth::Motion all = synth::load_cmu_motion(synth::default_bvh_path(), 0, 2752, 1);
  for (int cams : {4, 8}) {
    synth::RigOptions rig;
    rig.cameras = cams;
    const Calibration truth = synth::make_camera_ring(rig);
    for (size_t frames : {500, 5000}) {
      std::mt19937 rng(1);
      std::vector<std::vector<std::vector<Person2D>>> obs;
      for (size_t f = 0; f < frames; ++f)
        obs.push_back(synth::observe(truth, all.frames[f % all.frames.size()], LayoutId::body25, {1.0, 0.03, 0.02, 0}, rng));
      ExtrinsicsOptions opt;
      opt.person_height_m = 1.75;
      opt.max_frames = frames;  // no subsampling: time the full problem
      ExtrinsicsReport rep;
      const auto t0 = std::chrono::steady_clock::now();
      calibrate_extrinsics(truth, obs, LayoutId::body25, opt, &rep);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("%7d %7zu | %9.2f %9zu %10.2f %10d\n", cams, frames, s, rep.points, rep.final_rms_px, rep.iterations);
    }
  }
  return 0;
}
