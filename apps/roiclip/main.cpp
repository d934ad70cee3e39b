// SPDX-License-Identifier: MIT
// roiclip command line: set up the subcommands, dispatch, and turn exceptions into exit codes
// (exit_codes.hpp). The commands live in geometry_commands.* and run_command.*; `roiclip help
// [COMMAND]` prints the same help as `roiclip [COMMAND] --help`.
#include <exception>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include <roiclip/error.hpp>

#include "exit_codes.hpp"
#include "geometry_commands.hpp"

#ifdef ROICLIP_HAVE_BATCH
#include "merge_command.hpp"
#include "run_command.hpp"
#endif

namespace {

using namespace roiclip::app;

// One line on stderr for the exception being handled, and its exit code.
int reportCurrentException() {
  try {
    throw;
  } catch (const roiclip::InvalidInputError& e) {
    std::cerr << "roiclip: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const roiclip::ResourceLimitError& e) {
    std::cerr << "roiclip: error: " << e.what() << "; raise it with --max-crossings\n";
    return kExitLimit;
  } catch (const roiclip::InternalError& e) {
    std::cerr << "roiclip: internal error: " << e.what() << "\n";
    return kExitInternal;
  } catch (const roiclip::Error& e) {
    std::cerr << "roiclip: error: " << e.what() << "\n";
    return kExitCannotWrite;
  } catch (const std::exception& e) {
    std::cerr << "roiclip: internal error: " << e.what() << "\n";
  } catch (...) {
    std::cerr << "roiclip: internal error: unknown exception\n";
  }
  return kExitInternal;
}

// `roiclip help [COMMAND]`: the help `roiclip [COMMAND] --help` prints.
class HelpCommand {
 public:
  explicit HelpCommand(CLI::App& app) : app_(app) {
    cmd_ = app.add_subcommand("help", "print this help, or a command's (roiclip help run)");
    cmd_->add_option("command", topic_, "the command to explain");
  }
  [[nodiscard]] CLI::App* subcommand() const { return cmd_; }

  [[nodiscard]] int execute() const {
    if (topic_.empty()) {
      std::cout << app_.get_formatter()->make_help(&app_, app_.get_name(),
                                                   CLI::AppFormatMode::Normal);
      return kExitOk;
    }
    const CLI::App* command = nullptr;
    for (const CLI::App* sub : app_.get_subcommands({})) {
      if (sub->check_name(topic_) && sub != cmd_) command = sub;
    }
    if (command == nullptr) {
      std::cerr << "roiclip help: no command '" << topic_ << "' (roiclip --help lists them)\n";
      return kExitUsage;
    }
    std::cout << command->help(app_.get_name());
    return kExitOk;
  }

 private:
  CLI::App& app_;
  CLI::App* cmd_ = nullptr;
  std::string topic_;
};

int runMain(int argc, char** argv) {
  CLI::App app{"roiclip: exact clipping of self-intersecting polygons"};
  app.footer(exitCodesHelp(ExitCodesOf::Geometry));
  app.set_version_flag("--version", std::string("roiclip ") + ROICLIP_VERSION);
  app.require_subcommand(1);
#ifdef ROICLIP_HAVE_BATCH
  RunCommand runCommand(app);
  auto* run = runCommand.subcommand();
  MergeCommand merge(app);
#else
  auto* run = app.add_subcommand("run", "process a folder of images (not built: needs AprilTag)");
  run->allow_extras();
#endif
  GeometryCommands geometry(app);
  const HelpCommand help(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
#ifdef ROICLIP_HAVE_BATCH
    if (const std::optional<int> code = runCommand.badInputExit(e)) return *code;
#endif
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }

  if (help.subcommand()->parsed()) return help.execute();
#ifdef ROICLIP_HAVE_BATCH
  if (merge.subcommand()->parsed()) return merge.exitCode();
#endif
  if (run->parsed()) {
#ifdef ROICLIP_HAVE_BATCH
    return runCommand.execute();
#else
    std::cerr << "roiclip run: this build has no batch pipeline (configure with "
                 "ROICLIP_BUILD_APRILTAG=ON).\n";
    return kExitUsage;
#endif
  }
  geometry.execute();
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  // Nothing escapes main: setting up the command line can throw too (std::bad_alloc).
  try {
    return runMain(argc, argv);
  } catch (...) {
    return reportCurrentException();
  }
}
