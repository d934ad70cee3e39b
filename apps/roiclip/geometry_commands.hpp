// SPDX-License-Identifier: MIT
// `roiclip simplify`, `clip` and `clip-lines`: their options, and their work (read the files,
// call roiclip::io's feature-wise operations or the core, write GeoJSON or WKT).
#pragma once

#include <initializer_list>
#include <string>

#include <CLI/CLI.hpp>

#include <roiclip/io/feature.hpp>
#include <roiclip/roiclip.hpp>

namespace roiclip::app {

// Naming an error's file by its operand is roiclip::io's (the feature-wise operations do it).
using io::nameSource;
using io::Source;

/// simplify() on paths read from `source`; an InvalidInputError from the core is rethrown naming
/// `source` (nameSource()): "SOURCE: path i, vertex j: ...".
PolygonSet simplifyInput(const Paths& paths, const std::string& source, FillRule rule,
                         const Options& options = {});

/// clip() on paths read from two sources; a core InvalidInputError gets the source of the operand
/// it names (its location's operand), or both sources when it names none.
PolygonSet clipInputs(ClipOp op, const Paths& subject, const std::string& subjectSource,
                      const Paths& clipPaths, const std::string& clipSource, FillRule subjectRule,
                      FillRule clipRule, const Options& options = {});

/// clipLines() on polylines and region paths read from two sources; core InvalidInputErrors get
/// the source of the operand they name (Operand::Line: the lines, Operand::Clip: the region).
Paths clipLinesInputs(const Paths& lines, const std::string& linesSource, const Paths& region,
                      const std::string& regionSource, FillRule regionRule,
                      LinePart part = LinePart::Inside, const Options& options = {});

/// The three geometry subcommands, added to `app` with their options bound to this object (which
/// must outlive the parse).
class GeometryCommands {
 public:
  explicit GeometryCommands(CLI::App& app);

  /// Run the subcommand that was parsed, if any: read (a file or "-"), compute feature by feature
  /// (or dissolved), print warnings to stderr, write GeoJSON or WKT to stdout or atomically to
  /// the -o file.
  /// @throws InvalidInputError on bad input (naming the file), Error when the output cannot be
  ///         written.
  void execute() const;

 private:
  /// The options every command has: formats, and (regions only) ring order and --dissolve.
  struct Common {
    std::string output;
    std::string format = "geojson";
    std::string inputFormat = "auto";
    std::string orientation = "rfc7946";
    bool dissolve = false;
    double roundTo = 0;  ///< --round-to STEP: snap-round results onto multiples of STEP; 0: off
  };
  struct Simplify : Common {
    CLI::App* cmd = nullptr;
    std::string input;
    std::string rule = "evenodd";
  };
  struct Clip : Common {
    CLI::App* cmd = nullptr;
    std::string subject;
    std::string clip;
    std::string op = "intersection";
    std::string bothRule;
    std::string subjectRule;
    std::string clipRule;
  };
  struct ClipLines : Common {
    CLI::App* cmd = nullptr;
    std::string lines;
    std::string region;
    std::string part = "inside";
    std::string rule = "evenodd";
  };

  /// --grid auto|SCALE (and its old spelling --grid-scale), --max-crossings, --strict.
  void addCoreOptions(CLI::App* cmd);
  /// -o, --format, --input-format; with `regions` also --orientation and --dissolve.
  static void addCommon(CLI::App* cmd, Common& options, bool regions);

  Options options_{Grid::fitted(), Limits{Limits::kToolMaxCrossings}};
  bool strict_ = false;  ///< refuse degenerate rings and lines (io::ReadOptions)
  Simplify simplify_;
  Clip clip_;
  ClipLines clipLines_;
};

}  // namespace roiclip::app
