// One capture session: person selection -> 3D solve -> temporal filter -> skeleton joints -> bone rotations.
// The C ABI's session is a thin shell over this class.
#pragma once
#include <Eigen/Geometry>
#include <array>
#include <map>
#include <memory>
#include <vector>

#include "core/camera.h"
#include "core/layout.h"
#include "core/frame_sink.h"
#include "core/parallel.h"
#include "detect/detector.h"
#include "core/frame.h"
#include "stream/stream_config.h"
#include "io/openpose_json.h"
#include "rig/bone_solver.h"
#include "rig/foot_lock.h"
#include "solve/observation.h"
#include "solve/one_euro.h"
#include "solve/person_tracks.h"

namespace octocap::internal {

class ViewOrderCheck;

// More 2D people than this in one view is no capture (a crowd, a detector gone wrong): refused.
constexpr uint32_t kMaxPeoplePerView = 64;
// The most people one frame holds (max_people = 0, "all of them").
constexpr uint32_t kMaxPeople = 16;

enum class Method : int { subdivision = 0, triangulation = 1, automatic = 2 };
enum class UpAxis : int { y = 0, z = 1, automatic = 2 };

struct SessionConfig {
  LayoutId layout = LayoutId::body25;
  Method method = Method::automatic;
  bool filter = true;
  // The filter's minimum cutoff follows each keypoint's measured noise (its reprojection error, smoothed): a clean
  // keypoint is smoothed less, a noisy one more (docs/benchmarks.md "Choosing the defaults").
  bool filter_adaptive = true;
  UpAxis up = UpAxis::automatic;
  int sigma = 0;  // 0: camera count - 1, at least 2
  int min_views = 2;
  double delta = 0.01;
  double pixel_tolerance = 4;
  int max_candidates = 8;
  double min_confidence = 0.3;
  double outlier_threshold_px = 15;
  Eigen::Vector3d volume_min = Eigen::Vector3d::Zero();  // min == max: derived from the calibration
  Eigen::Vector3d volume_max = Eigen::Vector3d::Zero();
  double filter_min_cutoff = 1.5;
  double filter_beta = 20.0;
  // Feet in contact with the floor are reported either way; with foot_lock their ankles are held while planted
  // (rig/foot_lock.h: 2-4x less sliding from pixels for +-0.2 mm MPJPE; docs/command-line.md has the figures).
  bool foot_lock = true;
  unsigned threads = 0;
  int64_t first_frame_index = 0;  // frame numbers start here (a capture resumed mid-take keeps its numbering)
  // 1: one person (the one the views agree on, followed over time); N > 1: up to N people, associated across views
  // and tracked with stable ids; 0: as many as are there (up to kMaxPeople).
  uint32_t max_people = 1;
  bool publish = false;           // stream every frame over DDS
  StreamConfig stream;
  uint16_t vmc_port = 0;          // 0: no VMC output
  std::string vmc_host = "127.0.0.1";
  DetectorConfig detector;        // for solve_images() unless set_detector(); loaded on first use

  // Every value checked against itself and a rig of `cameras` cameras, and every per-frame cost bounded: a config
  // that could take seconds a frame is refused. Throws Error(invalid_argument) naming the first field out of range.
  // The one home of these rules: the Session constructor and the C ABI (through it) both come here.
  void validate(int cameras) const;
};



// A view whose 2D people were detected elsewhere (a capture node), in a picture of width x height pixels.
struct GivenView {
  const std::vector<Person2D>* people = nullptr;  // null: the view has no given people
  int width = 0, height = 0;
};

class Session {
 public:
  Session(const SessionConfig& config, Calibration calib);
  ~Session();

  // people[view][person]; throws Error(camera_mismatch / invalid_argument). Returns false when too few views
  // saw a person: the frame then holds nobody (all missing) and the session goes on.
  bool solve(const std::vector<std::vector<Person2D>>& people, int64_t timestamp_us);
  // Detects people in one image per camera (calibration order), then solve(). Throws as solve() does, and
  // Error(invalid_argument) for bad images or a model whose layout is not the session's. (session_images.cpp)
  // `given` (empty, or one per camera): views whose people are given instead (their image absent); the detector
  // runs only when some image is there.
  bool solve_images(const std::vector<ImageView>& images, int64_t timestamp_us, const std::vector<GivenView>& given = {});
  // Loads the detector solve_images() uses now (else the config's, on first use). Throws for a model of another
  // layout than the session's.
  void set_detector(const DetectorConfig& config);
  // What the detector found in each view during the last solve_images(), view pixels.
  const std::vector<std::vector<DetectedPerson>>& detections() const { return detections_; }
  // The 2D people the last solve_images() solved, per view in calibration pixels (what solve() would take again).
  const std::vector<std::vector<Person2D>>& image_people() const { return image_people_; }
  const Detector* detector() const { return detector_.get(); }
  Detector* detector() { return detector_.get(); }  // between solves: the live engine's rate governor steers it
  void reset();
  // Blocks until every published frame has been handed to DDS (no-op without publishing).
  void flush_stream();
  // Matched readers of this session's pose stream (0 when not streaming).
  uint32_t stream_readers() const;

