// SPDX-License-Identifier: MIT
// Stage 2: decide from the winding numbers on both sides of each piece whether it bounds the
// result, and on which side the result lies.
//
// The paper classifies whole contours as holes by their winding number and later deletes edges
// whose midpoint falls inside a hole. Doing the same per piece, from the exact winding numbers
// on its two sides, is what makes the decision correct for nested, overlapping and touching
// contours and for every fill rule, not just even-odd and non-zero.
#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"

namespace roiclip::detail {

bool BooleanSpec::inside(const Windings& w) const {
  const bool s = isFilled(subjectRule, w[0]);
  if (!binary) return s;
  const bool c = isFilled(clipRule, w[1]);
  switch (op) {
    case ClipOp::Intersection:
      return s && c;
    case ClipOp::Union:
      return s || c;
    case ClipOp::Difference:
      return s && !c;
    case ClipOp::Xor:
      return s != c;
  }
  return false;
}

Side classifyPiece(const Windings& below, const Windings& contribution,
                   const BooleanSpec& spec) {
  const bool in = spec.inside(below);
  const bool above = spec.inside({below[0] + contribution[0], below[1] + contribution[1]});
  if (in == above) return Side::None;
  return above ? Side::Above : Side::Below;
}

LinePlace classifyOpenPiece(const Windings& below, const Windings& above,
                            const BooleanSpec& spec) {
  const bool in = spec.inside(below);
  const bool out = spec.inside(above);
  if (in && out) return LinePlace::Inside;
  return in || out ? LinePlace::Boundary : LinePlace::Outside;
}

}  // namespace roiclip::detail
