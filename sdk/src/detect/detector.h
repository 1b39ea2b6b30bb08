// 2D detection for N views: per view (one inference each), the paper's mosaic (one inference for all), or crops
// around where the person was (one inference each, on more pixels of the person). Keypoints come back in each
// view's own pixel coordinates.
#pragma once
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "detect/decoders.h"
#include "detect/flow_tracker.h"
#include "detect/image.h"
#include "detect/model_card.h"
#include "detect/mosaic.h"
#include "detect/person_pick.h"
#include "detect/pose_network.h"

namespace octocap::internal {

enum class DetectMode : int { per_view = 0, mosaic = 1, crop = 2 };

struct DetectorConfig {
  std::string model;  // a path to a .onnx (its card beside it) or a shipped model's name; empty: the mode's default
  DetectMode mode = DetectMode::crop;  // the most accurate of the three at per-view cost (docs/detecting.md)
  PersonPick pick = PersonPick::all;
  int threads = 0;           // inference threads per view; 0 = the back end's default (all cores / parallel views)
  // Views inferred at once (per view and crop); 0 = as many as cores: every session has 2+ cameras
  // (docs/benchmarks.md "From images").
  int parallel_views = 0;
  int mosaic_tile = 256;     // mosaic cell height in pixels (the width follows the views' aspect)
  size_t max_people = 4;     // per view, for PersonPick::all (and the crops of several people)
  double min_confidence = 0.3;
  // Crop mode, several people: a crop per hinted person, and with a multi-person model a whole-view pass every
  // new_people_every-th frame of a view that has fewer than max_people, for people not yet followed. The session
  // turns it on when it solves several people. Off: one person, as always.
  bool find_new_people = false;
  int new_people_every = 10;
  // Detection scheduling (per view and crop): at most this many views run the network each frame, the others follow
  // their people from their last picture by optical flow (FlowTracker). Views that cannot be followed (no person,
  // no last picture, a track that lost half its keypoints) are detected anyway; of the rest, the views detected
  // longest ago. 0: every view every frame.
  int views_per_frame = 0;
  Device device = Device::cpu;  // a GPU only when asked: AUTO would load CUDA libraries a CPU user never needs
  // Also load the model card's lighter model (its "lighter" key), for a caller that trades accuracy for time set by
  // set (the live engine's rate governor, use_network()). Per view and crop only.
  bool load_lighter = false;
  // The inference back end and its arithmetic (detect/pose_network.h).
  Runtime runtime = Runtime::automatic;
  Precision precision = Precision::automatic;

  // Every value in range (enums known, counts bounded, the confidence finite). Throws Error(invalid_argument) naming
  // the field. The one home of these rules: the Detector constructor and the C ABI's mapping both come here, the
  // latter so that a session's detector config is refused when given, not when its first picture arrives.
  void validate() const;
};

struct DetectTimings {
  double total_ms = 0, preprocess_ms = 0, inference_ms = 0;
  double track_ms = 0;  // optical flow: the pictures made ready (every view) and the tracked views followed
  int inferences = 0;
  int views_tracked = 0;  // views followed by optical flow instead of detected
};

// Whether this CPU has VNNI (AVX-512 VNNI or AVX-VNNI): the integer dot products INT8 models need to be fast; without
// them ONNX Runtime's U8S8 kernels can saturate (measured on an AVX2-only CPU: INT8 Thunder 42 mm from Pose2Sim's 3D
// where the float model is 35, and hardly faster).
bool cpu_has_vnni();

// Where shipped models live: $OCTOCAP_MODELS_DIR, else the directory the build was configured with.
std::string models_directory();
// The .onnx a config names (a path, or a name looked up in models_directory()).
std::string resolve_model_path(const std::string& model, DetectMode mode);

class Detector {
 public:
  // Throws Error(io / parse / invalid_argument / unsupported) for a missing or unfit model.
  explicit Detector(const DetectorConfig& config);
  ~Detector();

