// SPDX-License-Identifier: MIT
// Throughput of the main job at 1080p: batch::Processor::process on 200 generated HD scenes
// (the bundled scenes upscaled to 1080 rows, padded to 1920 columns with the table grey, a
// brightness offset per copy, as tests/batch/make_hd_scenes.cpp writes them), one thread.
//
// Rows:
//   Hd/before: the settings of 0.1 (AprilTag quads at full resolution, the tags kept in the
//              region) through today's pipeline;
//   Hd/defaults: today's defaults (automatic decimation: 4 at 1080p, finer passes when needed,
//                tags excluded).
// Counters: images/s (per core), the per-stage milliseconds per image (ImageResult::seconds),
// tags found over all images, and the largest tag corner error against the generator's ground
// truth (px). Decoding is not included (the images are in memory): see bench/batch/README.md
// for the whole `roiclip run` on files.
//   build/bench/batch/roiclip_hd_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <array>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <roiclip/batch/process.hpp>

namespace {

constexpr int kWidth = 1920;
constexpr int kHeight = 1080;
constexpr int kScenes = 200;

struct Scene {
  cv::Mat image;
  std::vector<std::pair<int, std::array<glm::dvec2, 4>>> corners;  // ground truth, HD pixels
};

const std::vector<Scene>& scenes() {
  static const std::vector<Scene> all = [] {
    std::vector<Scene> out;
    for (int i = 0; i < kScenes; ++i) {
      const std::string stem = std::string(ROICLIP_IMAGES) + "/scene_0" + std::to_string(i % 8 + 1);
      const cv::Mat src = cv::imread(stem + ".png", cv::IMREAD_GRAYSCALE);
      const double scale = static_cast<double>(kHeight) / src.rows;
      cv::Mat big;
      cv::resize(src, big, cv::Size(), scale, scale, cv::INTER_CUBIC);
      const int pad = (kWidth - big.cols) / 2;
      cv::copyMakeBorder(big, big, 0, 0, pad, kWidth - big.cols - pad, cv::BORDER_CONSTANT,
                         cv::Scalar(95));
      big += cv::Scalar(i / 8 % 5);
      Scene s;
      s.image = big;
      std::ifstream in(stem + ".json");
      const nlohmann::json j = nlohmann::json::parse(in);
      for (const auto& tag : j.at("tags")) {
        std::array<glm::dvec2, 4> c{};
        for (int k = 0; k < 4; ++k) {
          // Pixel centres: x_hd + 0.5 = scale * (x + 0.5), then the padding.
          c[k] = {(tag["corners"][k][0].get<double>() + 0.5) * scale - 0.5 + pad,
                  (tag["corners"][k][1].get<double>() + 0.5) * scale - 0.5};
        }
        s.corners.emplace_back(tag["id"].get<int>(), c);
      }
      out.push_back(std::move(s));
    }
    return out;
  }();
  return all;
}

void run(benchmark::State& state, const roiclip::batch::RunOptions& options) {
  const std::vector<Scene>& all = scenes();
  const roiclip::batch::Processor processor(options);
  roiclip::batch::StageTimes sum;
  double worst = 0;
  std::int64_t tags = 0, wanted = 0, images = 0, ok = 0;
  for (auto _ : state) {
    for (const Scene& s : all) {
      const roiclip::batch::ImageResult r = processor.process(s.image);
      benchmark::DoNotOptimize(r.clippedArea);
      ++images;
      ok += r.status == roiclip::batch::Status::Ok ? 1 : 0;
      sum.detect += r.seconds.detect;
      sum.roi += r.seconds.roi;
      sum.contours += r.seconds.contours;
      sum.clip += r.seconds.clip;
      sum.check += r.seconds.check;
      sum.total += r.seconds.total;
      wanted += static_cast<std::int64_t>(s.corners.size());
      for (const auto& [id, truth] : s.corners) {
        for (const auto& d : r.tags) {
          if (d.id != id) continue;
          ++tags;
          for (int k = 0; k < 4; ++k) worst = std::max(worst, glm::length(d.corners[k] - truth[k]));
        }
      }
    }
  }
  const auto perImage = [&](double seconds) {
    return benchmark::Counter(1e3 * seconds / static_cast<double>(images));
  };
  state.counters["images_per_s"] =
      benchmark::Counter(static_cast<double>(images), benchmark::Counter::kIsRate);
  state.counters["ok"] = benchmark::Counter(static_cast<double>(ok) / static_cast<double>(images));
  state.counters["detect_ms"] = perImage(sum.detect);
  state.counters["roi_ms"] = perImage(sum.roi);
  state.counters["contours_ms"] = perImage(sum.contours);
  state.counters["clip_ms"] = perImage(sum.clip);
  state.counters["check_ms"] = perImage(sum.check);
  state.counters["total_ms"] = perImage(sum.total);
  state.counters["tags_found"] =
      benchmark::Counter(static_cast<double>(tags) / static_cast<double>(wanted));
  state.counters["max_corner_err_px"] = worst;
}

void before(benchmark::State& state) {
  roiclip::batch::RunOptions options;
  options.detector.quadDecimate = 1.0f;
  options.keepTags = true;
  run(state, options);
}

void defaults(benchmark::State& state) {
  const roiclip::batch::RunOptions options;  // a named object: GCC 12 warns on the temporary's
  run(state, options);                       // string (-Wmaybe-uninitialized, a false positive)
}

void decimate(benchmark::State& state) {
  roiclip::batch::RunOptions options;
  options.detector.quadDecimate = static_cast<float>(state.range(0));
  run(state, options);
}

BENCHMARK(before)->Name("Hd/before")->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(defaults)->Name("Hd/defaults")->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(decimate)
    ->Name("Hd/decimate")
    ->Arg(3)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
