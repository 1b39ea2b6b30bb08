#include "synth.h"

#include <Eigen/Geometry>
#include <cmath>
#include <tuple>
#include <utility>
#include <limits>

#include "io/bvh.h"

namespace octocap::internal::synth {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kCmuUnit = 0.0254 / 0.45;  // CMU BVH units are 1/0.45 inch

}  // namespace

Calibration make_camera_ring(const RigOptions& o) {
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> jitter(-1, 1);
  Calibration calib;
  for (int i = 0; i < o.cameras; ++i) {
    const double a = 2 * M_PI * i / o.cameras + 0.15 * jitter(rng);
    const Eigen::Vector3d centre(o.radius * std::sin(a), 1.6 + 0.5 * jitter(rng), o.radius * std::cos(a));
    const Eigen::Vector3d target(0.2 * jitter(rng), 1.0, 0.2 * jitter(rng));
    // Camera axes: z toward the target, y toward image-down (world down), x = y cross z.
    const Eigen::Vector3d z = (target - centre).normalized();
    const Eigen::Vector3d x = (-Eigen::Vector3d::UnitY()).cross(z).normalized();
    const Eigen::Vector3d y = z.cross(x);
    Camera c;
    c.name = "cam_" + std::to_string(i + 1);
    c.width = o.width;
    c.height = o.height;
    const double f = o.focal * (1 + 0.05 * jitter(rng));
    c.K << f, 0, o.width / 2.0 + 10 * jitter(rng), 0, f * (1 + 0.002 * jitter(rng)), o.height / 2.0 + 10 * jitter(rng),
        0, 0, 1;
    if (o.distortion) c.dist = {-0.12 + 0.05 * jitter(rng), 0.03 * jitter(rng), 0.001 * jitter(rng),
                                0.001 * jitter(rng), 0.01 * jitter(rng)};
    c.R.row(0) = x;
    c.R.row(1) = y;
    c.R.row(2) = z;
    c.t = -c.R * centre;
    calib.push_back(c);
  }
  return calib;
}

std::string default_bvh_path() { return "/usr/share/assimp/models/BVH/01_01.bvh"; }

Motion load_cmu_motion(const std::string& path, size_t first, size_t count, size_t step, bool toes_on_foot) {
  const BvhMotion bvh = read_bvh(path);
  auto idx = [&](const char* n) {
    const int i = bvh.find(n);
    if (i < 0) throw std::runtime_error(path + ": no joint " + n);
    return i;
  };
  const int hips = idx("Hips"), head = idx("Head"), head_end = idx("Head_end");
  const int ls = idx("LeftArm"), le = idx("LeftForeArm"), lw = idx("LeftHand");
  const int rs = idx("RightArm"), re = idx("RightForeArm"), rw = idx("RightHand");
  const int lh = idx("LeftUpLeg"), lk = idx("LeftLeg"), la = idx("LeftFoot");
  const int rh = idx("RightUpLeg"), rk = idx("RightLeg"), ra = idx("RightFoot");
  const int lt = idx("LeftToeBase_end"), rt = idx("RightToeBase_end");
  // Toes where the toe tip is at rest in the foot's own frame (toes_on_foot), else where the take's bent toe joint
  // puts them (a few degrees, std 6-9 deg in 01_01).
  auto toe_tip = [&](const char* toe) {
    const int t = idx(toe), end = idx((std::string(toe) + "_end").c_str());
    return Eigen::Vector3d((bvh.joints[t].offset + bvh.joints[end].offset) * kCmuUnit);
  };
  const Eigen::Vector3d l_toe = toe_tip("LeftToeBase"), r_toe = toe_tip("RightToeBase");
  Motion m;
  m.rate_hz = 1.0 / (bvh.frame_time * step);
  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Matrix3d> R;
  auto toes = [&](int foot, int tip, const Eigen::Vector3d& rest, const Eigen::Vector3d& small) {
    const Eigen::Vector3d big = toes_on_foot ? Eigen::Vector3d(P[foot] + R[foot] * rest) : P[tip];
    return std::pair<Eigen::Vector3d, Eigen::Vector3d>{big, big + R[foot] * small};
  };
  // Face and foot points hang off the head and feet in the rest pose's frame (left +X, up +Y, forward +Z).
  const Eigen::Vector3d L = Eigen::Vector3d::UnitX(), U = Eigen::Vector3d::UnitY(), F = Eigen::Vector3d::UnitZ();
  for (size_t n = 0; n < count; ++n) {
    const size_t f = first + n * step;
    if (f >= bvh.frames.size()) break;
    bvh.pose(f, P, R);
    for (auto& p : P) p *= kCmuUnit;
    const Eigen::Vector3d hc = 0.5 * (P[head] + P[head_end]);  // middle of the head
    auto on_head = [&](const Eigen::Vector3d& off) { return Eigen::Vector3d(hc + R[head] * off); };
    auto on_joint = [&](int j, const Eigen::Vector3d& off) { return Eigen::Vector3d(P[j] + R[j] * off); };
    std::vector<Eigen::Vector3d> k(25);
    k[0] = on_head(0.10 * F);                                 // Nose
    k[1] = 0.5 * (P[rs] + P[ls]);                             // Neck: OpenPose puts it between the shoulders
    k[2] = P[rs], k[3] = P[re], k[4] = P[rw];                 // right arm
    k[5] = P[ls], k[6] = P[le], k[7] = P[lw];                 // left arm
    k[8] = P[hips];                                           // MidHip
    k[9] = P[rh], k[10] = P[rk], k[11] = P[ra];               // right leg
    k[12] = P[lh], k[13] = P[lk], k[14] = P[la];              // left leg
    k[15] = on_head(0.08 * F + 0.03 * U - 0.035 * L);         // REye
    k[16] = on_head(0.08 * F + 0.03 * U + 0.035 * L);         // LEye
    k[17] = on_head(-0.075 * L);                              // REar
    k[18] = on_head(0.075 * L);                               // LEar
    std::tie(k[19], k[20]) = toes(la, lt, l_toe, 0.05 * L - 0.02 * F);   // LBigToe, LSmallToe
    k[21] = on_joint(la, -0.06 * F - 0.06 * U);                // LHeel
    std::tie(k[22], k[23]) = toes(ra, rt, r_toe, -0.05 * L - 0.02 * F);  // RBigToe, RSmallToe
    k[24] = on_joint(ra, -0.06 * F - 0.06 * U);                // RHeel
    m.frames.push_back(std::move(k));
    // Knuckles 9 cm out along the hand, index in front of the little finger (palm down at rest).
    m.knuckles.push_back({on_joint(rw, -0.09 * L + 0.035 * F), on_joint(rw, -0.08 * L - 0.035 * F),
                          on_joint(lw, 0.09 * L + 0.035 * F), on_joint(lw, 0.08 * L - 0.035 * F)});
  }
  // Centre the take on the origin, feet on the floor.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double floor = std::numeric_limits<double>::infinity();
  for (const auto& fr : m.frames) {
    mean += fr[8];
    for (const auto& p : fr) floor = std::min(floor, p.y());
  }
  mean /= static_cast<double>(m.frames.size());
  for (auto& fr : m.frames)
    for (auto& p : fr) p -= Eigen::Vector3d(mean.x(), floor, mean.z());
  for (auto& fr : m.knuckles)
    for (auto& p : fr) p -= Eigen::Vector3d(mean.x(), floor, mean.z());
  return m;
}

