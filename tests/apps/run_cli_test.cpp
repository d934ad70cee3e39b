// SPDX-License-Identifier: MIT
// `roiclip run` through the built binary (ROICLIP_CLI) on copies of the bundled scenes: exit
// codes, messages, nothing created on bad options, --config, several ROIs, tags cut out or kept,
// Ctrl-C and resume, other stderr output kept off the progress bar; and --version, help.
#include <fcntl.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <roiclip/batch/options.hpp>

#include "cli_support.hpp"
#include "exit_codes.hpp"
#include "support/run_files.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using roiclip::testing::CliRun;
using roiclip::testing::copyScene;
using roiclip::testing::hiddenFiles;
using roiclip::testing::lines;
using roiclip::testing::readJson;
using roiclip::testing::readText;

const fs::path kImages = ROICLIP_IMAGES;
const fs::path kData = ROICLIP_TEST_DATA;

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// Each test has in/a.png (scene_07: tags 0, 1, 2, 3) and `in` / `out` for the command line.
class RunCli : public roiclip::testing::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    copyScene("scene_07", dir_ / "in" / "a.png");
    in_ = quoted(dir_ / "in");
    out_ = " -o " + quoted(dir_ / "out");
  }
  // `run in -o out ARGS`
  [[nodiscard]] CliRun runIn(const std::string& args) const {
    return run("run " + in_ + out_ + " " + args);
  }
  [[nodiscard]] std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return quoted(dir_ / name);
  }
  // Bad input: exit 2, one line on stderr saying `problem`, no output folder.
  void expectRefused(const CliRun& r, const std::string& problem) const {
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << "output folder created: " << r.err;
  }

  std::string in_;
  std::string out_;
};

TEST_F(RunCli, ExitCodes) {
  const CliRun first = runIn("--jobs 1");
  EXPECT_EQ(first.exitCode, 0) << first.err;
  EXPECT_NE(first.err.find("[1/1] a.png ok"), std::string::npos)
      << "plain progress lines when not a terminal";
  const CliRun again = runIn("");
  EXPECT_EQ(again.exitCode, 0);
  EXPECT_NE(again.err.find("skipped (up to date)"), std::string::npos);

  // Other options: the outputs are not up to date for them, so the image is processed again.
  EXPECT_EQ(runIn("--roi tags:0,1,2,9").exitCode, 5);
  EXPECT_EQ(runIn("--roi tags:0,1,2,9 --force").exitCode, 5);
  EXPECT_EQ(runIn("--roi nonsense").exitCode, 2);
  EXPECT_EQ(runIn("--method sobel").exitCode, 2);
  EXPECT_EQ(runIn("--roi board:inspection").exitCode, 2);  // no --board
  EXPECT_EQ(run("run " + quoted(dir_ / "nowhere") + out_).exitCode, 2);
  EXPECT_EQ(runIn("--jobs many").exitCode, 1);
  EXPECT_EQ(runIn("--no-such-option").exitCode, 1);
  std::ofstream(dir_ / "file") << "x";
  EXPECT_EQ(run("run " + in_ + " -o " + quoted(dir_ / "file" / "out")).exitCode, 3);

  fs::copy_file(kData / "batch" / "corrupt.png", dir_ / "in" / "b.png");
  const CliRun corrupt = runIn("");
  EXPECT_EQ(corrupt.exitCode, 5);
  EXPECT_NE(corrupt.err.find("b.png: failed"), std::string::npos) << corrupt.err;
  fs::remove(dir_ / "in" / "b.png");

  // --max-pixels: refused from the header, reported as too-large; 0 lifts the limit. The limit
  // guards decoding and changes no result, so up-to-date images are still skipped.
  EXPECT_EQ(runIn("--max-pixels 1000").exitCode, 0);
  EXPECT_EQ(runIn("--max-pixels 1000 --force").exitCode, 5);
  EXPECT_NE(readText(dir_ / "out" / "summary.csv").find("a.png,failed,too-large,"),
            std::string::npos);
  EXPECT_EQ(runIn("--max-pixels 0").exitCode, 0);
  EXPECT_EQ(runIn("--max-pixels -1").exitCode, 2);  // a bad value, as for every other option
}

