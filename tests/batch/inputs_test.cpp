// SPDX-License-Identifier: MIT
// The inputs of roiclip::batch::run(): several inputs, image files, globs, list files, videos
// (one row per frame, resumed per frame), shards (an exact partition), EXIF orientation (a JPEG
// and a 16-bit PNG with alpha, written here with their EXIF bytes) and 12-bit data in 16 bits.
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <roiclip/batch/process.hpp>
#include <roiclip/batch/run.hpp>

#include "detail/folder.hpp"
#include "detail/image_file.hpp"
#include "detail/shard.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
namespace rb = roiclip::batch;
using Json = nlohmann::json;
using roiclip::testing::TempDir;

namespace {

const fs::path kImages = ROICLIP_IMAGES;

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeText(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

void copyScene(const std::string& scene, const fs::path& to) {
  fs::create_directories(to.parent_path());
  fs::copy_file(kImages / (scene + ".png"), to, fs::copy_options::overwrite_existing);
}

rb::BatchOptions optionsFor(std::vector<fs::path> inputs, const fs::path& output) {
  rb::BatchOptions o;
  o.inputs = std::move(inputs);
  o.output = output;
  o.jobs = 2;
  return o;
}

std::vector<std::string> images(const rb::RunSummary& s) {
  std::vector<std::string> out;
  for (const auto& r : s.images) out.push_back(r.image);
  return out;
}

std::vector<std::string> names(const std::vector<rb::detail::Job>& jobs) {
  std::vector<std::string> out;
  for (const auto& j : jobs) out.push_back(j.name);
  return out;
}

// A TIFF-structured EXIF block (little or big endian) with one IFD0 entry: Orientation.
std::string exifBlock(int orientation, bool littleEndian = true) {
  const auto u16 = [&](unsigned v) {
    return littleEndian ? std::string{static_cast<char>(v & 0xFF), static_cast<char>(v >> 8)}
                        : std::string{static_cast<char>(v >> 8), static_cast<char>(v & 0xFF)};
  };
  const auto u32 = [&](std::uint32_t v) {
    return littleEndian ? u16(v & 0xFFFF) + u16(v >> 16) : u16(v >> 16) + u16(v & 0xFFFF);
  };
  std::string t = littleEndian ? "II" : "MM";
  t += u16(42) + u32(8);                                           // header, IFD0 at offset 8
  t += u16(1);                                                     // one entry
  t += u16(0x0112) + u16(3) + u32(1) + u16(orientation) + u16(0);  // Orientation, SHORT, 1
  t += u32(0);                                                     // no next IFD
  return t;
}

// `jpeg` (a JPEG file's bytes) with an Exif APP1 segment saying `orientation` right after SOI.
std::string withExifApp1(const std::string& jpeg, int orientation) {
  const std::string payload = std::string("Exif\0\0", 6) + exifBlock(orientation, false);
  const std::size_t length = payload.size() + 2;
  std::string segment = "\xFF\xE1";
  segment += static_cast<char>(length >> 8);
  segment += static_cast<char>(length & 0xFF);
  return jpeg.substr(0, 2) + segment + payload + jpeg.substr(2);
}

// `png` (a PNG file's bytes) with an eXIf chunk saying `orientation` right after IHDR.
std::string withExifChunk(const std::string& png, int orientation) {
  const std::string body = "eXIf" + exifBlock(orientation);
  const auto be32 = [](std::uint32_t v) {
    return std::string{static_cast<char>(v >> 24), static_cast<char>((v >> 16) & 0xFF),
                       static_cast<char>((v >> 8) & 0xFF), static_cast<char>(v & 0xFF)};
  };
  const auto crc = static_cast<std::uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size())));
  const std::size_t afterIhdr = 8 + 4 + 4 + 13 + 4;
  return png.substr(0, afterIhdr) + be32(static_cast<std::uint32_t>(body.size() - 4)) + body +
         be32(crc) + png.substr(afterIhdr);
}

std::string encode(const std::string& ext, const cv::Mat& image) {
  std::vector<uchar> bytes;
  EXPECT_TRUE(cv::imencode(ext, image, bytes));
  return std::string(bytes.begin(), bytes.end());
}

// The stored pixels of an upright image that EXIF orientation `o` (3, 6 or 8: the rotations)
// turns upright again.
cv::Mat storedFor(const cv::Mat& upright, int o) {
  cv::Mat m;
  if (o == 3) cv::rotate(upright, m, cv::ROTATE_180);
  if (o == 6) cv::rotate(upright, m, cv::ROTATE_90_COUNTERCLOCKWISE);  // "turn clockwise to view"
  if (o == 8) cv::rotate(upright, m, cv::ROTATE_90_CLOCKWISE);
  return m;
}

