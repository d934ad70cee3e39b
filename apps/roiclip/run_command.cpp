// SPDX-License-Identifier: MIT
// `roiclip run`: option setup, checks, the run with its progress, and the summary.
#include "run_command.hpp"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>

#include <roiclip/apriltag/roi.hpp>

#include "config_json.hpp"
#include "exit_codes.hpp"
#include "progress_line.hpp"

namespace roiclip::app {

namespace {

// Set by SIGINT/SIGTERM; the run stops starting images and finishes the ones in flight.
std::atomic<bool> cancelRequested{false};

void onSignal(int) {
  if (cancelRequested.exchange(true))
    std::_Exit(kExitInterrupted);  // second Ctrl-C: stop now (temp files are hidden)
}

constexpr const char* kRunHelp = R"(
Per image: read it (PNG, JPEG, TIFF, BMP, ...; 8/16-bit or float; gray, gray+alpha, colour;
PNG/JPEG/TIFF/WebP headers are checked against --max-pixels before decoding), detect AprilTags,
build the ROIs, find contours (RETR_CCOMP: every outer contour with its holes), clip each one
exactly against the region, and check the vector result against the raster route (subject mask
AND region mask) off a boundary band. Writes into the output folder, each file atomically:
  NAME.json           tags, ROIs, every clipped polygon with holes, areas, mask-check figures
  NAME.overlay.png    image dimmed outside the region, ROI outlines, clipped regions, tag ids
  NAME.mask.png       clipped region as a mask (with --masks)
  summary.csv         one row per image and ROI
  summary.json, report.html   the same rows with run totals / overlays to look through
Images whose outputs are complete, newer than the image and made with the same options are
skipped (use --force to redo them). Bad options and an input folder without images are refused
before the output folder is created.

ROI specs (--roi, repeatable: each one is a region of its own, with its own row in summary.csv;
the image's region is their union):
  hull                convex hull of all detected tags (the default)
  hull:0,2,5          convex hull of those tags
  tags:0,1,2,3        polygon through the tag centres, in that order
  tags:22@top-left,24@top-right,25@bottom-right,23@bottom-left
                      polygon through each tag's own corner (centre, top-left, top-right,
                      bottom-right, bottom-left); tags:0,1,2,3@top-left: that corner of each
  board               every ROI of the board file (--board), each a region of its own
  board:NAME          the board ROI NAME
  tag:5:0.5,-0.5;2.5,-0.5;2.5,0.5;0.5,0.5   polygon in tag 5's frame (unit = tag side)
The tags are not objects: every detected tag's quad, grown by --tag-margin px, is cut out of the
region (--keep-tags keeps them in). An id listed twice, an id the tag family does not have and
a ROI given twice are refused.

Config file (--config FILE): a JSON object of these options, keys the long names without "--",
values strings, numbers, true/false for flags, arrays for --roi; the command line wins:
  {"roi": ["board:inspection", "hull"], "board": "images/board.json", "jobs": 2}

Examples:
  roiclip run images --output out
  roiclip run images -o out --roi board:inspection --board images/board.json --jobs 2
  roiclip run photos -o out --recursive --method adaptive --min-area 20 --masks
  roiclip run photos -o out --roi tags:0,1,2,3 --roi hull --tag-margin 4
  roiclip run photos -o out --config run.json --force

)";

// A check of a number option with a plain message ("must be >= 0, got -5"). Text that is not a
// number passes: converting it fails next, as a usage error.
CLI::Validator numberRule(bool (*ok)(double), const std::string& rule) {
  return CLI::Validator(
      [ok, rule](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value)) return {};
        return ok(value) ? std::string() : "must be " + rule + ", got " + text;
      },
      "");
}

CLI::Validator atLeastZero() {
  return numberRule([](double v) { return std::isfinite(v) && v >= 0; }, ">= 0");
}

// An option whose text a library function parses into a field (parseFillRule, parsePolarity,
// parseContourMethod): text it refuses is a ValidationError with the library's message; the
// default shown is the field's value as the library spells it.
CLI::Option* addParsed(CLI::App* cmd, const std::string& name,
                       std::function<void(const std::string&)> parse, const std::string& shown,
                       const std::string& help) {
  return cmd
      ->add_option_function<std::string>(
          name,
          [name, parse](const std::string& text) {
            try {
              parse(text);
            } catch (const InvalidInputError& e) {
              throw CLI::ValidationError(name, e.what());
            }
          },
          help)
      ->default_str(shown);
}

std::string methodText(const batch::ContourOptions& c) {
  const std::string name = batch::toString(c.method);
  return c.method == batch::ContourMethod::Threshold ? name + ":" + std::to_string(c.threshold)
                                                     : name;
}

