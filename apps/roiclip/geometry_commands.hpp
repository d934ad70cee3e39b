// `roiclip simplify`, `clip` and `clip-lines`: their options, and their work (read the files,
// call the core, write GeoJSON).
#pragma once

#include <initializer_list>
#include <string>

#include <CLI/CLI.hpp>

#include <roiclip/roiclip.hpp>

namespace roiclip::app {

/// The name of the input (a file) an operand of the core was read from.
struct Source {
  Operand operand;
  std::string name;
};

/// `e` naming the source of the operand it concerns (e.location().operand, a field: the message
/// is never read), or all of `sources` when it names no operand; an error that already names its
/// source (e.g. one from roiclip::io) is returned as it is.
InvalidInputError nameSource(const InvalidInputError& e, std::initializer_list<Source> sources);

/// simplify() on paths read from `source`; an InvalidInputError from the core is rethrown naming
/// `source` (nameSource()): "SOURCE: path i, vertex j: ...".
PolygonSet simplifyInput(const Paths& paths, const std::string& source, FillRule rule,
                         const Grid& grid = {});

/// clip() on paths read from two sources; a core InvalidInputError gets the source of the operand
/// it names (its location's operand), or both sources when it names none.
PolygonSet clipInputs(ClipOp op, const Paths& subject, const std::string& subjectSource,
                      const Paths& clipPaths, const std::string& clipSource, FillRule subjectRule,
                      FillRule clipRule, const Grid& grid = {});

/// clipLines() on polylines and region paths read from two sources; core InvalidInputErrors get
/// the source of the operand they name (Operand::Line: the lines, Operand::Clip: the region).
Paths clipLinesInputs(const Paths& lines, const std::string& linesSource, const Paths& region,
                      const std::string& regionSource, FillRule regionRule,
                      LinePart part = LinePart::Inside, const Grid& grid = {});

/// The three geometry subcommands, added to `app` with their options bound to this object (which
/// must outlive the parse).
class GeometryCommands {
 public:
  explicit GeometryCommands(CLI::App& app);

  /// Run the subcommand that was parsed, if any: read, compute, write the GeoJSON to stdout or
  /// atomically to the -o file.
  /// @throws InvalidInputError on bad input (naming the file), Error when the output cannot be
  ///         written.
  void execute() const;

 private:
  struct Simplify {
    CLI::App* cmd = nullptr;
    std::string input;
    std::string rule = "evenodd";
    std::string output;
  };
  struct Clip {
    CLI::App* cmd = nullptr;
    std::string subject;
    std::string clip;
    std::string op = "intersection";
    std::string bothRule;
    std::string subjectRule;
    std::string clipRule;
    std::string output;
  };
  struct ClipLines {
    CLI::App* cmd = nullptr;
    std::string lines;
    std::string region;
    std::string part = "inside";
    std::string rule = "evenodd";
    std::string output;
  };

  void addGridScale(CLI::App* cmd);

  Grid grid_;
  Simplify simplify_;
  Clip clip_;
  ClipLines clipLines_;
};

}  // namespace roiclip::app
