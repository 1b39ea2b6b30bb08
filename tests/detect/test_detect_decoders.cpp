// Each output decoder against hand-built tensors whose answer is known.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <cmath>

#include "core/error.h"
#include "detect/decoders.h"
#include "detect/person_pick.h"

using namespace octocap::internal;
using Catch::Approx;

namespace {

// A sampled Gaussian peak at a sub-pixel position.
float gauss(double x, double y, double cx, double cy, double sigma) {
  return static_cast<float>(std::exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (2 * sigma * sigma)));
}

}  // namespace

TEST_CASE("parabolic refinement finds the vertex of a sampled parabola") {
  for (double vertex : {-0.4, -0.1, 0.0, 0.25, 0.45}) {
    auto f = [&](double x) { return 5.0 - 2.0 * (x - vertex) * (x - vertex); };
    CHECK(parabolic_offset(f(-1), f(0), f(1)) == Approx(vertex).margin(1e-12));
  }
  CHECK(parabolic_offset(1, 1, 1) == 0);  // flat: no refinement
  CHECK(parabolic_offset(3, 1, 3) == 0);  // a minimum, not a peak
}

TEST_CASE("MoveNet single-pose rows become pixel-centred keypoints") {
  const size_t K = 17;
  Tensor t{{1, 1, static_cast<int64_t>(K), 3}, std::vector<float>(K * 3)};
  for (size_t k = 0; k < K; ++k) {
    t.data[k * 3 + 0] = 0.05f * static_cast<float>(k);  // y
    t.data[k * 3 + 1] = 1.0f - 0.05f * static_cast<float>(k);  // x
    t.data[k * 3 + 2] = 0.5f;
  }
  const auto people = decode_movenet(t, 256, 192, K);
  REQUIRE(people.size() == 1);
  for (size_t k = 0; k < K; ++k) {
    CHECK(people[0].keypoints[k].x == Approx((1.0 - 0.05 * k) * 256 - 0.5).margin(1e-4));
    CHECK(people[0].keypoints[k].y == Approx(0.05 * k * 192 - 0.5).margin(1e-4));
    CHECK(people[0].keypoints[k].confidence == Approx(0.5));
  }
  Tensor wrong{{1, 1, 16, 3}, std::vector<float>(48)};
  try {
    decode_movenet(wrong, 256, 256, K);
    FAIL("a wrong shape must be refused");
  } catch (const Error& e) {
    CHECK(e.code() == Errc::invalid_argument);
    CHECK(std::string(e.what()).find("[1,1,16,3]") != std::string::npos);
    CHECK(std::string(e.what()).find("expected [1,1,17,3]") != std::string::npos);
  }
}

TEST_CASE("MoveNet multipose keeps people above the score threshold, with their boxes") {
  const size_t K = 17, row = 3 * K + 5;
  Tensor t{{1, 3, static_cast<int64_t>(row)}, std::vector<float>(3 * row, 0.f)};
  const float scores[3] = {0.9f, 0.1f, 0.4f};
  for (size_t p = 0; p < 3; ++p) {
    float* v = &t.data[p * row];
    for (size_t k = 0; k < K; ++k) v[3 * k] = 0.5f, v[3 * k + 1] = 0.1f * (p + 1), v[3 * k + 2] = 0.8f;
    v[3 * K + 0] = 0.2f, v[3 * K + 1] = 0.1f, v[3 * K + 2] = 0.6f, v[3 * K + 3] = 0.3f, v[3 * K + 4] = scores[p];
  }
  const auto people = decode_movenet_multipose(t, 320, 160, K, 0.25);
  REQUIRE(people.size() == 2);
  CHECK(people[0].score == Approx(0.9));
  CHECK(people[1].score == Approx(0.4));
  CHECK(people[1].keypoints[3].x == Approx(0.3 * 320 - 0.5).margin(1e-4));
  CHECK(people[0].box.x == Approx(0.1 * 320).margin(1e-4));
  CHECK(people[0].box.height == Approx(0.4 * 160).margin(1e-4));
  CHECK_THROWS_AS(decode_movenet_multipose(Tensor{{1, 3, 50}, std::vector<float>(150)}, 320, 160, K, 0.25), Error);
}