  // people[view], best first, in the views' pixels. Throws Error(invalid_argument) for a bad image.
  std::vector<std::vector<DetectedPerson>> detect(const std::vector<ImageView>& views);
  // Where people are expected in each view next frame (the last 3D people reprojected): hints[view][person], the
  // person followed first; an empty list or person means no hint. The crop mode crops each (up to max_people with
  // find_new_people, else the first); PersonPick::nearest_previous uses the first.
  // A hint keypoint at a confidence under the detector's threshold (down to kHintConfidence) still shapes the crop
  // but is not matched against: where it was last seen, not where it is.
  void set_hints(std::vector<std::vector<Person2D>> hints) { hints_ = std::move(hints); }
  static constexpr double kHintConfidence = 0.01;

  // The card of the network running now (all networks give the same layout and number of people).
  const ModelCard& card() const { return card_; }
  // Networks loaded: the model named, then its lighter one where load_lighter found one.
  size_t networks() const { return networks_.size(); }
  size_t active_network() const { return active_; }
  // From the next detect(): which network runs, and on how many views (views_per_frame). Between detect()s only.
  void use_network(size_t network, int views_per_frame);
  const DetectorConfig& config() const { return config_; }
  const std::string& model_path() const { return path_; }
  const DetectTimings& timings() const { return timings_; }
  // Where the network runs: cpu or cuda (automatic resolved when the model was loaded).
  Device device() const;
  // The back end and precision the active network runs in (automatic resolved).
  Runtime runtime() const { return model_->runtime(); }
  Precision precision() const { return model_->precision(); }

 private:
  // The network on a prepared input (preparing it began at t0: the timings count it), in input pixels.
  std::vector<DetectedPerson> infer_canvas(const RgbCanvas& canvas, std::chrono::steady_clock::time_point t0);
  std::vector<DetectedPerson> infer_region(const ImageView& view, const Rect& region);
  // A crop around `person`'s keypoints: turned with the body when the card asks for it and the person has shoulders
  // and hips, else level (crop_around of `box`).
  // `box_confidence`: the least confidence of a keypoint the turned crop's extent counts.
  std::vector<DetectedPerson> infer_crop(const ImageView& view, const Rect& box, const Person2D* person,
                                         double box_confidence);
  std::vector<DetectedPerson> detect_view(size_t v, const ImageView& view);
  std::vector<std::vector<DetectedPerson>> detect_mosaic(const std::vector<ImageView>& views);
  std::pair<int, int> input_size_for(double aspect) const;
  // Which views run the network this frame (views_per_frame): 1 = detect, 0 = follow by optical flow.
  std::vector<char> schedule(const std::vector<ImageView>& views) const;
  // A view's people this frame: detected, or followed from last frame's by optical flow.
  std::vector<DetectedPerson> detect_or_track(size_t v, const ImageView& view, bool scheduled, bool detect);

  struct Network {
    std::string path;
    ModelCard card;
    std::unique_ptr<PoseNetwork> model;
  };
  // Reads the card beside `path`, loads the network and runs it once (Error(parse) when its outputs misfit the card).
  Network load_network(const std::string& path) const;

  DetectorConfig config_;
  std::vector<Network> networks_;
  size_t active_ = 0;
  // The active network's (use_network()).
  std::string path_;
  ModelCard card_;
  PoseNetwork* model_ = nullptr;
  int parallel_ = 1;
  // The threads that detect views at once, made once: threads made per frame cost their start, and every new
  // thread OpenCV runs on keeps thread-local buffers it never frees (a live take grew 1.6 MB a minute).
  std::unique_ptr<WorkerPool> views_pool_;
  std::mutex timing_mutex_;
  const Person2D& first_hint(size_t v) const;
  std::vector<std::vector<Person2D>> hints_;
  // The crop mode's fallback when no hint was given: last frame's people (their boxes, and their turn for a turned crop).
  std::vector<std::vector<Person2D>> last_people_;
  std::vector<int> frames_since_search_;       // per view, find_new_people
  // Detection scheduling, per view: the pictures flow starts from, last frame's people (detected or followed), how
  // many frames since the view was detected, and how many confident keypoints that detection had.
  std::vector<FlowTracker> trackers_;
  std::vector<std::vector<DetectedPerson>> last_result_;
  std::vector<int> frames_since_detect_;
  std::vector<int> detected_keypoints_;
  DetectTimings timings_;
};

}  // namespace octocap::internal
