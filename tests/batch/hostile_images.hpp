// SPDX-License-Identifier: MIT
// Hostile image files for `roiclip run`, made from one good scene: truncated PNG and JPEG, an
// empty file, a 1x1 image, decompression bombs (PNG, JPEG and TIFF headers claiming huge sizes, and
// a genuinely decodable 20000 x 20000 PNG of ~50 KB), 16-bit, float, 2- and 4-channel images, a
// text file named .png and a PNG named .jpg. Each comes with what a run must report for it. Used by
// hostile_test.cpp and by roiclip_batch_hostile_images (the folder the memory figures in the
// README were measured on).
#pragma once

#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace roiclip::testing {

/// One hostile file and what `roiclip run` must say about it.
struct HostileImage {
  std::string file;     ///< name inside the folder
  std::string status;   ///< "ok", "no-roi" or "failed"
  std::string failure;  ///< FailureKind name
  std::string reason;   ///< a piece of the reason (empty: no reason expected)
};

namespace hostile_detail {

inline void writeBytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string encode(const std::string& ext, const cv::Mat& image) {
  std::vector<uchar> buffer;
  cv::imencode(ext, image, buffer);
  return std::string(buffer.begin(), buffer.end());
}

inline void putBigEndian32(std::string& s, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) s += static_cast<char>((v >> shift) & 0xff);
}

// One PNG chunk: length, type, data, CRC of type + data.
inline std::string pngChunk(const std::string& type, const std::string& data) {
  std::string c;
  putBigEndian32(c, static_cast<std::uint32_t>(data.size()));
  const std::string body = type + data;
  c += body;
  putBigEndian32(c, static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(body.data()),
                                                     static_cast<uInt>(body.size()))));
  return c;
}

// A PNG of width x height, `colorType` (0 gray, 4 gray + alpha) at `bitDepth`, whose rows come
// from row(r) (without the filter byte), deflated row by row with zlib (never more than one row
// in memory). With rows < height only that many rows are written: the header claims the size
// but the data stops short.
template <class Row>
std::string rawPng(std::uint32_t width, std::uint32_t height, int bitDepth, int colorType,
                   std::uint32_t rows, Row row) {
  std::string ihdr;
  putBigEndian32(ihdr, width);
  putBigEndian32(ihdr, height);
  ihdr += static_cast<char>(bitDepth);
  ihdr += static_cast<char>(colorType);
  ihdr += std::string("\0\0\0", 3);  // deflate, filter 0, no interlace
  z_stream z{};
  deflateInit(&z, 9);
  std::string idat;
  std::vector<Bytef> out(1 << 16);
  for (std::uint32_t r = 0; r < rows; ++r) {
    const std::string line = std::string(1, '\0') + row(r);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(line.data()));
    z.avail_in = static_cast<uInt>(line.size());
    const int flush = r + 1 == rows ? Z_FINISH : Z_NO_FLUSH;
    do {
      z.next_out = out.data();
      z.avail_out = static_cast<uInt>(out.size());
      deflate(&z, flush);
      idat.append(reinterpret_cast<char*>(out.data()), out.size() - z.avail_out);
    } while (z.avail_out == 0);
  }
  deflateEnd(&z);
  return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) + pngChunk("IDAT", idat) +
         pngChunk("IEND", "");
}

// A gray PNG whose `rows` first rows are zero.
inline std::string zeroPng(std::uint32_t width, std::uint32_t height, int bitDepth,
                           std::uint32_t rows) {
  const std::string zeros((static_cast<std::size_t>(width) * bitDepth + 7) / 8, '\0');
  return rawPng(width, height, bitDepth, 0, rows, [&](std::uint32_t) { return zeros; });
}

// An 8-bit gray + alpha PNG of `gray` (opaque).
inline std::string grayAlphaPng(const cv::Mat& gray) {
  return rawPng(static_cast<std::uint32_t>(gray.cols), static_cast<std::uint32_t>(gray.rows), 8, 4,
                static_cast<std::uint32_t>(gray.rows), [&](std::uint32_t r) {
                  std::string line;
                  for (int x = 0; x < gray.cols; ++x) {
                    line += static_cast<char>(gray.at<uchar>(static_cast<int>(r), x));
                    line += '\xff';
                  }
                  return line;
                });
}

// A JPEG whose frame header (SOF0) claims width x height; the scan is that of a small image.
inline std::string hugeJpeg(const cv::Mat& small, std::uint16_t width, std::uint16_t height) {
  std::string jpeg = encode(".jpg", small);
  const std::size_t sof = jpeg.find("\xFF\xC0");
  jpeg[sof + 5] = static_cast<char>(height >> 8);
  jpeg[sof + 6] = static_cast<char>(height & 0xff);
  jpeg[sof + 7] = static_cast<char>(width >> 8);
  jpeg[sof + 8] = static_cast<char>(width & 0xff);
  return jpeg;
}