TEST(BatchInputs, ExifOrientationOfAJpegAsImreadAppliesIt) {
  const TempDir tmp("exif_jpeg");
  cv::Mat stored(30, 50, CV_8UC3);
  cv::randu(stored, 0, 255);
  cv::GaussianBlur(stored, stored, cv::Size(5, 5), 0);  // JPEG-friendly content
  const std::string jpeg = encode(".jpg", stored);
  for (int o = 1; o <= 8; ++o) {
    SCOPED_TRACE(o);
    const fs::path file = tmp.path() / ("o" + std::to_string(o) + ".jpg");
    writeText(file, withExifApp1(jpeg, o));
    EXPECT_EQ(rb::readImageHeader(file.string())->orientation, o);
    const cv::Mat ours = rb::readImage(file.string());
    const cv::Mat opencv = cv::imread(file.string(), cv::IMREAD_COLOR);  // applies EXIF
    ASSERT_EQ(ours.size(), opencv.size());
    EXPECT_EQ(ours.size(), o >= 5 ? cv::Size(30, 50) : cv::Size(50, 30));
    EXPECT_EQ(cv::norm(ours, opencv, cv::NORM_INF), 0.0);
    // IMREAD_UNCHANGED (what keeps 16-bit and alpha) ignores EXIF in OpenCV 4.6.
    EXPECT_EQ(cv::imread(file.string(), cv::IMREAD_UNCHANGED).size(), cv::Size(50, 30));
  }
  // Malformed or absent EXIF: upright as stored.
  EXPECT_EQ(rb::exifOrientation(nullptr, 0), 1);
  const std::string bad = exifBlock(9);
  EXPECT_EQ(rb::exifOrientation(reinterpret_cast<const unsigned char*>(bad.data()), bad.size()), 1);
  const std::string cut = exifBlock(6).substr(0, 16);
  EXPECT_EQ(rb::exifOrientation(reinterpret_cast<const unsigned char*>(cut.data()), cut.size()), 1);
  writeText(tmp.path() / "plain.jpg", jpeg);
  EXPECT_EQ(rb::readImageHeader((tmp.path() / "plain.jpg").string())->orientation, 1);
}

TEST(BatchInputs, ExifRotatedJpegIsProcessedUpright) {
  const TempDir tmp("exif_scene");
  const cv::Mat upright = cv::imread((kImages / "scene_07.png").string(), cv::IMREAD_COLOR);
  const fs::path file = tmp.path() / "in" / "rotated.jpg";
  // Stored turned a quarter counter-clockwise; orientation 6 says "turn clockwise to view".
  writeText(file, withExifApp1(encode(".jpg", storedFor(upright, 6)), 6));
  writeText(tmp.path() / "in" / "upright.jpg", encode(".jpg", upright));
  const cv::Mat read = rb::readImage(file.string());
  EXPECT_EQ(read.size(), upright.size());  // 640 x 480, not 480 x 640

  const rb::RunOptions defaults;
  const rb::ImageResult rotated = rb::processImage(read, defaults);
  const rb::ImageResult plain =
      rb::processImage(rb::readImage((tmp.path() / "in" / "upright.jpg").string()), defaults);
  ASSERT_EQ(rotated.status, rb::Status::Ok) << rotated.reason;
  ASSERT_EQ(plain.status, rb::Status::Ok) << plain.reason;
  ASSERT_EQ(rotated.tags.size(), 4u);
  ASSERT_EQ(plain.tags.size(), rotated.tags.size());
  for (std::size_t i = 0; i < plain.tags.size(); ++i) {
    EXPECT_EQ(rotated.tags[i].id, plain.tags[i].id);
    EXPECT_NEAR(rotated.tags[i].centre.x, plain.tags[i].centre.x, 1.0);
    EXPECT_NEAR(rotated.tags[i].centre.y, plain.tags[i].centre.y, 1.0);
  }

  const rb::RunSummary s = rb::run(optionsFor({file}, tmp.path() / "out"));
  ASSERT_EQ(s.images.size(), 1u);
  EXPECT_EQ(s.images[0].status, rb::Status::Ok);
  EXPECT_EQ(s.images[0].width, upright.cols);
  EXPECT_EQ(s.images[0].height, upright.rows);
  // The overlay is the upright image with the caption band above it.
  const cv::Mat overlay = cv::imread((tmp.path() / "out" / "rotated.overlay.png").string());
  EXPECT_EQ(overlay.cols, upright.cols);
  EXPECT_GT(overlay.rows, upright.rows);
}

