// SPDX-License-Identifier: MIT
// Runs the built `roiclip` command line (ROICLIP_CLI): simplify, clip and clip-lines on the files
// in tests/data/io; checks their output, their stderr and their exit codes.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "exit_codes.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using roiclip::testing::CliRun;

const std::string kData = std::string(ROICLIP_TEST_DATA) + "/io/";

using roiclip::testing::readText;

class Cli : public roiclip::testing::CliTest {
 protected:
  // Properties of the single Feature of a GeoJSON FeatureCollection written by the CLI.
  static json properties(const std::string& text) {
    const json root = json::parse(text);
    EXPECT_EQ(root.at("type"), "FeatureCollection");
    EXPECT_EQ(root.at("features").size(), 1u);
    return root.at("features")[0].at("properties");
  }
  static double area(const CliRun& r) { return properties(r.out).at("area").get<double>(); }

  // A bad-input run: exit code 2, nothing on stdout, one line on stderr naming the file.
  static void expectBadInput(const CliRun& r, const std::string& file, const std::string& problem) {
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
  }
};

TEST_F(Cli, HelpDocumentsExitCodes) {
  for (const char* args : {"--help", "simplify --help", "clip --help", "clip-lines --help"}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.exitCode, 0) << args;
    EXPECT_NE(r.out.find("Exit codes"), std::string::npos) << args;
    EXPECT_NE(r.out.find("2  invalid input"), std::string::npos) << args;
  }
}

TEST_F(Cli, HelpPrintsTheExitCodeTable) {
  using roiclip::app::exitCodesHelp;
  using roiclip::app::ExitCodesOf;
  const std::string geometry = exitCodesHelp(ExitCodesOf::Geometry);
  EXPECT_EQ(geometry.rfind("Exit codes:\n  0  success\n  1  command-line usage error\n", 0), 0u)
      << geometry;
  EXPECT_NE(
      geometry.find(
          "\n     --strict a degenerate ring (fewer than 3 distinct points, or all on one line)"),
      std::string::npos)
      << geometry;
  EXPECT_NE(geometry.find("\n  6  the input needs more work than --max-crossings allows"),
            std::string::npos)
      << geometry;
  EXPECT_EQ(geometry.find("130"), std::string::npos) << "run's codes are not the geometry's";
  for (const char* args : {"--help", "simplify --help", "clip --help", "clip-lines --help"}) {
    EXPECT_NE(run(args).out.find(geometry), std::string::npos) << args;
  }
  const CliRun batch = run("run --help");
  if (batch.out.find("AprilTag ROI + contours") != std::string::npos) {  // built with batch
    EXPECT_NE(batch.out.find(exitCodesHelp(ExitCodesOf::Run)), std::string::npos) << batch.out;
  }
}

TEST_F(Cli, SimplifyToStdout) {
  const CliRun r = run("simplify '" + kData + "bowtie.json'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty());
  const json props = properties(r.out);
  EXPECT_DOUBLE_EQ(props.at("area").get<double>(), 50.0);
  EXPECT_EQ(props.at("rings").get<int>(), 2);
  const json coords = json::parse(r.out).at("features")[0].at("geometry").at("coordinates");
  ASSERT_EQ(coords.size(), 2u);
  for (const json& polygon : coords) EXPECT_EQ(polygon[0].front(), polygon[0].back());
}

TEST_F(Cli, SimplifyFillRule) {
  const std::string twice = "'" + kData + "twice_wound.json'";
  EXPECT_DOUBLE_EQ(area(run("simplify --fill-rule nonzero " + twice)), 100.0);
  EXPECT_DOUBLE_EQ(area(run("simplify --fill-rule positive " + twice)), 100.0);
  EXPECT_DOUBLE_EQ(area(run("simplify --fill-rule negative " + twice)), 0.0);
  EXPECT_DOUBLE_EQ(area(run("simplify " + twice)), 0.0);  // evenodd by default
}

TEST_F(Cli, SimplifyToFile) {
  const fs::path out = dir_ / "result.geojson";
  const CliRun r =
      run("simplify --dissolve '" + kData + "frame.geojson' -o '" + out.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_DOUBLE_EQ(properties(readText(out)).at("area").get<double>(), 164.0);
  EXPECT_EQ(properties(readText(out)).at("rings").get<int>(), 3);
}

TEST_F(Cli, ClipOperations) {
  const std::string files = "'" + kData + "bowtie.json' '" + kData + "roi.geojson'";
  // bow-tie 50, ROI 72, overlap 18.
  EXPECT_DOUBLE_EQ(area(run("clip " + files)), 18.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op intersection " + files)), 18.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op union " + files)), 104.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op difference " + files)), 32.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op xor " + files)), 86.0);
}

TEST_F(Cli, ClipFillRulesSpecificOverridesGeneral) {
  const std::string twice = "'" + kData + "twice_wound.json'";
  // roi.geojson is a Feature: --dissolve gives the one feature with "area" and "rings".
  const std::string roi = "--dissolve '" + kData + "roi.geojson'";
  // The doubly wound square is empty under even-odd and the square [0,10]^2 otherwise.
  EXPECT_DOUBLE_EQ(area(run("clip " + twice + " " + roi)), 0.0);
  EXPECT_DOUBLE_EQ(area(run("clip --fill-rule nonzero " + twice + " " + roi)), 60.0);
  EXPECT_DOUBLE_EQ(area(run("clip --subject-fill-rule nonzero " + twice + " " + roi)), 60.0);
  EXPECT_DOUBLE_EQ(
      area(run("clip --fill-rule nonzero --subject-fill-rule evenodd " + twice + " " + roi)), 0.0);
  EXPECT_DOUBLE_EQ(area(run("clip --fill-rule nonzero " + roi + " " + twice)), 60.0);
  EXPECT_DOUBLE_EQ(
      area(run("clip --fill-rule nonzero --clip-fill-rule evenodd " + roi + " " + twice)), 0.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op union --clip-fill-rule nonzero " + roi + " " + twice)),
                   72.0 + 100.0 - 60.0);
}

