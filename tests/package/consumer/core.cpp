// SPDX-License-Identifier: MIT
// roiclip::core through the installed package: intersect two squares.
#include <roiclip/roiclip.hpp>

#include <iostream>

int main() {
  const roiclip::Paths a = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  const roiclip::Paths b = {{{5, 0}, {15, 0}, {15, 10}, {5, 10}}};
  const roiclip::PolygonSet r = roiclip::intersect(a, b);
  std::cout << "area " << r.area() << "\n";
  return r.area() == 50.0 ? 0 : 1;
}
