#pragma once
/** How much of a predicted image segment lies on detected edgels: the check that a segment placed
 * in the right image from disparities found elsewhere (its corners) is really there (thesis
 * 4.3.2.3: a match must be supported by the image, not only by its neighbours). */

#include <mrolr/stereo/EdgeStrings.h>

#include <opencv2/core.hpp>

#include <vector>

namespace mrolr::stereo
{
/** Fraction (0..1) of the segment a → b (px), sampled every pixel, that has an edgel of
 * @p strings within @p radius_px whose tangent is within @p max_angle_deg of the segment's
 * direction (either sense: the edge's contrast may flip between views). 0 for a segment shorter
 * than 2 px. */
double edgelSupport(const std::vector<EdgeString>& strings, cv::Point2d a, cv::Point2d b,
                    double max_angle_deg, double radius_px = 1.0);

}  // namespace mrolr::stereo
