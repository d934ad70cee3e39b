// SPDX-License-Identifier: MIT
// `roiclip merge`: shard output folders into one (options checked, per-image files copied,
// summaries and report written as one run over all the images would have).
#include <roiclip/batch/merge.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include <roiclip/io/atomic_file.hpp>

#include "detail/folder.hpp"
#include "detail/report.hpp"
#include "detail/report_html.hpp"
#include "detail/result_json.hpp"

namespace roiclip::batch {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

// The per-image files of a run, NAME.json last: its presence marks the image as complete.
constexpr const char* kImageFiles[] = {".overlay.png", ".mask.png", ".json"};

std::optional<std::string> readFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return s.str();
}

// One shard's summary.json.
struct ShardFolder {
  fs::path folder;
  Json summary;
};

ShardFolder readShard(const fs::path& folder) {
  const fs::path file = folder / "summary.json";
  const std::optional<std::string> text = readFile(file);
  if (!text) throw InvalidInputError(file.string() + ": cannot read (not a run output folder?)");
  ShardFolder shard{folder, Json::parse(*text, nullptr, false)};
  const Json& j = shard.summary;
  if (!j.is_object() || !j.contains("options") || !j["options"].is_object() ||
      !j.contains("images") || !j["images"].is_array()) {
    throw InvalidInputError(file.string() + ": not a roiclip run summary");
  }
  return shard;
}

// Every key of either shard's options, compared by value.
void checkSameOptions(const ShardFolder& first, const ShardFolder& other) {
  const Json& a = first.summary["options"];
  const Json& b = other.summary["options"];
  std::set<std::string> keys;
  for (const auto& [key, value] : a.items()) keys.insert(key);
  for (const auto& [key, value] : b.items()) keys.insert(key);
  for (const std::string& key : keys) {
    const Json va = a.contains(key) ? a[key] : Json();
    const Json vb = b.contains(key) ? b[key] : Json();
    if (va != vb) throw OptionsMismatchError(key, first.folder, va.dump(), other.folder, vb.dump());
  }
}

// One image of a shard, with the row as one run over everything would list it.
struct Entry {
  ImageRecord record;
  const ShardFolder* shard;
};

std::vector<Entry> entriesOf(const ShardFolder& shard) {
  std::vector<Entry> entries;
  const fs::path summaryFile = shard.folder / "summary.json";
  for (const Json& row : shard.summary["images"]) {
    if (!row.is_object() || !row.contains("name") || !row["name"].is_string()) {
      throw InvalidInputError(summaryFile.string() + ": an image row without a name");
    }
    // outputName() refuses names that would leave the folder ("..", absolute paths).
    const std::string name =
        detail::outputName(fs::path(row["name"].get<std::string>()), /*keepExtension=*/true);
    const fs::path jsonFile = shard.folder / (name + ".json");
    const std::optional<std::string> text = readFile(jsonFile);
    if (!text) {
      throw InvalidInputError(jsonFile.string() + ": missing (listed in " + summaryFile.string() +
                              ")");
    }
    std::optional<ImageRecord> record = detail::parseRecord(*text);
    if (!record) throw InvalidInputError(jsonFile.string() + ": not a roiclip image result");
    // The shard's own row says whether it was up to date and how long it took.
    record->name = name;
    record->image = row.value("image", record->image);
    record->skipped = row.value("skipped", false);
    record->seconds = row.value("seconds", 0.0);
    entries.push_back({std::move(*record), &shard});
  }
  return entries;
}

void copyImageFiles(const Entry& e, const fs::path& output) {
  const fs::path from = e.shard->folder / e.record.name;
  const fs::path to = output / e.record.name;
  std::error_code ec;
  fs::create_directories(to.parent_path(), ec);
  if (ec) {
    throw Error("cannot create output folder " + to.parent_path().string() + ": " + ec.message());
  }
  for (const char* suffix : kImageFiles) {
    const fs::path source = from.string() + suffix;
    const fs::path target = to.string() + suffix;
    if (!fs::exists(source, ec)) {
      fs::remove(target, ec);  // a stale file from an earlier run or merge would mislead
      continue;
    }
    const std::optional<std::string> bytes = readFile(source);
    if (!bytes) throw InvalidInputError(source.string() + ": cannot read");
    io::writeFileAtomically(target, *bytes);
  }
}