TEST(BatchInputs, ExifOrientationKeepsSixteenBitAndAlpha) {
  const TempDir tmp("exif_png16");
  cv::Mat upright(20, 36, CV_16UC4);
  cv::randu(upright, 0, 65535);
  for (int o : {3, 6, 8}) {
    SCOPED_TRACE(o);
    const fs::path file = tmp.path() / ("o" + std::to_string(o) + ".png");
    writeText(file, withExifChunk(encode(".png", storedFor(upright, o)), o));
    ASSERT_EQ(cv::imread(file.string(), cv::IMREAD_UNCHANGED).type(), CV_16UC4);
    EXPECT_EQ(rb::readImageHeader(file.string())->orientation, o);
    const cv::Mat read = rb::readImage(file.string());
    ASSERT_EQ(read.type(), CV_16UC4);
    ASSERT_EQ(read.size(), upright.size());
    EXPECT_EQ(cv::norm(read, upright, cv::NORM_INF), 0.0);
  }
}

TEST(BatchInputs, TwelveBitDataIsScaledByItsSignificantBits) {
  cv::Mat twelve(2, 3, CV_16UC1, cv::Scalar(0));
  twelve.at<std::uint16_t>(0, 1) = 4095;
  twelve.at<std::uint16_t>(1, 2) = 2048;
  cv::Mat m = twelve.clone();
  rb::scaleToSignificantBits(m);
  EXPECT_EQ(m.at<std::uint16_t>(0, 1), 65535);
  EXPECT_EQ(m.at<std::uint16_t>(1, 2), 32776);  // 2048 x 65535 / 4095, rounded
  EXPECT_EQ(m.at<std::uint16_t>(0, 0), 0);
  // All 16 bits used, or not 16-bit: unchanged.
  cv::Mat full = twelve.clone();
  full.at<std::uint16_t>(0, 0) = 40000;
  cv::Mat copy = full.clone();
  rb::scaleToSignificantBits(copy);
  EXPECT_EQ(cv::norm(copy, full, cv::NORM_INF), 0.0);
  cv::Mat eight(2, 2, CV_8UC1, cv::Scalar(7));
  rb::scaleToSignificantBits(eight);
  EXPECT_EQ(eight.at<uchar>(0, 0), 7);
  // Alpha is not data: 12-bit colour under an opaque 16-bit alpha is scaled, alpha kept.
  cv::Mat bgra(1, 1, CV_16UC4, cv::Scalar(4095, 0, 1000, 65535));
  rb::scaleToSignificantBits(bgra);
  using Bgra16 = cv::Vec<std::uint16_t, 4>;
  EXPECT_EQ(bgra.at<Bgra16>(0, 0), Bgra16(65535, 0, 16004, 65535));

  // Through a run: a 12-bit scene in a 16-bit PNG gives the 8-bit scene's figures.
  const TempDir tmp("twelve");
  const cv::Mat gray = cv::imread((kImages / "scene_05.png").string(), cv::IMREAD_GRAYSCALE);
  cv::Mat gray12;
  gray.convertTo(gray12, CV_16U, 4095.0 / 255.0);
  fs::create_directories(tmp.path() / "in");
  ASSERT_TRUE(cv::imwrite((tmp.path() / "in" / "g12.png").string(), gray12));
  copyScene("scene_05", tmp.path() / "in" / "g8.png");
  const cv::Mat read = rb::readImage((tmp.path() / "in" / "g12.png").string());
  cv::Mat back;
  read.convertTo(back, CV_8U, 255.0 / 65535.0);
  EXPECT_EQ(cv::norm(back, gray, cv::NORM_INF), 0.0);  // the full 8-bit range again
  const rb::RunSummary s = rb::run(optionsFor({tmp.path() / "in"}, tmp.path() / "out"));
  ASSERT_EQ(s.ok, 2u);
  EXPECT_DOUBLE_EQ(s.images[0].clippedArea, s.images[1].clippedArea);
}

