// SPDX-License-Identifier: MIT
// Benchmark workloads: deterministic (fixed-seed) polygon generators shaped like the inputs a
// vision pipeline feeds roiclip. Every coordinate lies on roiclip's default 1/256 px grid, so
// roiclip, Clipper (integer units), Boost.Geometry and GEOS (doubles) all see identical input.
#pragma once

#include <cstdint>
#include <string>

#include <roiclip/geometry.hpp>

namespace roiclip::bench {

/// Grid units per pixel used to feed integer libraries (matches roiclip's default Grid).
constexpr double kGridScale = 256.0;

/// A simple (non-self-intersecting) closed 8-connected-like pixel chain with integer coordinates,
/// shaped like a cv::findContours(CHAIN_APPROX_NONE) contour of a random blob. Vertices are in
/// strictly increasing angle around the blob centre, which makes the ring simple (a valid
/// polygon for Boost.Geometry and GEOS). Steps are mostly unit 8-neighbour moves.
/// @param vertices approximate vertex count (the result is within ~1% of it).
/// @param seed     fixed seed; the same arguments always give the same ring.
Path blobContour(std::size_t vertices, std::uint32_t seed);

/// blobContour() with `twists` local 2-opt reversals of short runs, each of which makes the chain
/// cross itself once (a small figure-eight), like a noisy contour that folds over.
Path twistedContour(std::size_t vertices, std::size_t twists, std::uint32_t seed);

/// `vertices` points drawn uniformly in [0, size)^2 (on the 1/256 px grid), joined in draw
/// order: a heavily self-intersecting polygon with O(vertices^2) crossings.
Path randomPolygon(std::size_t vertices, double size, std::uint32_t seed);

/// A convex quad with sub-pixel, non-axis-aligned corners (a perspective view of a square ROI)
/// covering roughly the middle of `ring`'s bounding box. Wound with a positive shoelace sum.
Path perspectiveQuad(const Path& ring, std::uint32_t seed);

/// Round to roiclip's default grid (1/kGridScale px), the snapping roiclip applies on input.
double snapToGrid(double v);

/// Write a clipping case as JSON {"subject": [[[x,y],...]], "clip": [...], "op": ...,
/// "subjectFillRule": ..., "clipFillRule": ...} (the tests/data/core_bugs format).
/// @throws roiclip::InvalidInputError when the file cannot be written.
void writeCaseJson(const std::string& file, const Paths& subject, const Paths& clip, ClipOp op,
                   FillRule subjectRule, FillRule clipRule);

}  // namespace roiclip::bench
