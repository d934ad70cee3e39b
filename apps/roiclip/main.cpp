// roiclip command line. Subcommands are thin: parse, call the library, write.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <roiclip/io/geojson.hpp>
#include <roiclip/roiclip.hpp>

#ifdef ROICLIP_HAVE_BATCH
#include <roiclip/batch/run.hpp>

#include "run_command.hpp"
#endif

namespace {

// Exit codes (also printed by --help).
constexpr int kExitOk = 0;
constexpr int kExitUsage = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitCannotWrite = 3;
constexpr int kExitInternal = 4;

constexpr const char* kExitCodesHelp =
    "Exit codes:\n"
    "  0  success\n"
    "  1  command-line usage error\n"
    "  2  invalid input: unreadable or malformed file, NaN or non-numeric coordinate, ring with\n"
    "     fewer than 3 distinct points, line with fewer than 2 points, coordinate outside the\n"
    "     grid range (one line on stderr names the file and the problem; no output file is\n"
    "     written)\n"
    "  3  the output file cannot be written\n"
    "  4  internal error (a bug in roiclip: please report the input)\n";

// Validates with the library's own parser so the CLI accepts exactly what parseFillRule() does.
CLI::Validator fillRuleValidator() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        try {
          roiclip::parseFillRule(value.c_str());
          return {};
        } catch (const roiclip::InvalidInputError& e) {
          return e.what();
        }
      },
      "evenodd|nonzero|positive|negative");
}

CLI::Validator clipOpValidator() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        try {
          roiclip::parseClipOp(value.c_str());
          return {};
        } catch (const roiclip::InvalidInputError& e) {
          return e.what();
        }
      },
      "intersection|union|difference|xor");
}

// GeoJSON to stdout, or atomically to the file `output`.
template <class Result>
void writeResult(const Result& result, const std::string& output,
                 std::string (*toText)(const Result&, int),
                 void (*writeFile)(const Result&, const std::string&, int)) {
  if (output.empty()) {
    std::cout << toText(result, -1);
    std::cout.flush();
  } else {
    writeFile(result, output, -1);
  }
}

constexpr const char* kClipLinesHelp =
    "LINES: GeoJSON LineString, MultiLineString, or a Feature, FeatureCollection or\n"
    "GeometryCollection of them, or {\"paths\": [[[x, y], ...], ...]} (a polyline whose last\n"
    "point repeats its first is a loop). REGION: as for `clip` (closed; its boundary counts as\n"
    "inside). Output: GeoJSON MultiLineString, properties \"length\" (px) and \"lines\".\n"
    "\n"
    "Example: a line from (-5, 5) via (5, 5) to (5, 15) and the square [0, 10]^2\n"
    "  roiclip clip-lines line.geojson square.geojson\n"
    "    -> [[0, 5], [5, 5], [5, 10]]                          length 10, lines 1\n"
    "  roiclip clip-lines line.geojson square.geojson --part outside -o outside.geojson\n"
    "    -> [[-5, 5], [0, 5]] and [[5, 10], [5, 15]]           length 10, lines 2\n"
    "\n";

}  // namespace