// While it exists, SIGINT and SIGTERM ask the run to stop (cancelRequested).
class CancelOnSignal {
 public:
  CancelOnSignal() {
    cancelRequested = false;
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
  }
  ~CancelOnSignal() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
  CancelOnSignal(const CancelOnSignal&) = delete;
  CancelOnSignal& operator=(const CancelOnSignal&) = delete;
};

void printSummary(const batch::RunSummary& summary, const batch::BatchOptions& options) {
  std::cerr << "roiclip run: " << summary.images.size() << " of " << summary.total
            << " images: " << summary.ok << " ok (" << summary.skipped << " up to date), "
            << summary.noRoi << " no-roi, " << summary.failed << " failed, " << summary.mismatched
            << " mask-mismatch in " << std::fixed << std::setprecision(2) << summary.seconds
            << " s; summary in " << (options.output / "summary.csv").string() << "\n";
  for (const auto& r : summary.images) {
    if (r.status != batch::Status::Ok) {
      std::cerr << "  " << r.image << ": " << batch::toString(r.status) << ": " << r.reason << "\n";
    }
  }
}

}  // namespace

RunCommand::RunCommand(CLI::App& app) {
  // The app's own defaults (the library has none for the folders).
  options_.inputs = {"images"};
  options_.output = "out";
  batch::RunOptions& p = options_.process;
  apriltag::DetectorOptions& d = p.detector;
  batch::ContourOptions& c = p.contours;

  cmd_ = app.add_subcommand("run", "process a folder of images (AprilTag ROI + contours)");
  cmd_->footer(kRunHelp + exitCodesHelp(ExitCodesOf::Run));
  cmd_->add_option("inputs", options_.inputs,
                   "folders, image or video files, globs, list files (.txt/.lst/.list: one path "
                   "per line, relative to the list, # comments)")
      ->default_str("images");
  cmd_->add_option("-o,--output", options_.output, "output folder")
      ->default_str(options_.output.string());

  // CLI11 reads config files on the main app only, before any option's callback: `run --config`
  // hands its file to the main app's config option (hidden from the main help) as soon as it is
  // parsed, and ConfigJson routes the file's items to `run`.
  config_ = app.set_config("--config", "", "JSON file of `roiclip run` options")->group("");
  app.config_formatter(std::make_shared<ConfigJson>(*cmd_));
  cmd_->add_option_function<std::string>(
          "--config", [this](const std::string& file) { config_->add_result(file); },
          "JSON file of options (see below)")
      ->trigger_on_parse()
      ->configurable(false);

  cmd_->add_option("--roi", p.rois, "ROI spec (see below); repeat for several ROIs")
      ->allow_extra_args(false)
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            try {
              (void)apriltag::parseRoiSpec(text);
              return {};
            } catch (const InvalidInputError& e) {
              return e.what();
            }
          },
          ""))
      ->capture_default_str();
  cmd_->add_option("--board", p.boardFile, "board JSON file for board ROIs");
  cmd_->add_option("--tag-margin", p.tagMargin,
                   "grow each tag quad cut out of the region by this many px")
      ->check(atLeastZero())
      ->capture_default_str();
  cmd_->add_flag("--keep-tags", p.keepTags, "keep the tags in the region (do not cut them out)");
  cmd_->add_option("--family", d.family, "tag family, or several separated by commas")
      ->capture_default_str();
  cmd_->add_option("--decimate", d.quadDecimate,
                   "AprilTag quad decimation: 0 = automatic from the image size, or a factor >= 1")
      ->check(numberRule([](double v) { return v == 0 || (std::isfinite(v) && v >= 1); },
                         "0 (automatic) or >= 1"))
      ->capture_default_str();
  cmd_->add_option("--max-hamming", d.maxHamming,
                   "reject tags decoded with more corrected bit errors (0..3)")
      ->check(numberRule([](double v) { return v >= 0 && v <= 3; }, "in 0..3"))
      ->capture_default_str();
  cmd_->add_option("--min-margin", d.minDecisionMargin,
                   "reject tags with a lower AprilTag decision margin")
      ->check(atLeastZero())
      ->capture_default_str();

  addParsed(
      cmd_, "--method", [&c](const std::string& t) { batch::parseContourMethod(t, c); },
      methodText(c), "contours: otsu|adaptive|canny|threshold:T");
  addParsed(
      cmd_, "--polarity", [&c](const std::string& t) { c.polarity = batch::parsePolarity(t); },
      batch::toString(c.polarity), "objects are dark|light");
  cmd_->add_option("--approx", c.approxEpsilon, "approxPolyDP epsilon in px (0 = off)")
      ->check(atLeastZero())
      ->capture_default_str();
  cmd_->add_option("--min-area", c.minArea, "drop outer contours smaller than this (px^2)")
      ->check(atLeastZero())
      ->capture_default_str();
  addParsed(
      cmd_, "--fill-rule",
      [&p](const std::string& t) { p.subjectFillRule = parseFillRule(t.c_str()); },
      toString(p.subjectFillRule), "fill rule of the contours");
  addParsed(
      cmd_, "--roi-fill-rule",
      [&p](const std::string& t) { p.roiFillRule = parseFillRule(t.c_str()); },
      toString(p.roiFillRule), "fill rule of the ROI");
  cmd_->add_option("--every", options_.every, "videos: process frames 0, N, 2N, ...")
      ->check(numberRule([](double v) { return v >= 1; }, ">= 1"))
      ->capture_default_str();
  cmd_->add_option_function<std::string>(
      "--shard", [this](const std::string& text) { options_.shard = batch::parseShard(text); },
      "process only shard I of N (0 <= I < N): the inputs whose FNV-1a 64 hash of the relative "
      "path is I mod N; I = 0..N-1 cover every input once (Slurm array, Kubernetes indexed "
      "Job, GNU parallel)");
  cmd_->add_option("--coco", options_.coco,
                   "also write the whole run as COCO instance annotations to this file "
                   "(docs/outputs.md)");
  cmd_->add_option("--max-pixels", p.maxPixels,
                   "refuse images with more pixels (width x height; read from the file's "
                   "header before decoding; 0 = no limit)")
      ->check(atLeastZero())
      ->capture_default_str();
  cmd_->add_option("--max-crossings", p.limits.maxCrossings,
                   "fail an image (too-large) when one of its clips finds more crossings (each "
                   "takes 200 to 320 bytes while it runs)")
      ->capture_default_str();

  cmd_->add_option("-j,--jobs", options_.jobs, "images in parallel (0 = all cores)")
      ->check(atLeastZero())
      ->capture_default_str();
  cmd_->add_flag("-r,--recursive", options_.recursive,
                 "descend into sub-folders (mirrored in output)");
  cmd_->add_flag("-f,--force", options_.force, "reprocess images whose outputs are up to date");
  cmd_->add_flag("--masks", options_.writeMasks, "also write NAME.mask.png");
  cmd_->add_flag("!--no-overlay", options_.writeOverlays,
                 "do not write NAME.overlay.png (NAME.json and the summaries only)");
  cmd_->add_flag("--edges", c.openEdges, "also clip Canny edges as open polylines (in NAME.json)");
  cmd_->add_flag_callback(
      "--no-report", [this] { options_.writeReport = false; }, "do not write report.html");
  cmd_->add_flag("-q,--quiet", quiet_, "no progress output");
}