TEST_F(Cli, BadInputSimplify) {
  const struct {
    const char* file;
    const char* problem;
  } cases[] = {
      {"bad_syntax.json", "not valid JSON"},
      {"bad_structure.json", "unsupported geometry type"},
      {"string_coordinate.json", "y is not a number"},
      {"null_coordinate.geojson", "x is not a number"},
      {"degenerate_ring.geojson", "polygon 1, ring 0"},
      {"out_of_range.json", "path 1, vertex 1"},
      {"no_such_file.json", "cannot open"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    // --strict refuses degenerate rings, and out_of_range.json is beyond a fixed 1/256 px grid
    // (the default fitted grid and lenient reading take both: see DegenerateRingsAreCounted).
    expectBadInput(run("simplify --strict --grid 256 '" + kData + c.file + "'"), c.file, c.problem);
  }
}

TEST_F(Cli, BadInputClipNamesTheBadOperand) {
  const std::string good = "'" + kData + "square.geojson'";
  expectBadInput(run("clip --grid 256 " + good + " '" + kData + "out_of_range.json'"),
                 "out_of_range.json", "outside the supported range");
  expectBadInput(run("clip '" + kData + "string_coordinate.json' " + good),
                 "string_coordinate.json", "not a number");
  const CliRun r = run("clip " + good + " '" + kData + "bad_syntax.json'");
  EXPECT_EQ(r.err.find("square.geojson"), std::string::npos) << r.err;
}

// Core errors name the file of the operand they concern, whatever the files are called (the
// message-matching code took a file name's first word for an operand label).
TEST_F(Cli, BadInputFileNamedLikeAnOperand) {
  const fs::path clipNamed = dir_ / "clip 1.json";
  const fs::path subjectNamed = dir_ / "subject 2.json";
  fs::copy_file(kData + "out_of_range.json", clipNamed);
  fs::copy_file(kData + "square.geojson", subjectNamed);
  const std::string at = ": path 1, vertex 1: x = 5000000.000000 is outside";
  const CliRun asSubject =
      run("clip --grid 256 '" + clipNamed.string() + "' '" + subjectNamed.string() + "'");
  expectBadInput(asSubject, clipNamed.string() + at, "supported range");
  const CliRun asClip =
      run("clip --grid 256 '" + subjectNamed.string() + "' '" + clipNamed.string() + "'");
  expectBadInput(asClip, clipNamed.string() + at, "supported range");
  const CliRun asLines =
      run("clip-lines --grid 256 '" + clipNamed.string() + "' '" + subjectNamed.string() + "'");
  expectBadInput(asLines, clipNamed.string() + at, "supported range");
  const CliRun bad = run("clip '" + subjectNamed.string() + "' '" + kData + "bad_syntax.json'");
  EXPECT_EQ(bad.err.find("subject 2.json"), std::string::npos) << bad.err;
}

TEST_F(Cli, BadInputWritesNoOutputFile) {
  const fs::path out = dir_ / "result.geojson";
  const CliRun r =
      run("simplify --strict '" + kData + "degenerate_ring.geojson' -o '" + out.string() + "'");
  expectBadInput(r, "degenerate_ring.geojson", "fewer than 3 distinct points");
  EXPECT_FALSE(fs::exists(out));
  // An existing output is left as it was, and no temporary remains.
  { std::ofstream(out) << "previous"; }
  const CliRun again =
      run("clip '" + kData + "square.geojson' '" + kData + "bad_syntax.json' -o " + out.string());
  EXPECT_EQ(again.exitCode, 2);
  EXPECT_EQ(readText(out), "previous");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1u);
}

