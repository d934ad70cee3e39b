// Paths in the JSON test data of tests/data/core: [[[x, y], ...], ...], one array per ring.
#pragma once

#include <utility>

#include <nlohmann/json.hpp>

#include <roiclip/geometry.hpp>

namespace roiclip::testing {

inline Paths readPaths(const nlohmann::json& j) {
  Paths out;
  for (const auto& ring : j) {
    Path p;
    for (const auto& v : ring) p.emplace_back(v.at(0).get<double>(), v.at(1).get<double>());
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace roiclip::testing