TEST_CASE("heatmap argmax with sub-pixel refinement lands within a tenth of a cell") {
  const size_t K = 3, H = 48, W = 64;
  const double peaks[K][2] = {{10.3, 7.6}, {50.8, 40.1}, {31.0, 22.5}};
  Tensor t{{1, static_cast<int64_t>(K), static_cast<int64_t>(H), static_cast<int64_t>(W)}, std::vector<float>(K * H * W)};
  for (size_t k = 0; k < K; ++k)
    for (size_t y = 0; y < H; ++y)
      for (size_t x = 0; x < W; ++x) t.data[(k * H + y) * W + x] = 0.9f * gauss(x, y, peaks[k][0], peaks[k][1], 2.0);
  // Input 4x the heatmap: cell centre c is input pixel centre 4c + 1.5.
  const auto people = decode_heatmaps(t, static_cast<int>(4 * W), static_cast<int>(4 * H), K);
  REQUIRE(people.size() == 1);
  for (size_t k = 0; k < K; ++k) {
    CHECK(people[0].keypoints[k].x == Approx(4 * peaks[k][0] + 1.5).margin(0.4));
    CHECK(people[0].keypoints[k].y == Approx(4 * peaks[k][1] + 1.5).margin(0.4));
    CHECK(people[0].keypoints[k].confidence > 0.85);
  }
  CHECK_THROWS_AS(decode_heatmaps(Tensor{{1, 2, H, W}, std::vector<float>(2 * H * W)}, 256, 192, K), Error);
}

TEST_CASE("SimCC picks each axis' peak and divides by the split ratio") {
  const size_t K = 2;
  const double ratio = 2.0, in_w = 192, in_h = 256;
  const size_t Wx = static_cast<size_t>(in_w * ratio), Hy = static_cast<size_t>(in_h * ratio);
  const double truth[K][2] = {{40.25, 100.75}, {150.5, 12.0}};
  Tensor x{{1, static_cast<int64_t>(K), static_cast<int64_t>(Wx)}, std::vector<float>(K * Wx)};
  Tensor y{{1, static_cast<int64_t>(K), static_cast<int64_t>(Hy)}, std::vector<float>(K * Hy)};
  for (size_t k = 0; k < K; ++k) {
    for (size_t i = 0; i < Wx; ++i) x.data[k * Wx + i] = 0.8f * gauss(i, 0, truth[k][0] * ratio, 0, 3.0);
    for (size_t i = 0; i < Hy; ++i) y.data[k * Hy + i] = 0.6f * gauss(i, 0, truth[k][1] * ratio, 0, 3.0);
  }
  const auto people = decode_simcc(x, y, static_cast<int>(in_w), static_cast<int>(in_h), K, ratio);
  REQUIRE(people.size() == 1);
  for (size_t k = 0; k < K; ++k) {
    CHECK(people[0].keypoints[k].x == Approx(truth[k][0]).margin(0.1));
    CHECK(people[0].keypoints[k].y == Approx(truth[k][1]).margin(0.1));
    CHECK(people[0].keypoints[k].confidence == Approx(0.6).margin(0.01));  // the weaker axis
  }
  CHECK_THROWS_AS(decode_simcc(x, Tensor{{1, 3, 10}, std::vector<float>(30)}, 192, 256, K, ratio), Error);
}

TEST_CASE("YOLO-pose rows: threshold, non-maximum suppression, both memory orders") {
  const size_t K = 17, A = 5 + 3 * K, N = 4;
  // Candidates: two overlapping boxes of one person (0.9, 0.7), one other person (0.6), one weak (0.1).
  const float boxes[N][5] = {{100, 100, 50, 120, 0.9f}, {104, 98, 52, 118, 0.7f}, {300, 120, 40, 100, 0.6f},
                             {200, 200, 30, 30, 0.1f}};
  std::vector<float> rows(N * A, 0.f);
  for (size_t i = 0; i < N; ++i) {
    for (size_t a = 0; a < 5; ++a) rows[i * A + a] = boxes[i][a];
    for (size_t k = 0; k < K; ++k) {
      rows[i * A + 5 + 3 * k] = boxes[i][0] + static_cast<float>(k);
      rows[i * A + 6 + 3 * k] = boxes[i][1];
      rows[i * A + 7 + 3 * k] = 0.9f;
    }
  }
  std::vector<float> attributes(N * A);
  for (size_t i = 0; i < N; ++i)
    for (size_t a = 0; a < A; ++a) attributes[a * N + i] = rows[i * A + a];
  for (const Tensor& t : {Tensor{{1, static_cast<int64_t>(N), static_cast<int64_t>(A)}, rows},
                          Tensor{{1, static_cast<int64_t>(A), static_cast<int64_t>(N)}, attributes}}) {
    const auto people = decode_yolo_pose(t, K, 0.25, 10);
    REQUIRE(people.size() == 2);
    CHECK(people[0].score == Approx(0.9));
    CHECK(people[1].score == Approx(0.6));
    CHECK(people[1].keypoints[16].x == Approx(316));
    CHECK(people[0].box.x == Approx(75));
  }
  CHECK(decode_yolo_pose(Tensor{{1, static_cast<int64_t>(N), static_cast<int64_t>(A)}, rows}, K, 0.25, 1).size() == 1);
}