// Degenerate rings are ignored and counted; --strict refuses them with the reader's message.
TEST_F(Cli, DegenerateRingsAreCounted) {
  const std::string file = "'" + kData + "degenerate_ring.geojson'";
  const CliRun r = run("simplify " + file);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(properties(r.out).at("ignoredRings"), 1);
  EXPECT_NEAR(area(r), 50.0, 0);
  EXPECT_NE(r.err.find("degenerate_ring.geojson: ignored 1 ring with fewer than 3 distinct "
                       "points or no area"),
            std::string::npos)
      << r.err;
  // WKT, and clip: the same count.
  const fs::path wkt = dir_ / "degenerate.wkt";
  std::ofstream(wkt) << "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 0)), ((3 3, 4 4, 3 3)), "
                        "((5 5, 6 6, 7 7, 5 5)))";
  const CliRun w = run("simplify '" + wkt.string() + "'");
  ASSERT_EQ(w.exitCode, 0) << w.err;
  EXPECT_EQ(properties(w.out).at("ignoredRings"), 2);
  const std::string square = "'" + kData + "square.geojson'";
  const CliRun c = run("clip " + file + " " + square);
  ASSERT_EQ(c.exitCode, 0) << c.err;
  EXPECT_EQ(properties(c.out).at("ignoredRings"), 1);
  EXPECT_FALSE(properties(c.out).contains("ignoredClipRings"));
  EXPECT_NE(r.err.find("degenerate_ring.geojson: ignored 1 ring with"), std::string::npos);
  EXPECT_NE(c.err.find("degenerate_ring.geojson: ignored 1 subject ring with"), std::string::npos)
      << c.err;
  // The clip operand's degenerate rings are counted too, and the warning says which operand.
  const CliRun byDegenerate = run("clip " + square + " " + file);
  ASSERT_EQ(byDegenerate.exitCode, 0) << byDegenerate.err;
  EXPECT_FALSE(properties(byDegenerate.out).contains("ignoredRings"));
  EXPECT_EQ(properties(byDegenerate.out).at("ignoredClipRings"), 1);
  EXPECT_NE(byDegenerate.err.find("degenerate_ring.geojson: ignored 1 clip ring with fewer than "
                                  "3 distinct points or no area"),
            std::string::npos)
      << byDegenerate.err;
  EXPECT_EQ(byDegenerate.err.find("subject"), std::string::npos) << byDegenerate.err;
  // Both operands, and --round-to keeps both counts.
  const CliRun both = run("clip --round-to 1 " + file + " '" + wkt.string() + "'");
  ASSERT_EQ(both.exitCode, 0) << both.err;
  EXPECT_EQ(properties(both.out).at("ignoredRings"), 1);
  EXPECT_EQ(properties(both.out).at("ignoredClipRings"), 2);
  EXPECT_NE(both.err.find("degenerate.wkt: ignored 2 clip rings"), std::string::npos) << both.err;
  // A clean input has no such property.
  EXPECT_FALSE(
      properties(run("simplify '" + kData + "square.geojson'").out).contains("ignoredRings"));
  expectBadInput(run("simplify --strict " + file), "degenerate_ring.geojson",
                 "polygon 1, ring 0 (path 1): ring has fewer than 3 distinct points");
  expectBadInput(run("simplify --strict '" + wkt.string() + "'"), "degenerate.wkt",
                 "ring has fewer than 3 distinct points");
  // --strict refuses them in either operand of clip.
  expectBadInput(run("clip --strict " + file + " " + square), "degenerate_ring.geojson",
                 "polygon 1, ring 0 (path 1): ring has fewer than 3 distinct points");
  expectBadInput(run("clip --strict " + square + " " + file), "degenerate_ring.geojson",
                 "polygon 1, ring 0 (path 1): ring has fewer than 3 distinct points");
  expectBadInput(run("clip --strict " + square + " '" + wkt.string() + "'"), "degenerate.wkt",
                 "ring has fewer than 3 distinct points");
}

// A clip operand's degenerate rings are warned about even when there is no subject feature (no
// result to carry the count): the warning is per operand file.
TEST_F(Cli, ClipOperandRingsAreWarnedAboutWithoutSubjectFeatures) {
  const fs::path empty = dir_ / "empty.geojson";
  std::ofstream(empty) << R"({"type":"FeatureCollection","features":[]})";
  const std::string degenerate = "'" + kData + "degenerate_ring.geojson'";
  const CliRun r = run("clip '" + empty.string() + "' " + degenerate);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(json::parse(r.out).at("features").empty()) << r.out;
  EXPECT_NE(r.err.find("degenerate_ring.geojson: ignored 1 clip ring with fewer than 3 distinct "
                       "points or no area"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("subject"), std::string::npos) << r.err;
  // A ring of 3 points on one line, the same.
  const fs::path flat = dir_ / "flat.wkt";
  std::ofstream(flat) << "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 0)), ((5 5, 6 6, 7 7, 5 5)))";
  const CliRun onALine = run("clip '" + empty.string() + "' '" + flat.string() + "'");
  ASSERT_EQ(onALine.exitCode, 0) << onALine.err;
  EXPECT_NE(onALine.err.find("flat.wkt: ignored 1 clip ring"), std::string::npos) << onALine.err;
  expectBadInput(run("clip --strict '" + empty.string() + "' " + degenerate),
                 "degenerate_ring.geojson", "ring has fewer than 3 distinct points");
  expectBadInput(run("clip --strict '" + empty.string() + "' '" + flat.string() + "'"), "flat.wkt",
                 "path 1: ring has no area (all its points on one line)");
}

// Degenerate means "all points on one line on the call's grid" (README, countDegeneratePaths()):
// 3 or more distinct points on one line, or a sliver that snapping flattens, are counted, warned
// about and refused by --strict just as rings of fewer than 3 distinct points are.
TEST_F(Cli, RingsOnOneLineAreCountedAndRefusedLikeTooFewPoints) {
  const fs::path flat = dir_ / "flat.wkt";
  std::ofstream(flat) << "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 0)), ((5 5, 6 6, 7 7, 5 5)))";
  const std::string file = "'" + flat.string() + "'";
  const std::string square = "'" + kData + "square.geojson'";
  const CliRun r = run("simplify " + file);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(properties(r.out).at("ignoredRings"), 1);
  EXPECT_NE(r.err.find("flat.wkt: ignored 1 ring with fewer than 3 distinct points or no area"),
            std::string::npos)
      << r.err;
  const std::string noArea = "path 1: ring has no area (all its points on one line)";
  expectBadInput(run("simplify --strict " + file), "flat.wkt", noArea);
  expectBadInput(run("clip --strict " + file + " " + square), "flat.wkt", noArea);
  expectBadInput(run("clip --strict " + square + " " + file), "flat.wkt", noArea);
  // The path index is the file's flat one: here the flat ring is the second feature's ring 1.
  const fs::path two = dir_ / "two.geojson";
  std::ofstream(two) << R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{"n":1},"geometry":{"type":"Polygon","coordinates":
       [[[0,0],[10,0],[10,10],[0,0]]]}},
      {"type":"Feature","properties":{"n":2},"geometry":{"type":"MultiPolygon","coordinates":
       [[[[0,0],[10,0],[10,10],[0,0]]], [[[5,5],[6,6],[7,7],[5,5]]]]}}]})";
  expectBadInput(run("simplify --strict '" + two.string() + "'"), "two.geojson",
                 "path 2: ring has no area");
  // A sliver (area 0.5) that the grid of 1 unit per px puts on one line: counted on that grid,
  // refused on it, and neither on the default fitted grid.
  const fs::path sliver = dir_ / "sliver.wkt";
  std::ofstream(sliver)
      << "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 0)), ((0 20, 10 20, 5 20.1, 0 20)))";
  const std::string sliverFile = "'" + sliver.string() + "'";
  const CliRun fitted = run("simplify " + sliverFile);
  ASSERT_EQ(fitted.exitCode, 0) << fitted.err;
  EXPECT_FALSE(properties(fitted.out).contains("ignoredRings")) << fitted.out;
  EXPECT_EQ(run("simplify --strict " + sliverFile).exitCode, 0);
  const CliRun coarse = run("simplify --grid 1 " + sliverFile);
  ASSERT_EQ(coarse.exitCode, 0) << coarse.err;
  EXPECT_EQ(properties(coarse.out).at("ignoredRings"), 1);
  EXPECT_NE(coarse.err.find("sliver.wkt: ignored 1 ring"), std::string::npos) << coarse.err;
  expectBadInput(run("simplify --strict --grid 1 " + sliverFile), "sliver.wkt", noArea);
}

