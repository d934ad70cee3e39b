// roiclip::batch::run() and `roiclip run`: the bundled images end to end, resumability,
// interruption, recursion, and every failure path (corrupt file, empty folder, no tags, missing
// id, unwritable output folder) with the documented exit codes.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <thread>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
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
#include "read_text.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
namespace rb = roiclip::batch;
using Json = nlohmann::json;

namespace {

const fs::path kImages = ROICLIP_IMAGES;
const fs::path kData = ROICLIP_TEST_DATA;

using roiclip::testing::TempDir;

using roiclip::testing::readText;

Json readJson(const fs::path& file) { return Json::parse(readText(file)); }

void copyScene(const std::string& scene, const fs::path& to) {
  fs::create_directories(to.parent_path());
  fs::copy_file(kImages / (scene + ".png"), to, fs::copy_options::overwrite_existing);
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Files whose name starts with '.' (our temporary files) anywhere under `dir`.
int hiddenFiles(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.path().filename().string()[0] == '.') ++n;
  }
  return n;
}

rb::BatchOptions optionsFor(const fs::path& input, const fs::path& output) {
  rb::BatchOptions o;
  o.input = input;
  o.output = output;
  o.jobs = 2;
  return o;
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

TEST(BatchRun, ConfigToArguments) {
  const auto args = rb::configToArguments(
      R"({"roi": "tags:0,1,2,3", "jobs": 2, "force": true, "masks": false, "approx": 1.5})");
  const std::vector<std::string> expected = {"--approx", "1.5",   "--force",     "--jobs",
                                             "2",        "--roi", "tags:0,1,2,3"};
  EXPECT_EQ(args, expected);
  EXPECT_THROW(rb::configToArguments("[1, 2]"), roiclip::InvalidInputError);
  EXPECT_THROW(rb::configToArguments("{oops"), roiclip::InvalidInputError);
  EXPECT_THROW(rb::configToArguments(R"({"roi": {"a": 1}})"), roiclip::InvalidInputError);
}

#ifdef ROICLIP_CLI
// Exit code of `roiclip ARGS` (stdout/stderr to files in `dir`).
int cli(const std::string& args, const fs::path& dir) {
  const std::string cmd = std::string("'") + ROICLIP_CLI + "' " + args + " >'" +
                          (dir / "stdout.txt").string() + "' 2>'" + (dir / "stderr.txt").string() +
                          "'";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(BatchCli, ExitCodes) {
  const TempDir tmp("cli");
  const fs::path t = tmp.path();
  copyScene("scene_07", t / "in" / "a.png");
  const std::string in = "'" + (t / "in").string() + "'";
  const std::string out = " -o '" + (t / "out").string() + "'";
  EXPECT_EQ(cli("run " + in + out + " --jobs 1", t), 0) << readText(t / "stderr.txt");
  EXPECT_NE(readText(t / "stderr.txt").find("[1/1] a.png ok"), std::string::npos)
      << "plain progress lines when not a terminal";
  EXPECT_EQ(cli("run " + in + out, t), 0);
  EXPECT_NE(readText(t / "stderr.txt").find("skipped (up to date)"), std::string::npos);

  // Other options: the outputs are not up to date for them, so the image is processed again.
  EXPECT_EQ(cli("run " + in + out + " --roi tags:0,1,2,9", t), 5);
  EXPECT_EQ(cli("run " + in + out + " --roi tags:0,1,2,9 --force", t), 5);
  EXPECT_EQ(cli("run " + in + out + " --roi nonsense", t), 2);
  EXPECT_EQ(cli("run " + in + out + " --method sobel", t), 2);
  EXPECT_EQ(cli("run " + in + out + " --roi board:inspection", t), 2);  // no --board
  EXPECT_EQ(cli("run '" + (t / "nowhere").string() + "'" + out, t), 2);
  fs::create_directories(t / "empty");
  EXPECT_EQ(cli("run '" + (t / "empty").string() + "'" + out, t), 2);
  std::ofstream(t / "file") << "x";
  EXPECT_EQ(cli("run " + in + " -o '" + (t / "file" / "out").string() + "'", t), 3);

  fs::copy_file(kData / "batch" / "corrupt.png", t / "in" / "b.png");
  EXPECT_EQ(cli("run " + in + out, t), 5);
  EXPECT_NE(readText(t / "stderr.txt").find("b.png: failed"), std::string::npos);
  fs::remove(t / "in" / "b.png");

  // --max-pixels: refused from the header, reported as too-large; 0 lifts the limit. The limit
  // guards decoding and changes no result, so up-to-date images are still skipped.
  EXPECT_EQ(cli("run " + in + out + " --max-pixels 1000", t), 0);
  EXPECT_EQ(cli("run " + in + out + " --max-pixels 1000 --force", t), 5);
  EXPECT_NE(readText(t / "out" / "summary.csv").find("a.png,failed,too-large,"), std::string::npos);
  EXPECT_EQ(cli("run " + in + out + " --max-pixels 0", t), 0);
  EXPECT_EQ(cli("run " + in + out + " --max-pixels -1", t), 1);

  // --config: its options apply, the command line wins.
  std::ofstream(t / "run.json") << R"({"roi": "tags:0,1,2,9", "force": true, "jobs": 1})";
  const std::string config = " --config '" + (t / "run.json").string() + "'";
  EXPECT_EQ(cli("run " + in + out + config, t), 5);
  EXPECT_EQ(cli("run " + in + out + config + " --roi hull", t), 0);
  std::ofstream(t / "bad.json") << "{not json";
  EXPECT_EQ(cli("run " + in + out + " --config '" + (t / "bad.json").string() + "'", t), 2);

  EXPECT_EQ(cli("run --help", t), 0);
  EXPECT_EQ(cli("--help", t), 0);
  EXPECT_NE(readText(t / "stdout.txt").find("run"), std::string::npos);
  EXPECT_EQ(cli("run --help", t), 0);
  const std::string help = readText(t / "stdout.txt");
  for (const char* needle : {"Exit codes", "--roi", "board:inspection", "--jobs", "--force",
                             "--recursive", "--config", "--max-pixels", "130"}) {
    EXPECT_NE(help.find(needle), std::string::npos) << needle;
  }
}

// Ctrl-C: SIGINT after the first image. The run stops taking images, writes the summary of
// what it finished, exits 130 and leaves no partial or temporary files; a second run finishes.
TEST(BatchCli, CtrlCThenResume) {
  const TempDir tmp("sigint");
  const fs::path t = tmp.path();
  for (int i = 0; i < 6; ++i)
    copyScene("scene_0" + std::to_string(i + 1), t / "in" / ("s" + std::to_string(i) + ".png"));
  const std::string errFile = (t / "stderr.txt").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int fd = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDERR_FILENO);
    const std::string in = (t / "in").string();
    const std::string out = (t / "out").string();
    ::execl(ROICLIP_CLI, ROICLIP_CLI, "run", in.c_str(), "-o", out.c_str(), "--jobs", "1",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (readText(errFile).find("[1/6]") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << readText(errFile);
  const fs::path out = t / "out";
  EXPECT_EQ(hiddenFiles(out), 0);
  const Json summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["interrupted"], true);
  const std::size_t finished = summary["images"].size();
  EXPECT_GE(finished, 1u);
  EXPECT_LT(finished, 6u);
  int jsons = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string f = e.path().filename().string();
    if (f.size() > 5 && f.compare(f.size() - 5, 5, ".json") == 0 && f != "summary.json") {
      EXPECT_EQ(readJson(e.path())["status"], "ok") << f;  // every file there is complete
      EXPECT_TRUE(fs::exists(out / (e.path().stem().string() + ".overlay.png"))) << f;
      ++jsons;
    }
  }
  EXPECT_EQ(static_cast<std::size_t>(jsons), finished);

  EXPECT_EQ(cli("run '" + (t / "in").string() + "' -o '" + out.string() + "'", t), 0);
  const Json resumed = readJson(out / "summary.json");
  EXPECT_EQ(resumed["ok"], 6);
  EXPECT_EQ(resumed["skipped"].get<std::size_t>(), finished);
}
#endif

}  // namespace
