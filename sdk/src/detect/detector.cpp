#include "detect/detector.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <dlfcn.h>
#include <sys/stat.h>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

#include "core/error.h"
#include "core/layout.h"
#include "core/log.h"
#include "core/stats.h"
#include "detect/turned_crop.h"

#ifndef OCTOCAP_DEFAULT_MODELS_DIR
#define OCTOCAP_DEFAULT_MODELS_DIR "models"
#endif

namespace octocap::internal {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int round_to_multiple(double v, int m) { return std::max(m, static_cast<int>(std::lround(v / m)) * m); }

// A crop around a person box with the network's aspect, padded so limbs moving since the box stay inside.
constexpr double kCropPad = 1.4;
Rect crop_around(const Rect& box, double aspect) {
  const double h = std::max(box.height, box.width / aspect) * kCropPad;
  const double w = h * aspect;
  return {box.x + box.width / 2 - w / 2, box.y + box.height / 2 - h / 2, w, h};
}

// Intersection over union of two boxes (0 when either is empty).
double overlap(const Rect& a, const Rect& b) {
  const double w = std::min(a.x + a.width, b.x + b.width) - std::max(a.x, b.x);
  const double h = std::min(a.y + a.height, b.y + b.height) - std::max(a.y, b.y);
  if (w <= 0 || h <= 0) return 0;
  const double both = w * h;
  return both / (a.width * a.height + b.width * b.height - both);
}

// How many of a person's keypoints are confident.
int confident_count(const Person2D& person, double min_confidence) {
  int n = 0;
  for (const Keypoint2D& k : person) n += k.confidence >= min_confidence;
  return n;
}

int confident_count(const std::vector<DetectedPerson>& people, double min_confidence) {
  int n = 0;
  for (const DetectedPerson& p : people) n += confident_count(p.keypoints, min_confidence);
  return n;
}

// The median pixel distance between the keypoints two people both have (confident), INFINITY with fewer than three.
double keypoint_distance(const Person2D& a, const Person2D& b, double min_confidence) {
  std::vector<double> d;
  for (size_t k = 0; k < a.size() && k < b.size(); ++k)
    if (a[k].confidence >= min_confidence && b[k].confidence >= min_confidence)
      d.push_back(std::hypot(a[k].x - b[k].x, a[k].y - b[k].y));
  return d.size() < 3 ? INFINITY : median_in_place(d, INFINITY);
}

// Two detections of one person (two crops, a crop and the whole view): their keypoints lie on each other (under a
// tenth of the body's height apart). Boxes would not tell: two people standing close, one in front of the other,
// have boxes that overlap as much.
bool same_person(const Person2D& a, const Person2D& b, double min_confidence) {
  const double height = std::max(keypoint_box(a, min_confidence).height, keypoint_box(b, min_confidence).height);
  return keypoint_distance(a, b, min_confidence) < 0.1 * height;
}

}  // namespace

bool cpu_has_vnni() {
#if defined(__x86_64__) || defined(__i386__)
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (!__get_cpuid_count(7, 0, &a, &b, &c, &d)) return false;
  if (c & (1u << 11)) return true;  // AVX512_VNNI
  if (!__get_cpuid_count(7, 1, &a, &b, &c, &d)) return false;
  return (a & (1u << 4)) != 0;      // AVX_VNNI
#else
  return false;  // other CPUs: ONNX Runtime's integer kernels there are not what the INT8 model was measured on
#endif
}

std::string models_directory() {
  const char* env = std::getenv("OCTOCAP_MODELS_DIR");
  if (env && *env) return env;
  auto is_dir = [](const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
  };
  // Where a package puts them first, relative to the library itself: a folder `models` beside it (the Unity package,
  // a plugin folder), then an install's <prefix>/lib/liboctocap.so -> <prefix>/share/octocap/models. The build's own
  // folder last, so an installed or packaged library never reads a checkout that happens to be on the machine.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&models_directory), &info) && info.dli_fname) {
    const std::string lib = info.dli_fname;
    const size_t slash = lib.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : lib.substr(0, slash);
    for (const std::string& candidate : {dir + "/models", dir + "/../share/octocap/models"})
      if (is_dir(candidate)) return candidate;
  }
  return OCTOCAP_DEFAULT_MODELS_DIR;
}