// The work budget: exit code 6, one line naming the limit and the flag, no output.
TEST_F(Cli, MaxCrossingsExitsWithCode6) {
  const std::string args = "'" + kData + "bowtie.json' '" + kData + "roi.geojson'";
  const CliRun r = run("clip --max-crossings 0 " + args);
  EXPECT_EQ(r.exitCode, 6);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err,
            "roiclip: error: more than 0 crossings (the limit maxCrossings); raise it with "
            "--max-crossings\n");
  EXPECT_EQ(run("clip --max-crossings 1 " + args).exitCode, 0);
  EXPECT_EQ(run("clip " + args).exitCode, 0);  // the default: 25,000,000
}

// Map coordinates as given: UTM northings of 5e6 with 0.1 mm detail.
TEST_F(Cli, MapCoordinatesAreTaken) {
  const fs::path utm = dir_ / "utm.geojson";
  std::ofstream(utm) << R"({"type":"Polygon","coordinates":[[[512345.1234,5087776.5678],
      [512445.1234,5087776.5678],[512445.1234,5087876.5678],[512345.1234,5087876.5678],
      [512345.1234,5087776.5678]]]})";
  const CliRun r = run("simplify '" + utm.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NEAR(area(r), 10000.0, 1e-5);
  EXPECT_EQ(run("simplify --grid 256 '" + utm.string() + "'").exitCode, 2);
}

TEST_F(Cli, UsageErrors) {
  const std::string square = "'" + kData + "square.geojson'";
  EXPECT_EQ(run("").exitCode, 1);
  EXPECT_EQ(run("simplify").exitCode, 1);
  EXPECT_EQ(run("clip " + square).exitCode, 1);
  const CliRun rule = run("simplify --fill-rule sometimes " + square);
  EXPECT_EQ(rule.exitCode, 1);
  EXPECT_NE(rule.err.find("sometimes"), std::string::npos) << rule.err;
  EXPECT_EQ(run("clip --op merge " + square + " " + square).exitCode, 1);
}

TEST_F(Cli, GridScale) {
  const std::string far = "'" + kData + "out_of_range.json'";
  // x = 5,000,000 px is outside a fixed 1/256 px grid but fits at 64 units/px (--grid-scale is
  // the old spelling of --grid SCALE), and on the fitted grid (--grid auto, the default).
  EXPECT_EQ(run("simplify --grid 256 " + far).exitCode, 2);
  const CliRun fitted = run("simplify " + far);
  ASSERT_EQ(fitted.exitCode, 0) << fitted.err;
  EXPECT_NEAR(area(fitted), 25000000.0 - 50.0, 1e-3);
  EXPECT_EQ(run("simplify --grid auto " + far).out, fitted.out);
  const CliRun coarse = run("simplify --grid-scale 64 " + far);
  ASSERT_EQ(coarse.exitCode, 0) << coarse.err;
  // Even-odd: the small triangle (area 50) lies inside the big one (area 2.5e7) but for a sliver
  // of ~2e-10 px^2 near (10, 10), so it is cut out.
  EXPECT_NEAR(area(coarse), 25000000.0 - 50.0, 1e-3);
  // A 1/1024 px square vanishes on a 1/256 px grid and survives on a finer one.
  const fs::path tiny = dir_ / "tiny.json";
  std::ofstream(tiny) << R"({"paths": [[[0, 0], [0.0009765625, 0], [0.0009765625, 0.0009765625],
                                         [0, 0.0009765625]]]})";
  EXPECT_DOUBLE_EQ(area(run("simplify --grid 256 '" + tiny.string() + "'")), 0.0);
  EXPECT_DOUBLE_EQ(area(run("simplify '" + tiny.string() + "'")), 0.0009765625 * 0.0009765625);
  EXPECT_DOUBLE_EQ(area(run("simplify --grid-scale 1024 '" + tiny.string() + "'")),
                   0.0009765625 * 0.0009765625);
  EXPECT_EQ(run("clip --grid-scale -1 " + far + " " + far).exitCode, 1);
  EXPECT_EQ(run("clip --grid fine " + far + " " + far).exitCode, 1);
}

