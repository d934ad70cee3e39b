// roiclip::batch internal: reading image files safely. A file's header is read first (format and
// size, without decoding a pixel), so an image that would not fit the pixel limit, a decompression
// bomb among them, is refused before anything the size of the image is allocated; then the file
// is decoded with OpenCV and problems come back as exceptions whose message names the file and
// what is wrong with it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include <roiclip/batch/options.hpp>  // kDefaultMaxPixels
#include <roiclip/error.hpp>

namespace roiclip::batch {

/// readImage() refused an image because it has more pixels than allowed.
class ImageTooLargeError : public InvalidInputError {
 public:
  using InvalidInputError::InvalidInputError;
};

/// An image file's format and size as its header states them.
struct ImageHeader {
  std::string format;  ///< "png", "jpeg", "tiff" or "webp"
  std::int64_t width = 0, height = 0;
  int channels = 0;  ///< samples per pixel as stored (gray 1, gray+alpha 2, RGB 3, RGBA 4)
};

/// Read the header of a PNG, JPEG, TIFF or WebP file (recognised by content, not by name)
/// with the library OpenCV decodes that format with (libpng, libjpeg, libtiff, libwebp), so the
/// size is the one the decoder would allocate. Reads a few bytes to a few kilobytes; never
/// decodes pixels and never allocates anything the size of the image.
/// @return nothing when the file is none of these formats or its header cannot be parsed.
std::optional<ImageHeader> readImageHeader(const std::string& path);

/// Read an image file unchanged (cv::IMREAD_UNCHANGED: 8/16-bit or float, 1 to 4 channels).
/// Before decoding: the file must exist, be non-empty and have content some OpenCV image reader
/// recognises (the format goes by content, so a PNG named x.jpg is read as a PNG), and a PNG,
/// JPEG, TIFF or WebP must not claim more than `maxPixels` pixels in its header. Other formats
/// (BMP, PNM, JPEG 2000, OpenEXR, ...) are checked after decoding, and before that only against
/// OpenCV's own limit (environment variable OPENCV_IO_MAX_IMAGE_PIXELS, default 2^30, read when
/// OpenCV is loaded). A JPEG whose last scan has no end-of-image marker after it is refused as
/// truncated (libjpeg would fill the missing rows with gray and only print a warning).
/// @param maxPixels the pixel limit; <= 0 means no limit of roiclip's own.
/// @throws ImageTooLargeError naming the file, its size and the limit;
///         InvalidInputError naming the file and the problem (missing, empty, not an image,
///         truncated, corrupt).
cv::Mat readImage(const std::string& path, std::int64_t maxPixels = kDefaultMaxPixels);

}  // namespace roiclip::batch
