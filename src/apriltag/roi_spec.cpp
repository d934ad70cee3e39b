// SPDX-License-Identifier: MIT
// ROI specs as a command line gives them (`--roi tags:0,1,2,3@top-left`).
#include <roiclip/apriltag/roi.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

namespace roiclip::apriltag {

TagAnchor parseTagAnchor(const std::string& text) {
  std::string t;
  for (char c : text)
    t += c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (t == "centre" || t == "center") return TagAnchor::Centre;
  if (t == "bottom-left") return TagAnchor::BottomLeft;
  if (t == "bottom-right") return TagAnchor::BottomRight;
  if (t == "top-right") return TagAnchor::TopRight;
  if (t == "top-left") return TagAnchor::TopLeft;
  throw InvalidInputError("unknown tag anchor '" + text +
                          "' (expected centre, top-left, top-right, bottom-right or bottom-left)");
}

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string::npos) return parts;
    start = end + 1;
  }
}

// Whole-string number parsing: "12x" or "" is an error, not 12 or 0.
int parseId(const std::string& text, const std::string& spec) {
  std::size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || value < 0) {
    throw InvalidInputError("ROI '" + spec + "': '" + text + "' is not a tag id");
  }
  return value;
}

double parseNumber(const std::string& text, const std::string& spec) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !std::isfinite(value)) {
    throw InvalidInputError("ROI '" + spec + "': '" + text + "' is not a number");
  }
  return value;
}

std::vector<int> parseIds(const std::string& text, const std::string& spec) {
  std::vector<int> ids;
  for (const std::string& part : split(text, ',')) ids.push_back(parseId(part, spec));
  return ids;
}

}  // namespace

RoiSpec parseRoiSpec(const std::string& text) {
  const std::size_t colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  const std::string rest = colon == std::string::npos ? std::string() : text.substr(colon + 1);
  const bool hasArgument = colon != std::string::npos;
  RoiSpec spec;
  if (kind == "tags") {
    spec.kind = RoiSpec::Kind::Tags;
    if (!hasArgument)
      throw InvalidInputError("ROI '" + text + "': expected tags:ID,ID,ID[@anchor]");
    // Each id may carry its own anchor (22@top-left); one anchor on the last id alone applies
    // to every tag (the older form tags:0,1,2,3@top-left).
    int anchored = 0;
    for (const std::string& part : split(rest, ',')) {
      const std::size_t at = part.find('@');
      spec.ids.push_back(parseId(part.substr(0, at), text));
      spec.anchors.push_back(at == std::string::npos ? TagAnchor::Centre
                                                     : parseTagAnchor(part.substr(at + 1)));
      if (at != std::string::npos) ++anchored;
    }
    if (anchored == 1 && rest.find('@') > rest.rfind(',')) {
      spec.anchors.assign(spec.ids.size(), spec.anchors.back());
    }
    if (spec.ids.size() < 3)
      throw InvalidInputError("ROI '" + text + "': a tag polygon needs at least 3 ids");
  } else if (kind == "hull") {
    spec.kind = RoiSpec::Kind::Hull;
    if (hasArgument) spec.ids = parseIds(rest, text);
  } else if (kind == "board") {
    spec.kind = RoiSpec::Kind::Board;
    spec.roiName = rest;
  } else if (kind == "tag") {
    spec.kind = RoiSpec::Kind::TagFrame;
    const std::size_t second = rest.find(':');
    if (!hasArgument || second == std::string::npos) {
      throw InvalidInputError("ROI '" + text + "': expected tag:ID:x,y;x,y;x,y");
    }
    spec.ids = {parseId(rest.substr(0, second), text)};
    for (const std::string& pathText : split(rest.substr(second + 1), '|')) {
      Path path;
      for (const std::string& vertex : split(pathText, ';')) {
        const std::vector<std::string> xy = split(vertex, ',');
        if (xy.size() != 2)
          throw InvalidInputError("ROI '" + text + "': vertex '" + vertex + "' is not x,y");
        path.push_back({parseNumber(xy[0], text), parseNumber(xy[1], text)});
      }
      if (path.size() < 3)
        throw InvalidInputError("ROI '" + text + "': a path needs at least 3 vertices");
      spec.tagFramePaths.push_back(std::move(path));
    }
  } else {
    throw InvalidInputError("ROI '" + text + "': unknown kind '" + kind +
                            "' (expected tags:, hull, board or tag:)");
  }
  std::vector<int> sorted = spec.ids;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) {
    throw InvalidInputError("ROI '" + text + "': tag id " + std::to_string(*twice) +
                            " is listed twice");
  }
  return spec;
}

}  // namespace roiclip::apriltag
