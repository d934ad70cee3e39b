// `roiclip run`: argument parsing, progress and summary printing. The work is roiclip::batch.
#pragma once

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <roiclip/batch/run.hpp>

#include "exit_codes.hpp"

namespace run_detail {

// Set by SIGINT/SIGTERM; the run stops starting images and finishes the ones in flight.
inline std::atomic<bool> gCancel{false};

inline void onSignal(int) {
  if (gCancel.exchange(true))
    std::_Exit(roiclip::app::kExitInterrupted);  // second Ctrl-C: stop now (temp files are hidden)
}

constexpr const char* kRunHelp = R"(
Per image: read it (PNG, JPEG, TIFF, BMP, ...; 8/16-bit or float; gray, gray+alpha, colour;
PNG/JPEG/TIFF/WebP headers are checked against --max-pixels before decoding), detect AprilTags,
build the ROI, find contours (RETR_CCOMP: every outer contour with its holes), clip each one
exactly against the ROI, and check the vector result against the raster route (subject mask AND
ROI mask) off a boundary band. Writes into the output folder, each file atomically:
  NAME.json           tags, ROI, every clipped polygon with holes, areas, mask-check figures
  NAME.overlay.png    image dimmed outside the ROI, ROI outline, clipped regions, tag ids
  NAME.mask.png       clipped region as a mask (with --masks)
  summary.csv, summary.json, report.html   one row per image / overlays to look through
Images whose outputs are complete, newer than the image and made with the same options are
skipped (use --force to redo them).

ROI specs (--roi):
  hull                convex hull of all detected tags (default)
  hull:0,2,5          convex hull of those tags
  tags:0,1,2,3        polygon through the tag centres in that order (@top-left etc. for corners)
  board[:NAME]        board ROI NAME (all when omitted) fitted through the tags; needs --board
  tag:5:0.5,-0.5;2.5,-0.5;2.5,0.5;0.5,0.5   polygon in tag 5's frame (unit = tag side)

Examples:
  roiclip run images --output out
  roiclip run images -o out --roi board:inspection --board images/board.json --jobs 2
  roiclip run photos -o out --recursive --method adaptive --min-area 20 --masks
  roiclip run photos -o out --config run.json --force      (run.json: {"roi": "hull", "jobs": 2})

Exit codes:
  0    every image processed, every mask check passed
  1    command-line usage error
  2    invalid input: input folder missing or unreadable, no images found, bad option value,
       bad --roi/--board/--config
  3    the output folder cannot be created or written
  4    internal error (a bug in roiclip: please report the input)
  5    at least one image failed (unreadable, not an image, truncated, more pixels than
       --max-pixels, unsupported type), had no ROI (no tags / missing id) or failed its
       mask check; see summary.csv; the other images were processed
  130  interrupted (Ctrl-C); finished images are complete, summary covers them
)";

}  // namespace run_detail

