#include "detect/decoders.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"

namespace octocap::internal {
namespace {

void expect(bool ok, const Tensor& t, const std::string& kind, const std::string& expected) {
  if (!ok)
    throw Error(Errc::invalid_argument, "model output " + shape_string(t.shape) + " does not fit output kind \"" + kind +
                                            "\": expected " + expected);
}

size_t element_count(const Tensor& t) {
  size_t n = 1;
  for (int64_t d : t.shape) n *= static_cast<size_t>(std::max<int64_t>(d, 0));
  return n;
}

double mean_score(const Person2D& p) {
  if (p.empty()) return 0;
  double s = 0;
  for (const Keypoint2D& k : p) s += k.confidence;
  return s / static_cast<double>(p.size());
}

// Argmax of a row with sub-bin refinement; returns (position in bins, value).
std::pair<double, double> refined_peak(const float* row, size_t n) {
  const size_t i = static_cast<size_t>(std::max_element(row, row + n) - row);
  double pos = static_cast<double>(i);
  if (i > 0 && i + 1 < n) pos += parabolic_offset(row[i - 1], row[i], row[i + 1]);
  return {pos, row[i]};
}

double iou(const Rect& a, const Rect& b) {
  const double x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
  const double x1 = std::min(a.x + a.width, b.x + b.width), y1 = std::min(a.y + a.height, b.y + b.height);
  const double inter = std::max(0.0, x1 - x0) * std::max(0.0, y1 - y0);
  const double uni = a.width * a.height + b.width * b.height - inter;
  return uni > 0 ? inter / uni : 0;
}

}  // namespace

std::string shape_string(const std::vector<int64_t>& shape) {
  std::string s = "[";
  for (size_t i = 0; i < shape.size(); ++i) s += (i ? "," : "") + std::to_string(shape[i]);
  return s + "]";
}

double parabolic_offset(double left, double centre, double right) {
  const double curvature = left - 2 * centre + right;
  if (!(curvature < 0)) return 0;  // flat or not a maximum: no refinement
  return std::clamp(0.5 * (left - right) / curvature, -0.5, 0.5);
}

Rect keypoint_box(const Person2D& person, double min_confidence) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  int n = 0;
  for (const Keypoint2D& k : person) {
    if (!(k.confidence >= min_confidence)) continue;
    x0 = std::min(x0, k.x), y0 = std::min(y0, k.y), x1 = std::max(x1, k.x), y1 = std::max(y1, k.y);
    ++n;
  }
  if (n < 2) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

std::vector<DetectedPerson> decode_movenet(const Tensor& t, int in_width, int in_height, size_t K) {
  expect(t.shape.size() == 4 && t.shape[0] == 1 && t.shape[1] == 1 && t.shape[2] == static_cast<int64_t>(K) &&
             t.shape[3] == 3 && t.data.size() == element_count(t),
         t, "movenet", "[1,1," + std::to_string(K) + ",3]");
  DetectedPerson p;
  p.keypoints.resize(K);
  for (size_t k = 0; k < K; ++k) {
    const float* v = &t.data[k * 3];
    p.keypoints[k] = {v[1] * in_width - 0.5, v[0] * in_height - 0.5, v[2]};  // normalised -> pixel centres
  }
  p.score = mean_score(p.keypoints);
  p.box = keypoint_box(p.keypoints, 0.2);
  return {p};
}

std::vector<DetectedPerson> decode_blazepose(const Tensor& landmarks, const Tensor& flag, size_t K, double min_score) {
  // 39 landmarks of (x, y, z, visibility, presence), the last six the model's own alignment points.
  constexpr size_t kLandmarks = 39, kValues = 5;
  expect(landmarks.data.size() == kLandmarks * kValues && landmarks.data.size() == element_count(landmarks) && K <= kLandmarks,
         landmarks, "blazepose", "195 landmark values (39 x 5)");
  expect(flag.data.size() == 1 && element_count(flag) == 1, flag, "blazepose", "one person-flag value");
  const double score = flag.data[0];  // already a probability (the graph ends in a sigmoid)
  if (!(score >= min_score)) return {};
  auto sigmoid = [](double x) { return 1 / (1 + std::exp(-x)); };
  DetectedPerson p;
  p.keypoints.resize(K);
  for (size_t k = 0; k < K; ++k) {
    const float* v = &landmarks.data[k * kValues];
    // Input pixels with 0 at the input's edge, as MoveNet's normalised coordinates: -0.5 to pixel centres. The
    // visibility (in the picture and not hidden) is the keypoint's confidence, as Pose2Sim takes it.
    p.keypoints[k] = {v[0] - 0.5, v[1] - 0.5, sigmoid(v[3])};
    if (!std::isfinite(p.keypoints[k].x) || !std::isfinite(p.keypoints[k].y)) p.keypoints[k].confidence = 0;
  }
  p.score = score;
  p.box = keypoint_box(p.keypoints, 0.2);
  return {p};
}

std::vector<DetectedPerson> decode_movenet_multipose(const Tensor& t, int in_width, int in_height, size_t K,
                                                     double min_score) {
  const int64_t row = static_cast<int64_t>(3 * K + 5);
  expect(t.shape.size() == 3 && t.shape[0] == 1 && t.shape[1] >= 1 && t.shape[2] == row &&
             t.data.size() == element_count(t),
         t, "movenet_multipose", "[1,P," + std::to_string(row) + "]");
  std::vector<DetectedPerson> people;
  for (int64_t i = 0; i < t.shape[1]; ++i) {
    const float* v = &t.data[static_cast<size_t>(i * row)];
    const double score = v[3 * K + 4];
    if (!(score >= min_score)) continue;
    DetectedPerson p;
    p.keypoints.resize(K);
    for (size_t k = 0; k < K; ++k)
      p.keypoints[k] = {v[3 * k + 1] * in_width - 0.5, v[3 * k] * in_height - 0.5, v[3 * k + 2]};
    p.score = score;
    const float* b = v + 3 * K;  // ymin, xmin, ymax, xmax
    p.box = {b[1] * in_width, b[0] * in_height, (b[3] - b[1]) * in_width, (b[2] - b[0]) * in_height};
    people.push_back(std::move(p));
  }
  return people;
}

std::vector<DetectedPerson> decode_heatmaps(const Tensor& t, int in_width, int in_height, size_t K) {
  expect(t.shape.size() == 4 && t.shape[0] == 1 && t.shape[1] >= static_cast<int64_t>(K) && t.shape[2] > 1 &&
             t.shape[3] > 1 && t.data.size() == element_count(t),
         t, "heatmap", "[1," + std::to_string(K) + "(or more),H,W]");
  const size_t H = static_cast<size_t>(t.shape[2]), W = static_cast<size_t>(t.shape[3]);
  DetectedPerson p;
  p.keypoints.resize(K);
  for (size_t k = 0; k < K; ++k) {
    const float* map = &t.data[k * H * W];
    const size_t i = static_cast<size_t>(std::max_element(map, map + H * W) - map);
    const size_t r = i / W, c = i % W;
    double x = static_cast<double>(c), y = static_cast<double>(r);
    if (c > 0 && c + 1 < W) x += parabolic_offset(map[i - 1], map[i], map[i + 1]);
    if (r > 0 && r + 1 < H) y += parabolic_offset(map[i - W], map[i], map[i + W]);
    // Heatmap cell centres to input pixel centres.
    p.keypoints[k] = {(x + 0.5) * in_width / static_cast<double>(W) - 0.5,
                      (y + 0.5) * in_height / static_cast<double>(H) - 0.5, std::clamp<double>(map[i], 0.0, 1.0)};
  }
  p.score = mean_score(p.keypoints);
  p.box = keypoint_box(p.keypoints, 0.2);
  return {p};
}

std::vector<DetectedPerson> decode_simcc(const Tensor& x, const Tensor& y, int in_width, int in_height, size_t K,
                                         double ratio) {
  const std::string want = "[1," + std::to_string(K) + ",W*ratio] and [1," + std::to_string(K) + ",H*ratio]";
  expect(x.shape.size() == 3 && x.shape[0] == 1 && x.shape[1] == static_cast<int64_t>(K) && x.shape[2] > 1 &&
             x.data.size() == element_count(x), x, "simcc", want);
  expect(y.shape.size() == 3 && y.shape[0] == 1 && y.shape[1] == static_cast<int64_t>(K) && y.shape[2] > 1 &&
             y.data.size() == element_count(y), y, "simcc", want);
  if (!(ratio > 0)) throw Error(Errc::invalid_argument, "simcc_ratio must be positive");
  const size_t Wx = static_cast<size_t>(x.shape[2]), Hy = static_cast<size_t>(y.shape[2]);
  DetectedPerson p;
  p.keypoints.resize(K);
  for (size_t k = 0; k < K; ++k) {
    const auto [px, vx] = refined_peak(&x.data[k * Wx], Wx);
    const auto [py, vy] = refined_peak(&y.data[k * Hy], Hy);
    // SimCC bins are input pixels times the split ratio; the weaker axis bounds the confidence.
    p.keypoints[k] = {std::clamp(px / ratio, 0.0, static_cast<double>(in_width)),
                      std::clamp(py / ratio, 0.0, static_cast<double>(in_height)), std::clamp(std::min(vx, vy), 0.0, 1.0)};
  }
  p.score = mean_score(p.keypoints);
  p.box = keypoint_box(p.keypoints, 0.2);
  return {p};
}

std::vector<DetectedPerson> decode_yolo_pose(const Tensor& t, size_t K, double min_score, size_t max_people) {
  const int64_t row = static_cast<int64_t>(5 + 3 * K);
  expect(t.shape.size() == 3 && t.shape[0] == 1 && (t.shape[1] == row || t.shape[2] == row) &&
             t.data.size() == element_count(t),
         t, "yolo_pose", "[1," + std::to_string(row) + ",N] or [1,N," + std::to_string(row) + "]");
  // Ultralytics exports attributes-major ([1,56,N]); others rows-major. A square [1,56,56] is read attributes-major.
  const bool attributes_major = t.shape[1] == row;
  const size_t N = static_cast<size_t>(attributes_major ? t.shape[2] : t.shape[1]);
  auto at = [&](size_t i, size_t a) {
    return attributes_major ? t.data[a * N + i] : t.data[i * static_cast<size_t>(row) + a];
  };
  std::vector<DetectedPerson> candidates;
  for (size_t i = 0; i < N; ++i) {
    const double score = at(i, 4);
    if (!(score >= min_score)) continue;
    DetectedPerson p;
    p.score = score;
    p.box = {at(i, 0) - at(i, 2) / 2, at(i, 1) - at(i, 3) / 2, at(i, 2), at(i, 3)};
    p.keypoints.resize(K);
    for (size_t k = 0; k < K; ++k) p.keypoints[k] = {at(i, 5 + 3 * k), at(i, 6 + 3 * k), at(i, 7 + 3 * k)};
    candidates.push_back(std::move(p));
  }
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) { return a.score > b.score; });
  std::vector<DetectedPerson> kept;
  for (auto& c : candidates) {
    if (kept.size() >= max_people) break;
    bool overlaps = false;
    for (const auto& k : kept) overlaps = overlaps || iou(c.box, k.box) > 0.45;
    if (!overlaps) kept.push_back(std::move(c));
  }
  return kept;
}

