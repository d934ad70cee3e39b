// SPDX-License-Identifier: MIT
// roiclip::batch through the installed package: a blank image has no tags, so no ROI.
#include <roiclip/batch/process.hpp>

#include <iostream>

int main() {
  const cv::Mat blank(60, 80, CV_8UC1, cv::Scalar(255));
  const roiclip::batch::ImageResult r = roiclip::batch::processImage(blank, {});
  std::cout << "status " << roiclip::batch::toString(r.status) << "\n";
  return r.status == roiclip::batch::Status::NoRoi ? 0 : 1;
}
