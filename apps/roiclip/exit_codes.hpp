// SPDX-License-Identifier: MIT
// roiclip command line: the exit codes, in one table. Every command returns these, and --help
// prints them from the same table (exitCodesHelp()).
#pragma once

#include <algorithm>
#include <string>

namespace roiclip::app {

constexpr int kExitOk = 0;
constexpr int kExitUsage = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitCannotWrite = 3;
constexpr int kExitInternal = 4;
constexpr int kExitImagesFailed = 5;   ///< `run` and `merge` only
constexpr int kExitLimit = 6;          ///< geometry commands: a work limit (--max-crossings)
constexpr int kExitInterrupted = 130;  ///< `run` only (Ctrl-C)

/// One exit code and what it means for the geometry commands (simplify, clip, clip-lines) and for
/// `run`; nullptr where a command never returns it. Lines of a meaning are separated by '\n'.
struct ExitCode {
  int code;
  const char* geometry;
  const char* run;
};

inline constexpr ExitCode kExitCodes[] = {
    {kExitOk, "success", "every image processed, every mask check passed"},
    {kExitUsage, "command-line usage error", "command-line usage error"},
    {kExitBadInput,
     "invalid input: unreadable or malformed file, NaN or non-numeric coordinate, a\n"
     "bounding box too large for doubles, a coordinate outside a fixed --grid's range, with\n"
     "--strict a degenerate ring (fewer than 3 distinct points, or all on one line) or a\n"
     "line with fewer than 2 points\n"
     "(one line on stderr names the file and the problem; no output file is written)",
     "invalid input: input folder missing or unreadable, no images found, bad option value,\n"
     "bad --roi/--board/--config"},
    {kExitCannotWrite, "the output file cannot be written",
     "the output folder cannot be created or written"},
    {kExitInternal, "internal error (a bug in roiclip: please report the input)",
     "internal error (a bug in roiclip: please report the input)"},
    {kExitImagesFailed, nullptr,
     "at least one image failed (unreadable, not an image, truncated, more pixels than\n"
     "--max-pixels, unsupported type), had no ROI (no tags / missing id) or failed its\n"
     "mask check; see summary.csv; the other images were processed"},
    {kExitLimit,
     "the input needs more work than --max-crossings allows (one line on stderr names the\n"
     "limit; no output file is written)",
     nullptr},
    {kExitInterrupted, nullptr,
     "interrupted (Ctrl-C); finished images are complete, summary covers them"},
};

/// Which commands' meanings exitCodesHelp() lists.
enum class ExitCodesOf { Geometry, Run };

/// "Exit codes:\n  0  success\n  1  ...": the codes `commands` return, with their meanings, the
/// codes in a column as wide as the widest of them.
inline std::string exitCodesHelp(ExitCodesOf commands) {
  const auto meaning = [commands](const ExitCode& e) {
    return commands == ExitCodesOf::Geometry ? e.geometry : e.run;
  };
  std::size_t width = 0;
  for (const ExitCode& e : kExitCodes) {
    if (meaning(e) != nullptr) width = std::max(width, std::to_string(e.code).size());
  }
  const std::string indent(2 + width + 2, ' ');
  std::string help = "Exit codes:\n";
  for (const ExitCode& e : kExitCodes) {
    if (meaning(e) == nullptr) continue;
    const std::string code = std::to_string(e.code);
    help += "  " + code + std::string(width - code.size() + 2, ' ');
    for (const char* c = meaning(e); *c != '\0'; ++c) {
      help += *c;
      if (*c == '\n') help += indent;
    }
    help += '\n';
  }
  return help;
}

}  // namespace roiclip::app
