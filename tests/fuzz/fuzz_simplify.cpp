// SPDX-License-Identifier: MIT
// libFuzzer target: roiclip::simplify on small path sets, checked against the exact winding
// number of the input (tests/support/oracle.hpp).
//
// Input bytes: [header: fill rule (bits 0-1), coordinate mode (bits 2-4)]
//              then paths, each a length byte (0..15) and one byte per vertex (x low nibble,
//              y high nibble), decoded by fuzz_support.hpp.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roiclip;
  if (size == 0) return 0;
  fuzz::ByteReader in(data, size);
  const std::uint8_t header = in.next();
  const auto rule = static_cast<FillRule>(header & 3);
  const int mode = (header >> 2) & 7;
  const Paths paths = fuzz::decodePaths(in, mode, 8, 48);
  PolygonSet result;
  // Small on-grid coordinates: no exception at all is expected.
  fuzz::expectDocumentedErrors(
      "simplify", [&] { result = simplify(paths, rule); }, true);
  fuzz::checkAgainstOracle(
      result, {&paths}, [&](const std::vector<long long>& w) { return isFilled(rule, w[0]); },
      [&] {
        return std::string("simplify, fill rule ") + toString(rule) +
               ", paths: " + testing::describe(paths);
      });
  return 0;
}
