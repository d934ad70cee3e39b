// SPDX-License-Identifier: MIT
// Stage 2 (src/core/classify.cpp): from the winding numbers below a piece and its contribution,
// the fill rules and the operation decide whether it bounds the result and on which side.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "stage_support.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

detail::Windings w(std::int64_t s, std::int64_t c = 0) { return {s, c}; }

const FillRule kRules[] = {FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive,
                           FillRule::Negative};
const ClipOp kOps[] = {ClipOp::Intersection, ClipOp::Union, ClipOp::Difference, ClipOp::Xor};

// Winding numbers in [-3, 3] and each of `far` in both signs.
std::vector<std::int64_t> windingsWith(std::initializer_list<std::int64_t> far) {
  std::vector<std::int64_t> windings;
  for (std::int64_t v = -3; v <= 3; ++v) windings.push_back(v);
  for (const std::int64_t v : far) {
    windings.push_back(v);
    windings.push_back(-v);
  }
  return windings;
}

TEST(StageClassify, SimplifyDecidesFromTheSubjectsFillRule) {
  const auto evenOdd = stages::simplifyWith(FillRule::EvenOdd);
  EXPECT_EQ(detail::classifyPiece(w(0), w(1), evenOdd), detail::Side::Above);
  EXPECT_EQ(detail::classifyPiece(w(1), w(-1), evenOdd), detail::Side::Below);
  EXPECT_EQ(detail::classifyPiece(w(1), w(1), evenOdd), detail::Side::Below);  // 2 is even
  EXPECT_EQ(detail::classifyPiece(w(2), w(1), evenOdd), detail::Side::Above);
  EXPECT_EQ(detail::classifyPiece(w(0), w(2), evenOdd), detail::Side::None);
  const auto nonZero = stages::simplifyWith(FillRule::NonZero);
  EXPECT_EQ(detail::classifyPiece(w(1), w(1), nonZero), detail::Side::None);  // 1 | 2
  EXPECT_EQ(detail::classifyPiece(w(-1), w(1), nonZero), detail::Side::Below);
  const auto positive = stages::simplifyWith(FillRule::Positive);
  EXPECT_EQ(detail::classifyPiece(w(0), w(-1), positive), detail::Side::None);
  EXPECT_EQ(detail::classifyPiece(w(-1), w(2), positive), detail::Side::Above);
  const auto negative = stages::simplifyWith(FillRule::Negative);
  EXPECT_EQ(detail::classifyPiece(w(0), w(-1), negative), detail::Side::Above);
  // A clip winding number means nothing to simplify.
  EXPECT_EQ(detail::classifyPiece(w(0, 0), w(0, 1), evenOdd), detail::Side::None);
}

TEST(StageClassify, BinaryOperationsCombineBothOperands) {
  // Below: in the subject only; above: in both.
  const detail::Windings below = w(1, 0), up = w(0, 1);
  EXPECT_EQ(detail::classifyPiece(below, up, stages::clipWith(ClipOp::Intersection)),
            detail::Side::Above);
  EXPECT_EQ(detail::classifyPiece(below, up, stages::clipWith(ClipOp::Union)), detail::Side::None);
  EXPECT_EQ(detail::classifyPiece(below, up, stages::clipWith(ClipOp::Difference)),
            detail::Side::Below);
  EXPECT_EQ(detail::classifyPiece(below, up, stages::clipWith(ClipOp::Xor)), detail::Side::Below);
  // Each operand has its own rule: the clip's w = 2 is outside under even-odd, inside under
  // non-zero.
  auto how = stages::clipWith(ClipOp::Intersection);
  how.clipRule = FillRule::NonZero;
  EXPECT_EQ(detail::classifyPiece(w(1, 1), w(0, 1), how), detail::Side::None);
  how.clipRule = FillRule::EvenOdd;
  EXPECT_EQ(detail::classifyPiece(w(1, 1), w(0, 1), how), detail::Side::Below);
}

