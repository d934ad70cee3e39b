// SPDX-License-Identifier: MIT
// <roiclip/version.hpp> is generated from the CMake project version (cmake/version.hpp.in).
#include <roiclip/version.hpp>

#include <gtest/gtest.h>

#include <string>

TEST(Version, MatchesTheCMakeProjectVersion) {
  EXPECT_EQ(std::string(roiclip::version()), ROICLIP_PROJECT_VERSION);
  EXPECT_EQ(std::string(ROICLIP_VERSION_STRING), ROICLIP_PROJECT_VERSION);
  EXPECT_EQ(std::to_string(ROICLIP_VERSION_MAJOR) + "." + std::to_string(ROICLIP_VERSION_MINOR) +
                "." + std::to_string(ROICLIP_VERSION_PATCH),
            ROICLIP_PROJECT_VERSION);
  static_assert(roiclip::version()[0] != '\0', "version() is usable in constant expressions");
}
