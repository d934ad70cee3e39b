// SPDX-License-Identifier: MIT
// roiclip::batch::run(): the bundled images end to end, resumability, interruption, recursion,
// and every failure path (corrupt file, empty folder, no tags, missing id, unwritable output
// folder); checkRun(). `roiclip run` itself is tested in tests/apps.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <roiclip/batch/run.hpp>
#include <roiclip/io/atomic_file.hpp>

#include "detail/folder.hpp"
#include "detail/report.hpp"
#include "support/run_files.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
namespace rb = roiclip::batch;
using Json = nlohmann::json;

namespace {

const fs::path kImages = ROICLIP_IMAGES;
const fs::path kData = ROICLIP_TEST_DATA;

using roiclip::testing::TempDir;

using roiclip::testing::copyScene;
using roiclip::testing::hiddenFiles;
using roiclip::testing::lines;
using roiclip::testing::readJson;
using roiclip::testing::readText;

rb::BatchOptions optionsFor(const fs::path& input, const fs::path& output) {
  rb::BatchOptions o;
  o.inputs = {input};
  o.output = output;
  o.jobs = 2;
  return o;
}

TEST(BatchRun, NoOverlayWritesTheRecordsOnlyAndStillResumes) {
  const TempDir tmp("no_overlay");
  copyScene("scene_01", tmp.path() / "in" / "scene_01.png");
  copyScene("scene_02", tmp.path() / "in" / "scene_02.png");
  rb::BatchOptions o = optionsFor(tmp.path() / "in", tmp.path() / "out");
  o.writeOverlays = false;
  const rb::RunSummary first = rb::run(o);
  ASSERT_TRUE(first.allOk());
  EXPECT_TRUE(fs::exists(tmp.path() / "out" / "scene_01.json"));
  EXPECT_FALSE(fs::exists(tmp.path() / "out" / "scene_01.overlay.png"));
  EXPECT_FALSE(fs::exists(tmp.path() / "out" / "scene_02.overlay.png"));
  const std::string html = readText(tmp.path() / "out" / "report.html");
  EXPECT_EQ(html.find(".overlay.png"), std::string::npos);
  EXPECT_NE(html.find("no overlay (--no-overlay)"), std::string::npos);
  // Without overlays the JSON alone marks an image as done.
  const rb::RunSummary again = rb::run(o);
  EXPECT_EQ(again.skipped, 2u);
  // Asking for overlays again redoes the images (their overlays are missing).
  o.writeOverlays = true;
  const rb::RunSummary withOverlays = rb::run(o);
  EXPECT_EQ(withOverlays.skipped, 0u);
  EXPECT_TRUE(fs::exists(tmp.path() / "out" / "scene_01.overlay.png"));
}

TEST(BatchRun, BundledImagesEndToEnd) {
  const TempDir tmp("bundled");
  rb::BatchOptions options = optionsFor(kImages, tmp.path() / "out");
  options.writeMasks = true;
  std::size_t progressCalls = 0;
  const rb::RunSummary s = rb::run(options, [&](const rb::Progress& p) {
    ++progressCalls;
    EXPECT_EQ(p.done, progressCalls);
    EXPECT_EQ(p.total, 8u);
  });
  EXPECT_EQ(progressCalls, 8u);
  EXPECT_EQ(s.total, 8u);
  EXPECT_EQ(s.ok, 8u);
  EXPECT_TRUE(s.allOk());
  const fs::path out = tmp.path() / "out";
  for (int i = 1; i <= 8; ++i) {
    const std::string name = "scene_0" + std::to_string(i);
    const cv::Mat image = cv::imread((kImages / (name + ".png")).string(), cv::IMREAD_UNCHANGED);
    const Json j = readJson(out / (name + ".json"));
    EXPECT_EQ(j["status"], "ok") << name;
    EXPECT_EQ(j["image"], name + ".png");
    EXPECT_EQ(j["tags"].size(), 4u) << name;
    EXPECT_EQ(j["mask_check"]["off_band_mismatches"], 0) << name;
    EXPECT_EQ(j["mask_check"]["opencv"]["agrees_off_band"], true) << name;
    EXPECT_GT(j["clipped_area"].get<double>(), 0.0);
    const cv::Mat overlay = cv::imread((out / (name + ".overlay.png")).string());
    ASSERT_FALSE(overlay.empty()) << name;
    EXPECT_EQ(overlay.cols, image.cols) << name;
    EXPECT_GT(overlay.rows, image.rows) << name;  // the caption band above the image
    const cv::Mat mask = cv::imread((out / (name + ".mask.png")).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(mask.type(), CV_8UC1);
    EXPECT_EQ(mask.size(), image.size());
  }
  const auto csv = lines(readText(out / "summary.csv"));
  ASSERT_EQ(csv.size(), 9u);
  EXPECT_EQ(csv[0], rb::detail::kSummaryColumns);
  EXPECT_EQ(csv[1].rfind("scene_01.png,ok,", 0), 0u) << csv[1];
  const Json summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["images"].size(), 8u);
  EXPECT_EQ(summary["ok"], 8);
  const std::string html = readText(out / "report.html");
  for (int i = 1; i <= 8; ++i) {
    EXPECT_NE(html.find("scene_0" + std::to_string(i) + ".overlay.png"), std::string::npos);
  }
  EXPECT_EQ(hiddenFiles(out), 0);
}

TEST(BatchRun, ResumeSkipsUpToDateOutputsAndForceRedoes) {
  const TempDir tmp("resume");
  copyScene("scene_07", tmp.path() / "in" / "a.png");
  copyScene("scene_08", tmp.path() / "in" / "b.png");
  rb::BatchOptions options = optionsFor(tmp.path() / "in", tmp.path() / "out");
  const rb::RunSummary first = rb::run(options);
  ASSERT_EQ(first.ok, 2u);
  EXPECT_EQ(first.skipped, 0u);

  const rb::RunSummary second = rb::run(options);
  EXPECT_EQ(second.ok, 2u);
  EXPECT_EQ(second.skipped, 2u);
  // Skipped rows carry the figures read back from NAME.json.
  EXPECT_DOUBLE_EQ(second.images[0].clippedArea, first.images[0].clippedArea);
  EXPECT_EQ(second.images[1].contoursIn, first.images[1].contoursIn);

  // A newer input is processed again.
  fs::last_write_time(tmp.path() / "in" / "b.png",
                      fs::file_time_type::clock::now() + std::chrono::hours(1));
  const rb::RunSummary third = rb::run(options);
  EXPECT_EQ(third.skipped, 1u);
  EXPECT_TRUE(third.images[0].skipped);
  EXPECT_FALSE(third.images[1].skipped);

  // An incomplete output (overlay gone) is processed again.
  fs::remove(tmp.path() / "out" / "a.overlay.png");
  fs::last_write_time(tmp.path() / "in" / "b.png",
                      fs::file_time_type::clock::now() - std::chrono::hours(1));
  const rb::RunSummary fourth = rb::run(options);
  EXPECT_FALSE(fourth.images[0].skipped);
  EXPECT_TRUE(fourth.images[1].skipped);
  EXPECT_TRUE(fs::exists(tmp.path() / "out" / "a.overlay.png"));

  // Changed options make the outputs stale.
  options.process.contours.minArea = 50.0;
  EXPECT_EQ(rb::run(options).skipped, 0u);
  EXPECT_EQ(rb::run(options).skipped, 2u);

  options.force = true;
  EXPECT_EQ(rb::run(options).skipped, 0u);
}

TEST(BatchRun, InterruptedRunLeavesCompleteFilesAndResumes) {
  const TempDir tmp("interrupt");
  for (const char* s : {"scene_06", "scene_07", "scene_08"}) {
    copyScene(s, tmp.path() / "in" / (std::string(s) + ".png"));
  }
  rb::BatchOptions options = optionsFor(tmp.path() / "in", tmp.path() / "out");
  options.jobs = 1;
  std::atomic<bool> cancel{false};
  // "Ctrl-C" right after the first image: the app's signal handler sets the same flag.
  const rb::RunSummary s = rb::run(
      options, [&](const rb::Progress&) { cancel = true; }, &cancel);
  EXPECT_TRUE(s.interrupted);
  EXPECT_FALSE(s.allOk());
  ASSERT_EQ(s.images.size(), 1u);
  const fs::path out = tmp.path() / "out";
  EXPECT_EQ(readJson(out / "scene_06.json")["status"], "ok");
  EXPECT_FALSE(fs::exists(out / "scene_07.json"));
  EXPECT_FALSE(fs::exists(out / "scene_08.overlay.png"));
  EXPECT_EQ(hiddenFiles(out), 0);
  EXPECT_EQ(lines(readText(out / "summary.csv")).size(), 2u);
  EXPECT_EQ(readJson(out / "summary.json")["interrupted"], true);

  const rb::RunSummary resumed = rb::run(options);
  EXPECT_FALSE(resumed.interrupted);
  EXPECT_EQ(resumed.ok, 3u);
  EXPECT_EQ(resumed.skipped, 1u);
  EXPECT_TRUE(resumed.images[0].skipped);
  EXPECT_TRUE(resumed.allOk());
}

TEST(BatchRun, CorruptFileFailsAndTheRunCarriesOn) {
  const TempDir tmp("corrupt");
  fs::create_directories(tmp.path() / "in");
  fs::copy_file(kData / "batch" / "corrupt.png", tmp.path() / "in" / "a_corrupt.png");
  copyScene("scene_07", tmp.path() / "in" / "b.png");
  const rb::RunSummary s = rb::run(optionsFor(tmp.path() / "in", tmp.path() / "out"));
  ASSERT_EQ(s.images.size(), 2u);
  EXPECT_EQ(s.failed, 1u);
  EXPECT_EQ(s.ok, 1u);
  EXPECT_EQ(s.images[0].status, rb::Status::Failed);
  EXPECT_EQ(s.images[0].failure, rb::FailureKind::Unreadable);
  EXPECT_NE(s.images[0].reason.find("a_corrupt.png"), std::string::npos) << s.images[0].reason;
  const Json j = readJson(tmp.path() / "out" / "a_corrupt.json");
  EXPECT_EQ(j["status"], "failed");
  EXPECT_EQ(j["failure"], "unreadable");
  EXPECT_FALSE(fs::exists(tmp.path() / "out" / "a_corrupt.overlay.png"));
  EXPECT_NE(readText(tmp.path() / "out" / "summary.csv").find("a_corrupt.png,failed,unreadable"),
            std::string::npos);
  // Failed images are retried on the next run, not skipped.
  EXPECT_EQ(rb::run(optionsFor(tmp.path() / "in", tmp.path() / "out")).skipped, 1u);
}

TEST(BatchRun, NoTagsAndMissingIdAreNoRoi) {
  const TempDir tmp("noroi");
  fs::create_directories(tmp.path() / "in");
  cv::Mat blank(200, 300, CV_8UC3, cv::Scalar(220, 220, 220));
  cv::rectangle(blank, cv::Rect(50, 50, 80, 60), cv::Scalar(20, 20, 20), cv::FILLED);
  ASSERT_TRUE(cv::imwrite((tmp.path() / "in" / "blank.bmp").string(), blank));
  copyScene("scene_07", tmp.path() / "in" / "tagged.png");
  rb::BatchOptions options = optionsFor(tmp.path() / "in", tmp.path() / "out");
  options.process.rois = {"tags:0,1,2,9"};
  const rb::RunSummary s = rb::run(options);
  ASSERT_EQ(s.images.size(), 2u);
  EXPECT_EQ(s.noRoi, 2u);
  EXPECT_EQ(s.images[0].failure, rb::FailureKind::NoTags);
  EXPECT_EQ(s.images[1].failure, rb::FailureKind::MissingTags);
  EXPECT_EQ(s.images[1].tagsFound, 4);
  const Json j = readJson(tmp.path() / "out" / "tagged.json");
  EXPECT_EQ(j["status"], "no-roi");
  EXPECT_EQ(j["missing_tags"]["missing"], Json::array({9}));
  // The overlay still shows what was found (tags), at the image's width (plus its caption band).
  EXPECT_EQ(cv::imread((tmp.path() / "out" / "blank.overlay.png").string()).cols, blank.cols);
  // no-roi is a final answer for these options: skipped on the next run, reason kept.
  const rb::RunSummary again = rb::run(options);
  EXPECT_EQ(again.skipped, 2u);
  EXPECT_EQ(again.noRoi, 2u);
  EXPECT_EQ(again.images[1].failure, rb::FailureKind::MissingTags);
  EXPECT_EQ(again.images[1].reason, s.images[1].reason);
}

TEST(BatchRun, EmptyFolderWritesAnEmptySummary) {
  const TempDir tmp("empty");
  fs::create_directories(tmp.path() / "in");
  std::ofstream(tmp.path() / "in" / "notes.txt") << "not an image";
  const rb::RunSummary s = rb::run(optionsFor(tmp.path() / "in", tmp.path() / "out"));
  EXPECT_EQ(s.total, 0u);
  EXPECT_EQ(lines(readText(tmp.path() / "out" / "summary.csv")).size(), 1u);
  EXPECT_THROW(rb::run(optionsFor(tmp.path() / "missing", tmp.path() / "out")),
               roiclip::InvalidInputError);
}

TEST(BatchRun, UnwritableOutputFolderThrows) {
  const TempDir tmp("unwritable");
  copyScene("scene_07", tmp.path() / "in" / "a.png");
  std::ofstream(tmp.path() / "file") << "a file, not a folder";
  EXPECT_THROW(rb::run(optionsFor(tmp.path() / "in", tmp.path() / "file" / "out")), roiclip::Error);
  EXPECT_THROW(roiclip::io::writeFileAtomically(tmp.path() / "file" / "x.json", "{}"),
               roiclip::Error);
}

TEST(BatchRun, RecursiveMirrorsFoldersInsideTheOutput) {
  const TempDir tmp("recursive");
  const fs::path in = tmp.path() / "in";
  copyScene("scene_07", in / "top.png");
  copyScene("scene_07", in / "a" / "x.png");
  copyScene("scene_08", in / "b" / "x.png");
  fs::create_directories(in / "b" / "c");
  const cv::Mat jpeg = cv::imread((kImages / "scene_08.png").string());
  ASSERT_TRUE(cv::imwrite((in / "b" / "c" / "y.jpg").string(), jpeg));
  copyScene("scene_07", in / "z.png");
  ASSERT_TRUE(cv::imwrite((in / "z.tif").string(), jpeg));

  const rb::RunSummary flat = rb::run(optionsFor(in, tmp.path() / "flat"));
  EXPECT_EQ(flat.total, 3u);                                    // top.png, z.png, z.tif
  EXPECT_TRUE(fs::exists(tmp.path() / "flat" / "z.png.json"));  // same stem: keep extensions
  EXPECT_TRUE(fs::exists(tmp.path() / "flat" / "z.tif.json"));
  EXPECT_TRUE(fs::exists(tmp.path() / "flat" / "top.json"));

  rb::BatchOptions options = optionsFor(in, tmp.path() / "deep");
  options.recursive = true;
  const rb::RunSummary deep = rb::run(options);
  EXPECT_EQ(deep.total, 6u);
  EXPECT_EQ(deep.ok, 6u);
  for (const char* f : {"a/x.json", "a/x.overlay.png", "b/x.json", "b/c/y.json", "top.json"}) {
    EXPECT_TRUE(fs::exists(tmp.path() / "deep" / f)) << f;
  }
  EXPECT_EQ(readJson(tmp.path() / "deep" / "b" / "c" / "y.json")["image"], "b/c/y.jpg");

  // Links: a linked file is an image of this folder (its output stays inside the output
  // folder); a linked folder is not followed (it could loop or lead anywhere).
  copyScene("scene_08", tmp.path() / "elsewhere" / "far.png");
  fs::create_directory_symlink(tmp.path() / "elsewhere", in / "linked_dir");
  fs::create_symlink(tmp.path() / "elsewhere" / "far.png", in / "a" / "link.png");
  rb::BatchOptions links = optionsFor(in.string() + "/", tmp.path() / "links");  // trailing '/'
  links.recursive = true;
  const rb::RunSummary linked = rb::run(links);
  EXPECT_EQ(linked.total, 7u);
  EXPECT_EQ(linked.ok, 7u);
  EXPECT_TRUE(fs::exists(tmp.path() / "links" / "a" / "link.json"));
  EXPECT_TRUE(fs::exists(tmp.path() / "links" / "top.json"));
  EXPECT_FALSE(fs::exists(tmp.path() / "links" / "linked_dir"));
  EXPECT_FALSE(fs::exists(tmp.path() / "elsewhere" / "far.json"));
  fs::remove(in / "linked_dir");
  fs::remove(in / "a" / "link.png");

  // An output folder inside the input folder is not read back as input.
  rb::BatchOptions nested = optionsFor(in, in / "out");
  nested.recursive = true;
  EXPECT_EQ(rb::run(nested).total, 6u);
  EXPECT_EQ(rb::run(nested).total, 6u);
  // ... while an output folder that contains the input folder takes nothing away.
  fs::remove_all(in / "out");
  rb::BatchOptions outer = optionsFor(in, tmp.path());
  outer.recursive = true;
  EXPECT_EQ(rb::run(outer).total, 6u);
}

TEST(BatchRun, ReadsSixteenBitAndColourFiles) {
  const TempDir tmp("types");
  const fs::path in = tmp.path() / "in";
  fs::create_directories(in);
  const cv::Mat gray = cv::imread((kImages / "scene_05.png").string(), cv::IMREAD_GRAYSCALE);
  cv::Mat gray16, bgr;
  gray.convertTo(gray16, CV_16U, 257.0);
  cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  ASSERT_TRUE(cv::imwrite((in / "g16.tif").string(), gray16));
  ASSERT_TRUE(cv::imwrite((in / "g16.png").string(), gray16));
  ASSERT_TRUE(cv::imwrite((in / "colour.jpg").string(), bgr));
  ASSERT_TRUE(cv::imwrite((in / "colour.bmp").string(), bgr));
  ASSERT_EQ(cv::imread((in / "g16.tif").string(), cv::IMREAD_UNCHANGED).depth(), CV_16U);
  const rb::RunSummary s = rb::run(optionsFor(in, tmp.path() / "out"));
  ASSERT_EQ(s.total, 4u);
  EXPECT_EQ(s.ok, 4u);
  for (const auto& r : s.images) {
    EXPECT_EQ(r.tagsFound, 4) << r.image;
    EXPECT_EQ(r.offBandMismatches, 0) << r.image;
    EXPECT_EQ(cv::imread((tmp.path() / "out" / (r.name + ".overlay.png")).string()).cols,
              gray.cols);
  }
  // 16-bit scaled back to 8 bits exactly: the same figures as the 8-bit colour BMP.
  EXPECT_DOUBLE_EQ(s.images[0].clippedArea, s.images[2].clippedArea);  // colour.bmp, g16.png
}

TEST(BatchRun, OutputNamesCannotEscape) {
  EXPECT_EQ(rb::detail::outputName("a/b/c.png"), "a/b/c");
  EXPECT_EQ(rb::detail::outputName("c.tar.png"), "c.tar");
  EXPECT_EQ(rb::detail::outputName("a/c.png", true), "a/c.png");
  for (const char* bad : {"../x.png", "a/../../x.png", "/etc/x.png", "./x.png", "a/./x.png", ""}) {
    EXPECT_THROW((void)rb::detail::outputName(bad), roiclip::InvalidInputError) << bad;
  }
}

// checkRun() refuses what run() would, and counts the images, without creating anything.
TEST(BatchRun, CheckRunCreatesNothing) {
  const TempDir tmp("check");
  copyScene("scene_07", tmp.path() / "in" / "a.png");
  copyScene("scene_08", tmp.path() / "in" / "b.png");
  rb::BatchOptions options = optionsFor(tmp.path() / "in", tmp.path() / "out");
  EXPECT_EQ(rb::checkRun(options), 2u);
  fs::create_directories(tmp.path() / "empty");
  EXPECT_EQ(rb::checkRun(optionsFor(tmp.path() / "empty", tmp.path() / "out")), 0u);
  EXPECT_THROW(rb::checkRun(optionsFor(tmp.path() / "missing", tmp.path() / "out")),
               roiclip::InvalidInputError);
  for (const char* bad : {"tags:0,0,0", "hull:0,5000", "board:inspection", "nonsense"}) {
    options.process.rois = {bad};
    EXPECT_THROW(rb::checkRun(options), roiclip::InvalidInputError) << bad;
  }
  options.process.rois = {"hull", "hull"};
  EXPECT_THROW(rb::checkRun(options), roiclip::InvalidInputError);
  options.process.rois = {"hull"};
  options.process.detector.quadDecimate = 0.5f;
  EXPECT_THROW(rb::checkRun(options), roiclip::InvalidInputError);
  EXPECT_FALSE(fs::exists(tmp.path() / "out"));
}

}  // namespace