class RunCommand {
 public:
  explicit RunCommand(CLI::App& app) {
    cmd_ = app.add_subcommand("run", "process a folder of images (AprilTag ROI + contours)");
    cmd_->footer(run_detail::kRunHelp);
    // Later occurrences win, so options from --config (inserted first) yield to the command line.
    cmd_->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    cmd_->add_option("input", input_, "folder of images")->capture_default_str();
    cmd_->add_option("-o,--output", output_, "output folder")->capture_default_str();
    cmd_->add_option("--config", config_, "JSON file of options (long names without --)");
    cmd_->add_option("--roi", roi_, "ROI spec (see below)")->capture_default_str();
    cmd_->add_option("--board", board_, "board JSON file for board ROIs");
    cmd_->add_option("--family", family_, "tag family")->capture_default_str();
    cmd_->add_option("--decimate", decimate_, "AprilTag quad decimation (>= 1)")
        ->capture_default_str();
    cmd_->add_option("--method", method_, "contours: otsu|adaptive|canny|threshold:T")
        ->capture_default_str();
    cmd_->add_option("--polarity", polarity_, "objects are dark|light")->capture_default_str();
    cmd_->add_option("--approx", approx_, "approxPolyDP epsilon in px (0 = off)")
        ->capture_default_str();
    cmd_->add_option("--min-area", minArea_, "drop outer contours smaller than this (px^2)")
        ->capture_default_str();
    cmd_->add_option("--fill-rule", fillRule_, "fill rule of the contours")->capture_default_str();
    cmd_->add_option("--roi-fill-rule", roiFillRule_, "fill rule of the ROI")
        ->capture_default_str();
    cmd_->add_option("--max-pixels", maxPixels_,
                     "refuse images with more pixels (width x height; read from the file's "
                     "header before decoding; 0 = no limit)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd_->add_option("-j,--jobs", jobs_, "images in parallel (0 = all cores)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd_->add_flag("-r,--recursive", recursive_, "descend into sub-folders (mirrored in output)");
    cmd_->add_flag("-f,--force", force_, "reprocess images whose outputs are up to date");
    cmd_->add_flag("--masks", masks_, "also write NAME.mask.png");
    cmd_->add_flag("--edges", edges_, "also clip Canny edges as open polylines (in NAME.json)");
    cmd_->add_flag("--no-report", noReport_, "do not write report.html");
    cmd_->add_flag("-q,--quiet", quiet_, "no progress output");
  }

  [[nodiscard]] CLI::App* subcommand() const { return cmd_; }

  /// argv with the options of `run --config FILE` inserted right after "run".
  /// @throws roiclip::InvalidInputError if the config file cannot be read or parsed.
  static std::vector<std::string> withConfig(int argc, char** argv) {
    std::vector<std::string> args(argv, argv + argc);
    std::size_t runAt = 0;
    for (std::size_t i = 1; i < args.size(); ++i) {
      if (args[i] == "run") {
        runAt = i;
        break;
      }
      if (args[i].empty() || args[i][0] != '-') return args;  // another subcommand
    }
    if (runAt == 0) return args;
    std::string file;
    for (std::size_t i = runAt + 1; i < args.size(); ++i) {
      if (args[i] == "--config" && i + 1 < args.size()) file = args[i + 1];
      if (args[i].rfind("--config=", 0) == 0) file = args[i].substr(9);
    }
    if (file.empty()) return args;
    std::ifstream in(file, std::ios::binary);
    if (!in) throw roiclip::InvalidInputError(file + ": cannot read config file");
    std::ostringstream text;
    text << in.rdbuf();
    const std::vector<std::string> extra = roiclip::batch::configToArguments(text.str(), file);
    for (const auto& e : extra) {
      if (e == "--config") throw roiclip::InvalidInputError(file + ": 'config' cannot nest");
    }
    args.insert(args.begin() + static_cast<std::ptrdiff_t>(runAt) + 1, extra.begin(), extra.end());
    return args;
  }

  /// Run and return the exit code (see kRunHelp).
  int execute() {
    namespace batch = roiclip::batch;
    batch::BatchOptions options;
    try {
      options.inputs = {input_};
      options.output = output_;
      options.jobs = jobs_;
      options.recursive = recursive_;
      options.force = force_;
      options.writeMasks = masks_;
      options.writeReport = !noReport_;
      batch::RunOptions& p = options.process;
      p.rois = {roi_};
      p.boardFile = board_;
      p.detector.family = family_;
      p.detector.quadDecimate = decimate_;
      batch::parseContourMethod(method_, p.contours);
      p.contours.polarity = batch::parsePolarity(polarity_);
      p.contours.approxEpsilon = approx_;
      p.contours.minArea = minArea_;
      p.contours.openEdges = edges_;
      p.subjectFillRule = roiclip::parseFillRule(fillRule_.c_str());
      p.roiFillRule = roiclip::parseFillRule(roiFillRule_.c_str());
      p.maxPixels = maxPixels_;
    } catch (const roiclip::InvalidInputError& e) {
      std::cerr << "roiclip run: error: " << e.what() << "\n";
      return roiclip::app::kExitBadInput;
    }

    std::signal(SIGINT, run_detail::onSignal);
    std::signal(SIGTERM, run_detail::onSignal);
    const bool tty = ::isatty(STDERR_FILENO) != 0;
    const auto progress = [this, tty](const batch::Progress& s) {
      if (quiet_) return;
      const double rate = s.elapsed > 0 ? static_cast<double>(s.done) / s.elapsed : 0.0;
      const double eta = rate > 0 ? static_cast<double>(s.total - s.done) / rate : 0.0;
      std::ostringstream line;
      line << std::fixed << std::setprecision(1);
      if (tty) {
        constexpr int kWidth = 28;
        const int filled = static_cast<int>(kWidth * s.done / std::max<std::size_t>(s.total, 1));
        line << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
             << std::string(static_cast<std::size_t>(kWidth - filled), '.') << "] " << s.done << "/"
             << s.total << "  " << rate << " img/s  ETA " << eta << " s  failed " << s.failed
             << "\x1b[K";
        if (s.done == s.total) line << "\n";
      } else {
        line << "[" << s.done << "/" << s.total << "] " << s.last->image << " "
             << (s.last->skipped ? "skipped (up to date)" : batch::toString(s.last->status));
        if (!s.last->reason.empty()) line << " (" << s.last->reason << ")";
        line << "  " << rate << " img/s, ETA " << eta << " s\n";
      }
      std::cerr << line.str() << std::flush;
    };

    batch::RunSummary summary;
    try {
      summary = batch::run(options, progress, &run_detail::gCancel);
    } catch (const roiclip::InvalidInputError& e) {
      std::cerr << "roiclip run: error: " << e.what() << "\n";
      return roiclip::app::kExitBadInput;
    } catch (const roiclip::Error& e) {
      std::cerr << "roiclip run: error: " << e.what() << "\n";
      return roiclip::app::kExitCannotWrite;
    }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);

    if (tty && !quiet_ && summary.interrupted) std::cerr << "\n";
    std::cerr << "roiclip run: " << summary.images.size() << " of " << summary.total
              << " images: " << summary.ok << " ok (" << summary.skipped << " up to date), "
              << summary.noRoi << " no-roi, " << summary.failed << " failed, " << summary.mismatched
              << " mask-mismatch in " << std::fixed << std::setprecision(2) << summary.seconds
              << " s; summary in " << (options.output / "summary.csv").string() << "\n";
    for (const auto& r : summary.images) {
      if (r.status != batch::Status::Ok) {
        std::cerr << "  " << r.image << ": " << batch::toString(r.status) << ": " << r.reason
                  << "\n";
      }
    }
    if (summary.interrupted) {
      std::cerr << "roiclip run: interrupted; run again to finish the remaining images\n";
      return roiclip::app::kExitInterrupted;
    }
    if (summary.total == 0) {
      std::cerr << "roiclip run: error: no images found in " << input_ << "\n";
      return roiclip::app::kExitBadInput;
    }
    return summary.allOk() ? roiclip::app::kExitOk : roiclip::app::kExitImagesFailed;
  }

 private:
  CLI::App* cmd_ = nullptr;
  std::string input_ = "images";
  std::string output_ = "out";
  std::string config_;
  std::string roi_ = "hull";
  std::string board_;
  std::string family_ = "tag36h11";
  float decimate_ = 1.0f;
  std::string method_ = "otsu";
  std::string polarity_ = "dark";
  double approx_ = 0.0;
  double minArea_ = 0.0;
  std::string fillRule_ = "evenodd";
  std::string roiFillRule_ = "evenodd";
  std::int64_t maxPixels_ = roiclip::batch::kDefaultMaxPixels;
  int jobs_ = 0;
  bool recursive_ = false;
  bool force_ = false;
  bool masks_ = false;
  bool edges_ = false;
  bool noReport_ = false;
  bool quiet_ = false;
};