std::vector<DetectedPerson> decode_pose(const ModelCard& card, const std::vector<Tensor>& outputs, int in_width,
                                        int in_height, size_t K) {
  const size_t needed = card.output == OutputKind::simcc || card.output == OutputKind::blazepose ? 2 : 1;
  if (outputs.size() < needed)
    throw Error(Errc::invalid_argument, "model has " + std::to_string(outputs.size()) + " outputs, output kind \"" +
                                            output_kind_name(card.output) + "\" needs " + std::to_string(needed));
  switch (card.output) {
    case OutputKind::movenet: return decode_movenet(outputs[0], in_width, in_height, K);
    case OutputKind::movenet_multipose:
      return decode_movenet_multipose(outputs[0], in_width, in_height, K, card.score_threshold);
    case OutputKind::heatmap: return decode_heatmaps(outputs[0], in_width, in_height, K);
    case OutputKind::simcc: return decode_simcc(outputs[0], outputs[1], in_width, in_height, K, card.simcc_ratio);
    case OutputKind::blazepose: return decode_blazepose(outputs[0], outputs[1], K, card.score_threshold);
    case OutputKind::yolo_pose:
      return decode_yolo_pose(outputs[0], K, card.score_threshold, static_cast<size_t>(card.max_people));
  }
  throw Error(Errc::internal, "unknown output kind");
}

}  // namespace octocap::internal
