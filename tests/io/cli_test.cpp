// Runs the built `roiclip` command line (ROICLIP_CLI) on the files in tests/data/io and checks
// its output, its stderr and its exit codes.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kData = std::string(ROICLIP_TEST_DATA) + "/io/";

struct CliRun {
  int exitCode = -1;
  std::string out;
  std::string err;
};

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    // The pid keeps concurrent runs of the suite (several builds on one machine) apart.
    dir_ = fs::temp_directory_path() /
           (std::string("roiclip_cli_test_") + info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliRun run(const std::string& args) const {
    const fs::path out = dir_ / "stdout.txt";
    const fs::path err = dir_ / "stderr.txt";
    const std::string command = std::string("'") + ROICLIP_CLI + "' " + args + " >'" +
                                out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(command.c_str());
    CliRun r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    fs::remove(out);
    fs::remove(err);
    return r;
  }

  // Properties of the single Feature of a GeoJSON FeatureCollection written by the CLI.
  static json properties(const std::string& text) {
    const json root = json::parse(text);
    EXPECT_EQ(root.at("type"), "FeatureCollection");
    EXPECT_EQ(root.at("features").size(), 1u);
    return root.at("features")[0].at("properties");
  }
  static double area(const CliRun& r) { return properties(r.out).at("area").get<double>(); }

  // A bad-input run: exit code 2, nothing on stdout, one line on stderr naming the file.
  static void expectBadInput(const CliRun& r, const std::string& file, const std::string& problem) {
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
  }

  fs::path dir_;
};

TEST_F(Cli, HelpDocumentsExitCodes) {
  for (const char* args : {"--help", "simplify --help", "clip --help"}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.exitCode, 0) << args;
    EXPECT_NE(r.out.find("Exit codes"), std::string::npos) << args;
    EXPECT_NE(r.out.find("2  invalid input"), std::string::npos) << args;
  }
}

TEST_F(Cli, SimplifyToStdout) {
  const CliRun r = run("simplify '" + kData + "bowtie.json'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty());
  const json props = properties(r.out);
  EXPECT_DOUBLE_EQ(props.at("area").get<double>(), 50.0);
  EXPECT_EQ(props.at("rings").get<int>(), 2);
  const json coords = json::parse(r.out).at("features")[0].at("geometry").at("coordinates");
  ASSERT_EQ(coords.size(), 2u);
  for (const json& polygon : coords) EXPECT_EQ(polygon[0].front(), polygon[0].back());
}

TEST_F(Cli, SimplifyFillRule) {
  const std::string twice = "'" + kData + "twice_wound.json'";
  EXPECT_DOUBLE_EQ(area(run("simplify --fill-rule nonzero " + twice)), 100.0);
  EXPECT_DOUBLE_EQ(area(run("simplify --fill-rule positive " + twice)), 100.0);
  EXPECT_DOUBLE_EQ(area(run("simplify --fill-rule negative " + twice)), 0.0);
  EXPECT_DOUBLE_EQ(area(run("simplify " + twice)), 0.0);  // evenodd by default
}

TEST_F(Cli, SimplifyToFile) {
  const fs::path out = dir_ / "result.geojson";
  const CliRun r = run("simplify '" + kData + "frame.geojson' -o '" + out.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_DOUBLE_EQ(properties(slurp(out)).at("area").get<double>(), 164.0);
  EXPECT_EQ(properties(slurp(out)).at("rings").get<int>(), 3);
}

TEST_F(Cli, ClipOperations) {
  const std::string files = "'" + kData + "bowtie.json' '" + kData + "roi.geojson'";
  // bow-tie 50, ROI 72, overlap 18.
  EXPECT_DOUBLE_EQ(area(run("clip " + files)), 18.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op intersection " + files)), 18.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op union " + files)), 104.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op difference " + files)), 32.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op xor " + files)), 86.0);
}

TEST_F(Cli, ClipFillRulesSpecificOverridesGeneral) {
  const std::string twice = "'" + kData + "twice_wound.json'";
  const std::string roi = "'" + kData + "roi.geojson'";
  // The doubly wound square is empty under even-odd and the square [0,10]^2 otherwise.
  EXPECT_DOUBLE_EQ(area(run("clip " + twice + " " + roi)), 0.0);
  EXPECT_DOUBLE_EQ(area(run("clip --fill-rule nonzero " + twice + " " + roi)), 60.0);
  EXPECT_DOUBLE_EQ(area(run("clip --subject-fill-rule nonzero " + twice + " " + roi)), 60.0);
  EXPECT_DOUBLE_EQ(
      area(run("clip --fill-rule nonzero --subject-fill-rule evenodd " + twice + " " + roi)), 0.0);
  EXPECT_DOUBLE_EQ(area(run("clip --fill-rule nonzero " + roi + " " + twice)), 60.0);
  EXPECT_DOUBLE_EQ(
      area(run("clip --fill-rule nonzero --clip-fill-rule evenodd " + roi + " " + twice)), 0.0);
  EXPECT_DOUBLE_EQ(area(run("clip --op union --clip-fill-rule nonzero " + roi + " " + twice)),
                   72.0 + 100.0 - 60.0);
}

