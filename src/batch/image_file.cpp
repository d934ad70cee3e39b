// SPDX-License-Identifier: MIT
// Reading image files: header first, size limit, then OpenCV decodes.
//
// Why these libraries: OpenCV 4.6 has no public call that returns an image's size without
// decoding it (imread reads the header internally and then checks it only against
// OPENCV_IO_MAX_IMAGE_PIXELS, a value fixed when the library is loaded, not per call). So the
// header is read here with the very libraries Debian's OpenCV decodes these formats with
// (libpng, libjpeg-turbo, libtiff, libwebp; all come with libopencv-dev), through their own
// header-only entry points: png_read_info, jpeg_read_header, TIFFOpenExt (first directory only)
// and WebPGetFeatures. The size they report is the size OpenCV would allocate. The JPEG and
// PNG readers also pick up the EXIF orientation, which imread ignores with IMREAD_UNCHANGED (the
// only flag that keeps 16-bit and alpha), so the run applies it itself.
#include "detail/image_file.hpp"

#include <algorithm>
#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include <jpeglib.h>
#include <png.h>
#include <tiffio.h>
#include <webp/decode.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

namespace roiclip::batch {

namespace {

using File = std::unique_ptr<FILE, int (*)(FILE*)>;

File openFile(const std::string& path) {
  return File(std::fopen(path.c_str(), "rb"), &std::fclose);
}

std::string readBytes(const std::string& path, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(count, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(count));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

bool startsWith(const std::string& bytes, const char* magic, std::size_t size) {
  return bytes.size() >= size && std::memcmp(bytes.data(), magic, size) == 0;
}

// libpng and libjpeg report errors by longjmp; nothing with a destructor lives in these two
// functions between setjmp and the jump.
[[noreturn]] void pngError(png_structp png, png_const_charp /*message*/) { png_longjmp(png, 1); }
void pngWarning(png_structp /*png*/, png_const_charp /*message*/) {}

bool readPngHeader(FILE* f, ImageHeader& h) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, &pngError, &pngWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, f);
  // Report what the header says (up to PNG's own 2^31 - 1); the caller judges the size.
  png_set_user_limits(png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
  png_read_info(png, info);
  h.width = png_get_image_width(png, info);
  h.height = png_get_image_height(png, info);
  h.channels = png_get_channels(png, info);
  png_uint_32 exifSize = 0;
  png_bytep exif = nullptr;
  if (png_get_eXIf_1(png, info, &exifSize, &exif) != 0 && exif) {
    h.orientation = exifOrientation(exif, exifSize);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

struct JpegErrors {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
};

[[noreturn]] void jpegError(j_common_ptr info) {
  std::longjmp(reinterpret_cast<JpegErrors*>(info->err)->jump, 1);
}
void jpegMessage(j_common_ptr /*info*/) {}

bool readJpegHeader(FILE* f, ImageHeader& h) {
  jpeg_decompress_struct info{};
  JpegErrors errors{};
  info.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = &jpegError;
  errors.manager.output_message = &jpegMessage;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    return false;
  }
  jpeg_create_decompress(&info);
  jpeg_stdio_src(&info, f);
  jpeg_save_markers(&info, JPEG_APP0 + 1, 0xFFFF);
  jpeg_read_header(&info, TRUE);
  h.width = info.image_width;
  h.height = info.image_height;
  h.channels = info.num_components;
  for (jpeg_saved_marker_ptr m = info.marker_list; m; m = m->next) {
    if (m->marker == JPEG_APP0 + 1 && m->data_length > 6 &&
        std::memcmp(m->data, "Exif\0\0", 6) == 0) {
      h.orientation = exifOrientation(m->data + 6, m->data_length - 6);
      break;  // the first Exif segment, as OpenCV
    }
  }
  jpeg_destroy_decompress(&info);
  return true;
}

int tiffQuiet(TIFF* /*tif*/, void* /*user*/, const char* /*module*/, const char* /*fmt*/,
              va_list /*args*/) {
  return 1;  // handled: libtiff prints nothing
}

bool readTiffHeader(const std::string& path, ImageHeader& h) {
  // Per-file handlers (libtiff >= 4.5) leave OpenCV's process-wide ones alone.
  TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetErrorHandlerExtR(options, &tiffQuiet, nullptr);
  TIFFOpenOptionsSetWarningHandlerExtR(options, &tiffQuiet, nullptr);
  TIFF* tif = TIFFOpenExt(path.c_str(), "r", options);
  TIFFOpenOptionsFree(options);
  if (!tif) return false;
  std::uint32_t width = 0, height = 0;
  std::uint16_t samples = 1;
  const bool ok = TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &width) == 1 &&
                  TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &height) == 1;
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &samples);
  TIFFClose(tif);
  h.width = width;
  h.height = height;
  h.channels = samples;
  return ok;
}