TEST_F(Cli, UnwritableOutput) {
  const CliRun r =
      run("simplify '" + kData + "square.geojson' -o '" + (dir_ / "no/such/x.json").string() + "'");
  EXPECT_EQ(r.exitCode, 3);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("no/such/x.json"), std::string::npos) << r.err;
}

// --- clip-lines ---

// The lines of a MultiLineString written by `clip-lines`, as nested JSON arrays.
json lineCoordinates(const std::string& text) {
  return json::parse(text).at("features")[0].at("geometry").at("coordinates");
}

TEST_F(Cli, ClipLinesHelpHasAnExample) {
  const CliRun r = run("clip-lines --help");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("Example"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--part outside"), std::string::npos) << r.out;
}

// lines_cross.geojson against the square [0, 10]^2, worked by hand:
//  line 0 (-5,5) -> (5,5) -> (5,15): enters at (0,5), leaves at (5,10);
//  line 1 (2,2) -> (8,2): inside throughout;
//  line 2 (-2,10) -> (12,10): runs along the top edge from (0,10) to (10,10), which is inside
//  (the region is closed).
TEST_F(Cli, ClipLinesInsideAndOutsideOfASquare) {
  const std::string files = "'" + kData + "lines_cross.geojson' '" + kData + "square.geojson'";
  const CliRun inside = run("clip-lines " + files);
  ASSERT_EQ(inside.exitCode, 0) << inside.err;
  EXPECT_TRUE(inside.err.empty());
  EXPECT_EQ(lineCoordinates(inside.out),
            json::parse("[[[0,5],[5,5],[5,10]], [[2,2],[8,2]], [[0,10],[10,10]]]"));
  EXPECT_DOUBLE_EQ(properties(inside.out).at("length").get<double>(), 10.0 + 6.0 + 10.0);
  EXPECT_EQ(properties(inside.out).at("lines").get<int>(), 3);
  EXPECT_EQ(run("clip-lines --part inside " + files).out, inside.out);  // the default

  const CliRun outside = run("clip-lines --part outside " + files);
  ASSERT_EQ(outside.exitCode, 0) << outside.err;
  EXPECT_EQ(lineCoordinates(outside.out),
            json::parse("[[[-5,5],[0,5]], [[5,10],[5,15]], [[-2,10],[0,10]], [[10,10],[12,10]]]"));
  EXPECT_DOUBLE_EQ(properties(outside.out).at("length").get<double>(), 5.0 + 5.0 + 2.0 + 2.0);
  EXPECT_EQ(properties(outside.out).at("lines").get<int>(), 4);
  EXPECT_EQ(run("clip-lines --part Outside " + files).out, outside.out);  // any case
}

// clip-lines counts REGION's degenerate rings (the clip operand's: "ignoredClipRings" and a
// warning); --strict refuses them, both kinds.
TEST_F(Cli, ClipLinesCountsAndRefusesDegenerateRegionRings) {
  const std::string lines = "'" + kData + "lines_cross.geojson'";
  const CliRun clean = run("clip-lines " + lines + " '" + kData + "square.geojson'");
  ASSERT_EQ(clean.exitCode, 0) << clean.err;
  EXPECT_FALSE(properties(clean.out).contains("ignoredClipRings")) << clean.out;
  // degenerate_ring.geojson: a triangle inside [0, 10]^2 and a ring of 2 distinct points.
  const std::string degenerate = "'" + kData + "degenerate_ring.geojson'";
  const CliRun r = run("clip-lines " + lines + " " + degenerate);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(properties(r.out).at("ignoredClipRings"), 1);
  EXPECT_GT(properties(r.out).at("lines").get<int>(), 0);  // the triangle still clips
  EXPECT_NE(r.err.find("degenerate_ring.geojson: ignored 1 clip ring with fewer than 3 distinct "
                       "points or no area (--strict refuses them)"),
            std::string::npos)
      << r.err;
  const fs::path flat = dir_ / "flat.wkt";
  std::ofstream(flat) << "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((5 5, 6 6, 7 7, 5 5)), "
                         "((1 1, 2 2, 1 1)))";
  const std::string flatFile = "'" + flat.string() + "'";
  const CliRun both = run("clip-lines " + lines + " " + flatFile);
  ASSERT_EQ(both.exitCode, 0) << both.err;
  EXPECT_EQ(properties(both.out).at("ignoredClipRings"), 2);
  EXPECT_EQ(lineCoordinates(both.out), lineCoordinates(clean.out));  // they contribute nothing
  EXPECT_NE(both.err.find("flat.wkt: ignored 2 clip rings"), std::string::npos) << both.err;
  expectBadInput(run("clip-lines --strict " + lines + " " + degenerate), "degenerate_ring.geojson",
                 "polygon 1, ring 0 (path 1): ring has fewer than 3 distinct points");
  // The reader refuses the ring of 2 distinct points first; alone, the flat one is refused on
  // the grid.
  expectBadInput(run("clip-lines --strict " + lines + " " + flatFile), "flat.wkt",
                 "ring has fewer than 3 distinct points");
  std::ofstream(flat) << "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((5 5, 6 6, 7 7, 5 5)))";
  expectBadInput(run("clip-lines --strict " + lines + " " + flatFile), "flat.wkt",
                 "path 1: ring has no area (all its points on one line)");
}

TEST_F(Cli, ClipLinesFillRuleAndOutputFile) {
  const std::string lines = "'" + kData + "lines_cross.geojson'";
  const std::string twice = "'" + kData + "twice_wound.json'";
  // The doubly wound square [0, 10]^2 is empty under even-odd (the default): every line is
  // outside, whole.
  const CliRun evenOdd = run("clip-lines " + lines + " " + twice);
  ASSERT_EQ(evenOdd.exitCode, 0) << evenOdd.err;
  EXPECT_EQ(properties(evenOdd.out).at("lines").get<int>(), 0);
  const CliRun whole = run("clip-lines --part outside " + lines + " " + twice);
  EXPECT_EQ(lineCoordinates(whole.out),
            json::parse("[[[-5,5],[5,5],[5,15]], [[2,2],[8,2]], [[-2,10],[12,10]]]"));
  const fs::path out = dir_ / "inside.geojson";
  const CliRun nonZero =
      run("clip-lines --fill-rule nonzero " + lines + " " + twice + " -o '" + out.string() + "'");
  ASSERT_EQ(nonZero.exitCode, 0) << nonZero.err;
  EXPECT_TRUE(nonZero.out.empty());
  EXPECT_DOUBLE_EQ(properties(readText(out)).at("length").get<double>(), 26.0);
}

TEST_F(Cli, ClipLinesBadInput) {
  const struct {
    const char* lines;
    const char* region;
    const char* file;  // named in the message
    const char* problem;
  } cases[] = {
      {"no_such_file.json", "square.geojson", "no_such_file.json", "cannot open"},
      {"lines_cross.geojson", "no_such_file.json", "no_such_file.json", "cannot open"},
      {"bad_syntax.json", "square.geojson", "bad_syntax.json", "not valid JSON"},
      {"lines_nan.json", "square.geojson", "lines_nan.json", "not valid JSON"},
      {"lines_cross.geojson", "string_coordinate.json", "string_coordinate.json",
       "y is not a number"},
      // A region file is not a lines file.
      {"square.geojson", "square.geojson", "square.geojson",
       "unsupported geometry type \"Polygon\""},
      // Out of range on the grid: the core's message, naming the file it came from.
      {"lines_cross.geojson", "out_of_range.json", "out_of_range.json: path 1, vertex 1",
       "outside the supported range"},
      {"out_of_range.json", "square.geojson", "out_of_range.json: path 1, vertex 1",
       "outside the supported range"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(c.lines) + " " + c.region);
    expectBadInput(
        run("clip-lines --grid 256 '" + kData + c.lines + "' '" + kData + c.region + "'"), c.file,
        c.problem);
  }
}

TEST_F(Cli, ClipLinesBadInputWritesNoOutputFile) {
  const fs::path out = dir_ / "lines.geojson";
  { std::ofstream(out) << "previous"; }
  const CliRun r = run("clip-lines '" + kData + "lines_nan.json' '" + kData +
                       "square.geojson' -o '" + out.string() + "'");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(readText(out), "previous");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1u);
  const CliRun unwritable = run("clip-lines '" + kData + "lines_cross.geojson' '" + kData +
                                "square.geojson' -o '" + (dir_ / "no/such/x.json").string() + "'");
  EXPECT_EQ(unwritable.exitCode, 3);
  EXPECT_TRUE(unwritable.out.empty());
}

