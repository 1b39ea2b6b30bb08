// Ground truth the tests make: cameras with distortion around a volume, real human motion (CMU mocap,
// Debian's assimp-testmodels) turned into keypoints, projected with noise, gaps and wrong detections.
#pragma once
#include <array>
#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/layout.h"
#include "io/openpose_json.h"

namespace octocap::internal::synth {

struct RigOptions {
  int cameras = 5;
  double radius = 4.0;      // metres from the volume centre
  int width = 1280, height = 720;
  double focal = 1000;      // px
  bool distortion = true;   // a different, realistic lens per camera
  unsigned seed = 7;
};
Calibration make_camera_ring(const RigOptions& options);

// 3D keypoints per frame in the BODY_25 order (plus nothing else), metres, Y up, centred on the origin
// with the feet on the floor.
struct Motion {
  std::vector<std::vector<Eigen::Vector3d>> frames;
  double rate_hz = 30;
  // Per frame, the hands' knuckles (BLAZEPOSE_33's RIndex, RPinky, LIndex, LPinky), rigid on the hands' frames.
  std::vector<std::array<Eigen::Vector3d, 4>> knuckles;
};
std::string default_bvh_path();  // CMU subject 1, trial 1
// Frames [first, first + count*step) of a CMU BVH, every `step`-th, as BODY_25 keypoints.
// toes_on_foot: the toes rigid on the foot's frame (the foot's true rotation is then that of the BVH's foot joint).
Motion load_cmu_motion(const std::string& bvh_path, size_t first, size_t count, size_t step, bool toes_on_foot = false);
// BODY_25 keypoints -> another layout by keypoint name (NaN where the layout has a point BODY_25 lacks:
// BODY_25B/HALPE "Head" is made from the ears and nose instead).
std::vector<Eigen::Vector3d> to_layout(const std::vector<Eigen::Vector3d>& body25, LayoutId layout);
// Frame `n` of a motion in another layout, its knuckles included (BLAZEPOSE_33's foot index is the big toe).
std::vector<Eigen::Vector3d> to_layout(const Motion& motion, size_t n, LayoutId layout);

struct NoiseOptions {
  double pixel_sigma = 1.0;   // Gaussian detection noise, px
  double missing = 0.03;      // chance a keypoint is not detected in a view
  double outlier = 0.02;      // chance a keypoint is detected somewhere wrong (confidently)
  double swap = 0.02;         // chance a view swaps left and right for the whole person
};

// One person per view (or none when the person is outside the image). `truth` in `layout` order.
std::vector<std::vector<Person2D>> observe(const Calibration& calib, const std::vector<Eigen::Vector3d>& truth,
                                           LayoutId layout, const NoiseOptions& noise, std::mt19937& rng);

// Flattens people[view] into the C ABI's keypoint array + counts.
struct FlatFrame {
  std::vector<float> xyc;  // x, y, confidence triples
  std::vector<uint32_t> people_per_view;
};
FlatFrame flatten(const std::vector<std::vector<Person2D>>& people);

}  // namespace octocap::internal::synth