// A little-endian TIFF (as OpenCV writes them) whose first directory claims width x height.
inline std::string hugeTiff(const cv::Mat& small, std::uint16_t width, std::uint16_t height) {
  std::string tiff = encode(".tiff", small);
  const auto u16 = [&](std::size_t at) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(tiff[at])) |
           static_cast<std::uint32_t>(static_cast<unsigned char>(tiff[at + 1])) << 8;
  };
  const std::size_t ifd = u16(4) | u16(6) << 16;
  for (std::size_t e = 0; e < u16(ifd); ++e) {
    const std::size_t entry = ifd + 2 + 12 * e;
    const std::uint32_t tag = u16(entry);
    if (tag != 256 && tag != 257) continue;  // ImageWidth, ImageLength
    const std::uint16_t v = tag == 256 ? width : height;
    tiff[entry + 2] = 3;  // SHORT, value in the entry
    tiff[entry + 3] = 0;
    tiff.replace(entry + 8, 4,
                 std::string{static_cast<char>(v & 0xff), static_cast<char>(v >> 8), '\0', '\0'});
  }
  return tiff;
}

}  // namespace hostile_detail

/// Write the hostile files into `dir` (which must exist) from `scene` (a BGR 8-bit image with
/// tags that `roiclip run` processes ok) and say what a run must report for each.
inline std::vector<HostileImage> writeHostileImages(const std::filesystem::path& dir,
                                                    const cv::Mat& scene) {
  using namespace hostile_detail;
  std::vector<HostileImage> out;
  const auto add = [&](const std::string& file, const std::string& bytes, HostileImage expect) {
    writeBytes(dir / file, bytes);
    expect.file = file;
    out.push_back(std::move(expect));
  };
  cv::Mat gray;
  cv::cvtColor(scene, gray, cv::COLOR_BGR2GRAY);

  add("good.png", encode(".png", scene), {"", "ok", "none", ""});
  const std::string png = encode(".png", gray);
  add("truncated.png", png.substr(0, png.size() * 6 / 10),
      {"", "failed", "unreadable",
       "PNG " + std::to_string(gray.cols) + " x " + std::to_string(gray.rows) +
           ": cannot decode the pixel data (truncated or corrupt file)"});
  const std::string jpeg = encode(".jpg", scene);
  add("truncated.jpg", jpeg.substr(0, jpeg.size() * 6 / 10),
      {"", "failed", "unreadable", "truncated JPEG"});
  add("empty.png", "", {"", "failed", "unreadable", "empty file (0 bytes)"});
  add("one_pixel.png", encode(".png", cv::Mat(1, 1, CV_8UC1, cv::Scalar(128))),
      {"", "no-roi", "no-tags", "no tag36h11 tags detected"});
  // Decompression bombs: refused from the header, before any pixel is decoded.
  add("bomb_header.png", zeroPng(100000, 100000, 8, 1),
      {"", "failed", "too-large", "PNG header says 100000 x 100000 = 10000000000 pixels"});
  add("bomb_zeros.png", zeroPng(20000, 20000, 1, 20000),
      {"", "failed", "too-large", "PNG header says 20000 x 20000 = 400000000 pixels"});
  add("bomb_header.jpg", hugeJpeg(gray(cv::Rect(0, 0, 64, 64)), 60000, 60000),
      {"", "failed", "too-large", "JPEG header says 60000 x 60000"});
  add("bomb_header.tiff", hugeTiff(gray(cv::Rect(0, 0, 64, 64)), 60000, 60000),
      {"", "failed", "too-large", "TIFF header says 60000 x 60000 = 3600000000 pixels"});
  // Types: 16-bit, float, gray + alpha, BGRA; all processable.
  cv::Mat gray16, grayFloat, bgra;
  gray.convertTo(gray16, CV_16U, 257.0);
  add("sixteen_bit.png", encode(".png", gray16), {"", "ok", "none", ""});
  gray.convertTo(grayFloat, CV_32F, 1.0 / 255.0);
  add("float.tiff", encode(".tiff", grayFloat), {"", "ok", "none", ""});
  add("gray_alpha.png", grayAlphaPng(gray), {"", "ok", "none", ""});
  cv::cvtColor(scene, bgra, cv::COLOR_BGR2BGRA);
  add("bgra.png", encode(".png", bgra), {"", "ok", "none", ""});
  // Names that lie: formats go by content.
  add("text.png", "hello, this is not an image\n",
      {"", "failed", "unreadable", "not an image (no image format recognised"});
  add("png_named.jpg", encode(".png", scene), {"", "ok", "none", ""});
  return out;
}

}  // namespace roiclip::testing