  bool has_result() const { return solved_any_; }
  const FrameResult& result() const { return frame_; }
  const FrameInfo& frame_info() const { return frame_.info; }
  // Person `i` of the last frame, or the blank person (all missing) when there is no such person.
  const PersonResult& person(size_t i = 0) const { return frame_.person_or_blank(i); }
  const std::vector<PointResult>& keypoints() const { return person().keypoints; }
  const std::array<PointResult, kJointCount>& joints() const { return person().joints; }
  const SkeletonPose& bones() const { return person().bones; }
  const std::vector<int>& selected_people() const { return person().selected; }
  const SessionConfig& config() const { return config_; }
  const Calibration& calibration() const { return calib_; }
  const KeypointLayout& keypoint_layout() const { return *layout_; }
  const Eigen::AlignedBox3d& volume() const { return volume_; }
  int effective_sigma() const { return sigma_; }
  bool z_up() const { return z_up_; }
  Method method() const { return method_; }

 private:
  // What one person carries from frame to frame: the unfiltered pose (the one person's selection follows it), the
  // filters, the rolls.
  struct PersonState {
    std::vector<Eigen::Vector3d> raw_previous;  // empty when unknown
    std::vector<OneEuroFilter3> filters;
    std::vector<double> noise_px;  // per keypoint, the smoothed reprojection error (0: none yet)
    BoneSolver bone_solver;
    FootLock feet;
    // Per keypoint, how far foot_lock moved it this frame (world frame; empty: nothing moved). The crops follow the
    // measured person, not the locked one: a lock must not change what the network is shown next.
    std::vector<Eigen::Vector3d> lock_shift;
  };
  PersonState new_person_state() const;
  PointResult solve_keypoint(const std::vector<ViewRay>& rays) const;
  // The 3D keypoints of the person made of `choice` (the 2D person per view, -1 none), unfiltered.
  std::vector<PointResult> solve_points(const std::vector<std::vector<Person2D>>& usable,
                                        const std::vector<int>& choice) const;
  // The valid keypoints' positions, NaN elsewhere.
  static std::vector<Eigen::Vector3d> raw_pose(const std::vector<PointResult>& keypoints);
  // Filters the person's keypoints with its state, then derives its joints and bones.
  void finish_person(PersonResult& person, PersonState& state, double dt) const;
  // The adaptive filter's factor on the minimum cutoff for this sample; updates the keypoint's noise estimate.
  double noise_cutoff_scale(const PointResult& r, double& noise_px) const;
  void solve_one(const std::vector<std::vector<Person2D>>& usable, const std::vector<std::vector<int>>& original,
                 double dt);
  void solve_several(const std::vector<std::vector<Person2D>>& usable, const std::vector<std::vector<int>>& original,
                     double dt, int64_t timestamp_us);
  void clear_frame();
  void publish();

  SessionConfig config_;
  Calibration calib_;
  const KeypointLayout* layout_;
  Eigen::AlignedBox3d volume_;
  int sigma_ = 2;
  bool z_up_ = false;
  Method method_ = Method::subdivision;
  std::unique_ptr<WorkerPool> pool_;
  std::unique_ptr<ViewOrderCheck> view_order_;  // are the views in the calibration's order?
  std::vector<std::unique_ptr<FrameSink>> sinks_;  // DDS stream, VMC: fed every frame

  std::vector<std::vector<Person2D>> reprojected_people() const;
  const PersonState* state_of(uint32_t id) const;  // the person's state (the one person's when max_people is 1)
  // The person's keypoints where they were measured, before foot_lock held any (NaN: not solved this frame).
  std::vector<Eigen::Vector3d> measured_keypoints(const PersonResult& person) const;
  // Each solved person's every keypoint, where it was last seen, moved along with the person since (NaN: never seen).
  void remember_whole_people();
  std::map<uint32_t, std::vector<Eigen::Vector3d>> whole_people_;

  std::unique_ptr<Detector> detector_;
  std::vector<std::vector<DetectedPerson>> detections_;
  std::vector<std::vector<Person2D>> image_people_;
  FrameResult frame_;
  PersonState single_;                          // max_people == 1: the one person
  std::unique_ptr<PersonTracks> tracks_;        // max_people != 1: identities
  std::map<uint32_t, PersonState> states_;      // max_people != 1: per track id
  // The layout's face keypoints (-1 where it has none), for the head's turn.
  int nose_ = -1, l_eye_ = -1, r_eye_ = -1, l_ear_ = -1, r_ear_ = -1;
  // ... and its hand points (index and little finger knuckles), for the palms' roll.
  int r_index_ = -1, r_pinky_ = -1, l_index_ = -1, l_pinky_ = -1;
  int64_t last_timestamp_us_ = 0;
  bool has_timestamp_ = false;
  bool solved_any_ = false;
};

}  // namespace octocap::internal