std::vector<Eigen::Vector3d> to_layout(const std::vector<Eigen::Vector3d>& body25, LayoutId id) {
  const KeypointLayout& src = layout(LayoutId::body25);
  const KeypointLayout& dst = layout(id);
  std::vector<Eigen::Vector3d> out;
  for (const char* name : dst.keypoints) {
    const std::string n = name;
    Eigen::Vector3d p = Eigen::Vector3d::Constant(kNan);
    for (size_t k = 0; k < src.keypoints.size(); ++k)
      if (n == src.keypoints[k]) p = body25[k];
    if (n == "Head") p = 0.5 * (body25[17] + body25[18]) + Eigen::Vector3d(0, 0.08, 0);
    if (n == "Hip") p = body25[8];
    out.push_back(p);
  }
  return out;
}

std::vector<Eigen::Vector3d> to_layout(const Motion& motion, size_t n, LayoutId id) {
  std::vector<Eigen::Vector3d> out = to_layout(motion.frames[n], id);
  const KeypointLayout& dst = layout(id);
  const char* const knuckle_names[4] = {"RIndex", "RPinky", "LIndex", "LPinky"};
  for (size_t k = 0; k < dst.keypoints.size(); ++k) {
    const std::string name = dst.keypoints[k];
    for (int i = 0; i < 4; ++i)
      if (n < motion.knuckles.size() && name == knuckle_names[i]) out[k] = motion.knuckles[n][i];
    if (name == "RFootIndex") out[k] = motion.frames[n][22];  // the big toe
    if (name == "LFootIndex") out[k] = motion.frames[n][19];
  }
  return out;
}

std::vector<std::vector<Person2D>> observe(const Calibration& calib, const std::vector<Eigen::Vector3d>& truth,
                                           LayoutId id, const NoiseOptions& noise, std::mt19937& rng) {
  const KeypointLayout& l = layout(id);
  std::normal_distribution<double> gauss(0, noise.pixel_sigma);
  std::uniform_real_distribution<double> u01(0, 1);
  std::vector<std::vector<Person2D>> views(calib.size());
  for (size_t v = 0; v < calib.size(); ++v) {
    const Camera& c = calib[v];
    Person2D person(truth.size());
    int visible = 0;
    for (size_t k = 0; k < truth.size(); ++k) {
      if (!truth[k].allFinite()) continue;
      const Eigen::Vector2d p = c.project(truth[k]);
      if (!p.allFinite() || p.x() < 0 || p.y() < 0 || p.x() >= c.width || p.y() >= c.height) continue;
      ++visible;
      if (u01(rng) < noise.missing) continue;
      if (u01(rng) < noise.outlier) {
        // A confident detection on something else in the image.
        person[k] = {u01(rng) * c.width, u01(rng) * c.height, 0.5 + 0.4 * u01(rng)};
        continue;
      }
      person[k] = {p.x() + gauss(rng), p.y() + gauss(rng), 0.6 + 0.4 * u01(rng)};
    }
    if (visible < 3) continue;
    if (u01(rng) < noise.swap)
      for (const auto& [a, b] : l.mirror_pairs) std::swap(person[a], person[b]);
    views[v].push_back(std::move(person));
  }
  return views;
}

FlatFrame flatten(const std::vector<std::vector<Person2D>>& people) {
  FlatFrame f;
  for (const auto& v : people) {
    f.people_per_view.push_back(static_cast<uint32_t>(v.size()));
    for (const auto& p : v)
      for (const auto& k : p) {
        f.xyc.push_back(static_cast<float>(k.x));
        f.xyc.push_back(static_cast<float>(k.y));
        f.xyc.push_back(static_cast<float>(k.confidence));
      }
  }
  return f;
}

}  // namespace octocap::internal::synth
