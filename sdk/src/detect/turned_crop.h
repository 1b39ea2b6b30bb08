// Crops turned with the body: a model trained on people standing up in its input (MediaPipe's BlazePose) loses a
// person who leans, bends or lies when the crop stays level (on Pose2Sim's balancing take, whole frames of four views
// were lost). Its own pipeline turns the crop so that the hips-to-shoulders line points up; so does this one, from the
// person's last keypoints. Keypoints use pixel centres at integers, as everywhere in detect/.
#pragma once
#include <optional>

#include "core/layout.h"
#include "core/person2d.h"
#include "detect/image.h"

namespace octocap::internal {

struct TurnedCrop {
  double centre_x = 0, centre_y = 0;  // source pixels
  double width = 0, height = 0;       // source pixels, along the crop's own axes
  double angle = 0;                   // radians: the crop's up is the image's up turned this far clockwise
};

// How far the body leans from upright: the angle of the hips-to-shoulders line (clockwise from the image's up), from
// the layout's neck and root sources (shoulders, hips). Nothing when the person lacks them.
std::optional<double> body_lean(const Person2D& person, const KeypointLayout& layout, double min_confidence);

// A crop of the network's aspect around the person's keypoints, turned by `angle`, padded as level crops are.
TurnedCrop turned_crop_around(const Person2D& person, double angle, double aspect, double pad, double min_confidence);

// Draws the crop into the whole canvas (RGB, black outside the image), and maps canvas keypoints back to the source.
void draw_turned(const ImageView& image, const TurnedCrop& crop, RgbCanvas& canvas);
void turned_to_source(const TurnedCrop& crop, int canvas_width, int canvas_height, double& x, double& y);

}  // namespace octocap::internal
