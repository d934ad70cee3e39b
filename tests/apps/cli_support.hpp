// SPDX-License-Identifier: MIT
// Running the built `roiclip` command line (ROICLIP_CLI) from a test: its exit code, stdout and
// stderr; a fresh folder per test.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/run_files.hpp"

namespace roiclip::testing {

struct CliRun {
  int exitCode = -1;
  std::string out;
  std::string err;
};

/// `roiclip ARGS` through the shell (ARGS quoted as a shell would need), stdout and stderr
/// caught in files in `dir` and removed again.
inline CliRun runCli(const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout.txt";
  const std::filesystem::path err = dir / "stderr.txt";
  const std::string command = std::string("'") + ROICLIP_CLI + "' " + args + " >'" + out.string() +
                              "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  CliRun r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readText(out);
  r.err = readText(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

/// A test with its own empty folder dir_ (removed afterwards; the pid keeps concurrent runs of
/// the suite apart) and run() for `roiclip ARGS` with its files in there.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("roiclip_cli_test_") + info->test_suite_name() + "_" + info->name() + "_" +
            std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  [[nodiscard]] CliRun run(const std::string& args) const { return runCli(args, dir_); }

  std::filesystem::path dir_;
};

}  // namespace roiclip::testing
