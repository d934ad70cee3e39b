// SPDX-License-Identifier: MIT
// Writes the hostile image files of hostile_images.hpp into a folder and lists what a run must
// report for each:  roiclip_batch_hostile_images DIR
#include <filesystem>
#include <iostream>

#include <opencv2/imgcodecs.hpp>

#include "hostile_images.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: roiclip_batch_hostile_images DIR\n";
    return 1;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  const cv::Mat scene = cv::imread(std::string(ROICLIP_IMAGES) + "/scene_07.png", cv::IMREAD_COLOR);
  if (scene.empty()) {
    std::cerr << "cannot read images/scene_07.png\n";
    return 1;
  }
  for (const auto& h : roiclip::testing::writeHostileImages(dir, scene)) {
    std::cout << h.file << ": " << h.status << " " << h.failure << " " << h.reason << "\n";
  }
  return 0;
}
