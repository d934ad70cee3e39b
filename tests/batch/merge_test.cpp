// SPDX-License-Identifier: MIT
// batch::merge() and `roiclip merge` (in-process): two shard folders give the summary one run
// over all their images gives; shards run with different options, an image in two shards and a
// folder that is no run output are refused.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <roiclip/batch/merge.hpp>
#include <roiclip/batch/run.hpp>

#include "support/run_files.hpp"
#include "temp_dir.hpp"

#ifdef ROICLIP_HAVE_MERGE_COMMAND
#include "merge_command.hpp"
#endif

namespace fs = std::filesystem;
namespace rb = roiclip::batch;
using Json = nlohmann::json;

namespace {

const fs::path kImages = ROICLIP_IMAGES;
using roiclip::testing::readText;
using roiclip::testing::TempDir;

// Copies of bundled scenes (and, for "broken.png", a file that is not an image) in `folder`.
void fill(const fs::path& folder, const std::vector<std::string>& files) {
  fs::create_directories(folder);
  for (const std::string& f : files) {
    if (f == "broken.png") {
      std::ofstream(folder / f) << "not a png";
    } else {
      fs::copy_file(kImages / f, folder / f);
    }
  }
}

rb::RunSummary runInto(const fs::path& input, const fs::path& output, double minArea = 0.0) {
  rb::BatchOptions o;
  o.inputs = {input};
  o.output = output;
  o.jobs = 2;
  if (minArea > 0) o.process.contours.minArea = minArea;
  return rb::run(o);
}

// `text` with every occurrence of each of `folders` replaced by "IN" (failure reasons name the
// image by the path it was read from).
std::string withoutFolders(std::string text, const std::vector<fs::path>& folders) {
  for (const fs::path& folder : folders) {
    const std::string f = folder.string();
    for (std::size_t at; (at = text.find(f)) != std::string::npos;)
      text.replace(at, f.size(), "IN");
  }
  return text;
}

// Shards s1 (scene_01, default options) and s2 (scene_02, min_area minArea2 when > 0) in `t`,
// run from input folders in1 and in2.
void twoShards(const fs::path& t, double minArea2 = 0.0) {
  fill(t / "in1", {"scene_01.png"});
  fill(t / "in2", {"scene_02.png"});
  runInto(t / "in1", t / "s1");
  runInto(t / "in2", t / "s2", minArea2);
}

// summary.csv without its `seconds` column (times differ from run to run) and the input
// `folders`.
std::vector<std::string> rowsWithoutTimes(const fs::path& csv,
                                          const std::vector<fs::path>& folders = {}) {
  std::vector<std::string> rows;
  std::istringstream in(withoutFolders(readText(csv), folders));
  std::size_t secondsColumn = 0;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::istringstream f(line);
    for (std::string field; std::getline(f, field, ',');) fields.push_back(field);
    if (rows.empty()) {
      secondsColumn = std::find(fields.begin(), fields.end(), "seconds") - fields.begin();
    }
    EXPECT_LT(secondsColumn, fields.size()) << line;
    if (secondsColumn < fields.size()) fields.erase(fields.begin() + secondsColumn);
    std::string joined;
    for (const auto& field : fields) joined += field + ",";
    rows.push_back(joined);
  }
  return rows;
}

// summary.json's image rows without "seconds", and its totals.
Json withoutTimes(Json summary) {
  for (Json& row : summary["images"]) {
    row.erase("seconds");
    row.erase("stage_seconds");
  }
  summary.erase("seconds");
  summary.erase("input");
  summary.erase("output");
  summary.erase("merged_from");
  return summary;
}

