// SPDX-License-Identifier: MIT
// The public roiclip::apriltag headers must not drag in libapriltag's headers: its
// common/math_util.h defines a `max` macro that breaks <algorithm> and std::max.
#include <roiclip/apriltag/detector.hpp>
#include <roiclip/apriltag/projective.hpp>
#include <roiclip/apriltag/roi.hpp>

#ifdef max
#error "a public roiclip::apriltag header leaked libapriltag's max macro"
#endif
#ifdef APRILTAG_TASKS_PER_THREAD_TARGET
#error "a public roiclip::apriltag header includes apriltag.h"
#endif

#include <algorithm>

#include <gtest/gtest.h>

TEST(AprilTagPublicHeaders, StdMaxStillWorks) {
  EXPECT_EQ(std::max(2, 3), 3);
  EXPECT_EQ((std::max)({4, 1, 7}), 7);
}