std::string resolve_model_path(const std::string& model, DetectMode mode) {
  std::string name = model;
  if (name.empty()) name = mode == DetectMode::mosaic ? "movenet-multipose" : "movenet-thunder";
  if (name.find('/') != std::string::npos || ends_with(name, ".onnx")) return name;
  return models_directory() + "/" + name + ".onnx";
}

void DetectorConfig::validate() const {
  auto fail = [](const std::string& what) { throw Error(Errc::invalid_argument, "detector " + what); };
  if (mode != DetectMode::per_view && mode != DetectMode::mosaic && mode != DetectMode::crop)
    fail("mode " + std::to_string(static_cast<int>(mode)) + " is not a known mode");
  if (pick < PersonPick::all || pick > PersonPick::nearest_previous)
    fail("person_pick " + std::to_string(static_cast<int>(pick)) + " is not known");
  if (device != Device::cpu && device != Device::automatic && device != Device::cuda)
    fail("device " + std::to_string(static_cast<int>(device)) + " is not a known device");
  if (runtime < Runtime::automatic || runtime > Runtime::openvino)
    fail("runtime " + std::to_string(static_cast<int>(runtime)) + " is not a known runtime");
  if (precision < Precision::automatic || precision > Precision::reduced)
    fail("precision " + std::to_string(static_cast<int>(precision)) + " is not a known precision");
  // Thread and view counts beyond 256 are typos, not machines: bounded, so nothing sizes a pool from garbage.
  if (threads < 0 || threads > 256) fail("threads must be 0..256");
  if (parallel_views < 0 || parallel_views > 256) fail("parallel_views must be 0..256");
  if (views_per_frame < 0 || views_per_frame > 256) fail("views_per_frame must be 0..256");
  if (max_people == 0 || max_people > 64) fail("max_people must be 1..64");
  if (mosaic_tile < 32 || mosaic_tile > 4096) fail("mosaic tile must be 32..4096 pixels, got " + std::to_string(mosaic_tile));
  if (!std::isfinite(min_confidence)) fail("min_confidence is NaN or infinite");
  if (new_people_every < 1) fail("new_people_every must be at least 1");
}

Detector::Detector(const DetectorConfig& config) : config_(config) {
  config.validate();
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  parallel_ = config.mode == DetectMode::mosaic ? 1 : config.parallel_views == 0 ? cores : config.parallel_views;
  networks_.push_back(load_network(resolve_model_path(config.model, config.mode)));
  const ModelCard& named = networks_.front().card;
  if (config.mode == DetectMode::mosaic && (named.max_people < 2 || !named.dynamic_size))
    throw Error(Errc::invalid_argument, "the mosaic needs a multi-person model that accepts any input size (one "
                                        "person per tile); " + named.name + " is not one: use movenet-multipose");
  if (config.load_lighter && !named.lighter.empty() && config.mode != DetectMode::mosaic) {
    // The card's path is relative to the card: a shipped name is looked up as any model name is.
    std::string lighter = named.lighter;
    if (lighter.find('/') != std::string::npos && lighter.front() != '/') {
      const std::string& first = networks_.front().path;
      lighter = first.substr(0, first.find_last_of('/') + 1) + lighter;
    }
    Network light = load_network(resolve_model_path(lighter, config.mode));
    if (light.card.layout != named.layout || light.card.max_people != named.max_people)
      throw Error(Errc::parse, "model " + named.name + ": its lighter model " + light.card.name + " (" + light.path +
                                   ") gives another keypoint layout or number of people");
    networks_.push_back(std::move(light));
  }
  use_network(0, config.views_per_frame);
}

