// SPDX-License-Identifier: MIT
// `roiclip run`'s command line in-process (RunCommand, ConfigJson): the options land in the
// library's structs, whose defaults are the command's; the JSON config reader's items and errors.
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <roiclip/batch/options.hpp>
#include <roiclip/batch/run.hpp>

#include "config_json.hpp"
#include "run_command.hpp"

namespace {

namespace batch = roiclip::batch;
using roiclip::app::ConfigFileError;
using roiclip::app::ConfigJson;
using roiclip::app::RunCommand;

// `roiclip ARGS...` parsed into a RunCommand (nothing runs; no ARGS: not parsed).
struct Parsed {
  CLI::App app{"roiclip"};
  RunCommand command{app};
  explicit Parsed(std::vector<std::string> args) {
    if (args.empty()) return;
    std::reverse(args.begin(), args.end());  // CLI11 takes them last first
    app.parse(args);
  }
};

TEST(RunCommand, DefaultsAreTheLibrarysDefaults) {
  const Parsed parsed({"run"});
  const batch::BatchOptions& o = parsed.command.options();
  const batch::BatchOptions library;
  EXPECT_EQ(batch::optionsKey(o.process), batch::optionsKey(library.process));
  EXPECT_EQ(o.process.maxPixels, library.process.maxPixels);
  EXPECT_EQ(o.jobs, library.jobs);
  EXPECT_EQ(o.recursive, library.recursive);
  EXPECT_EQ(o.force, library.force);
  EXPECT_EQ(o.writeMasks, library.writeMasks);
  EXPECT_EQ(o.writeReport, library.writeReport);
  EXPECT_EQ(o.inputs, std::vector<std::filesystem::path>{"images"});
  EXPECT_EQ(o.output, "out");
}

TEST(RunCommand, OptionsBindToTheLibrarysFields) {
  const Parsed parsed({"run",
                       "photos",
                       "-o",
                       "results",
                       "--roi",
                       "tags:0,1,2,3",
                       "--roi",
                       "hull",
                       "--tag-margin",
                       "2.5",
                       "--keep-tags",
                       "--family",
                       "tag36h11,tag25h9",
                       "--decimate",
                       "1.5",
                       "--max-hamming",
                       "2",
                       "--min-margin",
                       "12",
                       "--method",
                       "threshold:90",
                       "--polarity",
                       "light",
                       "--approx",
                       "0.5",
                       "--min-area",
                       "20",
                       "--fill-rule",
                       "nonzero",
                       "--roi-fill-rule",
                       "positive",
                       "--max-pixels",
                       "0",
                       "-j",
                       "3",
                       "-r",
                       "-f",
                       "--masks",
                       "--edges",
                       "--no-report",
                       "--board",
                       "b.json"});
  const batch::BatchOptions& o = parsed.command.options();
  const batch::RunOptions& p = o.process;
  EXPECT_EQ(o.inputs, std::vector<std::filesystem::path>{"photos"});
  EXPECT_EQ(o.output, "results");
  EXPECT_EQ(p.rois, (std::vector<std::string>{"tags:0,1,2,3", "hull"}));
  EXPECT_EQ(p.tagMargin, 2.5);
  EXPECT_TRUE(p.keepTags);
  EXPECT_EQ(p.detector.family, "tag36h11,tag25h9");
  EXPECT_EQ(p.detector.quadDecimate, 1.5f);
  EXPECT_EQ(p.detector.maxHamming, 2);
  EXPECT_EQ(p.detector.minDecisionMargin, 12.0);
  EXPECT_EQ(p.contours.method, batch::ContourMethod::Threshold);
  EXPECT_EQ(p.contours.threshold, 90);
  EXPECT_EQ(p.contours.polarity, batch::Polarity::Light);
  EXPECT_EQ(p.contours.approxEpsilon, 0.5);
  EXPECT_EQ(p.contours.minArea, 20.0);
  EXPECT_TRUE(p.contours.openEdges);
  EXPECT_EQ(p.subjectFillRule, roiclip::FillRule::NonZero);
  EXPECT_EQ(p.roiFillRule, roiclip::FillRule::Positive);
  EXPECT_EQ(p.maxPixels, 0);
  EXPECT_EQ(p.boardFile, "b.json");
  EXPECT_EQ(o.jobs, 3);
  EXPECT_TRUE(o.recursive);
  EXPECT_TRUE(o.force);
  EXPECT_TRUE(o.writeMasks);
  EXPECT_FALSE(o.writeReport);
}

TEST(RunCommand, OneRoiPerOccurrence) {
  // --roi takes one value each time: the folder after it is the input, not a second ROI.
  const Parsed parsed({"run", "--roi", "hull", "photos"});
  EXPECT_EQ(parsed.command.options().process.rois, std::vector<std::string>{"hull"});
  EXPECT_EQ(parsed.command.options().inputs, std::vector<std::filesystem::path>{"photos"});
}

TEST(RunCommand, RefusedValuesAreValidationErrors) {
  for (const char* bad : {"--decimate=0.5", "--method=sobel", "--roi=tags:1,1,1", "--jobs=-1"}) {
    EXPECT_THROW(Parsed({"run", bad}), CLI::ValidationError) << bad;
  }
  EXPECT_THROW(Parsed({"run", "--jobs=x"}), CLI::ConversionError);
}

std::vector<CLI::ConfigItem> read(const CLI::App& command, const std::string& text) {
  std::istringstream in(text);
  return ConfigJson(command).from_config(in);
}

TEST(ConfigJson, ItemsGoToTheCommand) {
  const Parsed parsed({"run"});
  const auto items =
      read(*parsed.command.subcommand(),
           R"({"roi": ["hull", "tags:0,1,2,3"], "jobs": 2, "force": true, "masks": false,
               "approx": 1.5, "max-pixels": 1e3, "board": null, "inputs": "photos", "o": "x"})");
  ASSERT_EQ(items.size(), 8u);
  for (const CLI::ConfigItem& item : items) {
    EXPECT_EQ(item.parents, std::vector<std::string>{"run"}) << item.name;
  }
  const auto inputs = [&items](const std::string& name) {
    for (const CLI::ConfigItem& item : items) {
      if (item.name == name) return item.inputs;
    }
    return std::vector<std::string>{"<none>"};
  };
  EXPECT_EQ(inputs("roi"), (std::vector<std::string>{"hull", "tags:0,1,2,3"}));
  EXPECT_EQ(inputs("jobs"), std::vector<std::string>{"2"});
  EXPECT_EQ(inputs("force"), std::vector<std::string>{"true"});
  EXPECT_EQ(inputs("masks"), std::vector<std::string>{"false"});
  EXPECT_EQ(inputs("approx"), std::vector<std::string>{"1.5"});
  EXPECT_EQ(inputs("max-pixels"), std::vector<std::string>{"1000"});  // an integer still
  EXPECT_EQ(inputs("board"), std::vector<std::string>{"<none>"});
  EXPECT_EQ(inputs("inputs"), std::vector<std::string>{"photos"});
  EXPECT_EQ(inputs("o"), std::vector<std::string>{"x"});
}

