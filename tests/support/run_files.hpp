// SPDX-License-Identifier: MIT
// Files of a `roiclip run` test, header-only: a bundled scene copied in, the outputs read back
// (tests/batch and tests/apps). Include as "support/run_files.hpp".
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace roiclip::testing {

/// The whole file as bytes (empty when it cannot be read).
inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline nlohmann::json readJson(const std::filesystem::path& file) {
  return nlohmann::json::parse(readText(file));
}

/// The lines of `text`, without their '\n'.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

/// images/SCENE.png (ROICLIP_IMAGES) copied to `to`, its folder created.
inline void copyScene(const std::string& scene, const std::filesystem::path& to) {
  std::filesystem::create_directories(to.parent_path());
  std::filesystem::copy_file(std::filesystem::path(ROICLIP_IMAGES) / (scene + ".png"), to,
                             std::filesystem::copy_options::overwrite_existing);
}

/// Files whose name starts with '.' (io's temporary files) anywhere under `dir`.
inline int hiddenFiles(const std::filesystem::path& dir) {
  int n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (e.path().filename().string()[0] == '.') ++n;
  }
  return n;
}

}  // namespace roiclip::testing