Detector::Network Detector::load_network(const std::string& path) const {
  Network n;
  n.path = path;
  n.card = read_model_card(model_card_path(path));
  if (n.card.quantized && !cpu_has_vnni())
    log(LogLevel::warning, "model " + n.card.name + " is quantised to INT8, and this CPU has no VNNI: here it runs "
                           "hardly faster and less accurately than the float model it was made from");
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  // Views in parallel share the cores: each inference gets its part unless the caller chose.
  const int intra = config_.threads > 0 ? config_.threads : parallel_ > 1 ? std::max(1, cores / parallel_) : 0;
  NetworkOptions options;
  options.runtime = config_.runtime;
  options.precision = config_.precision;
  options.device = config_.device;
  options.threads = intra;
  options.callers = parallel_;
  n.model = load_pose_network(path, n.card, options);
  // One run on a blank canvas: a card whose outputs do not fit its kind fails here, once, at load, instead of on
  // every frame of a live take that then solves nothing.
  const int w = n.card.dynamic_size ? round_to_multiple(n.card.input_width, n.card.size_multiple) : n.card.input_width;
  const int h = n.card.dynamic_size ? round_to_multiple(n.card.input_height, n.card.size_multiple) : n.card.input_height;
  RgbCanvas canvas;
  canvas.reset(w, h);
  try {
    decode_pose(n.card, n.model->run(canvas), w, h, layout(n.card.layout).keypoints.size());
  } catch (const std::exception& e) {
    throw Error(Errc::parse, "model " + n.card.name + " (" + path + "): its outputs do not fit its card's output kind \"" +
                                 output_kind_name(n.card.output) + "\": " + e.what());
  }
  return n;
}

void Detector::use_network(size_t network, int views_per_frame) {
  if (network >= networks_.size() || views_per_frame < 0)
    throw Error(Errc::invalid_argument, "no such network or views per frame");
  active_ = network;
  path_ = networks_[network].path;
  card_ = networks_[network].card;
  model_ = networks_[network].model.get();
  config_.views_per_frame = views_per_frame;
}

Detector::~Detector() = default;

Device Detector::device() const { return model_->on_gpu() ? Device::cuda : Device::cpu; }

std::pair<int, int> Detector::input_size_for(double aspect) const {
  if (!card_.dynamic_size) return {card_.input_width, card_.input_height};
  const int h = round_to_multiple(card_.input_height, card_.size_multiple);
  return {round_to_multiple(h * aspect, card_.size_multiple), h};
}

std::vector<DetectedPerson> Detector::infer_canvas(const RgbCanvas& canvas, std::chrono::steady_clock::time_point t0) {
  const auto t1 = Clock::now();
  const std::vector<Tensor> out = model_->run(canvas);
  {
    const std::lock_guard<std::mutex> lock(timing_mutex_);
    timings_.preprocess_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
    timings_.inference_ms += ms_since(t1);
    ++timings_.inferences;
  }
  return decode_pose(card_, out, canvas.width, canvas.height, layout(card_.layout).keypoints.size());
}

std::vector<DetectedPerson> Detector::infer_region(const ImageView& view, const Rect& region) {
  const auto t0 = Clock::now();
  const auto [w, h] = input_size_for(region.width / region.height);
  RgbCanvas canvas;
  canvas.reset(w, h);
  const Rect dst{0, 0, static_cast<double>(w), static_cast<double>(h)};
  const Letterbox box = fit_letterbox(region, dst);
  draw_letterboxed(view, region, dst, box, canvas);
  std::vector<DetectedPerson> people = infer_canvas(canvas, t0);
  // Back to view pixels; keypoints on the padding are the model's guesses at what it cannot see.
  const double vx0 = std::max(0.0, region.x), vy0 = std::max(0.0, region.y);
  const double vx1 = std::min<double>(view.width, region.x + region.width);
  const double vy1 = std::min<double>(view.height, region.y + region.height);
  for (DetectedPerson& p : people) {
    for (Keypoint2D& k : p.keypoints) {
      k.x = box.to_source_x(k.x);
      k.y = box.to_source_y(k.y);
      if (k.x < vx0 || k.x > vx1 || k.y < vy0 || k.y > vy1) k.confidence = 0;
    }
    p.box = {box.to_source_x(p.box.x), box.to_source_y(p.box.y), p.box.width / box.scale, p.box.height / box.scale};
  }
  return people;
}

std::vector<DetectedPerson> Detector::infer_crop(const ImageView& view, const Rect& box, const Person2D* person,
                                                 double box_confidence) {
  const double aspect = static_cast<double>(card_.input_width) / card_.input_height;
  const std::optional<double> lean =
      card_.upright && person ? body_lean(*person, layout(card_.layout), config_.min_confidence) : std::nullopt;
  if (!lean) return infer_region(view, crop_around(box, aspect));
  const TurnedCrop crop = turned_crop_around(*person, *lean, aspect, kCropPad, box_confidence);
  if (!(crop.height > 0)) return infer_region(view, crop_around(box, aspect));
  const auto t0 = Clock::now();
  const auto [w, h] = input_size_for(aspect);
  RgbCanvas canvas;
  canvas.reset(w, h);
  draw_turned(view, crop, canvas);
  std::vector<DetectedPerson> people = infer_canvas(canvas, t0);
  for (DetectedPerson& p : people) {
    for (Keypoint2D& k : p.keypoints) {
      turned_to_source(crop, w, h, k.x, k.y);
      if (k.x < 0 || k.x > view.width || k.y < 0 || k.y > view.height) k.confidence = 0;  // a guess past the picture
    }
    p.box = keypoint_box(p.keypoints, config_.min_confidence);
  }
  return people;
}

