// SPDX-License-Identifier: MIT
// Clipper 1 (libpolyclipping) for the tests and bench/core: roiclip paths in Clipper's integer
// units, roiclip's fill rules and operations as Clipper's enums, and the area of a solution
// with the error bound Clipper's rounding of crossing points implies.
#pragma once

#include <clipper.hpp>

#include <roiclip/roiclip.hpp>

namespace roiclip::testing {

/// Clipper works on the same 1/256 px grid as roiclip's default Grid.
constexpr double kClipperUnits = 256.0;

/// Snap to integer units with the rounding roiclip's grid uses (nearest, ties to even).
ClipperLib::Path toClipper(const Path& path);
ClipperLib::Paths toClipper(const Paths& paths);
/// Clipper's fill type for a roiclip fill rule (both count the winding of the raw (x, y)
/// numbers; Clipper's Orientation() == true is roiclip's positive shoelace sum).
ClipperLib::PolyFillType toClipper(FillRule rule);
ClipperLib::ClipType toClipper(ClipOp op);

/// Signed area (sum of the rings' shoelace areas) and perimeter of a Clipper solution, in px.
struct ClipperMeasure {
  double area = 0;
  double perimeter = 0;
};
ClipperMeasure measure(const ClipperLib::Paths& paths);

/// Filled area in square pixels of a Clipper solution (outer rings and holes together).
double clipperArea(const ClipperLib::Paths& paths);

/// Clipper moves each crossing point by at most half a unit diagonally; the area changes by at
/// most that displacement times the perimeter of its output.
double roundingTolerance(const ClipperMeasure& m);

}  // namespace roiclip::testing
