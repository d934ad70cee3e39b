// SPDX-License-Identifier: MIT
// `roiclip simplify`, `clip` and `clip-lines`: option setup and execution.
#include "geometry_commands.hpp"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <roiclip/io/feature.hpp>
#include <roiclip/io/geojson.hpp>

#include "exit_codes.hpp"

namespace roiclip::app {
namespace {

// Validates with the library's own parser (parseFillRule, parseClipOp) so the CLI accepts exactly
// what it does.
template <class Result>
CLI::Validator parserValidator(Result (*parse)(const char*), const char* names) {
  return CLI::Validator(
      [parse](std::string& value) -> std::string {
        try {
          parse(value.c_str());
          return {};
        } catch (const InvalidInputError& e) {
          return e.what();
        }
      },
      names);
}

CLI::Validator fillRuleValidator() {
  return parserValidator(parseFillRule, "evenodd|nonzero|positive|negative");
}

CLI::Validator clipOpValidator() {
  return parserValidator(parseClipOp, "intersection|union|difference|xor");
}

void printWarnings(const std::vector<io::Warning>& warnings) {
  for (const io::Warning& w : warnings) std::cerr << "roiclip: warning: " << w.what() << "\n";
}

constexpr const char* kFeaturesHelp =
    "Features: each GeoJSON Feature is processed on its own and keeps its \"id\" and\n"
    "\"properties\" (clip: each SUBJECT feature is clipped by the union of the CLIP features);\n"
    "--dissolve merges them first and writes one feature with properties \"area\" and \"rings\"\n"
    "(so does an input without features: a bare geometry, {\"paths\": ...}, WKT). Rings are\n"
    "written in RFC 7946 order (exterior: positive shoelace sum, i.e. counter-clockwise with y\n"
    "up, clockwise on a y-down image); --orientation opencv writes cv::findContours' order.\n"
    "'-' reads standard input or writes standard output. Warnings (stderr): a z coordinate\n"
    "is dropped; snapping to a fixed --grid moved a vertex by more than 1/4 grid step;\n"
    "degenerate rings were ignored (fewer than 3 distinct points, or all points on one line:\n"
    "no area; the summary properties count them: \"ignoredRings\", and for the CLIP operand of\n"
    "clip \"ignoredClipRings\"; --strict refuses them).\n"
    "\n";

constexpr const char* kClipLinesHelp =
    "LINES: GeoJSON LineString, MultiLineString, or a Feature, FeatureCollection or\n"
    "GeometryCollection of them, or {\"paths\": [[[x, y], ...], ...]} (a polyline whose last\n"
    "point repeats its first is a loop). REGION: as for `clip` (closed; its boundary counts as\n"
    "inside). Output: GeoJSON MultiLineString, properties \"length\" (px) and \"lines\", and\n"
    "\"ignoredClipRings\" when REGION has degenerate rings (fewer than 3 distinct points, or\n"
    "all on one line: ignored with a warning; --strict refuses them).\n"
    "\n"
    "Example: a line from (-5, 5) via (5, 5) to (5, 15) and the square [0, 10]^2\n"
    "  roiclip clip-lines line.geojson square.geojson\n"
    "    -> [[0, 5], [5, 5], [5, 10]]                          length 10, lines 1\n"
    "  roiclip clip-lines line.geojson square.geojson --part outside -o outside.geojson\n"
    "    -> [[-5, 5], [0, 5]] and [[5, 10], [5, 15]]           length 10, lines 2\n"
    "\n";

}  // namespace

PolygonSet simplifyInput(const Paths& paths, const std::string& source, FillRule rule,
                         const Options& options) {
  try {
    return simplify(paths, rule, options);
  } catch (const InvalidInputError& e) {
    throw nameSource(e, {{Operand::Subject, source}});
  }
}

PolygonSet clipInputs(ClipOp op, const Paths& subject, const std::string& subjectSource,
                      const Paths& clipPaths, const std::string& clipSource, FillRule subjectRule,
                      FillRule clipRule, const Options& options) {
  try {
    return clip(op, subject, clipPaths, subjectRule, clipRule, options);
  } catch (const InvalidInputError& e) {
    throw nameSource(e, {{Operand::Subject, subjectSource}, {Operand::Clip, clipSource}});
  }
}

Paths clipLinesInputs(const Paths& lines, const std::string& linesSource, const Paths& region,
                      const std::string& regionSource, FillRule regionRule, LinePart part,
                      const Options& options) {
  try {
    return clipLines(lines, region, regionRule, part, options);
  } catch (const InvalidInputError& e) {
    throw nameSource(e, {{Operand::Line, linesSource}, {Operand::Clip, regionSource}});
  }
}

GeometryCommands::GeometryCommands(CLI::App& app) {
  const std::string exitCodes = exitCodesHelp(ExitCodesOf::Geometry);

  // Input files: GeoJSON (Polygon, MultiPolygon, Feature, FeatureCollection; every ring is one
  // path) or plain {"paths": [[[x, y], ...], ...]}. Output: GeoJSON FeatureCollection.
  Simplify& s = simplify_;
  s.cmd = app.add_subcommand(
      "simplify",
      "resolve self-intersecting paths into simple polygons with holes (GeoJSON or WKT out)");
  s.cmd->footer(kFeaturesHelp + exitCodes);
  s.cmd->add_option("input", s.input, "GeoJSON, {\"paths\": ...} JSON or WKT file ('-': stdin)")
      ->required();
  s.cmd->add_option("--fill-rule", s.rule, "fill rule for the input paths")
      ->check(fillRuleValidator())
      ->capture_default_str();
  addCommon(s.cmd, s, true);
  addCoreOptions(s.cmd);

  Clip& c = clip_;
  c.cmd = app.add_subcommand("clip", "boolean operation SUBJECT op CLIP (GeoJSON or WKT out)");
  c.cmd->footer(kFeaturesHelp + exitCodes);
  c.cmd->add_option("subject", c.subject, "subject paths file ('-': stdin)")->required();
  c.cmd->add_option("clip", c.clip, "clip paths file ('-': stdin)")->required();
  c.cmd->add_option("--op", c.op, "operation")->check(clipOpValidator())->capture_default_str();
  c.cmd->add_option("--fill-rule", c.bothRule, "fill rule for both operands (default evenodd)")
      ->check(fillRuleValidator());
  c.cmd->add_option("--subject-fill-rule", c.subjectRule, "fill rule for SUBJECT (overrides)")
      ->check(fillRuleValidator());
  c.cmd->add_option("--clip-fill-rule", c.clipRule, "fill rule for CLIP (overrides)")
      ->check(fillRuleValidator());
  addCommon(c.cmd, c, true);
  addCoreOptions(c.cmd);

  ClipLines& l = clipLines_;
  l.cmd = app.add_subcommand(
      "clip-lines",
      "the parts of open polylines LINES inside (or outside) REGION (GeoJSON or WKT out)");
  l.cmd->footer(kClipLinesHelp + exitCodes);
  l.cmd->add_option("lines", l.lines, "open polylines file ('-': stdin)")->required();
  l.cmd->add_option("region", l.region, "region paths file ('-': stdin)")->required();
  l.cmd->add_option("--part", l.part, "which parts of LINES to keep")
      ->transform(CLI::IsMember({"inside", "outside"}, CLI::ignore_case))
      ->capture_default_str();
  l.cmd->add_option("--fill-rule", l.rule, "fill rule for REGION")
      ->check(fillRuleValidator())
      ->capture_default_str();
  addCommon(l.cmd, l, false);
  addCoreOptions(l.cmd);
}

void GeometryCommands::addCommon(CLI::App* cmd, Common& options, bool regions) {
  cmd->add_option("-o,--output", options.output, "output file (default or '-': stdout)");
  cmd->add_option("--format", options.format, "output format")
      ->transform(CLI::IsMember({"geojson", "wkt"}, CLI::ignore_case))
      ->capture_default_str();
  cmd->add_option("--input-format", options.inputFormat,
                  "input format (auto: WKT when the text starts with a letter)")
      ->transform(CLI::IsMember({"auto", "geojson", "wkt"}, CLI::ignore_case))
      ->capture_default_str();
  if (!regions) return;
  cmd->add_option("--orientation", options.orientation,
                  "ring order written: rfc7946 (exterior counter-clockwise with y up) or opencv "
                  "(as cv::findContours)")
      ->transform(CLI::IsMember({"rfc7946", "opencv"}, CLI::ignore_case))
      ->capture_default_str();
  cmd->add_flag("--dissolve", options.dissolve,
                "merge all features first and write one (properties \"area\", \"rings\")");
  cmd->add_option("--round-to", options.roundTo,
                  "snap-round each result onto multiples of STEP (1: integer pixels, 1e-6: GIS "
                  "degrees), keeping it valid: no crossings, holes inside (roiclip::roundTo)")
      ->type_name("STEP")
      ->check(CLI::PositiveNumber);
}

void GeometryCommands::addCoreOptions(CLI::App* cmd) {
  const auto setGrid = [this](const std::string& text) {
    if (text == "auto") {
      options_.grid = Grid::fitted();
      return;
    }
    double scale = 0;
    std::size_t used = 0;
    try {
      scale = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || !(scale > 0) || !std::isfinite(scale)) {
      throw CLI::ValidationError("--grid", "expected auto or a positive scale, got " + text);
    }
    options_.grid = Grid::fixed(scale);
  };
  cmd->add_option_function<std::string>(
         "--grid", setGrid,
         "auto (default): fitted to each call's operands, any finite coordinates, snapping by at "
         "most ~2^-31 of the extent; or SCALE: one fixed grid of SCALE units per coordinate unit "
         "(a power of two; |coordinate * SCALE| <= 2^30), identical snapping across calls")
      ->default_str("auto");
  cmd->add_option_function<std::string>("--grid-scale", setGrid, "the same as --grid SCALE")
      ->group("");  // the old spelling, kept working
  cmd->add_option("--max-crossings", options_.limits.maxCrossings,
                  "give up (exit code 6) when the input has more crossings than this (each takes "
                  "200 to 320 bytes while it runs)")
      ->capture_default_str();
  cmd->add_flag("--strict", strict_,
                "refuse degenerate rings (fewer than 3 distinct points, or all points on one "
                "line) and lines with fewer than 2 points (by default such rings are ignored and "
                "counted: \"ignoredRings\", \"ignoredClipRings\")");
}

namespace {

// An input read as features, warnings collected, dissolved on request.
std::vector<io::Feature> readRegions(const std::string& file, const std::string& format,
                                     bool dissolve, bool strict,
                                     std::vector<io::Warning>& warnings) {
  io::ReadOptions options;
  options.warnings = &warnings;
  options.allowDegenerateRings = !strict;
  std::vector<io::Feature> features =
      io::readAnyFeatures(file, io::parseFormat(format.c_str()), options);
  if (dissolve) features = {io::dissolve(features)};
  return features;
}

// --round-to: each result snap-rounded onto the step grid; ids and input properties kept, the
// summary properties ("area", "rings") of a feature that had none recomputed.
void roundResults(std::vector<io::Feature>& results, const std::vector<io::Feature>& inputs,
                  double step) {
  if (step == 0) return;
  for (std::size_t i = 0; i < results.size(); ++i) {
    PolygonSet set;
    for (const Paths& rings : results[i].polygons) {
      Polygon polygon;
      polygon.outer = rings.front();
      polygon.holes.assign(rings.begin() + 1, rings.end());
      set.polygons.push_back(std::move(polygon));
    }
    io::Feature rounded =
        io::toFeature(roundTo(set, step), results[i].ignoredRings, results[i].ignoredClipRings);
    rounded.id = results[i].id;
    if (!inputs[i].propertiesJson.empty()) {
      rounded.propertiesJson = results[i].propertiesJson;
      rounded.properties = results[i].properties;
    }
    results[i] = std::move(rounded);
  }
}

void refuseTwoStdins(const std::string& a, const std::string& b) {
  if (a == "-" && b == "-") {
    throw InvalidInputError("<stdin>: only one input can be standard input ('-')");
  }
}

}  // namespace

void GeometryCommands::execute() const {
  std::vector<io::Warning> warnings;
  const auto snapCheck = [&](const Paths& paths, const std::string& file) {
    for (io::Warning& w : io::snapWarnings(paths, io::sourceName(file), options_.grid)) {
      warnings.push_back(std::move(w));
    }
  };
  // Degenerate rings are ignored (not an error without --strict): one line per input says so,
  // naming the operand when there are two ("ignored 1 clip ring ...").
  const auto ignoredWarning = [&](std::size_t ignored, const std::string& file, Operand operand) {
    if (ignored == 0) return;
    const std::string which = operand == Operand::None ? "" : toString(operand) + std::string(" ");
    warnings.push_back({io::sourceName(file),
                        "ignored " + std::to_string(ignored) + " " + which +
                            (ignored == 1 ? "ring" : "rings") +
                            " with fewer than 3 distinct points or no area (--strict refuses "
                            "them)"});
  };
  const auto subjectIgnored = [](const std::vector<io::Feature>& result) {
    std::size_t ignored = 0;
    for (const io::Feature& f : result) ignored += f.ignoredRings;
    return ignored;
  };
  const io::DegenerateRings degenerate =
      strict_ ? io::DegenerateRings::Refuse : io::DegenerateRings::Count;
  const auto writeOptions = [](const Common& options) {
    return io::WriteOptions{io::parseRingOrientation(options.orientation.c_str()), -1};
  };
  if (simplify_.cmd->parsed()) {
    const Simplify& s = simplify_;
    const FillRule rule = parseFillRule(s.rule.c_str());
    const auto input = readRegions(s.input, s.inputFormat, s.dissolve, strict_, warnings);
    snapCheck(io::allRings(input), s.input);
    auto result = io::simplifyFeatures(input, io::sourceName(s.input), rule, options_, degenerate);
    ignoredWarning(subjectIgnored(result), s.input, Operand::None);
    roundResults(result, input, s.roundTo);
    printWarnings(warnings);
    io::writeFeatures(result, s.output, io::parseFormat(s.format.c_str()), writeOptions(s));
  } else if (clip_.cmd->parsed()) {
    const Clip& c = clip_;
    const std::string base = c.bothRule.empty() ? "evenodd" : c.bothRule;
    const FillRule subjectRule =
        parseFillRule((c.subjectRule.empty() ? base : c.subjectRule).c_str());
    const FillRule clipRule = parseFillRule((c.clipRule.empty() ? base : c.clipRule).c_str());
    const ClipOp op = parseClipOp(c.op.c_str());
    refuseTwoStdins(c.subject, c.clip);
    const auto subject = readRegions(c.subject, c.inputFormat, c.dissolve, strict_, warnings);
    const auto clipRegion = readRegions(c.clip, c.inputFormat, c.dissolve, strict_, warnings);
    snapCheck(io::allRings(subject), c.subject);
    snapCheck(io::allRings(clipRegion), c.clip);
    auto result =
        io::clipFeatures(op, subject, io::sourceName(c.subject), clipRegion, io::sourceName(c.clip),
                         subjectRule, clipRule, options_, degenerate);
    ignoredWarning(subjectIgnored(result), c.subject, Operand::Subject);
    // Every result counts the whole clip operand's; without a subject feature there is none to
    // carry the count, but the file still has them.
    ignoredWarning(result.empty() ? io::countDegenerateRings(clipRegion, options_)
                                  : result.front().ignoredClipRings,
                   c.clip, Operand::Clip);
    roundResults(result, subject, c.roundTo);
    printWarnings(warnings);
    io::writeFeatures(result, c.output, io::parseFormat(c.format.c_str()), writeOptions(c));
  } else if (clipLines_.cmd->parsed()) {
    const ClipLines& l = clipLines_;
    const FillRule rule = parseFillRule(l.rule.c_str());
    // IsMember() has already turned any spelling into "inside" or "outside".
    const LinePart part = l.part == "outside" ? LinePart::Outside : LinePart::Inside;
    refuseTwoStdins(l.lines, l.region);
    io::ReadOptions options;
    options.warnings = &warnings;
    options.allowDegenerateRings = !strict_;
    const io::Format inputFormat = io::parseFormat(l.inputFormat.c_str());
    const Paths lines = io::readAnyLines(l.lines, inputFormat, options);
    const Paths region = io::allRings(io::readAnyFeatures(l.region, inputFormat, options));
    snapCheck(lines, l.lines);
    snapCheck(region, l.region);
    const Paths result = clipLinesInputs(lines, io::sourceName(l.lines), region,
                                         io::sourceName(l.region), rule, part, options_);
    // The region's degenerate rings on the call's grid (the one clipLines() fits to both).
    std::size_t ignored = 0;
    try {
      ignored = io::checkDegenerateRings(region, resolveGrid(options_.grid, lines, region),
                                         Operand::Clip, degenerate);
    } catch (const InvalidInputError& e) {
      throw nameSource(e, {{Operand::Clip, io::sourceName(l.region)}});
    }
    ignoredWarning(ignored, l.region, Operand::Clip);
    printWarnings(warnings);
    io::writeLines(result, l.output, io::parseFormat(l.format.c_str()), -1, ignored);
  }
}

}  // namespace roiclip::app