std::vector<std::vector<DetectedPerson>> Detector::detect_mosaic(const std::vector<ImageView>& views) {
  const auto t0 = Clock::now();
  std::vector<ViewSize> sizes;
  std::vector<double> aspects;
  ViewSize stand_in{0, 0};  // an absent view keeps its tile (black) at a present view's size
  for (const ImageView& v : views)
    if (!absent(v)) stand_in = {v.width, v.height};
  for (const ImageView& v : views) {
    sizes.push_back(absent(v) ? stand_in : ViewSize{v.width, v.height});
    if (!absent(v)) aspects.push_back(static_cast<double>(v.width) / v.height);
  }
  std::nth_element(aspects.begin(), aspects.begin() + aspects.size() / 2, aspects.end());
  const int m = card_.size_multiple;
  const int tile_h = round_to_multiple(config_.mosaic_tile, m);
  const int tile_w = round_to_multiple(tile_h * aspects[aspects.size() / 2], m);
  const MosaicLayout layout_plan = plan_mosaic(sizes, tile_w, tile_h);
  RgbCanvas canvas;
  canvas.reset(layout_plan.width, layout_plan.height);
  for (size_t v = 0; v < views.size(); ++v)
    if (!absent(views[v]))
      draw_letterboxed(views[v], {0, 0, static_cast<double>(views[v].width), static_cast<double>(views[v].height)},
                     layout_plan.tiles[v].cell, layout_plan.tiles[v].box, canvas);
  const auto t1 = Clock::now();
  timings_.preprocess_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
  const std::vector<Tensor> out = model_->run(canvas);
  timings_.inference_ms += ms_since(t1);
  ++timings_.inferences;
  const auto people = decode_pose(card_, out, layout_plan.width, layout_plan.height, layout(card_.layout).keypoints.size());
  return split_mosaic_people(layout_plan, people, config_.min_confidence);
}

const Person2D& Detector::first_hint(size_t v) const {
  static const Person2D none;
  return v < hints_.size() && !hints_[v].empty() ? hints_[v].front() : none;
}