TEST(BatchInputs, ShardsPartitionTheInputsExactly) {
  // The FNV-1a 64 test vectors.
  EXPECT_EQ(rb::fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(rb::fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(rb::fnv1a64("foobar"), 0x85944171f73967e8ULL);

  std::vector<rb::detail::Job> jobs;
  for (int i = 0; i < 60; ++i) {
    rb::detail::Job j;
    j.rel = (i % 3 == 0 ? "sub/" : "") + std::string("img_") + std::to_string(i) +
            (i % 7 == 0 ? ".mp4" : ".png");
    j.name = j.rel;
    jobs.push_back(j);
  }
  for (int n = 1; n <= 5; ++n) {
    SCOPED_TRACE(n);
    std::map<std::string, int> seen;
    std::size_t smallest = jobs.size();
    for (int i = 0; i < n; ++i) {
      const auto share = rb::detail::selectShard(jobs, {i, n});
      EXPECT_EQ(names(share), names(rb::detail::selectShard(jobs, {i, n})));  // deterministic
      EXPECT_TRUE(std::is_sorted(share.begin(), share.end(), [&](const auto& a, const auto& b) {
        return std::stoi(a.rel.substr(a.rel.find('_') + 1)) <
               std::stoi(b.rel.substr(b.rel.find('_') + 1));
      })) << "input order kept";
      smallest = std::min(smallest, share.size());
      for (const auto& j : share) ++seen[j.rel];
    }
    EXPECT_EQ(seen.size(), jobs.size());
    for (const auto& [rel, count] : seen) EXPECT_EQ(count, 1) << rel;
    EXPECT_GT(smallest, jobs.size() / n / 3) << "every shard gets a fair share";
  }
  EXPECT_THROW(rb::detail::selectShard(jobs, {2, 2}), roiclip::InvalidInputError);
  EXPECT_THROW(rb::detail::selectShard(jobs, {0, 0}), roiclip::InvalidInputError);

  EXPECT_EQ(rb::parseShard("0/1").count, 1);
  EXPECT_EQ(rb::parseShard("3/4").index, 3);
  EXPECT_EQ(rb::parseShard("3/4").count, 4);
  for (const char* bad : {"4/4", "-1/4", "1", "/4", "1/", "a/b", "1/0", "1/4x", " 1/4", ""}) {
    EXPECT_THROW(rb::parseShard(bad), roiclip::InvalidInputError) << bad;
  }
}

TEST(BatchInputs, ShardedRunsShareOneOutputFolder) {
  const TempDir tmp("shard_run");
  const char* scenes[] = {"scene_07", "scene_08", "scene_07", "scene_08", "scene_07"};
  std::set<std::string> all;
  for (int i = 0; i < 5; ++i) {
    const std::string f = "s" + std::to_string(i) + ".png";
    copyScene(scenes[i], tmp.path() / "in" / f);
    all.insert(f);
  }
  std::multiset<std::string> done;
  for (int i = 0; i < 2; ++i) {
    rb::BatchOptions o = optionsFor({tmp.path() / "in"}, tmp.path() / "out");
    o.shard = {i, 2};
    const rb::RunSummary s = rb::run(o);
    EXPECT_EQ(s.total, s.images.size());
    EXPECT_TRUE(s.allOk());
    for (const auto& r : s.images) {
      done.insert(r.image);
      EXPECT_TRUE(fs::exists(tmp.path() / "out" / (r.name + ".json")));
    }
  }
  EXPECT_EQ(std::set<std::string>(done.begin(), done.end()), all);
  EXPECT_EQ(done.size(), all.size());
  rb::BatchOptions bad = optionsFor({tmp.path() / "in"}, tmp.path() / "out");
  bad.shard = {1, 1};
  EXPECT_THROW(rb::run(bad), roiclip::InvalidInputError);
}

TEST(BatchInputs, FilesGlobsAndListFiles) {
  const TempDir tmp("lists");
  const fs::path in = tmp.path() / "in";
  copyScene("scene_07", in / "a.png");
  copyScene("scene_08", in / "b.png");
  copyScene("scene_07", in / "sub" / "c.png");
  copyScene("scene_08", in / "other" / "a.png");
  writeText(in / "notes.md", "not an image");
  const fs::path out = tmp.path() / "out";

  // Files: named by their file name; the same file name from two folders stays apart.
  const auto files = rb::detail::listJobs(
      {in / "sub" / "c.png", in / "a.png", in / "other" / "a.png"}, out, false);
  EXPECT_EQ(names(files), (std::vector<std::string>{"c", "a.png", "a.png~2"}));
  EXPECT_EQ(files[1].rel, "a.png");
  EXPECT_EQ(files[2].rel, "a.png");
  // A folder and a file in it: the file once, under its first name.
  const auto twice =
      rb::detail::listJobs({in, in / "a.png", in / "sub" / ".." / "b.png"}, out, false);
  EXPECT_EQ(names(twice), (std::vector<std::string>{"a", "b"}));

  // Globs: sorted matches; folders among them are folder inputs; non-media files left out.
  const auto globbed = rb::detail::listJobs({(in / "*").string()}, out, false);
  std::vector<std::string> rels;
  for (const auto& j : globbed) rels.push_back(j.rel);
  EXPECT_EQ(rels, (std::vector<std::string>{"a.png", "b.png", "a.png", "c.png"}));
  EXPECT_EQ(names(globbed), (std::vector<std::string>{"a.png", "b", "a.png~2", "c"}));
  EXPECT_THROW(rb::detail::listJobs({(in / "*.tif").string()}, out, false),
               roiclip::InvalidInputError);
  EXPECT_THROW(rb::detail::listJobs({in / "nowhere.png"}, out, false), roiclip::InvalidInputError);

  // A list file: comments, blank lines, relative (to the list), absolute and missing entries.
  writeText(tmp.path() / "lists" / "batch.txt",
            "# images for today\n\n../in/a.png\n  ../in/sub/c.png  \r\n" + (in / "b.png").string() +
                "\n# ../in/other/a.png\n../in/gone.png\n../in/gone.mp4\n");
  const rb::RunSummary s = rb::run(optionsFor({tmp.path() / "lists" / "batch.txt"}, out));
  EXPECT_EQ(images(s),
            (std::vector<std::string>{"a.png", "c.png", "b.png", "gone.png", "gone.mp4"}));
  ASSERT_EQ(s.images.size(), 5u);
  EXPECT_EQ(s.ok, 3u);
  EXPECT_EQ(s.failed, 2u);
  for (std::size_t i : {3u, 4u}) {
    EXPECT_EQ(s.images[i].status, rb::Status::Failed);
    EXPECT_EQ(s.images[i].failure, rb::FailureKind::Unreadable);
    EXPECT_NE(s.images[i].reason.find("no such file"), std::string::npos) << s.images[i].reason;
    EXPECT_NE(s.images[i].reason.find("gone"), std::string::npos) << s.images[i].reason;
  }
  EXPECT_EQ(Json::parse(readText(out / "gone.png.json"))["status"], "failed");
  EXPECT_EQ(s.images[4].frame, -1);
  EXPECT_THROW(rb::run(optionsFor({tmp.path() / "lists" / "missing.txt"}, out)),
               roiclip::InvalidInputError);

  // Several inputs of every kind in one run, in the order given.
  const rb::RunSummary mixed =
      rb::run(optionsFor({in / "sub", (in / "b*.png").string(), in / "notes.md"}, out));
  EXPECT_EQ(images(mixed), (std::vector<std::string>{"c.png", "b.png", "notes.md"}));
  EXPECT_EQ(mixed.ok, 2u);
  EXPECT_EQ(mixed.images[2].failure, rb::FailureKind::Unreadable);  // given, so reported
}

// The bundled 800 x 600 scenes as the frames of an MJPG AVI (OpenCV's FFmpeg writer; Debian's
// OpenCV has it), so the frames are JPEG-compressed like most camera footage.
fs::path writeSceneVideo(const fs::path& file) {
  cv::VideoWriter writer(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                         5.0, cv::Size(800, 600));
  if (!writer.isOpened()) return {};
  for (int i = 1; i <= 6; ++i) {
    writer.write(cv::imread((kImages / ("scene_0" + std::to_string(i) + ".png")).string(),
                            cv::IMREAD_COLOR));
  }
  writer.release();
  return file;
}

TEST(BatchInputs, VideoGivesOneRowPerFrameAndResumesPerFrame) {
  const TempDir tmp("video");
  fs::create_directories(tmp.path() / "in");
  const fs::path video = writeSceneVideo(tmp.path() / "in" / "scenes.avi");
  ASSERT_FALSE(video.empty()) << "this OpenCV cannot write MJPG AVI files (.ci/install-deps "
                                 "installs libopencv-dev, which can)";
  copyScene("scene_07", tmp.path() / "in" / "still.png");
  const fs::path out = tmp.path() / "out";
  rb::BatchOptions options = optionsFor({tmp.path() / "in"}, out);
  std::size_t lastTotal = 0;
  const rb::RunSummary s = rb::run(options, [&](const rb::Progress& p) { lastTotal = p.total; });
  EXPECT_EQ(lastTotal, 7u);
  EXPECT_EQ(s.total, 7u);
  ASSERT_EQ(s.images.size(), 7u);
  EXPECT_TRUE(s.allOk());
  for (int k = 0; k < 6; ++k) {
    SCOPED_TRACE(k);
    const rb::ImageRecord& r = s.images[static_cast<std::size_t>(k)];
    EXPECT_EQ(r.image, "scenes.avi");
    EXPECT_EQ(r.frame, k);
    EXPECT_EQ(r.name, "scenes.f00000" + std::to_string(k));
    EXPECT_EQ(r.status, rb::Status::Ok) << r.reason;
    EXPECT_EQ(r.tagsFound, 4);
    EXPECT_EQ(r.width, 800);
    const Json j = Json::parse(readText(out / (r.name + ".json")));
    EXPECT_EQ(j["frame"], k);
    EXPECT_EQ(j["image"], "scenes.avi");
    EXPECT_TRUE(fs::exists(out / (r.name + ".overlay.png")));
  }
  EXPECT_EQ(s.images[6].image, "still.png");
  EXPECT_EQ(s.images[6].frame, -1);

  // A second run skips every frame, figures read back.
  const rb::RunSummary again = rb::run(options);
  EXPECT_EQ(again.skipped, 7u);
  EXPECT_TRUE(again.allOk());
  ASSERT_EQ(again.images.size(), 7u);
  EXPECT_EQ(again.images[3].frame, 3);
  EXPECT_DOUBLE_EQ(again.images[3].clippedArea, s.images[3].clippedArea);

  // Per frame: a frame whose outputs are gone is redone, the others skipped.
  fs::remove(out / "scenes.f000004.json");
  const rb::RunSummary third = rb::run(options);
  EXPECT_EQ(third.skipped, 6u);
  EXPECT_FALSE(third.images[4].skipped);

  // Every other frame (of the video given as a file): frames 0, 2, 4, all up to date.
  rb::BatchOptions every = optionsFor({video}, out);
  every.every = 2;
  const rb::RunSummary sparse = rb::run(every);
  ASSERT_EQ(sparse.images.size(), 3u);
  EXPECT_EQ(sparse.images[2].frame, 4);
  EXPECT_EQ(sparse.skipped, 3u);
  every.every = 0;
  EXPECT_THROW(rb::run(every), roiclip::InvalidInputError);

  // Interrupted after two frames: the video is unfinished; the run resumes from frame 2.
  std::atomic<bool> cancel{false};
  rb::BatchOptions fresh = optionsFor({video}, tmp.path() / "fresh");
  fresh.jobs = 1;
  const rb::RunSummary cut = rb::run(
      fresh, [&](const rb::Progress& p) { cancel = p.done >= 2; }, &cancel);
  EXPECT_TRUE(cut.interrupted);
  EXPECT_EQ(cut.images.size(), 2u);
  EXPECT_FALSE(cut.allOk());
  const rb::RunSummary resumed = rb::run(fresh);
  EXPECT_EQ(resumed.images.size(), 6u);
  EXPECT_EQ(resumed.skipped, 2u);
  EXPECT_TRUE(resumed.allOk());

  // Frames over the pixel limit: refused from the container's frame size, one row.
  rb::BatchOptions small = optionsFor({video}, tmp.path() / "small");
  small.process.maxPixels = 1000;
  const rb::RunSummary refused = rb::run(small);
  ASSERT_EQ(refused.images.size(), 1u);
  EXPECT_EQ(refused.images[0].failure, rb::FailureKind::TooLarge);
  EXPECT_EQ(refused.images[0].name, "scenes");
  EXPECT_NE(refused.images[0].reason.find("800 x 600"), std::string::npos);

  // Not a video after all: one failed row, the run carries on.
  writeText(tmp.path() / "bad" / "broken.mp4", "not a video");
  const rb::RunSummary broken = rb::run(optionsFor({tmp.path() / "bad"}, tmp.path() / "bad_out"));
  ASSERT_EQ(broken.images.size(), 1u);
  EXPECT_EQ(broken.images[0].status, rb::Status::Failed);
  EXPECT_EQ(broken.images[0].failure, rb::FailureKind::Unreadable);
  EXPECT_NE(broken.images[0].reason.find("broken.mp4"), std::string::npos);
}

}  // namespace