TEST_F(Cli, ClipLinesUsageErrors) {
  const std::string square = "'" + kData + "square.geojson'";
  const std::string lines = "'" + kData + "lines_cross.geojson'";
  EXPECT_EQ(run("clip-lines " + lines).exitCode, 1);
  const CliRun part = run("clip-lines --part sideways " + lines + " " + square);
  EXPECT_EQ(part.exitCode, 1);
  EXPECT_NE(part.err.find("sideways"), std::string::npos) << part.err;
  EXPECT_EQ(run("clip-lines --fill-rule sometimes " + lines + " " + square).exitCode, 1);
  EXPECT_EQ(run("clip-lines --grid-scale 0 " + lines + " " + square).exitCode, 1);
}

// --- features, orientation, formats, streams, warnings ---

json features(const std::string& text) { return json::parse(text).at("features"); }

TEST_F(Cli, SimplifyKeepsEachFeatureWithItsIdAndProperties) {
  const CliRun r = run("simplify '" + kData + "parcels.geojson'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const json f = features(r.out);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0].at("id"), "a");
  EXPECT_EQ(f[0].at("properties"),
            json::parse(R"({"name":"left","area_m2":12.5,"tags":["x","y"],"owner":null})"));
  EXPECT_EQ(f[1].at("id"), 7);
  EXPECT_EQ(f[1].at("properties").at("nested"), json::parse(R"({"b":1,"a":[true,false]})"));
  EXPECT_FALSE(f[2].contains("id"));
  EXPECT_TRUE(f[2].at("properties").is_null());
  // The key order of the input is kept.
  EXPECT_NE(r.out.find(R"("properties":{"name":"right","n":3,"nested":{"b":1,"a":[true,false]}})"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(f[2].at("geometry").at("coordinates").size(), 2u);  // from a GeometryCollection
}

TEST_F(Cli, ClipEachSubjectFeatureByTheUnionOfTheClipFeatures) {
  const std::string files = "'" + kData + "parcels.geojson' '" + kData + "two_rois.geojson'";
  const CliRun r = run("clip " + files);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json f = features(r.out);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0].at("id"), "a");
  EXPECT_EQ(f[1].at("properties").at("name"), "right");
  EXPECT_EQ(f[0].at("geometry").at("coordinates"),
            json::parse("[[[[2,10],[2,0],[6,0],[6,10],[2,10]]]]"));
  EXPECT_TRUE(f[2].at("geometry").at("coordinates").empty());
  // --dissolve: today's single feature (even-odd over all rings: ROI A and B cancel where they
  // overlap).
  const CliRun one = run("clip --dissolve " + files);
  ASSERT_EQ(one.exitCode, 0) << one.err;
  EXPECT_DOUBLE_EQ(area(one), 65.0);
  EXPECT_EQ(properties(one.out).at("rings").get<int>(), 2);
}

TEST_F(Cli, OrientationRfc7946ByDefaultOpenCvOnRequest) {
  const std::string frame = "'" + kData + "frame.geojson' --dissolve";
  const auto firstRings = [](const CliRun& r) {
    return json::parse(r.out).at("features")[0].at("geometry").at("coordinates")[0];
  };
  const json rfc = firstRings(run("simplify " + frame));
  EXPECT_EQ(rfc, json::parse("[[[0,10],[0,0],[10,0],[10,10],[0,10]],"
                             "[[8,8],[8,2],[2,2],[2,8],[8,8]]]"));
  EXPECT_EQ(firstRings(run("simplify --orientation rfc7946 " + frame)), rfc);
  EXPECT_EQ(firstRings(run("simplify --orientation OpenCV " + frame)),
            json::parse("[[[0,10],[10,10],[10,0],[0,0],[0,10]],"
                        "[[8,8],[2,8],[2,2],[8,2],[8,8]]]"));
  EXPECT_EQ(run("simplify --orientation clockwise " + frame).exitCode, 1);
}

TEST_F(Cli, WktInAndOut) {
  const CliRun r = run("simplify --format wkt '" + kData + "frame.wkt'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out,
            "MULTIPOLYGON(((0 10,0 0,10 0,10 10,0 10),(8 8,8 2,2 2,2 8,8 8)),"
            "((20 10,20 0,30 0,30 10,20 10)))\n");
  // WKT in, GeoJSON out (detected from the text), and --input-format forcing a reader.
  EXPECT_DOUBLE_EQ(area(run("simplify '" + kData + "frame.wkt'")), 164.0);
  expectBadInput(run("simplify --input-format geojson '" + kData + "frame.wkt'"), "frame.wkt",
                 "not valid JSON");
  // Clip with WKT written to a file, read back by the next command.
  const fs::path out = dir_ / "clipped.wkt";
  const CliRun clipped = run("clip --format wkt '" + kData + "frame.wkt' '" + kData +
                             "roi.geojson' -o '" + out.string() + "'");
  ASSERT_EQ(clipped.exitCode, 0) << clipped.err;
  EXPECT_EQ(readText(out).rfind("MULTIPOLYGON(", 0), 0u) << readText(out);
  const CliRun back = run("simplify '" + out.string() + "'");
  // frame.wkt's first square without its hole, within the ROI's x in [2, 8]: 60 - 36.
  EXPECT_DOUBLE_EQ(area(back), 24.0);
  const CliRun lines =
      run("clip-lines --format wkt '" + kData + "lines_cross.geojson' '" + kData + "frame.wkt'");
  ASSERT_EQ(lines.exitCode, 0) << lines.err;
  EXPECT_EQ(lines.out.rfind("MULTILINESTRING(", 0), 0u) << lines.out;
}

TEST_F(Cli, RoundToSnapRoundsEachResult) {
  // B's apex (5.40625, 0.515625) lies just below A's edge (0,0)-(10,1); at whole pixels the edge is
  // routed through (5,1), where the two parts then touch.
  const fs::path in = dir_ / "near.json";
  std::ofstream(in) << R"({"paths": [[[0, 0], [10, 1], [10, 5], [0, 5]],
                                     [[5.40625, 0.515625], [7, -3], [4, -3]]]})";
  const CliRun exact = run("simplify --fill-rule nonzero --format wkt '" + in.string() + "'");
  ASSERT_EQ(exact.exitCode, 0) << exact.err;
  EXPECT_NE(exact.out.find("5.40625 0.515625"), std::string::npos) << exact.out;
  const CliRun r =
      run("simplify --fill-rule nonzero --round-to 1 --format wkt '" + in.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "MULTIPOLYGON(((0 5,0 0,5 1,10 1,10 5,0 5)),((5 1,4 -3,7 -3,5 1)))\n");
  const CliRun clipped =
      run("clip --round-to 0.5 --op union '" + in.string() + "' '" + in.string() + "'");
  ASSERT_EQ(clipped.exitCode, 0) << clipped.err;
  EXPECT_GT(area(clipped), 40.0);
  EXPECT_EQ(run("simplify --round-to 0 '" + in.string() + "'").exitCode, 1);
  EXPECT_EQ(run("simplify --round-to -1 '" + in.string() + "'").exitCode, 1);
}

