// SPDX-License-Identifier: MIT
// Stage 2: decide from the winding numbers on both sides of each piece whether it bounds the
// result, and on which side the result lies.
//
// The paper classifies whole contours as holes by their winding number and later deletes edges
// whose midpoint falls inside a hole. Doing the same per piece, from the exact winding numbers
// on its two sides, is what makes the decision correct for nested, overlapping and touching
// contours and for every fill rule, not just even-odd and non-zero.
//
// classifyPiece(), sideBetween(), BooleanSpec::inside() and the sweep's PieceClassifier are
// inline in pipeline.hpp: the sweep asks them for every piece (4% of a crossing-heavy row as
// calls into this file).
#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"

namespace roiclip::detail {

LinePlace classifyOpenPiece(const Windings& below, const Windings& above, const BooleanSpec& spec) {
  const bool in = spec.inside(below);
  const bool out = spec.inside(above);
  if (in && out) return LinePlace::Inside;
  return in || out ? LinePlace::Boundary : LinePlace::Outside;
}

}  // namespace roiclip::detail
