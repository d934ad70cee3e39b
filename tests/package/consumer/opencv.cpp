// SPDX-License-Identifier: MIT
// roiclip::opencv through the installed package: rasterise a 10 x 5 px rectangle.
#include <roiclip/opencv/rasterize.hpp>

#include <iostream>

int main() {
  const roiclip::Paths rect = {{{-0.5, -0.5}, {9.5, -0.5}, {9.5, 4.5}, {-0.5, 4.5}}};
  const cv::Mat mask =
      roiclip::opencv::rasterize(rect, roiclip::FillRule::EvenOdd, cv::Size(20, 20));
  const int pixels = cv::countNonZero(mask);
  std::cout << "area " << pixels << "\n";
  return pixels == 50 ? 0 : 1;
}
