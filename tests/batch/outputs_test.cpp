// SPDX-License-Identifier: MIT
// The output files a program reads (docs/outputs.md): the COCO file against the run's own masks,
// its RLE encoder, null IoU for images the mask check did not see, and stage times that cover
// the whole image. With ROICLIP_COCO_OUT set, the COCO file is kept there for check_coco.py.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <roiclip/batch/run.hpp>
#include <roiclip/opencv/rasterize.hpp>

#include "detail/coco.hpp"
#include "detail/result_json.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
namespace rb = roiclip::batch;
using Json = nlohmann::json;
using roiclip::Path;
using roiclip::Paths;

namespace {

const fs::path kImages = ROICLIP_IMAGES;

Json readJson(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return Json::parse(in);
}

std::vector<std::string> lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// COCO's uncompressed RLE back to a mask: column-major runs, 0s first.
cv::Mat decodeRle(const std::vector<std::int64_t>& counts, cv::Size size) {
  cv::Mat mask(size, CV_8UC1, cv::Scalar(0));
  std::int64_t at = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    EXPECT_GE(counts[i], 0);
    if (i > 0) {
      EXPECT_GT(counts[i], 0) << "run " << i << " is empty";
    }
    if (i % 2 == 1) {
      for (std::int64_t k = at; k < at + counts[i]; ++k) {
        mask.at<std::uint8_t>(static_cast<int>(k % size.height),
                              static_cast<int>(k / size.height)) = 255;
      }
    }
    at += counts[i];
  }
  EXPECT_EQ(at, static_cast<std::int64_t>(size.area()));
  return mask;
}

// One annotation's pixels, by the exact rule NAME.mask.png is drawn with.
cv::Mat annotationMask(const Json& a, cv::Size size) {
  const Json& s = a["segmentation"];
  if (s.is_object()) {
    EXPECT_EQ(s["size"], Json::array({size.height, size.width}));
    return decodeRle(s["counts"].get<std::vector<std::int64_t>>(), size);
  }
  Paths rings;
  for (const Json& flat : s) {
    EXPECT_GE(flat.size(), 6u);
    EXPECT_EQ(flat.size() % 2, 0u);
    Path ring;
    for (std::size_t i = 0; i + 1 < flat.size(); i += 2) {
      ring.emplace_back(flat[i].get<double>() - 0.5, flat[i + 1].get<double>() - 0.5);
    }
    rings.push_back(ring);
  }
  return roiclip::opencv::rasterize(rings, roiclip::FillRule::EvenOdd, size);
}

TEST(CocoRle, CountsAreColumnMajorRunsOfTheExactMask) {
  const cv::Size size(12, 9);
  const Paths ring = {{{1.5, 1}, {1.5, 7.25}, {9, 7.25}, {9, 1}},  // outer, with a hole
                      {{3, 3}, {6.5, 3}, {6.5, 5.5}, {3, 5.5}}};
  const std::vector<std::int64_t> counts = rb::detail::cocoRleCounts(ring, size);
  const cv::Mat expected = roiclip::opencv::rasterize(ring, roiclip::FillRule::EvenOdd, size);
  EXPECT_EQ(cv::countNonZero(decodeRle(counts, size) != expected), 0);
  // Column 0 is empty: the first run (0s) spans it and reaches into column 1.
  EXPECT_GT(counts.front(), size.height);
  // A region touching the first pixel starts with an empty run of 0s; one outside the image is
  // all 0s.
  EXPECT_EQ(rb::detail::cocoRleCounts({{{-1, -1}, {-1, 0.5}, {0.5, 0.5}, {0.5, -1}}}, size)[0], 0);
  EXPECT_EQ(rb::detail::cocoRleCounts({{{20, 20}, {20, 25}, {25, 25}, {25, 20}}}, size),
            std::vector<std::int64_t>({size.area()}));
}

struct CocoRun {
  roiclip::testing::TempDir tmp{"coco"};
  fs::path out = tmp.path() / "out";
  fs::path coco;
  rb::RunSummary summary;
  Json file;

  CocoRun() {
    const fs::path in = tmp.path() / "in";
    fs::create_directories(in / "sub");
    fs::copy_file(kImages / "scene_01.png", in / "a.png");
    fs::copy_file(kImages / "scene_07.png", in / "sub" / "b.png");
    cv::imwrite((in / "c_blank.png").string(), cv::Mat(48, 64, CV_8UC1, cv::Scalar(200)));
    std::ofstream(in / "d_corrupt.png") << "not a png";
    const char* keep = std::getenv("ROICLIP_COCO_OUT");
    coco = keep ? fs::path(keep) : tmp.path() / "coco" / "run.json";
    rb::BatchOptions options;
    options.inputs = {in};
    options.output = out;
    options.recursive = true;
    options.writeMasks = true;
    options.jobs = 2;
    options.coco = coco;
    summary = rb::run(options);
    file = readJson(coco);
  }
};

