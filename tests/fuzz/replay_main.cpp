// SPDX-License-Identifier: MIT
// Corpus replay without libFuzzer: runs every file of the given folders (or the given files)
// through LLVMFuzzerTestOneInput, in name order. A bug in a target aborts the process, so the
// CTest test fails and the last "replay:" line names the input. A folder that is missing or
// holds no file is an error too: a corpus that silently vanished must not pass.
//
// With --expect-failure first, every input must still fail (each runs in a child process): that
// is how known_bugs/<target>/ holds reproducers of reported, unfixed bugs without failing CI,
// and it fails as soon as one of them passes, so the file moves into the corpus.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const bool expectFailure = argc > 1 && std::string(argv[1]) == "--expect-failure";
  const int first = expectFailure ? 2 : 1;
  if (argc <= first) {
    std::cerr << "usage: " << argv[0] << " [--expect-failure] CORPUS_DIR_OR_FILE...\n";
    return 2;
  }
  std::vector<fs::path> files;
  for (int a = first; a < argc; ++a) {
    const fs::path arg = argv[a];
    std::error_code ec;
    if (fs::is_regular_file(arg, ec)) {
      files.push_back(arg);
      continue;
    }
    if (!fs::is_directory(arg, ec)) {
      std::cerr << "replay: " << arg.string() << ": no such corpus folder or file\n";
      return 1;
    }
    std::vector<fs::path> inDir;
    for (const auto& entry : fs::directory_iterator(arg)) {
      if (entry.is_regular_file()) inDir.push_back(entry.path());
    }
    if (inDir.empty()) {
      std::cerr << "replay: " << arg.string() << ": corpus folder is empty\n";
      return 1;
    }
    std::sort(inDir.begin(), inDir.end());
    files.insert(files.end(), inDir.begin(), inDir.end());
  }
  for (const fs::path& file : files) {
    std::cout << "replay: " << file.string() << std::endl;
    std::ifstream in(file, std::ios::binary);
    if (!in) {
      std::cerr << "replay: cannot read " << file.string() << "\n";
      return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    const auto run = [&] {
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    };
    if (!expectFailure) {
      run();
      continue;
    }
    const pid_t child = fork();
    if (child == 0) {
      run();
      std::_Exit(0);
    }
    int status = 0;
    if (child < 0 || waitpid(child, &status, 0) != child) {
      std::cerr << "replay: cannot run a child process\n";
      return 1;
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      std::cerr << "replay: " << file.string()
                << " no longer fails: the bug is fixed, move the file into the corpus\n";
      return 1;
    }
    std::cout << "replay: still fails, as expected\n";
  }
  std::cout << "replay: " << files.size()
            << (expectFailure ? " inputs, all failing as expected\n" : " inputs, no failure\n");
  return 0;
}