TEST_F(Cli, DashIsStandardInputAndOutput) {
  const CliRun in = run("simplify --dissolve - < '" + kData + "frame.geojson'");
  ASSERT_EQ(in.exitCode, 0) << in.err;
  EXPECT_DOUBLE_EQ(area(in), 164.0);
  const CliRun out = run("clip - '" + kData + "roi.geojson' -o - < '" + kData + "bowtie.json'");
  ASSERT_EQ(out.exitCode, 0) << out.err;
  EXPECT_DOUBLE_EQ(area(out), 18.0);
  EXPECT_FALSE(fs::exists(dir_ / "-"));
  const CliRun wkt =
      run("clip-lines - '" + kData + "square.geojson' < '" + kData + "lines_cross.geojson'");
  ASSERT_EQ(wkt.exitCode, 0) << wkt.err;
  EXPECT_DOUBLE_EQ(properties(wkt.out).at("length").get<double>(), 26.0);
  // Errors name standard input; it cannot be both operands.
  expectBadInput(run("simplify - < '" + kData + "bad_syntax.json'"), "<stdin>: ", "not valid JSON");
  expectBadInput(run("clip - - < '" + kData + "square.geojson'"), "<stdin>", "only one input");
}

TEST_F(Cli, ZCoordinatesAreDroppedWithAWarning) {
  const CliRun r = run("simplify '" + kData + "square_z.wkt'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_DOUBLE_EQ(area(r), 100.0);
  EXPECT_EQ(r.err, "roiclip: warning: " + kData +
                       "square_z.wkt: ignored the z coordinate of 5 points (roiclip is 2-D)\n");
  const fs::path z = dir_ / "z.geojson";
  std::ofstream(z) << R"({"type":"Polygon","coordinates":[[[0,0,3],[4,0,3],[4,3,3],[0,0,3]]]})";
  const CliRun geojson = run("simplify '" + z.string() + "'");
  EXPECT_EQ(geojson.exitCode, 0);
  EXPECT_NE(geojson.err.find("z.geojson: ignored the z coordinate of 4 points"), std::string::npos)
      << geojson.err;
}

TEST_F(Cli, GeometryCollectionOfPolygons) {
  const fs::path gc = dir_ / "gc.geojson";
  std::ofstream(gc) << R"({"type":"GeometryCollection","geometries":[
      {"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]]]},
      {"type":"GeometryCollection","geometries":[
        {"type":"MultiPolygon","coordinates":[[[[10,0],[12,0],[12,2],[10,0]]]]}]}]})";
  const CliRun r = run("simplify '" + gc.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_DOUBLE_EQ(area(r), 16.0 + 2.0);
  EXPECT_EQ(properties(r.out).at("rings").get<int>(), 2);
  const fs::path wkt = dir_ / "gc.wkt";
  std::ofstream(wkt) << "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)))";
  EXPECT_DOUBLE_EQ(area(run("simplify '" + wkt.string() + "'")), 16.0);
}