std::vector<DetectedPerson> Detector::detect_view(size_t v, const ImageView& view) {
  const Rect whole{0, 0, static_cast<double>(view.width), static_cast<double>(view.height)};
  if (config_.mode == DetectMode::per_view) return infer_region(view, whole);
  // Crop: around each hinted person, else around last frame's people, else find someone on the whole view first.
  const size_t wanted = config_.find_new_people ? config_.max_people : 1;
  // Each crop's box, and the person it should find (the hint; none for last frame's boxes).
  std::vector<Rect> boxes;
  std::vector<const Person2D*> expected;
  if (v < hints_.size())
    for (const Person2D& hint : hints_[v]) {
      const Rect box = keypoint_box(hint, kHintConfidence);
      if ((box.width > 0 || box.height > 0) && boxes.size() < wanted) boxes.push_back(box), expected.push_back(&hint);
    }
  // Whose keypoints shape each crop (its turn with the body): the hint, else last frame's person.
  std::vector<const Person2D*> shapes = expected;
  if (boxes.empty()) {
    for (const Person2D& p : last_people_[v]) boxes.push_back(keypoint_box(p, config_.min_confidence)), shapes.push_back(&p);
    expected.assign(boxes.size(), nullptr);
  }
  if (boxes.size() > wanted) boxes.resize(wanted), expected.resize(wanted);
  std::vector<DetectedPerson> people;
  auto add_unless_seen = [&](DetectedPerson p) {
    for (const DetectedPerson& q : people)
      if (same_person(p.keypoints, q.keypoints, config_.min_confidence)) return;  // two crops, one person
    people.push_back(std::move(p));
  };
  const bool searches = config_.find_new_people && card_.max_people > 1;
  if (boxes.empty() && !searches) {
    auto found = infer_region(view, whole);
    pick_people(found, config_.pick == PersonPick::all ? PersonPick::most_confident : config_.pick, first_hint(v), 1,
                config_.min_confidence);
    if (found.empty()) return {};
    const Rect box = keypoint_box(found[0].keypoints, config_.min_confidence);
    if (box.width <= 0 && box.height <= 0) return {};
    boxes.push_back(box);
    expected.push_back(nullptr);
    last_people_[v] = {found[0].keypoints};
    shapes.assign(1, &last_people_[v][0]);
  }
  for (size_t i = 0; i < boxes.size(); ++i) {
    // A hint's keypoints all count for the crop's extent (those its frame did not solve are remembered ones, at a
    // low confidence); a detection's unconfident keypoints are guesses that would stretch it.
    const bool hinted = i < expected.size() && expected[i] != nullptr;
    auto found = infer_crop(view, boxes[i], i < shapes.size() ? shapes[i] : nullptr,
                            hinted ? kHintConfidence : config_.min_confidence);
    if (found.empty()) continue;
    if (found.size() == 1 && !searches) {  // one person, as always
      add_unless_seen(std::move(found[0]));
      continue;
    }
    // A crop may show others too (a multi-person model, someone close by, in front): keep the one where the
    // expected person's keypoints are, and none when nobody is there (they are hidden; someone else is not them).
    size_t best = found.size();
    double best_distance = INFINITY;
    for (size_t j = 0; j < found.size(); ++j) {
      const double d = expected[i] ? keypoint_distance(found[j].keypoints, *expected[i], config_.min_confidence)
                                   : 1 - overlap(keypoint_box(found[j].keypoints, config_.min_confidence), boxes[i]);
      if (d < best_distance) best_distance = d, best = j;
    }
    const double limit = expected[i] ? 0.25 * boxes[i].height : 0.7;
    if (best < found.size() && best_distance < limit) add_unless_seen(std::move(found[best]));
  }
  // Several people: now and then the whole view, for whoever is not followed yet (needs a multi-person model); at
  // once when someone of the last frame is missing (a crop lost its person, or the 3D solve lost them: someone
  // stepped in front, and the whole view may still show them).
  const size_t before = std::max(boxes.size(), last_people_[v].size());
  if (searches && people.size() < wanted &&
      (people.size() < std::max<size_t>(before, 1) || ++frames_since_search_[v] >= config_.new_people_every)) {
    frames_since_search_[v] = 0;
    for (DetectedPerson& p : infer_region(view, whole)) add_unless_seen(std::move(p));
  }
  // An empty box (nobody confident) is no box: next frame then looks at the whole view again.
  last_people_[v].clear();
  for (const DetectedPerson& p : people) {
    const Rect box = keypoint_box(p.keypoints, config_.min_confidence);
    if (box.width > 0 || box.height > 0) last_people_[v].push_back(p.keypoints);
  }
  return people;
}

std::vector<char> Detector::schedule(const std::vector<ImageView>& views) const {
  std::vector<char> detect(views.size(), 0);
  std::vector<size_t> followable;
  int budget = config_.views_per_frame;
  for (size_t v = 0; v < views.size(); ++v) {
    if (absent(views[v])) continue;
    const int confident = confident_count(last_result_[v], config_.min_confidence);
    // Nobody to follow, no picture to follow from, or a track that lost half of what its detection found.
    const bool must = !trackers_[v].follows(views[v]) || confident == 0 || 2 * confident < detected_keypoints_[v];
    if (must)
      detect[v] = 1, --budget;
    else
      followable.push_back(v);
  }
  // The views detected longest ago first (round robin), ties by view order.
  std::stable_sort(followable.begin(), followable.end(),
                   [&](size_t a, size_t b) { return frames_since_detect_[a] > frames_since_detect_[b]; });
  for (size_t i = 0; i < followable.size() && budget > 0; ++i, --budget) detect[followable[i]] = 1;
  return detect;
}

