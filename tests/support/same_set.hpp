// SPDX-License-Identifier: MIT
// Test helper (GoogleTest): two polygon sets equal polygon for polygon, vertex for vertex, with
// the same nesting (parent, parentHole). For results that must not depend on how they were
// reached (kept buffers, prepared regions, operand forms, freed pipeline arrays).
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <string>

#include <roiclip/geometry.hpp>

namespace roiclip::testing {

inline void expectSameSet(const PolygonSet& a, const PolygonSet& b, const std::string& what) {
  ASSERT_EQ(a.polygons.size(), b.polygons.size()) << what;
  for (std::size_t i = 0; i < a.polygons.size(); ++i) {
    EXPECT_EQ(a.polygons[i].outer, b.polygons[i].outer) << what << ", polygon " << i;
    EXPECT_EQ(a.polygons[i].holes, b.polygons[i].holes) << what << ", polygon " << i;
    EXPECT_EQ(a.polygons[i].parent, b.polygons[i].parent) << what << ", polygon " << i;
    EXPECT_EQ(a.polygons[i].parentHole, b.polygons[i].parentHole) << what << ", polygon " << i;
  }
}

}  // namespace roiclip::testing
