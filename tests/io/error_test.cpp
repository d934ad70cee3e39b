// SPDX-License-Identifier: MIT
// roiclip::InvalidInputError as a structured error: the core's throw sites fill in the fields
// (operand, path, vertex, axis), what() is formatted from them, and roiclip::io sets the source.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <roiclip/error.hpp>
#include <roiclip/io/geojson.hpp>
#include <roiclip/roiclip.hpp>

namespace roiclip {
namespace {

const Path kSquare = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};

// The error the core throws for `bad` as the subject of simplify() (Operand::Subject), the clip
// operand of intersect() or the region of clipLines() (Operand::Clip), or the polylines of
// clipLines() (Operand::Line).
InvalidInputError coreError(Operand operand, const Paths& bad) {
  try {
    switch (operand) {
      case Operand::Subject:
        simplify(bad, FillRule::NonZero, Grid::fixed(256));  // the range of the messages below
        break;
      case Operand::Clip:
        intersect({kSquare}, bad, FillRule::EvenOdd, Grid::fixed(256));
        break;
      case Operand::Line:
        clipLines(bad, {kSquare}, FillRule::EvenOdd, LinePart::Inside, Grid::fixed(256));
        break;
      case Operand::None:
        break;
    }
  } catch (const InvalidInputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InvalidInputError thrown";
  return InvalidInputError("none");
}

TEST(InvalidInputError, CoreThrowSitesSetTheFields) {
  const double nan = std::nan("");
  const struct {
    Operand operand;
    Paths paths;
    std::size_t path, vertex;
    Axis axis;
    const char* what;
  } cases[] = {
      {Operand::Subject,
       {kSquare, {{0, 0}, {1, 0}, {1, nan}}},
       1,
       2,
       Axis::Y,
       "subject path 1, vertex 2: y is not a finite number"},
      {Operand::Subject,
       {{{0, 0}, {INFINITY, 0}, {1, 1}}},
       0,
       1,
       Axis::X,
       "subject path 0, vertex 1: x is not a finite number"},
      {Operand::Clip,
       {kSquare, {{0, 0}, {1, nan}, {2, 0}}},
       1,
       1,
       Axis::Y,
       "clip path 1, vertex 1: y is not a finite number"},
      {Operand::Clip,
       {{{0, 0}, {1, 0}, {1, -1e7}}},
       0,
       2,
       Axis::Y,
       "clip path 0, vertex 2: y = -10000000.000000 is outside the supported range "
       "+-4194304.000000"},
      {Operand::Line,
       {{{1, 1}, {2, 2}}, {{1, 1}, {nan, 2}}},
       1,
       1,
       Axis::X,
       "line path 1, vertex 1: x is not a finite number"},
      {Operand::Line,
       {{{5e6, 1}, {2, 2}}},
       0,
       0,
       Axis::X,
       "line path 0, vertex 0: x = 5000000.000000 is outside the supported range "
       "+-4194304.000000"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    const InvalidInputError e = coreError(c.operand, c.paths);
    EXPECT_EQ(std::string(e.what()), c.what);
    EXPECT_TRUE(e.location().source.empty());
    EXPECT_EQ(e.location().operand, c.operand);
    EXPECT_EQ(e.location().path, c.path);
    EXPECT_EQ(e.location().vertex, c.vertex);
    EXPECT_EQ(e.location().axis, c.axis);
    // The message is formatted from the fields, and a source replaces the operand's name.
    EXPECT_EQ(InvalidInputError::format(e.location(), e.problem()), e.what());
    const std::string where = std::string(toString(c.operand)) + " ";
    EXPECT_EQ(std::string(e.withSource("f.json").what()),
              "f.json: " + std::string(c.what).substr(where.size()));
  }
  // The region of clipLines() is the clip operand.
  const InvalidInputError region = [] {
    try {
      clipLines({{{1, 1}, {2, 2}}}, {{{0, 0}, {1e9, 0}, {0, 1}}}, FillRule::EvenOdd,
                LinePart::Inside, Grid::fixed(256));
    } catch (const InvalidInputError& e) {
      return e;
    }
    return InvalidInputError("none");
  }();
  EXPECT_EQ(region.location().operand, Operand::Clip);
  EXPECT_EQ(region.location().vertex, 1u);
}

TEST(InvalidInputError, WhatIsFormattedFromTheFields) {
  InputLocation at;
  EXPECT_EQ(InvalidInputError(at, "bad").what(), std::string("bad"));
  at.operand = Operand::Clip;
  at.path = 3;
  EXPECT_EQ(InvalidInputError(at, "is empty").what(), std::string("clip path 3: is empty"));
  at.vertex = 4;
  at.axis = Axis::X;
  const InvalidInputError e(at, "is not a finite number");
  EXPECT_EQ(e.what(), std::string("clip path 3, vertex 4: x is not a finite number"));
  EXPECT_EQ(e.problem(), "is not a finite number");
  const InvalidInputError named = e.withSource("clip 1.json");
  EXPECT_EQ(named.what(), std::string("clip 1.json: path 3, vertex 4: x is not a finite number"));
  EXPECT_EQ(named.location().operand, Operand::Clip);  // the fields stay
  EXPECT_EQ(named.location().vertex, 4u);
  // A plain message is its own problem; a source goes in front of it.
  const InvalidInputError plain("grid scale must be positive");
  EXPECT_EQ(plain.location().operand, Operand::None);
  EXPECT_EQ(plain.withSource("a, b").what(), std::string("a, b: grid scale must be positive"));
}

TEST(InvalidInputError, IoErrorsCarryTheirSource) {
  try {
    io::parsePaths(R"({"paths": [[[0, 0], [1, "1"], [1, 0]]]})", "subject 1.json");
    FAIL() << "accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_EQ(e.location().source, "subject 1.json");
    EXPECT_EQ(e.location().operand, Operand::None);
    EXPECT_EQ(std::string(e.what()), "subject 1.json: path 0, point 1: y is not a number (string)");
  }
}

}  // namespace
}  // namespace roiclip
