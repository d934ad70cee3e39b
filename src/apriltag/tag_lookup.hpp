// SPDX-License-Identifier: MIT
// Private to roiclip::apriltag: detections indexed by id, shared by the ROI builders and the
// board fit.
#pragma once

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <roiclip/apriltag/roi.hpp>

namespace roiclip::apriltag::detail {

inline std::string idList(const std::vector<int>& ids) {
  std::ostringstream out;
  out << '[';
  for (std::size_t i = 0; i < ids.size(); ++i) out << (i ? " " : "") << ids[i];
  out << ']';
  return out.str();
}

// Index detections by id; `needed` decides which ids must be present exactly once.
struct Lookup {
  std::map<int, std::vector<const Detection*>> byId;
  MissingTags status;

  Lookup(const std::vector<Detection>& detections, std::vector<int> needed, int minimumNeeded) {
    for (const Detection& d : detections) byId[d.id].push_back(&d);
    std::sort(needed.begin(), needed.end());
    needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
    status.needed = needed;
    status.minimumNeeded = minimumNeeded;
    for (const auto& [id, list] : byId) status.seen.push_back(id);
    for (int id : needed) {
      auto it = byId.find(id);
      if (it == byId.end()) {
        status.missing.push_back(id);
      } else if (it->second.size() > 1) {
        status.duplicated.push_back(id);
      }
    }
  }
  [[nodiscard]] bool ok() const {
    const int found = static_cast<int>(status.needed.size() - status.missing.size());
    return status.duplicated.empty() && found >= status.minimumNeeded;
  }
  [[nodiscard]] const Detection& get(int id) const { return *byId.at(id).front(); }
};

inline glm::dvec2 anchorPoint(const Detection& d, TagAnchor anchor) {
  switch (anchor) {
    case TagAnchor::Centre:
      return d.centre;
    case TagAnchor::BottomLeft:
      return d.corner(Corner::BottomLeft);
    case TagAnchor::BottomRight:
      return d.corner(Corner::BottomRight);
    case TagAnchor::TopRight:
      return d.corner(Corner::TopRight);
    case TagAnchor::TopLeft:
      return d.corner(Corner::TopLeft);
  }
  return d.centre;
}

}  // namespace roiclip::apriltag::detail
