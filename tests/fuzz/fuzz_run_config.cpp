// SPDX-License-Identifier: MIT
// libFuzzer target: the `roiclip run --config FILE` reader (roiclip::app::ConfigJson) on the
// bytes, then CLI11's config path with it as `roiclip` sets it up (RunCommand: the items go to
// `run`'s options, through their checks and the library's parsers: parseContourMethod,
// parsePolarity, parseFillRule, parseRoiSpec). A refused file is a CLI::ParseError (the app
// turns it into exit 1 or 2); any other exception is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <typeinfo>

#include <CLI/CLI.hpp>

#include "config_json.hpp"
#include "fuzz_support.hpp"
#include "run_command.hpp"

namespace {

template <class Body>
void expectParseErrorsOnly(const char* what, Body&& body) {
  try {
    body();
  } catch (const CLI::ParseError&) {
  } catch (const std::exception& e) {
    roiclip::fuzz::fail(std::string(what) + ": exception " + typeid(e).name() + ": " + e.what());
  } catch (...) {
    roiclip::fuzz::fail(std::string(what) + ": exception not derived from std::exception");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  CLI::App app{"roiclip"};
  const roiclip::app::RunCommand run(app);
  expectParseErrorsOnly("ConfigJson::from_config", [&] {
    std::istringstream in(text);
    (void)roiclip::app::ConfigJson(*run.subcommand()).from_config(in);
  });
  expectParseErrorsOnly("parse_from_stream", [&] {
    std::istringstream in(text);
    app.parse_from_stream(in);
  });
  return 0;
}
