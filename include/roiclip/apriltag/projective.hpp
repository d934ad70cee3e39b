// SPDX-License-Identifier: MIT
// roiclip::apriltag: plane-to-image homographies on GLM types (core-facing, no OpenCV types).
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include <roiclip/geometry.hpp>

namespace roiclip::apriltag {

/// Apply a homography (column-major GLM, acting on homogeneous (x, y, 1)) to a point.
/// @throws Error if the point maps to infinity (homogeneous w == 0).
glm::dvec2 applyHomography(const glm::dmat3& h, glm::dvec2 p);

/// Map every vertex of `paths` through `h`. A homography maps straight edges to straight edges,
/// so the result is the exact image of the polygons, as long as no polygon crosses the line `h`
/// sends to infinity. Orientation is kept when det(h) > 0 and reversed when det(h) < 0.
/// @throws InvalidInputError if the vertices do not all lie on the same side of that line (the
///         image would be unbounded or wrapped through infinity).
Paths mapPaths(const glm::dmat3& h, const Paths& paths);

}  // namespace roiclip::apriltag