TEST(Coco, RunWritesAnnotationsOfEveryOkImage) {
  const CocoRun run;
  ASSERT_EQ(run.summary.images.size(), 4u);
  ASSERT_EQ(run.summary.ok, 2u);
  const Json& coco = run.file;
  EXPECT_EQ(coco["schema_version"], rb::kSchemaVersion);
  EXPECT_EQ(coco["roiclip_version"], rb::roiclipVersion());
  EXPECT_EQ(coco["categories"],
            Json::parse(R"([{"id": 1, "name": "object", "supercategory": "object"}])"));
  // Only the ok images, with ids from their place in the summary.
  ASSERT_EQ(coco["images"].size(), 2u);
  EXPECT_EQ(coco["images"][0], Json::parse(R"({"id": 1, "file_name": "a.png", "width": 800,
                                               "height": 600})"));
  EXPECT_EQ(coco["images"][1]["file_name"], "sub/b.png");
  EXPECT_EQ(coco["images"][1]["id"], 4);  // after c_blank.png and d_corrupt.png

  std::set<int> ids;
  int rle = 0;
  int polygons = 0;
  for (const Json& image : coco["images"]) {
    const cv::Size size(image["width"].get<int>(), image["height"].get<int>());
    const std::string name = image["file_name"].get<std::string>();
    const std::string stem = name.substr(0, name.size() - 4);
    const Json result = readJson(run.out / (stem + ".json"));
    cv::Mat all(size, CV_8UC1, cv::Scalar(0));
    double area = 0;
    int annotations = 0;
    for (const Json& a : coco["annotations"]) {
      if (a["image_id"] != image["id"]) continue;
      SCOPED_TRACE(name + " annotation " + a["id"].dump());
      EXPECT_TRUE(ids.insert(a["id"].get<int>()).second);
      EXPECT_EQ(a["iscrowd"], 0);
      EXPECT_EQ(a["category_id"], 1);
      EXPECT_EQ(a["rois"], Json::array({"hull"}));
      (a["segmentation"].is_object() ? rle : polygons) += 1;
      const cv::Mat mask = annotationMask(a, size);
      EXPECT_EQ(cv::countNonZero(mask & all), 0) << "annotations overlap";
      all |= mask;
      area += a["area"].get<double>();
      ++annotations;
      // The box holds every pixel centre of the annotation (COCO: centres at col + 0.5).
      const std::vector<double> box = a["bbox"].get<std::vector<double>>();
      std::vector<cv::Point> pixels;
      cv::findNonZero(mask, pixels);
      for (const cv::Point& p : pixels) {
        ASSERT_GE(p.x + 0.5, box[0]);
        ASSERT_LE(p.x + 0.5, box[0] + box[2]);
        ASSERT_GE(p.y + 0.5, box[1]);
        ASSERT_LE(p.y + 0.5, box[1] + box[3]);
      }
    }
    // One annotation per contour inside the ROI, together exactly the run's mask.
    EXPECT_EQ(annotations, result["contours_out"].get<int>()) << name;
    EXPECT_NEAR(area, result["clipped_area"].get<double>(), 1e-6 * area) << name;
    const cv::Mat expected =
        cv::imread((run.out / (stem + ".mask.png")).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(expected.size(), size);
    EXPECT_EQ(cv::countNonZero(all != expected), 0) << name;
  }
  EXPECT_EQ(ids.size(), coco["annotations"].size());
  EXPECT_GT(rle, 0);  // the scenes have objects with holes
  EXPECT_GT(polygons, 0);
}

TEST(Outputs, UncheckedImagesHaveNullIouAndEveryStageIsTimed) {
  const CocoRun run;
  const Json summary = readJson(run.out / "summary.json");
  EXPECT_EQ(summary["schema_version"], rb::kSchemaVersion);
  EXPECT_EQ(summary["roiclip_version"], rb::roiclipVersion());
  EXPECT_EQ(summary["coco"], run.coco.string());
  ASSERT_EQ(summary["images"].size(), 4u);
  for (const Json& row : summary["images"]) {
    SCOPED_TRACE(row["image"].get<std::string>());
    const bool ok = row["status"] == "ok";
    EXPECT_EQ(row["iou"].is_null(), !ok);
    const Json& t = row["stage_seconds"];
    EXPECT_EQ(t["total"], row["seconds"]);
    double sum = 0;
    for (const auto& [name, member] : rb::detail::kStageTimes) {
      (void)member;
      if (std::string(name) == "total") continue;
      EXPECT_GE(t[name].get<double>(), 0.0) << name;
      sum += t[name].get<double>();
    }
    // The stages cover the image: what they leave out is glue (checks, moves), well under 10 %.
    EXPECT_LE(sum, t["total"].get<double>() * (1 + 1e-9));
    EXPECT_GE(sum, 0.9 * t["total"].get<double>() - 1e-3);
    if (row["status"] != "failed") {
      EXPECT_GT(t["read"].get<double>(), 0.0);
    }
    if (ok) {
      EXPECT_GT(t["overlay"].get<double>(), 0.0);
      EXPECT_GT(t["write"].get<double>(), 0.0);
      // NAME.json holds the same times except its own write.
      const std::string name = row["name"].get<std::string>();
      const Json own = readJson(run.out / (name + ".json"))["seconds"];
      EXPECT_EQ(own["detect"], t["detect"]);
      EXPECT_LT(own["write"].get<double>(), t["write"].get<double>());
    }
  }
  // summary.csv: an empty IoU field for the rows without a check.
  const std::vector<std::string> csv = lines(run.out / "summary.csv");
  ASSERT_EQ(csv.size(), 5u);
  EXPECT_NE(csv[2].find(",no-roi,no-tags,"), std::string::npos) << csv[2];
  EXPECT_NE(csv[2].find(",0.000,,0,"), std::string::npos) << csv[2];  // clipped_area, iou, off-band
  EXPECT_NE(csv[3].find(",failed,unreadable,"), std::string::npos) << csv[3];
  EXPECT_NE(csv[3].find(",0.000,,0,"), std::string::npos) << csv[3];
}

}  // namespace