TEST_F(Cli, OutputDirectoryIsADirectory) {
  for (const char* command : {"simplify '", "clip-lines '"}) {
    const std::string input = std::string(command) == "simplify '"
                                  ? kData + "square.geojson'"
                                  : kData + "lines_cross.geojson' '" + kData + "square.geojson'";
    const CliRun r = run(command + input + " -o '" + dir_.string() + "'");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_EQ(r.err, "roiclip: error: cannot write " + dir_.string() + ": is a directory\n");
    EXPECT_TRUE(r.out.empty());
  }
  // No temporary is left in the folder above.
  for (const auto& e : fs::directory_iterator(dir_.parent_path())) {
    EXPECT_NE(e.path().filename().string().rfind("." + dir_.filename().string() + ".tmp.", 0), 0u)
        << e.path();
  }
  expectBadInput(run("simplify '" + dir_.string() + "'"), dir_.string() + ": is a directory",
                 "directory");
}

TEST_F(Cli, SnappingWarning) {
  // 0.123456789 px is 31.605 grid units at 1/256 px: snapping moves it by 0.395 of a step.
  // Only on a fixed grid: the fitted default moves nothing by a visible amount.
  EXPECT_TRUE(run("simplify '" + kData + "gis_square.geojson'").err.empty());
  const CliRun r = run("simplify --grid 256 '" + kData + "gis_square.geojson'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("roiclip: warning: " + kData +
                       "gis_square.geojson: snapping to the 1/256 px grid moved 2 of 4 vertices "
                       "by more than 1/4 grid step"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  // 3/2048 px moves by 3/8 of a 1/256 px step (a warning); on a 1/2048 px grid it does not move.
  const fs::path fine = dir_ / "fine.json";
  std::ofstream(fine) << R"({"paths": [[[0.00146484375, 0], [5, 0], [5, 5]]]})";
  EXPECT_NE(run("simplify --grid 256 '" + fine.string() + "'").err.find("moved 1 of 3 vertices"),
            std::string::npos);
  const CliRun finer = run("simplify --grid-scale 2048 '" + fine.string() + "'");
  EXPECT_EQ(finer.exitCode, 0) << finer.err;
  EXPECT_TRUE(finer.err.empty()) << finer.err;
  // Only the operand whose vertices move warns.
  const CliRun clip =
      run("clip --grid 256 '" + kData + "square.geojson' '" + kData + "gis_square.geojson'");
  EXPECT_EQ(clip.exitCode, 0) << clip.err;
  EXPECT_NE(clip.err.find("gis_square.geojson: snapping"), std::string::npos) << clip.err;
  EXPECT_EQ(clip.err.find("snapping"), clip.err.rfind("snapping")) << clip.err;
}

}  // namespace