TEST(ConfigJson, ErrorsNameTheKey) {
  const Parsed parsed({"run"});
  const CLI::App& run = *parsed.command.subcommand();
  const struct {
    const char* text;
    const char* key;
    const char* problem;
  } cases[] = {
      {R"({"roii": "hull"})", "roii", "no such option of `run`"},
      {R"({"": 1})", "", "no such option of `run`"},
      {R"({"help": true})", "help", "cannot be set in a config file"},
      {R"({"config": "x.json"})", "config", "cannot be set in a config file"},
      {R"({"force": 1})", "force", "takes true or false (a flag)"},
      {R"({"jobs": true})", "jobs", "must be a string or a number"},
      {R"({"jobs": [1]})", "jobs", "takes one value, not an array"},
      {R"({"roi": [["hull"]]})", "roi", "must be a string or a number"},
      {R"({"roi": {"a": 1}})", "roi", "must be a string or a number"},
      {"[1, 2]", "", "expected a JSON object of options"},
      {"{oops", "", "not valid JSON (at byte 2)"},
      {"", "", "not valid JSON (at byte 1)"},
      {R"({"approx": 5e308})", "", "not valid JSON (a number out of range)"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    try {
      (void)read(run, c.text);
      ADD_FAILURE() << "no error";
    } catch (const ConfigFileError& e) {
      EXPECT_EQ(e.key(), c.key);
      EXPECT_EQ(e.problem(), c.problem);
      EXPECT_EQ(std::string(e.what()),
                (std::string(c.key).empty() ? "" : "'" + std::string(c.key) + "': ") + c.problem);
    }
  }
}

TEST(ConfigJson, WritesWhatItReads) {
  const Parsed parsed({"run", "photos", "--roi", "hull", "--roi", "board:x", "--jobs", "2",
                       "--force", "--method", "canny"});
  const CLI::App& run = *parsed.command.subcommand();
  const std::string text = ConfigJson(run).to_config(&parsed.app, false, false, "");
  const auto items = read(run, text);
  ASSERT_EQ(items.size(), 5u) << text;
  // The same options through CLI11's own config path (the main app's reader).
  Parsed fromFile({});
  std::istringstream in(text);
  fromFile.app.parse_from_stream(in);
  EXPECT_EQ(batch::optionsKey(fromFile.command.options().process),
            batch::optionsKey(parsed.command.options().process));
  EXPECT_EQ(fromFile.command.options().jobs, 2);
  EXPECT_TRUE(fromFile.command.options().force);
  EXPECT_EQ(fromFile.command.options().inputs, std::vector<std::filesystem::path>{"photos"});
}

}  // namespace
