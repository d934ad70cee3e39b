// SPDX-License-Identifier: MIT
// The roiclip::io tests' check of an error: an InvalidInputError whose one-line message holds
// every fragment given.
#pragma once

#include <functional>
#include <initializer_list>
#include <string>

#include <gtest/gtest.h>

#include <roiclip/error.hpp>
#include <roiclip/io/feature.hpp>

namespace roiclip::io {

// What the CLI's --strict reads with: degenerate rings and lines refused (the default keeps them).
inline ReadOptions strictOptions() {
  ReadOptions options;
  options.allowDegenerateRings = false;
  return options;
}

// Runs `f`, requires an InvalidInputError and every fragment in its message.
inline void expectInvalid(const std::function<void()>& f,
                          std::initializer_list<std::string> fragments) {
  try {
    f();
    ADD_FAILURE() << "no InvalidInputError thrown";
  } catch (const InvalidInputError& e) {
    const std::string message = e.what();
    for (const std::string& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "message \"" << message << "\" lacks \"" << fragment << "\"";
    }
    EXPECT_EQ(message.find('\n'), std::string::npos) << "message must be one line: " << message;
  }
}

}  // namespace roiclip::io
