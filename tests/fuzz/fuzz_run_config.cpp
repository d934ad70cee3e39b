// libFuzzer target: the `roiclip run --config FILE` reader (roiclip::batch::configToArguments)
// on the bytes as text, then the option values through the parsers the app hands them to
// (parseContourMethod, parsePolarity, parseFillRule, parseRoiSpec), as `roiclip run` does.
// Only roiclip::Error may escape.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <roiclip/apriltag/roi.hpp>
#include <roiclip/batch/process.hpp>
#include <roiclip/batch/run.hpp>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roiclip;
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> args;
  fuzz::expectDocumentedErrors("configToArguments",
                               [&] { args = batch::configToArguments(text, "<fuzz>"); });
  // Every option name with the argument after it (a flag's neighbour is another option name:
  // the parsers must reject that too with a documented error).
  for (std::size_t i = 0; i + 1 < args.size(); ++i) {
    const std::string& key = args[i];
    const std::string& value = args[i + 1];
    fuzz::expectDocumentedErrors(key.c_str(), [&] {
      batch::ContourOptions contours;
      if (key == "--method") batch::parseContourMethod(value, contours);
      if (key == "--polarity") batch::parsePolarity(value);
      if (key == "--fill-rule" || key == "--roi-fill-rule") parseFillRule(value.c_str());
      if (key == "--roi") apriltag::parseRoiSpec(value);
    });
  }
  return 0;
}