// inside() looks the operation up in a truth table; here every operation, every pair of fill
// rules and every pair of winding numbers in [-3, 3] and a few far ones (+-2^31 +- 1, +-2^62,
// the 64-bit extremes) against the oracle's combine().
TEST(StageClassify, InsideIsTheOperationOfBothFillRules) {
  constexpr std::int64_t kFar = std::int64_t{1} << 31;
  std::vector<std::int64_t> windings = windingsWith(
      {kFar - 1, kFar, kFar + 1, std::int64_t{1} << 62, std::numeric_limits<std::int64_t>::max()});
  windings.push_back(std::numeric_limits<std::int64_t>::min());
  int checked = 0;
  for (const FillRule subjectRule : kRules) {
    for (const FillRule clipRule : kRules) {
      for (const std::int64_t sw : windings) {
        for (const std::int64_t cw : windings) {
          const bool s = isFilled(subjectRule, sw), c = isFilled(clipRule, cw);
          auto simplify = stages::simplifyWith(subjectRule);
          EXPECT_EQ(simplify.inside(w(sw, cw)), s);
          for (const ClipOp op : kOps) {
            auto spec = stages::clipWith(op);
            spec.subjectRule = subjectRule;
            spec.clipRule = clipRule;
            EXPECT_EQ(spec.inside(w(sw, cw)), testing::combine(op, s, c))
                << "op " << int(op) << " windings " << sw << ", " << cw;
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_EQ(checked, 4 * 4 * 18 * 18 * 4);
}

// The sweep's PieceClassifier (each fill rule as a sign and a mask, the truth table read once)
// against BooleanSpec::inside(): every operation and pair of fill rules, simplify too, winding
// numbers in [-3, 3] and far ones (up to 2^62 - 1 in magnitude).
TEST(StageClassify, PieceClassifierAgreesWithInside) {
  const std::vector<std::int64_t> windings = windingsWith(
      {(std::int64_t{1} << 31) + 1, std::int64_t{1} << 40, (std::int64_t{1} << 62) - 1});
  std::vector<detail::BooleanSpec> specs;
  for (const FillRule subjectRule : kRules) {
    specs.push_back(stages::simplifyWith(subjectRule));
    for (const FillRule clipRule : kRules) {
      for (const ClipOp op : kOps) {
        auto spec = stages::clipWith(op);
        spec.subjectRule = subjectRule;
        spec.clipRule = clipRule;
        specs.push_back(spec);
      }
    }
  }
  int inside = 0, checked = 0;
  for (const detail::BooleanSpec& spec : specs) {
    const detail::PieceClassifier classifier(spec);
    for (const std::int64_t sw : windings) {
      for (const std::int64_t cw : windings) {
        const bool expected = spec.inside(w(sw, cw));
        ASSERT_EQ(classifier.inside(w(sw, cw)), expected) << sw << ", " << cw;
        inside += expected ? 1 : 0;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, (4 + 4 * 4 * 4) * 13 * 13);
  EXPECT_GT(inside, checked / 4);  // both answers occur
  EXPECT_LT(inside, checked * 3 / 4);
}

TEST(StageClassify, OpenPiecesAreInsideOnTheBoundaryOrOutside) {
  const auto how = stages::simplifyWith(FillRule::EvenOdd);
  EXPECT_EQ(detail::classifyOpenPiece(w(1), w(1), how), detail::LinePlace::Inside);
  EXPECT_EQ(detail::classifyOpenPiece(w(0), w(1), how), detail::LinePlace::Boundary);
  EXPECT_EQ(detail::classifyOpenPiece(w(1), w(2), how), detail::LinePlace::Boundary);
  EXPECT_EQ(detail::classifyOpenPiece(w(0), w(2), how), detail::LinePlace::Outside);
  EXPECT_EQ(detail::classifyOpenPiece(w(0), w(0), how), detail::LinePlace::Outside);
}

}  // namespace
}  // namespace roiclip
