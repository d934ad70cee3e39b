// SPDX-License-Identifier: MIT
// Throughput input for `roiclip run`: N 1920x1080 scenes made from the bundled ones (upscaled to
// 1080 rows, padded left and right with the table grey, a small brightness offset per copy so
// the files differ). Not a test; build it with
//   cmake --build BUILD --target roiclip_batch_hd_scenes
//   BUILD/tests/batch/roiclip_batch_hd_scenes images /tmp/hd 200
//   /usr/bin/time -v BUILD/apps/roiclip/roiclip run /tmp/hd -o /tmp/hd_out --jobs 2 --force -q
// (roiclip-make-scenes renders only the eight bundled scenes at their own sizes.)
#include <cstdio>
#include <iostream>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: roiclip_batch_hd_scenes IMAGES_DIR OUT_DIR COUNT\n";
    return 1;
  }
  const std::string in = argv[1];
  const std::string out = argv[2];
  const int count = std::stoi(argv[3]);
  constexpr int kWidth = 1920;
  constexpr int kHeight = 1080;
  constexpr int kTableGrey = 95;
  for (int i = 0; i < count; ++i) {
    const std::string source = in + "/scene_0" + std::to_string(i % 8 + 1) + ".png";
    const cv::Mat src = cv::imread(source, cv::IMREAD_GRAYSCALE);
    if (src.empty()) {
      std::cerr << source << ": cannot read\n";
      return 2;
    }
    cv::Mat big;
    const double scale = static_cast<double>(kHeight) / src.rows;
    cv::resize(src, big, cv::Size(), scale, scale, cv::INTER_CUBIC);
    const int pad = (kWidth - big.cols) / 2;
    cv::copyMakeBorder(big, big, 0, 0, pad, kWidth - big.cols - pad, cv::BORDER_CONSTANT,
                       cv::Scalar(kTableGrey));
    big += cv::Scalar(i / 8 % 5);
    char name[32];
    std::snprintf(name, sizeof name, "/hd_%03d.png", i);
    if (!cv::imwrite(out + name, big)) {
      std::cerr << out << name << ": cannot write\n";
      return 3;
    }
  }
  return 0;
}
