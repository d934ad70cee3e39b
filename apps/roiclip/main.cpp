// roiclip command line. Subcommands are thin: parse, call the library, write.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include <roiclip/io/geojson.hpp>
#include <roiclip/roiclip.hpp>

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
    "     fewer than 3 distinct points, coordinate outside the grid range (one line on stderr\n"
    "     names the file and the problem; no output file is written)\n"
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

void writeResult(const roiclip::PolygonSet& result, const std::string& output) {
  if (output.empty()) {
    std::cout << roiclip::io::toGeoJson(result);
    std::cout.flush();
  } else {
    roiclip::io::writeGeoJson(result, output);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"roiclip: exact clipping of self-intersecting polygons"};
  app.footer(kExitCodesHelp);
  app.require_subcommand(1);
  std::string input = "images";
  std::string output = "out";
  auto* run = app.add_subcommand("run", "process a folder of images (AprilTag ROI + contours)");
  run->add_option("input", input, "folder of images")->capture_default_str();
  run->add_option("-o,--output", output, "output folder")->capture_default_str();

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

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }

  try {
    if (run->parsed()) {
      std::cerr << "roiclip run: the batch pipeline (tag detection, contours, clipping) is not "
                   "built yet; it needs the AprilTag layer, the OpenCV layer and the batch app.\n";
      return 0;
    }
    if (simplifyCmd->parsed()) {
      const roiclip::Paths paths = roiclip::io::readPaths(simplifyInput);
      const roiclip::FillRule rule = roiclip::parseFillRule(simplifyRule.c_str());
      writeResult(roiclip::io::simplifyInput(paths, simplifyInput, rule, grid), simplifyOutput);
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
                  clipOutput);
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