// Everything the run would refuse is refused before the output folder exists: exit 2 and one
// line naming the option and the problem in plain words.
// `merge` says what `run` over all the images would have said: 0 when every image is ok, 5
// (with OUT written) when one is not.
TEST_F(RunCli, MergeExitCodeFollowsTheImages) {
  ASSERT_EQ(runIn("").exitCode, 0);
  fs::create_directories(dir_ / "in2");
  fs::copy_file(kData / "batch" / "corrupt.png", dir_ / "in2" / "b.png");
  ASSERT_EQ(run("run " + quoted(dir_ / "in2") + " -o " + quoted(dir_ / "out2")).exitCode, 5);

  const CliRun good = run("merge " + quoted(dir_ / "m1") + " " + quoted(dir_ / "out"));
  EXPECT_EQ(good.exitCode, 0) << good.err;
  const CliRun bad = run("merge " + quoted(dir_ / "m2") + " " + quoted(dir_ / "out") + " " +
                         quoted(dir_ / "out2"));
  EXPECT_EQ(bad.exitCode, 5) << bad.err;
  EXPECT_NE(bad.out.find("1 ok"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("1 failed"), std::string::npos) << bad.out;
  const std::string summary = readText(dir_ / "m2" / "summary.csv");
  EXPECT_NE(summary.find("a.png,ok,"), std::string::npos) << summary;
  EXPECT_NE(summary.find("b.png,failed,"), std::string::npos) << summary;
  EXPECT_TRUE(fs::exists(dir_ / "m2" / "a.json"));
}

TEST_F(RunCli, BadOptionsLeaveNoOutputFolder) {
  const struct {
    std::string args;
    const char* problem;
  } cases[] = {
      {"--roi tags:0,0,0", "--roi: ROI 'tags:0,0,0': tag id 0 is listed twice"},
      {"--roi hull:0,5000", "tag id 5000 does not exist in tag36h11"},
      {"--roi hull --roi hull", "ROI 'hull' is given twice"},
      {"--roi nonsense", "--roi: ROI 'nonsense'"},
      {"--roi board:inspection", "needs a board file (--board)"},
      {"--roi board --board " + std::string(ROICLIP_TEST_DATA) + "/no_such_board.json",
       "no_such_board.json"},
      {"--decimate 0.5", "--decimate: must be 0 (automatic) or >= 1, got 0.5"},
      {"--min-area -5", "--min-area: must be >= 0, got -5"},
      {"--approx nan", "--approx: must be >= 0, got nan"},
      {"--tag-margin -1", "--tag-margin: must be >= 0, got -1"},
      {"--max-hamming 4", "--max-hamming: must be in 0..3, got 4"},
      {"--min-margin -0.5", "--min-margin: must be >= 0, got -0.5"},
      {"--max-pixels -1", "--max-pixels: must be >= 0, got -1"},
      {"--jobs -2", "--jobs: must be >= 0, got -2"},
      {"--family nope", "unknown AprilTag family 'nope'"},
      {"--family tag36h11,tag36h11", "listed twice"},
      {"--method sobel", "--method: contour method 'sobel'"},
      {"--method threshold:300", "threshold must be 0..255"},
      {"--polarity grey", "--polarity: polarity 'grey'"},
      {"--fill-rule sometimes", "--fill-rule:"},
      {"--roi-fill-rule sometimes", "--roi-fill-rule:"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    expectRefused(runIn(c.args), c.problem);
  }
  for (const char* wrongType : {"--jobs 1.5", "--max-hamming x", "--decimate fast"}) {
    const CliRun r = runIn(wrongType);
    EXPECT_EQ(r.exitCode, 1) << wrongType << ": " << r.err;  // not a number: a usage error
    EXPECT_FALSE(fs::exists(dir_ / "out")) << wrongType;
  }
}

TEST_F(RunCli, EmptyInputExitsTwoAndWritesNothing) {
  fs::create_directories(dir_ / "empty");
  std::ofstream(dir_ / "empty" / "notes.txt") << "not an image";
  const CliRun r = run("run " + quoted(dir_ / "empty") + out_);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("no images found in " + (dir_ / "empty").string()), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  // An existing output folder keeps its summaries.
  fs::create_directories(dir_ / "out");
  std::ofstream(dir_ / "out" / "summary.csv") << "earlier";
  EXPECT_EQ(run("run " + quoted(dir_ / "empty") + out_).exitCode, 2);
  EXPECT_EQ(readText(dir_ / "out" / "summary.csv"), "earlier");
}

TEST_F(RunCli, ConfigFile) {
  // Its options apply, the command line wins.
  const std::string config =
      " --config " + write("run.json", R"({"roi": "tags:0,1,2,9", "force": true, "jobs": 1})");
  EXPECT_EQ(runIn(config).exitCode, 5);
  EXPECT_EQ(runIn(config + " --roi hull").exitCode, 0);
  // Arrays are repeated options; null is not given; the input folder is a key too.
  const std::string rois = write("rois.json", R"({"roi": ["hull:0,1,2", "hull"], "masks": null,
                                                  "inputs": ")" +
                                                  (dir_ / "in").string() + "\"}");
  const CliRun fromFile = run("run -o " + quoted(dir_ / "out") + " --config " + rois);
  EXPECT_EQ(fromFile.exitCode, 0) << fromFile.err;
  EXPECT_EQ(lines(readText(dir_ / "out" / "summary.csv")).size(), 3u);
  fs::remove_all(dir_ / "out");

  // What a config file cannot say names the file and the key; nothing is created.
  const struct {
    const char* name;
    const char* text;
    const char* problem;
  } cases[] = {
      {"typo.json", R"({"roii": "hull"})", "typo.json: 'roii': no such option of `run`"},
      {"syntax.json", "{not json", "syntax.json: not valid JSON (at byte 3)"},
      {"list.json", "[1, 2]", "list.json: expected a JSON object of options"},
      {"flag.json", R"({"force": "yes"})", "flag.json: 'force': takes true or false"},
      {"nested.json", R"({"roi": {"kind": "hull"}})", "nested.json: 'roi': must be a string"},
      {"array.json", R"({"jobs": [1, 2]})", "array.json: 'jobs': takes one value"},
      {"nest.json", R"({"config": "other.json"})", "nest.json: 'config': cannot be set"},
      {"value.json", R"({"decimate": 0.5})", "--decimate: must be 0 (automatic) or >= 1"},
      {"ids.json", R"({"roi": "tags:0,0,0"})", "tag id 0 is listed twice"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    expectRefused(runIn("--config " + write(c.name, c.text)), c.problem);
  }
  expectRefused(runIn("--config " + quoted(dir_ / "missing.json")),
                "missing.json: cannot read the config file");
}

// Each --roi is a region of its own: one summary.csv row per image and ROI.
TEST_F(RunCli, RepeatableRoiGivesOneRowPerRoi) {
  const CliRun r = runIn("--roi hull:0,1,2 --roi hull --roi tags:0,1,2,3@top-left");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto csv = lines(readText(dir_ / "out" / "summary.csv"));
  ASSERT_EQ(csv.size(), 4u);
  EXPECT_NE(csv[1].find(",\"hull:0,1,2\","), std::string::npos) << csv[1];
  EXPECT_NE(csv[2].find(",hull,"), std::string::npos) << csv[2];
  EXPECT_NE(csv[3].find(",\"tags:0,1,2,3@top-left\","), std::string::npos) << csv[3];
  for (std::size_t i = 1; i < csv.size(); ++i) EXPECT_EQ(csv[i].rfind("a.png,ok,", 0), 0u);
  const Json j = readJson(dir_ / "out" / "a.json");
  EXPECT_EQ(j["rois"].size(), 3u);
}

// The tags are cut out of the region unless --keep-tags; --tag-margin cuts more.
TEST_F(RunCli, KeepTagsAndTagMarginChangeTheClippedArea) {
  const auto clipped = [this](const std::string& args) {
    const CliRun r = runIn("--force " + args);
    EXPECT_EQ(r.exitCode, 0) << args << ": " << r.err;
    const Json j = readJson(dir_ / "out" / "a.json");
    return std::make_pair(j.at("clipped_area").get<double>(), j.at("roi").at("area").get<double>());
  };
  const auto [cut, cutRoi] = clipped("");
  const auto [kept, keptRoi] = clipped("--keep-tags");
  const auto [margin, marginRoi] = clipped("--tag-margin 4");
  EXPECT_GT(kept, cut + 1000.0) << "the tags' black borders are contours inside the hull";
  EXPECT_GT(keptRoi, cutRoi);
  EXPECT_LT(marginRoi, cutRoi);
  EXPECT_LE(margin, cut);
}

TEST_F(RunCli, DetectorOptions) {
  const CliRun r =
      runIn("--family tag36h11,tag25h9 --max-hamming 1 --min-margin 5 --decimate 2 --jobs 1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Json j = readJson(dir_ / "out" / "a.json");
  EXPECT_EQ(j["tags"].size(), 4u);
  EXPECT_EQ(j["quad_decimate"].get<double>(), 2.0);
  EXPECT_EQ(j["detect_passes"].get<int>(), 1);
  // The automatic decimation (the default) is 1.5 for a 640 x 480 image.
  ASSERT_EQ(runIn("--force").exitCode, 0);
  const Json automatic = readJson(dir_ / "out" / "a.json");
  EXPECT_EQ(automatic["quad_decimate"].get<double>(), 1.5);
  EXPECT_EQ(automatic["detect_passes"].get<int>(), 1);
}

TEST_F(RunCli, Version) {
  const CliRun r = run("--version");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out, std::string("roiclip ") + ROICLIP_VERSION + "\n");
}

TEST_F(RunCli, HelpCommandPrintsTheHelpOfHelp) {
  EXPECT_EQ(run("help").out, run("--help").out);
  EXPECT_EQ(run("help run").out, run("run --help").out);
  EXPECT_EQ(run("help clip-lines").out, run("clip-lines --help").out);
  EXPECT_EQ(run("help").exitCode, 0);
  const CliRun unknown = run("help nope");
  EXPECT_EQ(unknown.exitCode, 1);
  EXPECT_NE(unknown.err.find("'nope'"), std::string::npos) << unknown.err;
  EXPECT_NE(run("--help").out.find("help"), std::string::npos);
}

// The help says what the command does, with the library's defaults and the one exit-code table.
TEST_F(RunCli, HelpMatchesBehaviour) {
  const CliRun r = run("run --help");
  EXPECT_EQ(r.exitCode, 0);
  const std::string& help = r.out;
  const roiclip::batch::RunOptions defaults;
  const std::vector<std::string> needles = {
      "tags:22@top-left,24@top-right,25@bottom-right,23@bottom-left",
      "--roi TEXT=[hull] ...",
      "repeat",
      "board               every ROI of the board file",
      "cut out of the\nregion (--keep-tags keeps them in)",
      "--keep-tags",
      "--tag-margin FLOAT=0",
      "--family TEXT=" + defaults.detector.family,
      "--decimate FLOAT=0 ",
      "0 = automatic",
      "--max-hamming INT=" + std::to_string(defaults.detector.maxHamming),
      "--min-margin FLOAT=0",
      "--max-pixels INT=" + std::to_string(defaults.maxPixels),
      "--method TEXT=otsu",
      "--fill-rule TEXT=evenodd",
      "--config",
      "board:inspection",
      "--jobs",
      "--recursive",
      "--force",
      roiclip::app::exitCodesHelp(roiclip::app::ExitCodesOf::Run)};
  for (const std::string& needle : needles) {
    EXPECT_NE(help.find(needle), std::string::npos) << needle;
  }
}

// A libpng warning (here an ancillary chunk with a bad CRC) is printed on a line of its own above
// the progress bar, which is then redrawn, rather than in the middle of the bar.
TEST_F(RunCli, OtherStderrOutputStaysOffTheProgressBar) {
  std::string png = readText(kImages / "scene_08.png");
  const std::string badText("\0\0\0\3tEXta\0b\0\0\0\0", 15);  // CRC 0: wrong
  png.insert(33, badText);                                    // after the signature and IHDR
  std::ofstream(dir_ / "in" / "b.png", std::ios::binary) << png;
  copyScene("scene_06", dir_ / "in" / "c.png");

  int terminal = -1;
  int child = -1;
  ASSERT_EQ(::openpty(&terminal, &child, nullptr, nullptr, nullptr), 0);
  const std::string in = (dir_ / "in").string();
  const std::string out = (dir_ / "out").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::dup2(child, STDERR_FILENO);
    ::close(terminal);
    ::execl(ROICLIP_CLI, ROICLIP_CLI, "run", in.c_str(), "-o", out.c_str(), "--jobs", "1",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(child);
  std::string screen;
  char buffer[4096];
  while (true) {
    const ssize_t n = ::read(terminal, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // EIO once the child has closed the terminal
    screen.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(terminal);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << screen;
  const std::size_t warning = screen.find("libpng warning: tEXt: CRC error");
  ASSERT_NE(warning, std::string::npos) << screen;
  EXPECT_EQ(screen.compare(warning - 4, 4, "\r\x1b[K"), 0)
      << "the bar is cleared before the warning: " << screen;
  const std::size_t bar = screen.find("\r\x1b[K[", warning);
  EXPECT_NE(bar, std::string::npos) << screen;
  EXPECT_EQ(screen.substr(warning, bar - warning).find('['), std::string::npos)
      << "the warning line holds no bar: " << screen;
  EXPECT_NE(screen.find("3/3"), std::string::npos) << screen;
}

// Ctrl-C: SIGINT after the first image. The run stops taking images, writes the summary of
// what it finished, exits 130 and leaves no partial or temporary files; a second run finishes.
TEST_F(RunCli, CtrlCThenResume) {
  for (int i = 0; i < 6; ++i)
    copyScene("scene_0" + std::to_string(i + 1), dir_ / "in" / ("s" + std::to_string(i) + ".png"));
  fs::remove(dir_ / "in" / "a.png");
  const std::string errFile = (dir_ / "progress.txt").string();
  const std::string in = (dir_ / "in").string();
  const std::string out = (dir_ / "out").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int fd = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDERR_FILENO);
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
  EXPECT_EQ(hiddenFiles(dir_ / "out"), 0);
  const Json summary = readJson(dir_ / "out" / "summary.json");
  EXPECT_EQ(summary["interrupted"], true);
  const std::size_t finished = summary["images"].size();
  EXPECT_GE(finished, 1u);
  EXPECT_LT(finished, 6u);
  int jsons = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "out")) {
    const std::string f = e.path().filename().string();
    if (f.size() > 5 && f.compare(f.size() - 5, 5, ".json") == 0 && f != "summary.json") {
      EXPECT_EQ(readJson(e.path())["status"], "ok") << f;  // every file there is complete
      EXPECT_TRUE(fs::exists(dir_ / "out" / (e.path().stem().string() + ".overlay.png"))) << f;
      ++jsons;
    }
  }
  EXPECT_EQ(static_cast<std::size_t>(jsons), finished);

  EXPECT_EQ(runIn("").exitCode, 0);
  const Json resumed = readJson(dir_ / "out" / "summary.json");
  EXPECT_EQ(resumed["ok"], 6);
  EXPECT_EQ(resumed["skipped"].get<std::size_t>(), finished);
}

}  // namespace
