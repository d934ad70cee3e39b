// roiclip command line. Subcommands are thin: parse, call the library, write.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"roiclip: exact clipping of self-intersecting polygons"};
  app.require_subcommand(1);
  std::string input = "images";
  std::string output = "out";
  auto* run = app.add_subcommand("run", "process a folder of images (AprilTag ROI + contours)");
  run->add_option("input", input, "folder of images")->capture_default_str();
  run->add_option("-o,--output", output, "output folder")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  if (run->parsed()) {
    std::cerr << "roiclip run: the batch pipeline (tag detection, contours, clipping) is not "
                 "built yet; it needs the AprilTag layer, the OpenCV layer and the batch app.\n";
    return 0;
  }
  return 0;
}
