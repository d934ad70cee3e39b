// A whole file as a string (empty when it cannot be read), for the batch tests' output checks.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace roiclip::testing {

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace roiclip::testing