// summary.json: summaryJson()'s rows and totals, with the shards' own options (every key, as
// they wrote them) and where the rows came from.
std::string mergedSummaryJson(const RunSummary& summary, const std::vector<ShardFolder>& shards,
                              const fs::path& output, const std::string& input) {
  BatchOptions options;
  if (!input.empty()) options.inputs = {input};
  options.output = output;
  Json j = Json::parse(detail::summaryJson(summary, options));
  j["options"] = shards.front().summary["options"];
  Json from = Json::array();
  for (const ShardFolder& s : shards) from.push_back(s.folder.string());
  j["merged_from"] = std::move(from);
  return j.dump(1) + "\n";
}

std::string mergedReportHtml(const RunSummary& summary, const std::vector<ShardFolder>& shards,
                             const std::string& input) {
  detail::ReportPage page{"roiclip merge", {}};
  std::string from;
  for (const ShardFolder& s : shards) from += (from.empty() ? "" : ", ") + s.folder.string();
  page.facts.emplace_back("shards", from);
  if (!input.empty()) page.facts.emplace_back("input", input);
  for (const auto& [key, value] : shards.front().summary["options"].items()) {
    page.facts.emplace_back(key, value.is_string() ? value.get<std::string>() : value.dump());
  }
  return detail::reportHtml(summary, page);
}

}  // namespace

OptionsMismatchError::OptionsMismatchError(std::string key, fs::path firstShard,
                                           std::string firstValue, fs::path otherShard,
                                           std::string otherValue)
    : InvalidInputError("option \"" + key + "\" differs between shards: " + firstValue + " in " +
                        (firstShard / "summary.json").string() + ", " + otherValue + " in " +
                        (otherShard / "summary.json").string()),
      key_(std::move(key)),
      firstShard_(std::move(firstShard)),
      otherShard_(std::move(otherShard)),
      firstValue_(std::move(firstValue)),
      otherValue_(std::move(otherValue)) {}

RunSummary merge(const MergeOptions& options) {
  if (options.shards.empty()) throw InvalidInputError("merge: no shard folders given");
  std::vector<ShardFolder> shards;
  shards.reserve(options.shards.size());
  for (const fs::path& folder : options.shards) {
    std::error_code ec;
    if (fs::equivalent(folder, options.output, ec)) {
      throw InvalidInputError(folder.string() + ": is the merge's output folder");
    }
    shards.push_back(readShard(folder));
    checkSameOptions(shards.front(), shards.back());
  }

  std::vector<Entry> entries;
  std::map<std::string, const ShardFolder*> owner;
  for (const ShardFolder& shard : shards) {
    for (Entry& e : entriesOf(shard)) {
      const auto [it, fresh] = owner.emplace(e.record.name, &shard);
      if (!fresh) {
        throw InvalidInputError("image " + e.record.name + " is in two shards: " +
                                it->second->folder.string() + " and " + shard.folder.string());
      }
      entries.push_back(std::move(e));
    }
  }
  // One run lists its images in path order.
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return fs::path(a.record.image) < fs::path(b.record.image);
  });

  detail::prepareOutputFolder(options.output);

  RunSummary summary;
  std::string input = shards.front().summary.value("input", std::string());
  for (const ShardFolder& s : shards) {
    summary.total += s.summary.value("total", std::size_t{0});
    summary.seconds += s.summary.value("seconds", 0.0);
    summary.interrupted = summary.interrupted || s.summary.value("interrupted", false);
    if (s.summary.value("input", std::string()) != input) input.clear();
  }
  for (Entry& e : entries) {
    copyImageFiles(e, options.output);
    summary.add(std::move(e.record));
  }

  io::writeFileAtomically(options.output / "summary.csv", detail::summaryCsv(summary));
  io::writeFileAtomically(options.output / "summary.json",
                          mergedSummaryJson(summary, shards, options.output, input));
  if (options.writeReport) {
    io::writeFileAtomically(options.output / "report.html",
                            mergedReportHtml(summary, shards, input));
  }
  return summary;
}

}  // namespace roiclip::batch