TEST_F(Cli, BadInputSimplify) {
  const struct {
    const char* file;
    const char* problem;
  } cases[] = {
      {"bad_syntax.json", "not valid JSON"},
      {"bad_structure.json", "unsupported geometry type"},
      {"string_coordinate.json", "y is not a number"},
      {"null_coordinate.geojson", "x is not a number"},
      {"degenerate_ring.geojson", "polygon 1, ring 0"},
      {"out_of_range.json", "path 1, vertex 1"},
      {"no_such_file.json", "cannot open"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    expectBadInput(run("simplify '" + kData + c.file + "'"), c.file, c.problem);
  }
}

TEST_F(Cli, BadInputClipNamesTheBadOperand) {
  const std::string good = "'" + kData + "square.geojson'";
  expectBadInput(run("clip " + good + " '" + kData + "out_of_range.json'"), "out_of_range.json",
                 "outside the supported range");
  expectBadInput(run("clip '" + kData + "string_coordinate.json' " + good),
                 "string_coordinate.json", "not a number");
  const CliRun r = run("clip " + good + " '" + kData + "bad_syntax.json'");
  EXPECT_EQ(r.err.find("square.geojson"), std::string::npos) << r.err;
}

TEST_F(Cli, BadInputWritesNoOutputFile) {
  const fs::path out = dir_ / "result.geojson";
  const CliRun r = run("simplify '" + kData + "degenerate_ring.geojson' -o '" + out.string() + "'");
  expectBadInput(r, "degenerate_ring.geojson", "fewer than 3 distinct points");
  EXPECT_FALSE(fs::exists(out));
  // An existing output is left as it was, and no temporary remains.
  { std::ofstream(out) << "previous"; }
  const CliRun again =
      run("clip '" + kData + "square.geojson' '" + kData + "bad_syntax.json' -o " + out.string());
  EXPECT_EQ(again.exitCode, 2);
  EXPECT_EQ(slurp(out), "previous");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1u);
}

TEST_F(Cli, UsageErrors) {
  const std::string square = "'" + kData + "square.geojson'";
  EXPECT_EQ(run("").exitCode, 1);
  EXPECT_EQ(run("simplify").exitCode, 1);
  EXPECT_EQ(run("clip " + square).exitCode, 1);
  const CliRun rule = run("simplify --fill-rule sometimes " + square);
  EXPECT_EQ(rule.exitCode, 1);
  EXPECT_NE(rule.err.find("sometimes"), std::string::npos) << rule.err;
  EXPECT_EQ(run("clip --op merge " + square + " " + square).exitCode, 1);
}

TEST_F(Cli, GridScale) {
  const std::string far = "'" + kData + "out_of_range.json'";
  // x = 5,000,000 px is outside the default grid (256 units/px) but fits at 64 units/px.
  EXPECT_EQ(run("simplify " + far).exitCode, 2);
  const CliRun coarse = run("simplify --grid-scale 64 " + far);
  ASSERT_EQ(coarse.exitCode, 0) << coarse.err;
  // Even-odd: the small triangle (area 50) lies inside the big one (area 2.5e7) but for a sliver
  // of ~2e-10 px^2 near (10, 10), so it is cut out.
  EXPECT_NEAR(area(coarse), 25000000.0 - 50.0, 1e-3);
  // A 1/1024 px square vanishes on a 1/256 px grid and survives on a finer one.
  const fs::path tiny = dir_ / "tiny.json";
  std::ofstream(tiny) << R"({"paths": [[[0, 0], [0.0009765625, 0], [0.0009765625, 0.0009765625],
                                         [0, 0.0009765625]]]})";
  EXPECT_DOUBLE_EQ(area(run("simplify '" + tiny.string() + "'")), 0.0);
  EXPECT_DOUBLE_EQ(area(run("simplify --grid-scale 1024 '" + tiny.string() + "'")),
                   0.0009765625 * 0.0009765625);
  EXPECT_EQ(run("clip --grid-scale -1 " + far + " " + far).exitCode, 1);
}

TEST_F(Cli, UnwritableOutput) {
  const CliRun r =
      run("simplify '" + kData + "square.geojson' -o '" + (dir_ / "no/such/x.json").string() + "'");
  EXPECT_EQ(r.exitCode, 3);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("no/such/x.json"), std::string::npos) << r.err;
}

}  // namespace