TEST_CASE("person picking: largest, most confident, nearest to last frame, or all best first") {
  auto person = [](double x, double y, double size, double score) {
    DetectedPerson p;
    for (int k = 0; k < 17; ++k) p.keypoints.push_back({x + size * (k % 3), y + size * (k / 3), 0.9});
    p.score = score;
    p.box = {x, y, 2 * size, 5 * size};
    return p;
  };
  const std::vector<DetectedPerson> people = {person(0, 0, 10, 0.5), person(300, 0, 40, 0.4), person(600, 0, 20, 0.9)};
  auto pick = [&](PersonPick how, const Person2D& hint, size_t max) {
    std::vector<DetectedPerson> p = people;
    pick_people(p, how, hint, max, 0.3);
    return p;
  };
  CHECK(pick(PersonPick::largest, {}, 4).size() == 1);
  CHECK(pick(PersonPick::largest, {}, 4)[0].box.x == 300);
  CHECK(pick(PersonPick::most_confident, {}, 4)[0].box.x == 600);
  const Person2D near_first = person(2, 1, 10, 0).keypoints;
  CHECK(pick(PersonPick::nearest_previous, near_first, 4)[0].box.x == 0);
  CHECK(pick(PersonPick::nearest_previous, {}, 4)[0].box.x == 600);  // no history: most confident
  const auto all = pick(PersonPick::all, {}, 2);
  REQUIRE(all.size() == 2);
  CHECK(all[0].score == Approx(0.9));
  CHECK(all[1].score == Approx(0.5));
}

TEST_CASE("BlazePose landmarks become pixel-centred keypoints with their visibility as confidence") {
  const size_t K = 33;
  Tensor landmarks{{1, 195}, std::vector<float>(195)};
  for (size_t k = 0; k < 39; ++k) {
    landmarks.data[k * 5 + 0] = 10.0f + static_cast<float>(k);  // x, input pixels
    landmarks.data[k * 5 + 1] = 200.0f - static_cast<float>(k);  // y
    landmarks.data[k * 5 + 2] = -3;                              // depth: not used
    landmarks.data[k * 5 + 3] = k % 2 ? 2.0f : -2.0f;            // visibility logit
    landmarks.data[k * 5 + 4] = 5;                               // presence logit
  }
  landmarks.data[7 * 5] = NAN;
  const Tensor flag{{1, 1}, {0.9f}};
  const auto people = decode_blazepose(landmarks, flag, K, 0.5);
  REQUIRE(people.size() == 1);
  CHECK(people[0].score == Approx(0.9));
  REQUIRE(people[0].keypoints.size() == K);
  for (size_t k = 0; k < K; ++k) {
    if (k == 7) continue;
    CHECK(people[0].keypoints[k].x == Approx(10.0 + k - 0.5));
    CHECK(people[0].keypoints[k].y == Approx(200.0 - k - 0.5));
    CHECK(people[0].keypoints[k].confidence == Approx(1 / (1 + std::exp(k % 2 ? -2.0 : 2.0))));
  }
  CHECK(people[0].keypoints[7].confidence == 0);  // a NaN landmark is no keypoint
  // The person flag below the card's threshold: nobody there (the crop lost them).
  CHECK(decode_blazepose(landmarks, Tensor{{1, 1}, {0.2f}}, K, 0.5).empty());
  CHECK_THROWS_AS(decode_blazepose(Tensor{{1, 117}, std::vector<float>(117)}, flag, K, 0.5), Error);
  CHECK_THROWS_AS(decode_blazepose(landmarks, Tensor{{1, 2}, {0.5f, 0.5f}}, K, 0.5), Error);
}