TEST(BatchMerge, TwoShardsGiveTheSummaryOfOneRunOverAll) {
  const TempDir tmp("merge_equal");
  const fs::path t = tmp.path();
  fill(t / "all", {"scene_01.png", "scene_02.png", "broken.png", "scene_03.png"});
  fill(t / "in1", {"scene_01.png", "broken.png"});
  fill(t / "in2", {"scene_02.png", "scene_03.png"});
  const rb::RunSummary one = runInto(t / "all", t / "one");
  runInto(t / "in1", t / "s1");
  runInto(t / "in2", t / "s2");

  rb::MergeOptions m;
  m.output = t / "merged";
  m.shards = {t / "s2", t / "s1"};  // any order: rows come out in image path order
  const rb::RunSummary merged = rb::merge(m);
  EXPECT_EQ(merged.total, one.total);
  EXPECT_EQ(merged.ok, 3u);
  EXPECT_EQ(merged.failed, 1u);
  EXPECT_FALSE(merged.interrupted);
  ASSERT_EQ(merged.images.size(), one.images.size());
  for (std::size_t i = 0; i < one.images.size(); ++i) {
    EXPECT_EQ(merged.images[i].image, one.images[i].image);
    EXPECT_EQ(merged.images[i].name, one.images[i].name);
    EXPECT_EQ(merged.images[i].status, one.images[i].status);
    EXPECT_EQ(merged.images[i].clippedArea, one.images[i].clippedArea);
  }

  const std::vector<fs::path> inputs = {t / "all", t / "in1", t / "in2"};
  EXPECT_EQ(rowsWithoutTimes(t / "merged" / "summary.csv", inputs),
            rowsWithoutTimes(t / "one" / "summary.csv", inputs));
  const Json mj = Json::parse(withoutFolders(readText(t / "merged" / "summary.json"), inputs));
  const Json oj = Json::parse(withoutFolders(readText(t / "one" / "summary.json"), inputs));
  EXPECT_EQ(withoutTimes(mj), withoutTimes(oj));
  EXPECT_EQ(mj["merged_from"], Json::array({(t / "s2").string(), (t / "s1").string()}));
  EXPECT_EQ(mj["input"], "");  // the shards had different input folders

  // Every image's files are copied: the merged folder stands on its own.
  const std::pair<const char*, const char*> copies[] = {{"s1", "scene_01.json"},
                                                        {"s1", "scene_01.overlay.png"},
                                                        {"s1", "broken.json"},
                                                        {"s2", "scene_02.json"},
                                                        {"s2", "scene_03.overlay.png"}};
  for (const auto& [shard, f] : copies) {
    EXPECT_EQ(readText(t / "merged" / f), readText(t / shard / f)) << f;
  }
  EXPECT_FALSE(fs::exists(t / "merged" / "broken.overlay.png"));
  const std::string html = readText(t / "merged" / "report.html");
  EXPECT_NE(html.find("<h1>roiclip merge</h1>"), std::string::npos);
  for (const char* f : {"scene_01.overlay.png", "scene_02.overlay.png", "scene_03.overlay.png"}) {
    EXPECT_NE(html.find(std::string("src=\"") + f + "\""), std::string::npos) << f;
  }

  // A run into the merged folder finds the merged images up to date (the failed one is redone).
  const rb::RunSummary again = runInto(t / "all", t / "merged");
  EXPECT_EQ(again.skipped, 3u);

  // A merged folder (now with that run's summary) merges again, row for row.
  rb::MergeOptions m2;
  m2.output = t / "merged2";
  m2.shards = {t / "merged"};
  EXPECT_EQ(rb::merge(m2).images.size(), 4u);
  EXPECT_EQ(rowsWithoutTimes(t / "merged2" / "summary.csv"),
            rowsWithoutTimes(t / "merged" / "summary.csv"));
}