std::optional<int> RunCommand::badInputExit(const CLI::ParseError& error) const {
  if (!cmd_->parsed()) return std::nullopt;
  const std::string file = config_->count() > 0 ? config_->results().back() : "config file";
  if (dynamic_cast<const ConfigFileError*>(&error) != nullptr) {
    std::cerr << "roiclip run: error: " << file << ": " << error.what() << "\n";
  } else if (dynamic_cast<const CLI::FileError*>(&error) != nullptr) {
    std::cerr << "roiclip run: error: " << file << ": cannot read the config file\n";
  } else if (dynamic_cast<const CLI::ValidationError*>(&error) != nullptr) {
    std::cerr << "roiclip run: error: " << error.what() << "\n";
  } else {
    return std::nullopt;
  }
  return kExitBadInput;
}

int RunCommand::execute() const {
  try {
    if (batch::checkRun(options_) == 0) {
      std::string inputs;
      for (const auto& input : options_.inputs)
        inputs += (inputs.empty() ? "" : " ") + input.string();
      std::cerr << "roiclip run: error: no images found in " << inputs << "\n";
      return kExitBadInput;
    }
  } catch (const InvalidInputError& e) {
    std::cerr << "roiclip run: error: " << e.what() << "\n";
    return kExitBadInput;
  }

  batch::RunSummary summary;
  try {
    const CancelOnSignal cancel;
    std::optional<ProgressLine> progress;
    if (!quiet_) progress.emplace(::isatty(STDERR_FILENO) != 0);
    summary = batch::run(
        options_,
        [&progress](const batch::Progress& s) {
          if (progress) progress->show(s);
        },
        &cancelRequested);
  } catch (const InvalidInputError& e) {
    std::cerr << "roiclip run: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const Error& e) {
    std::cerr << "roiclip run: error: " << e.what() << "\n";
    return kExitCannotWrite;
  }
  printSummary(summary, options_);
  if (summary.interrupted) {
    std::cerr << "roiclip run: interrupted; run again to finish the remaining images\n";
    return kExitInterrupted;
  }
  return summary.allOk() ? kExitOk : kExitImagesFailed;
}

}  // namespace roiclip::app
