// SPDX-License-Identifier: MIT
// The geometry commands in-process: the core calls of simplify / clip / clip-lines, and how their
// errors come to name the file each operand was read from (by the error's fields, never by its
// message text).
#include <functional>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include <roiclip/io/geojson.hpp>

#include "geometry_commands.hpp"

namespace roiclip::app {
namespace {

const std::string kData = std::string(ROICLIP_TEST_DATA) + "/io/";
// out_of_range.json's x = 5e6 is beyond a fixed 1/256 px grid (the fitted default takes it).
const Grid kPixelGrid = Grid::fixed(256);
const std::string kOutOfRange =
    "x = 5000000.000000 is outside the supported range +-4194304.000000";

// The InvalidInputError `f` throws, or nothing (a failure) when it throws none.
std::optional<InvalidInputError> thrown(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InvalidInputError thrown";
  return std::nullopt;
}

TEST(GeometryCommands, CoordinateOutOfRangeNamesFileAndPath) {
  const std::string file = kData + "out_of_range.json";
  const Paths paths = io::readPaths(file);
  const Paths square = io::readPaths(kData + "square.geojson");
  const std::string expected = file + ": path 1, vertex 1: " + kOutOfRange;
  const auto e = thrown([&] { simplifyInput(paths, file, FillRule::NonZero, kPixelGrid); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->what(), expected);
  EXPECT_EQ(e->location().source, file);
  EXPECT_EQ(e->location().operand, Operand::Subject);  // the core's fields are kept
  EXPECT_EQ(e->location().path, 1u);
  EXPECT_EQ(e->location().vertex, 1u);
  EXPECT_EQ(e->location().axis, Axis::X);
  const auto asClip = thrown([&] {
    clipInputs(ClipOp::Intersection, square, "square.geojson", paths, file, FillRule::EvenOdd,
               FillRule::EvenOdd, kPixelGrid);
  });
  ASSERT_TRUE(asClip);
  EXPECT_EQ(asClip->what(), expected);
  const auto asSubject = thrown([&] {
    clipInputs(ClipOp::Union, paths, file, square, "square.geojson", FillRule::EvenOdd,
               FillRule::EvenOdd, kPixelGrid);
  });
  ASSERT_TRUE(asSubject);
  EXPECT_EQ(asSubject->what(), expected);
}

TEST(ClipLinesInputs, InsideAndOutsideOfASquare) {
  const Paths lines = io::readLines(kData + "lines_cross.geojson");
  const Paths square = io::readPaths(kData + "square.geojson");
  // The square [0, 10]^2 is closed: the part of line 2 along its top edge is inside.
  EXPECT_EQ(clipLinesInputs(lines, "l", square, "r", FillRule::EvenOdd),
            (Paths{{{0, 5}, {5, 5}, {5, 10}}, {{2, 2}, {8, 2}}, {{0, 10}, {10, 10}}}));
  EXPECT_EQ(
      clipLinesInputs(lines, "l", square, "r", FillRule::EvenOdd, LinePart::Outside),
      (Paths{{{-5, 5}, {0, 5}}, {{5, 10}, {5, 15}}, {{-2, 10}, {0, 10}}, {{10, 10}, {12, 10}}}));
}

TEST(ClipLinesInputs, CoreErrorsNameTheSource) {
  const std::string far = kData + "out_of_range.json";
  const Paths farLines = io::readLines(far);
  const Paths lines = io::readLines(kData + "lines_cross.geojson");
  const Paths square = io::readPaths(kData + "square.geojson");
  const std::string expected = far + ": path 1, vertex 1: " + kOutOfRange;
  const auto line = thrown([&] {
    clipLinesInputs(farLines, far, square, "square.geojson", FillRule::EvenOdd, LinePart::Inside,
                    kPixelGrid);
  });
  ASSERT_TRUE(line);
  EXPECT_EQ(line->what(), expected);
  EXPECT_EQ(line->location().operand, Operand::Line);
  const auto region = thrown([&] {
    clipLinesInputs(lines, "lines.geojson", io::readPaths(far), far, FillRule::NonZero,
                    LinePart::Inside, kPixelGrid);
  });
  ASSERT_TRUE(region);
  EXPECT_EQ(region->what(), expected);
  EXPECT_EQ(region->location().operand, Operand::Clip);
}

// The bug of matching the message's first word: an input whose name starts with "clip " or
// "subject " was taken for an operand label. Relabelling by field cannot confuse the two.
TEST(NameSource, InputNamedLikeAnOperandIsNotMistakenForIt) {
  // An io error names its input already (location().source); relabelling leaves it as it is.
  // The message-matching code read "clip 1.json: ..." as an error of the clip operand and gave
  // "b.json: 1.json: ...".
  const std::string degenerate = R"({"paths": [[[0, 0], [1, 0], [0, 1]], [[0, 0], [1, 1]]]})";
  for (const std::string name : {"clip 1.json", "subject 1.json", "line 1.json"}) {
    SCOPED_TRACE(name);
    io::ReadOptions strict;  // --strict: the reader refuses the degenerate ring
    strict.allowDegenerateRings = false;
    const auto read = thrown([&] { io::parsePaths(degenerate, name, strict); });
    ASSERT_TRUE(read);
    EXPECT_EQ(read->location().source, name);
    EXPECT_EQ(read->location().operand, Operand::None);
    const std::string expected = name + ": path 1: ring has fewer than 3 distinct points";
    EXPECT_EQ(read->what(), expected);
    const InvalidInputError relabelled =
        nameSource(*read, {{Operand::Subject, "a.json"}, {Operand::Clip, "b.json"}});
    EXPECT_EQ(relabelled.what(), expected);
  }

  // Core errors go to the name given with the operand the core names, whatever the names say.
  const Paths far = io::readPaths(kData + "out_of_range.json");
  const Paths square = io::readPaths(kData + "square.geojson");
  const std::string clipNamed = "clip 1.json";
  const std::string subjectNamed = "subject 2.json";
  const std::string at = ": path 1, vertex 1: " + kOutOfRange;
  const auto asSubject = thrown([&] {
    clipInputs(ClipOp::Union, far, clipNamed, square, subjectNamed, FillRule::EvenOdd,
               FillRule::EvenOdd, kPixelGrid);
  });
  ASSERT_TRUE(asSubject);
  EXPECT_EQ(asSubject->what(), clipNamed + at);
  const auto asClip = thrown([&] {
    clipInputs(ClipOp::Union, square, clipNamed, far, subjectNamed, FillRule::EvenOdd,
               FillRule::EvenOdd, kPixelGrid);
  });
  ASSERT_TRUE(asClip);
  EXPECT_EQ(asClip->what(), subjectNamed + at);
  const auto asLines = thrown([&] {
    clipLinesInputs(far, clipNamed, square, subjectNamed, FillRule::EvenOdd, LinePart::Inside,
                    kPixelGrid);
  });
  ASSERT_TRUE(asLines);
  EXPECT_EQ(asLines->what(), clipNamed + at);
  const auto asRegion = thrown([&] {
    clipLinesInputs(square, clipNamed, far, subjectNamed, FillRule::EvenOdd, LinePart::Inside,
                    kPixelGrid);
  });
  ASSERT_TRUE(asRegion);
  EXPECT_EQ(asRegion->what(), subjectNamed + at);
}

TEST(NameSource, AnErrorNamingNoOperandNamesEverySource) {
  const InvalidInputError e("grid scale must be positive and finite, got 0.000000");
  EXPECT_EQ(
      std::string(nameSource(e, {{Operand::Subject, "a.json"}, {Operand::Clip, "b.json"}}).what()),
      "a.json, b.json: grid scale must be positive and finite, got 0.000000");
  const auto core = thrown([] {
    simplifyInput({{{0, 0}, {1, 0}, {1, 1}}}, "a.json", FillRule::EvenOdd, Grid{-1.0});
  });
  ASSERT_TRUE(core);
  EXPECT_EQ(core->location().operand, Operand::None);
  EXPECT_EQ(std::string(core->what()),
            "a.json: grid scale must be positive and finite, got -1.000000");
}

}  // namespace
}  // namespace roiclip::app