bool readWebpHeader(const std::string& bytes, ImageHeader& h) {
  WebPBitstreamFeatures features;
  if (WebPGetFeatures(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(),
                      &features) != VP8_STATUS_OK) {
    return false;
  }
  h.width = features.width;
  h.height = features.height;
  h.channels = features.has_alpha ? 4 : 3;
  return true;
}

// A complete JPEG has an end-of-image marker (FF D9) after its last start-of-scan (FF DA). Both
// can only stand for themselves inside a scan (a data byte FF is always followed by 00), and
// whatever follows the image (a camera's trailer, a second image) keeps the rule.
bool jpegHasEndAfterLastScan(const std::string& bytes) {
  const std::size_t scan = bytes.rfind("\xFF\xDA");
  return scan != std::string::npos && bytes.find("\xFF\xD9", scan + 2) != std::string::npos;
}

std::string printable(const std::string& bytes) {
  std::string out;
  for (char c : bytes.substr(0, 12)) out += (c >= 0x20 && c < 0x7f) ? c : '.';
  return out;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

int exifOrientation(const unsigned char* data, std::size_t size) {
  if (size < 8) return 1;
  const bool little = data[0] == 'I' && data[1] == 'I';
  if (!little && !(data[0] == 'M' && data[1] == 'M')) return 1;
  const auto u16 = [&](std::size_t at) -> unsigned {
    return little ? data[at] | (data[at + 1] << 8) : (data[at] << 8) | data[at + 1];
  };
  const auto u32 = [&](std::size_t at) -> std::uint32_t {
    return little ? u16(at) | (static_cast<std::uint32_t>(u16(at + 2)) << 16)
                  : (static_cast<std::uint32_t>(u16(at)) << 16) | u16(at + 2);
  };
  if (u16(2) != 42) return 1;
  const std::uint32_t ifd = u32(4);
  if (ifd > size - 2) return 1;
  const unsigned entries = u16(ifd);
  for (unsigned i = 0; i < entries; ++i) {
    const std::size_t at = ifd + 2 + 12 * static_cast<std::size_t>(i);
    if (at + 12 > size) return 1;
    constexpr unsigned kOrientation = 0x0112, kShort = 3;
    if (u16(at) == kOrientation && u16(at + 2) == kShort) {
      const unsigned value = u16(at + 8);
      return value >= 1 && value <= 8 ? static_cast<int>(value) : 1;
    }
  }
  return 1;
}

void applyExifOrientation(cv::Mat& image, int orientation) {
  // The EXIF table: 2 mirrored, 3 rotated 180, 4 flipped; 5..8 are those after a transpose.
  if (orientation >= 5 && orientation <= 8) cv::transpose(image, image);
  switch (orientation) {
    case 2:
    case 6:
      cv::flip(image, image, 1);
      break;
    case 3:
    case 7:
      cv::flip(image, image, -1);
      break;
    case 4:
    case 8:
      cv::flip(image, image, 0);
      break;
    default:
      break;
  }
}

void scaleToSignificantBits(cv::Mat& image) {
  if (image.empty() || image.depth() != CV_16U) return;
  const int channels = image.channels();
  const int colours = (channels == 2 || channels == 4) ? channels - 1 : channels;
  double largest = 0;
  cv::Mat plane;
  for (int c = 0; c < colours; ++c) {
    cv::extractChannel(image, plane, c);
    double high = 0;
    cv::minMaxLoc(plane, nullptr, &high);
    largest = std::max(largest, high);
  }
  int bits = 8;
  while (bits < 16 && largest > static_cast<double>((1 << bits) - 1)) ++bits;
  if (bits == 16) return;
  const double gain = 65535.0 / static_cast<double>((1 << bits) - 1);
  if (colours == channels) {
    image.convertTo(image, CV_16U, gain);
    return;
  }
  std::vector<cv::Mat> planes;
  cv::split(image, planes);
  for (int c = 0; c < colours; ++c) planes[c].convertTo(planes[c], CV_16U, gain);
  cv::merge(planes, image);
}

std::optional<ImageHeader> readImageHeader(const std::string& path) {
  const std::string magic = readBytes(path, 64);
  ImageHeader h;
  bool ok = false;
  if (startsWith(magic, "\x89PNG\r\n\x1a\n", 8)) {
    h.format = "png";
    if (File f = openFile(path)) ok = readPngHeader(f.get(), h);
  } else if (startsWith(magic, "\xFF\xD8\xFF", 3)) {
    h.format = "jpeg";
    if (File f = openFile(path)) ok = readJpegHeader(f.get(), h);
  } else if (startsWith(magic, "II*\0", 4) || startsWith(magic, "MM\0*", 4) ||
             startsWith(magic, "II+\0", 4) || startsWith(magic, "MM\0+", 4)) {
    h.format = "tiff";
    ok = readTiffHeader(path, h);
  } else if (startsWith(magic, "RIFF", 4) && magic.size() >= 12 &&
             magic.compare(8, 4, "WEBP") == 0) {
    h.format = "webp";
    ok = readWebpHeader(magic, h);
  }
  if (!ok) return std::nullopt;
  return h;
}

cv::Mat readImage(const std::string& path, std::int64_t maxPixels) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw InvalidInputError(path + ": no such file");
  if (!fs::is_regular_file(status)) throw InvalidInputError(path + ": not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw InvalidInputError(path + ": cannot read file (" + ec.message() + ")");
  if (size == 0) throw InvalidInputError(path + ": empty file (0 bytes)");
  if (!openFile(path)) throw InvalidInputError(path + ": cannot open file (permission denied?)");
  // OpenCV picks the reader by content, as imread will.
  if (!cv::haveImageReader(path)) {
    throw InvalidInputError(path + ": not an image (no image format recognised; the file starts " +
                            "with \"" + printable(readBytes(path, 12)) + "\")");
  }

  const std::optional<ImageHeader> header = readImageHeader(path);
  const auto tooLarge = [&](std::int64_t w, std::int64_t h, const std::string& what) {
    return ImageTooLargeError(path + ": " + what + " " + std::to_string(w) + " x " +
                              std::to_string(h) + " = " + std::to_string(w * h) +
                              " pixels, more than the limit of " + std::to_string(maxPixels) +
                              " (--max-pixels); not decoded");
  };
  std::string what = "image";
  if (header) {
    what = upper(header->format) + " " + std::to_string(header->width) + " x " +
           std::to_string(header->height);
    if (maxPixels > 0 && header->width * header->height > maxPixels) {
      throw tooLarge(header->width, header->height, upper(header->format) + " header says");
    }
    if (header->format == "jpeg" && !jpegHasEndAfterLastScan(readBytes(path, size))) {
      throw InvalidInputError(path + ": " + what +
                              ": truncated JPEG (no end-of-image marker after the last scan)");
    }
  }

  cv::Mat image;
  try {
    image = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    // Among others OpenCV's own size check (OPENCV_IO_MAX_IMAGE_PIXELS) for formats read here
    // without a header.
    throw InvalidInputError(path + ": " + what + ": cannot decode (OpenCV: " + e.err + ")");
  }
  if (image.empty()) {
    throw InvalidInputError(path + ": " + what +
                            ": cannot decode the pixel data (truncated or corrupt file)");
  }
  if (maxPixels > 0 && static_cast<std::int64_t>(image.total()) > maxPixels) {
    throw tooLarge(image.cols, image.rows, "decoded image is");
  }
  if (header) applyExifOrientation(image, header->orientation);
  scaleToSignificantBits(image);
  return image;
}

}  // namespace roiclip::batch
