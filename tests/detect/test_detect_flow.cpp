// Optical flow between detections (detect/flow_tracker): keypoints on a textured picture moved by a known shift are
// followed to where they went; a point whose surroundings change is dropped, not reported wrong.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

#include "detect/flow_tracker.h"

using namespace octocap::internal;

namespace {

// A picture with texture at every scale the tracker looks at (blurred noise), BGR.
cv::Mat textured(int width, int height, unsigned seed) {
  cv::Mat noise(height / 8, width / 8, CV_8UC3);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 255);
  cv::Mat picture;
  cv::resize(noise, picture, cv::Size(width, height), 0, 0, cv::INTER_CUBIC);
  return picture;
}

cv::Mat shifted(const cv::Mat& picture, double dx, double dy) {
  cv::Mat moved;
  const cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, dx, 0, 1, dy);
  cv::warpAffine(picture, moved, m, picture.size(), cv::INTER_CUBIC, cv::BORDER_REFLECT);
  return moved;
}

ImageView view_of(const cv::Mat& m) {
  return {m.data, m.cols, m.rows, static_cast<int>(m.step[0]), PixelFormat::bgr8};
}

DetectedPerson person_at(const std::vector<cv::Point2d>& points) {
  DetectedPerson p;
  for (const cv::Point2d& q : points) p.keypoints.push_back({q.x, q.y, 0.8});
  return p;
}

}  // namespace

TEST_CASE("optical flow follows keypoints shifted by a known amount, in view pixels, across a downscale") {
  // 1088x1920 (Pose2Sim's portrait cameras): tracked at a quarter size, reported in view pixels.
  const cv::Mat first = textured(1088, 1920, 3);
  const std::vector<cv::Point2d> points = {{300, 400}, {544, 960}, {800, 1500}, {120.5, 1700.25}, {1000, 200}};
  const std::vector<std::pair<double, double>> moves = {{7.5, -4.25}, {-13, 9}, {2.2, 16.8}};
  FlowTracker tracker;
  tracker.advance(view_of(first));
  CHECK_FALSE(tracker.ready());  // one picture: nothing to follow yet
  DetectedPerson person = person_at(points);
  double x = 0, y = 0;
  cv::Mat previous = first;
  for (const auto& [dx, dy] : moves) {
    x += dx, y += dy;
    const cv::Mat next = shifted(first, x, y);
    CHECK(tracker.follows(view_of(next)));
    tracker.advance(view_of(next));
    REQUIRE(tracker.ready());
    const auto moved = tracker.track({person}, 0.3);
    REQUIRE(moved.size() == 1);
    for (size_t k = 0; k < points.size(); ++k) {
      INFO("keypoint " << k << " after a move of " << dx << ", " << dy);
      const Keypoint2D& kp = moved[0].keypoints[k];
      CHECK(kp.confidence == 0.8);
      CHECK(std::hypot(kp.x - (points[k].x + x), kp.y - (points[k].y + y)) < 1.0);  // a quarter pixel where tracked
    }
    person = moved[0];
  }
  CHECK(person.box.width > 0);
}

TEST_CASE("optical flow drops keypoints whose surroundings changed, and follows nothing across a size change") {
  const cv::Mat first = textured(960, 540, 5);
  cv::Mat next = shifted(first, 4, 3);
  // Around the second point, another picture altogether (someone walked in front).
  textured(200, 200, 9).copyTo(next(cv::Rect(600, 300, 200, 200)));
  FlowTracker tracker;
  tracker.advance(view_of(first));
  tracker.advance(view_of(next));
  DetectedPerson person = person_at({{200, 200}, {700, 400}, {400, 100}});
  person.keypoints.push_back({100, 100, 0.1});  // unconfident: not followed, reported as lost
  const auto moved = tracker.track({person}, 0.3);
  CHECK(moved[0].keypoints[0].confidence == 0.8);
  CHECK(std::hypot(moved[0].keypoints[0].x - 204, moved[0].keypoints[0].y - 203) < 1.0);
  CHECK(moved[0].keypoints[1].confidence == 0);
  CHECK(moved[0].keypoints[2].confidence == 0.8);
  CHECK(moved[0].keypoints[3].confidence == 0);

  const cv::Mat smaller = textured(480, 270, 5);
  CHECK_FALSE(tracker.follows(view_of(smaller)));
  tracker.advance(view_of(smaller));
  CHECK_FALSE(tracker.ready());
  const auto across = tracker.track({person}, 0.3);
  for (const Keypoint2D& k : across[0].keypoints) CHECK(k.confidence == 0);
  tracker.reset();
  CHECK_FALSE(tracker.ready());
}
