// SPDX-License-Identifier: MIT
// The run as COCO instance annotations. Choices (docs/outputs.md says why):
// - one annotation per source contour (its clipped parts are one object), category "object";
// - coordinates shifted by +0.5: COCO measures from the top-left corner of the image, roiclip
//   from the centre of the top-left pixel;
// - polygons for hole-free annotations; an annotation with a hole is an uncompressed RLE mask
//   (COCO unions an annotation's polygons, so a hole cannot be a polygon), still iscrowd 0:
//   it is one object, and COCOeval ignores whatever matches an iscrowd 1 annotation;
// - area is the exact polygon area, bbox the tight box of the exact polygons.
#include "detail/coco.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <nlohmann/json.hpp>

#include <roiclip/opencv/rasterize.hpp>

#include "detail/report.hpp"
#include "detail/result_json.hpp"

namespace roiclip::batch::detail {

namespace {

using Json = nlohmann::ordered_json;

constexpr double kCocoShift = 0.5;  // roiclip pixel centre (0, 0) is COCO's (0.5, 0.5)
constexpr int kObjectCategory = 1;

struct Box {
  double minX = std::numeric_limits<double>::infinity(), minY = minX;
  double maxX = -minX, maxY = -minX;
  void add(const Path& ring) {
    for (const Point& p : ring) {
      minX = std::min(minX, p.x);
      minY = std::min(minY, p.y);
      maxX = std::max(maxX, p.x);
      maxY = std::max(maxY, p.y);
    }
  }
};

// The features of one NAME.json grouped by source contour, in the order they first appear;
// features of no known contour stay alone.
std::vector<std::vector<const ClippedFeature*>> byContour(
    const std::vector<ClippedFeature>& features) {
  std::vector<std::vector<const ClippedFeature*>> groups;
  std::map<int, std::size_t> groupOf;
  for (const ClippedFeature& f : features) {
    if (f.contourIndex >= 0) {
      const auto [it, added] = groupOf.emplace(f.contourIndex, groups.size());
      if (!added) {
        groups[it->second].push_back(&f);
        continue;
      }
    }
    groups.push_back({&f});
  }
  return groups;
}

Json annotationJson(const std::vector<const ClippedFeature*>& parts, cv::Size size,
                    const Grid& grid) {
  Box box;
  double area = 0;
  bool holes = false;
  Paths rings;
  for (const ClippedFeature* f : parts) {
    box.add(f->polygon.outer);
    area += f->area;
    holes = holes || !f->polygon.holes.empty();
    rings.push_back(f->polygon.outer);
    rings.insert(rings.end(), f->polygon.holes.begin(), f->polygon.holes.end());
  }
  Json segmentation;
  if (holes) {
    segmentation = {{"size", {size.height, size.width}},
                    {"counts", cocoRleCounts(rings, size, grid)}};
  } else {
    segmentation = Json::array();
    for (const ClippedFeature* f : parts) {
      Json flat = Json::array();
      for (const Point& p : f->polygon.outer) {
        flat.push_back(p.x + kCocoShift);
        flat.push_back(p.y + kCocoShift);
      }
      segmentation.push_back(std::move(flat));
    }
  }
  Json contour =
      parts.front()->contourIndex < 0 ? Json(nullptr) : Json(parts.front()->contourIndex);
  return {
      {"category_id", kObjectCategory},
      {"segmentation", std::move(segmentation)},
      {"area", area},
      {"bbox",
       {box.minX + kCocoShift, box.minY + kCocoShift, box.maxX - box.minX, box.maxY - box.minY}},
      {"iscrowd", 0},
      {"contour_index", std::move(contour)},
      {"rois", parts.front()->rois}};
}

}  // namespace

std::vector<std::int64_t> cocoRleCounts(const Paths& rings, cv::Size size, const Grid& grid) {
  Box box;
  for (const Path& ring : rings) box.add(ring);
  // Pixels whose centre can be inside, clamped to the image; integer shifts keep the pixel rule.
  const int x0 = std::max(0, static_cast<int>(std::floor(box.minX)));
  const int y0 = std::max(0, static_cast<int>(std::floor(box.minY)));
  const int x1 = std::min(size.width - 1, static_cast<int>(std::ceil(box.maxX)));
  const int y1 = std::min(size.height - 1, static_cast<int>(std::ceil(box.maxY)));
  cv::Mat mask;
  if (x0 <= x1 && y0 <= y1) {
    Paths shifted = rings;
    for (Path& ring : shifted) {
      for (Point& p : ring) p -= Point(x0, y0);
    }
    mask = opencv::rasterize(shifted, FillRule::EvenOdd, cv::Size(x1 - x0 + 1, y1 - y0 + 1), grid);
  }
  std::vector<std::int64_t> counts;
  std::int64_t run = 0;
  bool on = false;
  const auto add = [&](bool value, std::int64_t n) {
    if (n == 0) return;
    if (value != on) {
      counts.push_back(run);
      run = 0;
      on = value;
    }
    run += n;
  };
  for (int x = 0; x < size.width; ++x) {
    if (mask.empty() || x < x0 || x > x1) {
      add(false, size.height);
      continue;
    }
    add(false, y0);
    for (int y = y0; y <= y1; ++y) add(mask.at<std::uint8_t>(y - y0, x - x0) != 0, 1);
    add(false, size.height - 1 - y1);
  }
  counts.push_back(run);
  return counts;
}

std::string cocoJson(const RunSummary& summary, const BatchOptions& options) {
  Json images = Json::array();
  Json annotations = Json::array();
  for (std::size_t i = 0; i < summary.images.size(); ++i) {
    const ImageRecord& r = summary.images[i];
    if (r.status != Status::Ok) continue;  // no region, or a result the check does not vouch for
    const int imageId = static_cast<int>(i) + 1;
    images.push_back(
        {{"id", imageId}, {"file_name", r.image}, {"width", r.width}, {"height", r.height}});
    const std::filesystem::path file = options.output / (r.name + ".json");
    const std::optional<std::vector<ClippedFeature>> features = readClipped(file);
    if (!features) throw Error("cannot read back " + file.string() + " for the COCO file");
    for (const auto& parts : byContour(*features)) {
      Json a = {{"id", annotations.size() + 1}, {"image_id", imageId}};
      a.update(annotationJson(parts, cv::Size(r.width, r.height), options.process.grid));
      annotations.push_back(std::move(a));
    }
  }
  const Json j = {
      {"schema_version", kSchemaVersion},
      {"roiclip_version", roiclipVersion()},
      {"coordinates",
       "pixel, x right, y down, origin at the top-left corner of the top-left pixel (COCO's; "
       "NAME.json's coordinates + 0.5)"},
      {"info",
       {{"description", "roiclip run of " + inputList(options)}, {"version", roiclipVersion()}}},
      {"licenses", Json::array()},
      {"images", std::move(images)},
      {"annotations", std::move(annotations)},
      {"categories", {{{"id", kObjectCategory}, {"name", "object"}, {"supercategory", "object"}}}}};
  return j.dump() + "\n";
}

}  // namespace roiclip::batch::detail
