// roiclip command line: set up the subcommands, dispatch, and turn exceptions into exit codes
// (exit_codes.hpp). The commands live in geometry_commands.* and run_command.hpp.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <roiclip/error.hpp>

#include "exit_codes.hpp"
#include "geometry_commands.hpp"

#ifdef ROICLIP_HAVE_BATCH
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

int runMain(int argc, char** argv) {
  CLI::App app{"roiclip: exact clipping of self-intersecting polygons"};
  app.footer(exitCodesHelp(ExitCodesOf::Geometry));
  app.require_subcommand(1);
#ifdef ROICLIP_HAVE_BATCH
  RunCommand runCommand(app);
  auto* run = runCommand.subcommand();
#else
  auto* run = app.add_subcommand("run", "process a folder of images (not built: needs AprilTag)");
  run->allow_extras();
#endif
  GeometryCommands geometry(app);

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
  }

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