std::vector<DetectedPerson> Detector::detect_or_track(size_t v, const ImageView& view, bool scheduled, bool detect) {
  if (scheduled) {
    const auto t0 = Clock::now();
    trackers_[v].advance(view);
    const std::lock_guard<std::mutex> lock(timing_mutex_);
    timings_.track_ms += ms_since(t0);
  } else {
    trackers_[v].reset();  // a later frame that schedules starts from a detection
  }
  if (detect) {
    frames_since_detect_[v] = 0;
    return detect_view(v, view);
  }
  const auto t0 = Clock::now();
  std::vector<DetectedPerson> people = trackers_[v].track(last_result_[v], config_.min_confidence);
  ++frames_since_detect_[v];
  // The crop follows the followed people, as it follows detected ones.
  last_people_[v].clear();
  for (const DetectedPerson& p : people) last_people_[v].push_back(p.keypoints);
  const std::lock_guard<std::mutex> lock(timing_mutex_);
  timings_.track_ms += ms_since(t0);
  ++timings_.views_tracked;
  return people;
}

std::vector<std::vector<DetectedPerson>> Detector::detect(const std::vector<ImageView>& views) {
  if (views.empty()) throw Error(Errc::invalid_argument, "no images");
  size_t present = 0;
  for (size_t v = 0; v < views.size(); ++v) {
    if (absent(views[v])) continue;
    validate_image(views[v], ("image " + std::to_string(v)).c_str());
    ++present;
  }
  if (present == 0) return std::vector<std::vector<DetectedPerson>>(views.size());
  const auto t0 = Clock::now();
  timings_ = {};
  std::vector<std::vector<DetectedPerson>> result;
  if (config_.mode == DetectMode::mosaic) {
    result = detect_mosaic(views);
  } else {
    result.resize(views.size());
    last_people_.resize(views.size());
    frames_since_search_.resize(views.size(), 0);
    trackers_.resize(views.size());
    last_result_.resize(views.size());
    frames_since_detect_.resize(views.size(), 0);
    detected_keypoints_.resize(views.size(), 0);
    const bool scheduled = config_.views_per_frame > 0 && present > static_cast<size_t>(config_.views_per_frame);
    const std::vector<char> detect_now = scheduled ? schedule(views) : std::vector<char>(views.size(), 1);
    // Views are independent here: up to parallel_ of them at once, each writing only its own slots. The views that
    // run the network go first: a worker that starts on a 25 ms inference last would leave the other idle.
    std::vector<size_t> order(views.size());
    for (size_t v = 0; v < order.size(); ++v) order[v] = v;
    std::stable_partition(order.begin(), order.end(), [&](size_t v) { return detect_now[v] != 0; });
    std::exception_ptr failure;
    std::mutex failure_mutex;
    const std::function<void(size_t)> one = [&](size_t i) {
      const size_t v = order[i];
      try {
        // A view without a picture this set (a live camera that lagged) keeps its last picture and people: the
        // next picture is followed from them across the gap (the way-back check drops what moved too far).
        if (!absent(views[v])) result[v] = detect_or_track(v, views[v], scheduled, detect_now[v] != 0);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    };
    // Made at the first frame of several views: a capture node's one-camera detectors never start its threads.
    if (!views_pool_ && parallel_ > 1 && order.size() > 1)
      views_pool_ = std::make_unique<WorkerPool>(static_cast<unsigned>(std::min<size_t>(parallel_, order.size())));
    if (views_pool_ && order.size() > 1) {
      views_pool_->parallel_for(order.size(), one);  // in `order`: the views that run the network first
    } else {
      for (size_t i = 0; i < order.size(); ++i) one(i);
    }
    if (failure) std::rethrow_exception(failure);
  }
  // A single-person model always answers with someone; fewer than three confident keypoints is nobody.
  for (auto& people : result)
    people.erase(std::remove_if(people.begin(), people.end(),
                                [&](const DetectedPerson& p) {
                                  return confident_count(p.keypoints, config_.min_confidence) < 3;
                                }),
                 people.end());
  for (size_t v = 0; v < result.size(); ++v)
    pick_people(result[v], config_.pick, first_hint(v), config_.max_people, config_.min_confidence);
  // What each view reports, kept to follow from; and, for the views detected now, how many keypoints the detection
  // gave (as picked: a track is judged against what was passed on, not against people dropped).
  if (config_.mode != DetectMode::mosaic)
    for (size_t v = 0; v < result.size(); ++v) {
      if (absent(views[v])) continue;
      last_result_[v] = result[v];
      if (frames_since_detect_[v] != 0) continue;
      detected_keypoints_[v] = confident_count(result[v], config_.min_confidence);
    }
  timings_.total_ms = ms_since(t0);
  return result;
}

}  // namespace octocap::internal
