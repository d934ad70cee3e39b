// SPDX-License-Identifier: MIT
// The JSON test data of tests/data/core: listing a folder's files, naming a test after its file,
// and reading paths ([[[x, y], ...], ...], one array per ring).
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <roiclip/geometry.hpp>

namespace roiclip::testing {

/// The .json files directly in each of `folders` (below tests/data), sorted; missing folders
/// give nothing.
inline std::vector<std::string> jsonFiles(std::initializer_list<const char*> folders) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for (const char* folder : folders) {
    const fs::path dir = fs::path(ROICLIP_TEST_DATA) / folder;
    if (!fs::exists(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// A GoogleTest-safe test name: the file's stem with every other character than [A-Za-z0-9]
/// replaced by '_'.
inline std::string testNameOf(const std::string& file) {
  std::string name = std::filesystem::path(file).stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

inline Paths readPaths(const nlohmann::json& j) {
  Paths out;
  for (const auto& ring : j) {
    Path p;
    for (const auto& v : ring) p.emplace_back(v.at(0).get<double>(), v.at(1).get<double>());
    out.push_back(std::move(p));
  }
  return out;
}

/// A fixture of tests/data/core: its subject, and the first ring of its clip (an ROI).
struct SubjectAndRoi {
  std::string file;
  Paths subject;
  Path roi;
};
/// The fixtures of tests/data/core whose names start with `prefix`.
inline std::vector<SubjectAndRoi> coreFixtures(const std::string& prefix) {
  std::vector<SubjectAndRoi> out;
  for (const std::string& file : jsonFiles({"core"})) {
    if (std::filesystem::path(file).filename().string().rfind(prefix, 0) != 0) continue;
    std::ifstream in(file);
    const nlohmann::json j = nlohmann::json::parse(in);
    out.push_back({file, readPaths(j.at("subject")), readPaths(j.at("clip")).at(0)});
  }
  return out;
}

}  // namespace roiclip::testing