TEST(BatchMerge, DifferentOptionsAreRefusedNamingTheKey) {
  const TempDir tmp("merge_options");
  const fs::path t = tmp.path();
  twoShards(t, /*minArea2=*/50.0);
  rb::MergeOptions m;
  m.output = t / "merged";
  m.shards = {t / "s1", t / "s2"};
  try {
    rb::merge(m);
    FAIL() << "merge accepted shards with different options";
  } catch (const rb::OptionsMismatchError& e) {
    EXPECT_EQ(e.key(), "min_area");
    EXPECT_EQ(e.firstShard(), t / "s1");
    EXPECT_EQ(e.otherShard(), t / "s2");
    EXPECT_EQ(e.otherValue(), "50.0");
    EXPECT_NE(std::string(e.what()).find("\"min_area\""), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(t / "merged" / "summary.json"));  // nothing written
}

TEST(BatchMerge, AnImageInTwoShardsOrAFolderThatIsNoRunIsRefused) {
  const TempDir tmp("merge_refused");
  const fs::path t = tmp.path();
  fill(t / "in", {"scene_01.png"});
  runInto(t / "in", t / "s1");
  runInto(t / "in", t / "s2");
  rb::MergeOptions m;
  m.output = t / "merged";
  m.shards = {t / "s1", t / "s2"};
  EXPECT_THROW(rb::merge(m), roiclip::InvalidInputError);  // scene_01 twice
  fs::create_directories(t / "empty");
  m.shards = {t / "s1", t / "empty"};
  EXPECT_THROW(rb::merge(m), roiclip::InvalidInputError);  // no summary.json
  m.shards = {t / "s1"};
  m.output = t / "s1";
  EXPECT_THROW(rb::merge(m), roiclip::InvalidInputError);  // onto itself
  m.shards = {};
  EXPECT_THROW(rb::merge(m), roiclip::InvalidInputError);
  // A NAME in summary.json that would leave the shard folder.
  std::string summary = readText(t / "s2" / "summary.json");
  const std::string name = "\"name\": \"scene_01\"";
  ASSERT_NE(summary.find(name), std::string::npos);
  summary.replace(summary.find(name), name.size(), "\"name\": \"../in/scene_01\"");
  std::ofstream(t / "s2" / "summary.json") << summary;
  m.output = t / "merged";
  m.shards = {t / "s2"};
  EXPECT_THROW(rb::merge(m), roiclip::InvalidInputError);
  EXPECT_FALSE(fs::exists(t / "merged"));
}

#ifdef ROICLIP_HAVE_MERGE_COMMAND
// The command as main() runs it: parse, work in the callback, errors as roiclip exceptions
// (InvalidInputError: exit code 2).
TEST(BatchMerge, CommandMergesAndRefusesDifferentOptions) {
  const TempDir tmp("merge_command");
  const fs::path t = tmp.path();
  twoShards(t);
  runInto(t / "in2", t / "s3", /*minArea=*/50.0);
  // The exit code main() returns after parsing.
  const auto parse = [](std::vector<std::string> args, std::ostream& out) {
    CLI::App app;
    roiclip::app::MergeCommand merge(app, out);
    std::vector<const char*> argv = {"roiclip"};
    for (const auto& a : args) argv.push_back(a.c_str());
    app.parse(static_cast<int>(argv.size()), argv.data());
    return merge.exitCode();
  };
  std::ostringstream out;
  EXPECT_EQ(parse({"merge", (t / "m").string(), (t / "s1").string(), (t / "s2").string()}, out), 0);
  EXPECT_NE(out.str().find("roiclip merge: 2 of 2 images from 2 shards: 2 ok"), std::string::npos)
      << out.str();
  EXPECT_TRUE(fs::exists(t / "m" / "report.html"));
  EXPECT_THROW(parse({"merge", (t / "m2").string(), (t / "s1").string(), (t / "s3").string()}, out),
               rb::OptionsMismatchError);
  parse({"merge", "--no-report", (t / "m3").string(), (t / "s1").string()}, out);
  EXPECT_TRUE(fs::exists(t / "m3" / "summary.csv"));
  EXPECT_FALSE(fs::exists(t / "m3" / "report.html"));
  EXPECT_THROW(parse({"merge", (t / "m4").string()}, out), CLI::ParseError);  // no shard
  EXPECT_THROW(parse({"merge", (t / "m4").string(), (t / "nowhere").string()}, out),
               CLI::ParseError);
}
#endif

}  // namespace
