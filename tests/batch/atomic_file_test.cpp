// SPDX-License-Identifier: MIT
// roiclip::io atomic files: the one writer, its temporary names and the cleaner. (Here rather
// than in tests/io because `roiclip run` is the writer's main user; the cases need only
// roiclip::io.)
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <roiclip/error.hpp>
#include <roiclip/io/atomic_file.hpp>
#include <roiclip/io/geojson.hpp>

#include "temp_dir.hpp"

namespace roiclip {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::recursive_directory_iterator(dir)) ++n;
  return n;
}

// A pid that has surely exited: a child we waited for.
pid_t deadPid() {
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  return dead;
}

TEST(AtomicFile, WritesReplacesAndLeavesNoTemporary) {
  const TempDir tmp("atomic_write");
  const fs::path file = tmp.path() / "a.json";
  io::writeFileAtomically(file, "first");
  EXPECT_EQ(readText(file), "first");
  io::writeFileAtomically(file, std::string("sec\0nd", 6));  // bytes as they are
  EXPECT_EQ(readText(file), std::string("sec\0nd", 6));
  io::writeFileAtomically(file, "");
  EXPECT_EQ(readText(file), "");
  EXPECT_EQ(entries(tmp.path()), 1u);
}

TEST(AtomicFile, TemporaryNamesAreHiddenInTheSameFolderWithPidAndCounter) {
  const fs::path t = io::temporaryPath(fs::path("out") / "sub" / "x.overlay.png", 1234, 7);
  EXPECT_EQ(t, fs::path("out") / "sub" / ".x.overlay.png.tmp.1234.7");
  EXPECT_EQ(io::temporaryOwner(t.filename().string()), 1234);
  EXPECT_EQ(io::temporaryOwner(".a.tmp.b.tmp.42.0"), 42);  // the last marker counts
  for (const char* other :
       {"x.png", ".x.png", "x.json.tmp.1.1", ".c.tmp.x.1", ".c.tmp.1.x", ".c.tmp.1", ".c.tmp..1",
        ".tmp.1.1", ".c.tmp.1234567890.1", "out.geojson.roiclip-tmp-99"}) {
    EXPECT_FALSE(io::temporaryOwner(other).has_value()) << other;
  }
}

TEST(AtomicFile, ErrorsNameTheFileNotTheTemporary) {
  const TempDir tmp("atomic_errors");
  const fs::path file = tmp.path() / "missing" / "out.json";
  try {
    io::writeFileAtomically(file, "{}");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_EQ(what.find(".tmp."), std::string::npos) << what;
  }
  // Renaming onto a folder fails after the temporary was written: it is removed again.
  fs::create_directories(tmp.path() / "folder" / "inside");
  EXPECT_THROW(io::writeFileAtomically(tmp.path() / "folder", "x"), Error);
  EXPECT_EQ(entries(tmp.path()), 2u);  // folder and folder/inside, no temporary
  // io's GeoJSON writers go through it too.
  try {
    io::writeGeoJson(PolygonSet{}, file.string());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find(".tmp."), std::string::npos) << e.what();
  }
}

TEST(AtomicFile, ConcurrentWritersOfOneFileNeverMeet) {
  const TempDir tmp("atomic_threads");
  const fs::path file = tmp.path() / "shared.txt";
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&file, t] {
      const std::string text(1000, static_cast<char>('a' + t));
      for (int i = 0; i < 50; ++i) io::writeFileAtomically(file, text);
    });
  }
  for (auto& t : threads) t.join();
  const std::string text = readText(file);
  ASSERT_EQ(text.size(), 1000u);
  EXPECT_EQ(text, std::string(1000, text[0]));  // one writer's bytes, never a mix
  EXPECT_EQ(entries(tmp.path()), 1u);
}

TEST(AtomicFile, StaleTemporariesOfDeadRunsAreRemoved) {
  const TempDir tmp("stale");
  fs::create_directories(tmp.path() / "sub");
  const pid_t dead = deadPid();
  const std::string deadTmp = ".a.json.tmp." + std::to_string(dead) + ".3";
  const std::string liveTmp = ".b.json.tmp." + std::to_string(::getppid()) + ".0";
  for (const std::string& f :
       {deadTmp, liveTmp, std::string(".c.tmp.x.1"), std::string("d.json.tmp.1.1")}) {
    std::ofstream(tmp.path() / "sub" / f) << "partial";
  }
  EXPECT_EQ(io::removeStaleTemporaries(tmp.path()), 1u);
  EXPECT_FALSE(fs::exists(tmp.path() / "sub" / deadTmp));
  EXPECT_TRUE(fs::exists(tmp.path() / "sub" / liveTmp));  // its process still runs
  EXPECT_TRUE(fs::exists(tmp.path() / "sub" / ".c.tmp.x.1"));
  EXPECT_TRUE(fs::exists(tmp.path() / "sub" / "d.json.tmp.1.1"));
}

TEST(AtomicFile, CleanerRemovesTemporariesOfEveryWriterOfADeadProcess) {
  // batch's NAME.json / overlays and io's GeoJSON files share the one temporary scheme, so one
  // cleaner finds all of them; temporaries of this process and of live ones stay.
  const TempDir tmp("atomic_clean");
  const long dead = deadPid();
  const std::vector<fs::path> stale = {
      io::temporaryPath(tmp.path() / "clipped.geojson", dead, 0),
      io::temporaryPath(tmp.path() / "a" / "b" / "scene.json", dead, 12),
      io::temporaryPath(tmp.path() / "scene.overlay.png", dead, 3)};
  const std::vector<fs::path> live = {
      io::temporaryPath(tmp.path() / "mine.json", ::getpid(), 0),
      io::temporaryPath(tmp.path() / "parent.json", ::getppid(), 0)};
  for (const auto& f : stale) {
    fs::create_directories(f.parent_path());
    std::ofstream(f) << "partial";
  }
  for (const auto& f : live) std::ofstream(f) << "partial";
  EXPECT_EQ(io::removeStaleTemporaries(tmp.path()), stale.size());
  for (const auto& f : stale) EXPECT_FALSE(fs::exists(f)) << f;
  for (const auto& f : live) EXPECT_TRUE(fs::exists(f)) << f;
  EXPECT_EQ(io::removeStaleTemporaries(tmp.path() / "no such folder"), 0u);
}

}  // namespace
}  // namespace roiclip
