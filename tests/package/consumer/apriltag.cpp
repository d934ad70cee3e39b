// SPDX-License-Identifier: MIT
// roiclip::apriltag through the installed package: a detector finds no tag in a blank image.
#include <roiclip/apriltag/detector.hpp>

#include <iostream>

int main() {
  roiclip::apriltag::Detector detector{roiclip::apriltag::DetectorOptions{}};
  const cv::Mat blank(60, 80, CV_8UC1, cv::Scalar(255));
  const auto tags = detector.detect(blank);
  std::cout << "tags " << tags.size() << "\n";
  return tags.empty() ? 0 : 1;
}