namespace {

int runMain(int argc, char** argv) {
  CLI::App app{"roiclip: exact clipping of self-intersecting polygons"};
  app.footer(kExitCodesHelp);
  app.require_subcommand(1);
#ifdef ROICLIP_HAVE_BATCH
  RunCommand runCommand(app);
  auto* run = runCommand.subcommand();
#else
  auto* run = app.add_subcommand("run", "process a folder of images (not built: needs AprilTag)");
  run->allow_extras();
#endif

  // Input files: GeoJSON (Polygon, MultiPolygon, Feature, FeatureCollection; every ring is one
  // path) or plain {"paths": [[[x, y], ...], ...]}. Output: GeoJSON FeatureCollection.
  std::string simplifyInput;
  std::string simplifyRule = "evenodd";
  std::string simplifyOutput;
  auto* simplifyCmd = app.add_subcommand(
      "simplify", "resolve self-intersecting paths into simple polygons with holes (GeoJSON out)");
  simplifyCmd->footer(kExitCodesHelp);
  simplifyCmd->add_option("input", simplifyInput, "GeoJSON or {\"paths\": ...} JSON file")
      ->required();
  simplifyCmd->add_option("--fill-rule", simplifyRule, "fill rule for the input paths")
      ->check(fillRuleValidator())
      ->capture_default_str();
  simplifyCmd->add_option("-o,--output", simplifyOutput, "output GeoJSON file (default: stdout)");
  roiclip::Grid grid;
  const auto addGridScale = [&grid](CLI::App* cmd) {
    cmd->add_option("--grid-scale", grid.scale,
                    "grid units per coordinate unit (a power of two; |coordinate * scale| must "
                    "stay <= 2^30)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
  };
  addGridScale(simplifyCmd);

  std::string subjectFile;
  std::string clipFile;
  std::string opName = "intersection";
  std::string bothRule;
  std::string subjectRule;
  std::string clipRule;
  std::string clipOutput;
  auto* clipCmd = app.add_subcommand("clip", "boolean operation SUBJECT op CLIP (GeoJSON out)");
  clipCmd->footer(kExitCodesHelp);
  clipCmd->add_option("subject", subjectFile, "subject paths file")->required();
  clipCmd->add_option("clip", clipFile, "clip paths file")->required();
  clipCmd->add_option("--op", opName, "operation")->check(clipOpValidator())->capture_default_str();
  clipCmd->add_option("--fill-rule", bothRule, "fill rule for both operands (default evenodd)")
      ->check(fillRuleValidator());
  clipCmd->add_option("--subject-fill-rule", subjectRule, "fill rule for SUBJECT (overrides)")
      ->check(fillRuleValidator());
  clipCmd->add_option("--clip-fill-rule", clipRule, "fill rule for CLIP (overrides)")
      ->check(fillRuleValidator());
  clipCmd->add_option("-o,--output", clipOutput, "output GeoJSON file (default: stdout)");
  addGridScale(clipCmd);

  std::string linesFile;
  std::string regionFile;
  std::string partName = "inside";
  std::string regionRule = "evenodd";
  std::string linesOutput;
  auto* clipLinesCmd = app.add_subcommand(
      "clip-lines", "the parts of open polylines LINES inside (or outside) REGION (GeoJSON out)");
  clipLinesCmd->footer(std::string(kClipLinesHelp) + kExitCodesHelp);
  clipLinesCmd->add_option("lines", linesFile, "open polylines file")->required();
  clipLinesCmd->add_option("region", regionFile, "region paths file")->required();
  clipLinesCmd->add_option("--part", partName, "which parts of LINES to keep")
      ->transform(CLI::IsMember({"inside", "outside"}, CLI::ignore_case))
      ->capture_default_str();
  clipLinesCmd->add_option("--fill-rule", regionRule, "fill rule for REGION")
      ->check(fillRuleValidator())
      ->capture_default_str();
  clipLinesCmd->add_option("-o,--output", linesOutput, "output GeoJSON file (default: stdout)");
  addGridScale(clipLinesCmd);

  try {
#ifdef ROICLIP_HAVE_BATCH
    // Options from --config go in front of the command line's own, so the command line wins.
    const std::vector<std::string> args = RunCommand::withConfig(argc, argv);
    std::vector<const char*> argvWithConfig;
    argvWithConfig.reserve(args.size());
    for (const auto& a : args) argvWithConfig.push_back(a.c_str());
    app.parse(static_cast<int>(argvWithConfig.size()), argvWithConfig.data());
#else
    app.parse(argc, argv);
#endif
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  } catch (const roiclip::InvalidInputError& e) {
    std::cerr << "roiclip: error: " << e.what() << "\n";
    return kExitBadInput;
  }

  try {
    if (run->parsed()) {
#ifdef ROICLIP_HAVE_BATCH
      return runCommand.execute();
#else
      std::cerr << "roiclip run: this build has no batch pipeline (configure with "
                   "ROICLIP_BUILD_APRILTAG=ON).\n";
      return kExitUsage;
#endif
    }
    if (simplifyCmd->parsed()) {
      const roiclip::Paths paths = roiclip::io::readPaths(simplifyInput);
      const roiclip::FillRule rule = roiclip::parseFillRule(simplifyRule.c_str());
      writeResult(roiclip::io::simplifyInput(paths, simplifyInput, rule, grid), simplifyOutput,
                  roiclip::io::toGeoJson, roiclip::io::writeGeoJson);
    } else if (clipCmd->parsed()) {
      const std::string base = bothRule.empty() ? "evenodd" : bothRule;
      const roiclip::FillRule sRule =
          roiclip::parseFillRule((subjectRule.empty() ? base : subjectRule).c_str());
      const roiclip::FillRule cRule =
          roiclip::parseFillRule((clipRule.empty() ? base : clipRule).c_str());
      const roiclip::ClipOp op = roiclip::parseClipOp(opName.c_str());
      const roiclip::Paths subject = roiclip::io::readPaths(subjectFile);
      const roiclip::Paths clipPaths = roiclip::io::readPaths(clipFile);
      writeResult(roiclip::io::clipInputs(op, subject, subjectFile, clipPaths, clipFile, sRule,
                                          cRule, grid),
                  clipOutput, roiclip::io::toGeoJson, roiclip::io::writeGeoJson);
    } else if (clipLinesCmd->parsed()) {
      const roiclip::FillRule rule = roiclip::parseFillRule(regionRule.c_str());
      // IsMember() has already turned any spelling into "inside" or "outside".
      const roiclip::LinePart part =
          partName == "outside" ? roiclip::LinePart::Outside : roiclip::LinePart::Inside;
      const roiclip::Paths lines = roiclip::io::readLines(linesFile);
      const roiclip::Paths region = roiclip::io::readPaths(regionFile);
      writeResult(
          roiclip::io::clipLinesInputs(lines, linesFile, region, regionFile, rule, part, grid),
          linesOutput, roiclip::io::linesToGeoJson, roiclip::io::writeLinesGeoJson);
    }
  } catch (const roiclip::InvalidInputError& e) {
    std::cerr << "roiclip: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const roiclip::InternalError& e) {
    std::cerr << "roiclip: internal error: " << e.what() << "\n";
    return kExitInternal;
  } catch (const roiclip::Error& e) {
    std::cerr << "roiclip: error: " << e.what() << "\n";
    return kExitCannotWrite;
  } catch (const std::exception& e) {
    std::cerr << "roiclip: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  // Setting up the command line can throw too (std::bad_alloc); nothing escapes main.
  try {
    return runMain(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "roiclip: internal error: " << e.what() << "\n";
  } catch (...) {
    std::cerr << "roiclip: internal error: unknown exception\n";
  }
  return kExitInternal;
}
