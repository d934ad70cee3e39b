// `roiclip simplify`, `clip` and `clip-lines`: option setup and execution.
#include "geometry_commands.hpp"

#include <iostream>

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

InvalidInputError nameSource(const InvalidInputError& e, std::initializer_list<Source> sources) {
  if (!e.location().source.empty()) return e;
  std::string all;
  for (const Source& source : sources) {
    if (e.location().operand == source.operand) return e.withSource(source.name);
    all += (all.empty() ? "" : ", ") + source.name;
  }
  return e.withSource(all);
}

PolygonSet simplifyInput(const Paths& paths, const std::string& source, FillRule rule,
                         const Grid& grid) {
  try {
    return simplify(paths, rule, grid);
  } catch (const InvalidInputError& e) {
    throw nameSource(e, {{Operand::Subject, source}});
  }
}

PolygonSet clipInputs(ClipOp op, const Paths& subject, const std::string& subjectSource,
                      const Paths& clipPaths, const std::string& clipSource, FillRule subjectRule,
                      FillRule clipRule, const Grid& grid) {
  try {
    return clip(op, subject, clipPaths, subjectRule, clipRule, grid);
  } catch (const InvalidInputError& e) {
    throw nameSource(e, {{Operand::Subject, subjectSource}, {Operand::Clip, clipSource}});
  }
}

Paths clipLinesInputs(const Paths& lines, const std::string& linesSource, const Paths& region,
                      const std::string& regionSource, FillRule regionRule, LinePart part,
                      const Grid& grid) {
  try {
    return clipLines(lines, region, regionRule, part, grid);
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
      "simplify", "resolve self-intersecting paths into simple polygons with holes (GeoJSON out)");
  s.cmd->footer(exitCodes);
  s.cmd->add_option("input", s.input, "GeoJSON or {\"paths\": ...} JSON file")->required();
  s.cmd->add_option("--fill-rule", s.rule, "fill rule for the input paths")
      ->check(fillRuleValidator())
      ->capture_default_str();
  s.cmd->add_option("-o,--output", s.output, "output GeoJSON file (default: stdout)");
  addGridScale(s.cmd);

  Clip& c = clip_;
  c.cmd = app.add_subcommand("clip", "boolean operation SUBJECT op CLIP (GeoJSON out)");
  c.cmd->footer(exitCodes);
  c.cmd->add_option("subject", c.subject, "subject paths file")->required();
  c.cmd->add_option("clip", c.clip, "clip paths file")->required();
  c.cmd->add_option("--op", c.op, "operation")->check(clipOpValidator())->capture_default_str();
  c.cmd->add_option("--fill-rule", c.bothRule, "fill rule for both operands (default evenodd)")
      ->check(fillRuleValidator());
  c.cmd->add_option("--subject-fill-rule", c.subjectRule, "fill rule for SUBJECT (overrides)")
      ->check(fillRuleValidator());
  c.cmd->add_option("--clip-fill-rule", c.clipRule, "fill rule for CLIP (overrides)")
      ->check(fillRuleValidator());
  c.cmd->add_option("-o,--output", c.output, "output GeoJSON file (default: stdout)");
  addGridScale(c.cmd);

  ClipLines& l = clipLines_;
  l.cmd = app.add_subcommand(
      "clip-lines", "the parts of open polylines LINES inside (or outside) REGION (GeoJSON out)");
  l.cmd->footer(kClipLinesHelp + exitCodes);
  l.cmd->add_option("lines", l.lines, "open polylines file")->required();
  l.cmd->add_option("region", l.region, "region paths file")->required();
  l.cmd->add_option("--part", l.part, "which parts of LINES to keep")
      ->transform(CLI::IsMember({"inside", "outside"}, CLI::ignore_case))
      ->capture_default_str();
  l.cmd->add_option("--fill-rule", l.rule, "fill rule for REGION")
      ->check(fillRuleValidator())
      ->capture_default_str();
  l.cmd->add_option("-o,--output", l.output, "output GeoJSON file (default: stdout)");
  addGridScale(l.cmd);
}

void GeometryCommands::addGridScale(CLI::App* cmd) {
  cmd->add_option("--grid-scale", grid_.scale,
                  "grid units per coordinate unit (a power of two; |coordinate * scale| must "
                  "stay <= 2^30)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

void GeometryCommands::execute() const {
  if (simplify_.cmd->parsed()) {
    const Simplify& s = simplify_;
    const Paths paths = io::readPaths(s.input);
    const FillRule rule = parseFillRule(s.rule.c_str());
    writeResult(simplifyInput(paths, s.input, rule, grid_), s.output, io::toGeoJson,
                io::writeGeoJson);
  } else if (clip_.cmd->parsed()) {
    const Clip& c = clip_;
    const std::string base = c.bothRule.empty() ? "evenodd" : c.bothRule;
    const FillRule subjectRule =
        parseFillRule((c.subjectRule.empty() ? base : c.subjectRule).c_str());
    const FillRule clipRule = parseFillRule((c.clipRule.empty() ? base : c.clipRule).c_str());
    const ClipOp op = parseClipOp(c.op.c_str());
    const Paths subject = io::readPaths(c.subject);
    const Paths clipPaths = io::readPaths(c.clip);
    writeResult(clipInputs(op, subject, c.subject, clipPaths, c.clip, subjectRule, clipRule, grid_),
                c.output, io::toGeoJson, io::writeGeoJson);
  } else if (clipLines_.cmd->parsed()) {
    const ClipLines& l = clipLines_;
    const FillRule rule = parseFillRule(l.rule.c_str());
    // IsMember() has already turned any spelling into "inside" or "outside".
    const LinePart part = l.part == "outside" ? LinePart::Outside : LinePart::Inside;
    const Paths lines = io::readLines(l.lines);
    const Paths region = io::readPaths(l.region);
    writeResult(clipLinesInputs(lines, l.lines, region, l.region, rule, part, grid_), l.output,
                io::linesToGeoJson, io::writeLinesGeoJson);
  }
}

}  // namespace roiclip::app
