// SPDX-License-Identifier: MIT
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
  /// EXIF orientation (1..8, 1 = upright; width and height are as stored, before it): from a
  /// JPEG's Exif APP1 segment or a PNG's eXIf chunk, the two places cv::imread reads it from.
  int orientation = 1;
};

/// Read the header of a PNG, JPEG, TIFF or WebP file (recognised by content, not by name)
/// with the library OpenCV decodes that format with (libpng, libjpeg, libtiff, libwebp), so the
/// size is the one the decoder would allocate. Reads a few bytes to a few kilobytes; never
/// decodes pixels and never allocates anything the size of the image.
/// @return nothing when the file is none of these formats or its header cannot be parsed.
std::optional<ImageHeader> readImageHeader(const std::string& path);

/// The EXIF orientation tag (0x0112) of a TIFF-structured EXIF block (the payload of a JPEG's
/// APP1 segment after "Exif\0\0", or of a PNG's eXIf chunk): 1..8, or 1 when there is none or
/// the block is malformed.
int exifOrientation(const unsigned char* data, std::size_t size);

/// Turn an image stored with EXIF orientation `orientation` (1..8) upright, as cv::imread does
/// without cv::IMREAD_IGNORE_ORIENTATION (5..8 swap width and height).
void applyExifOrientation(cv::Mat& image, int orientation);

/// Scale 16-bit data that uses fewer bits (a 12-bit camera's, say) to the full 16-bit range:
/// by 65535 / (2^b - 1), b the fewest bits (at least 8) that hold the largest colour value
/// (alpha left as it is), so toGray8()/toBgr8() give the detection and the overlay the whole
/// 8-bit range instead of the bottom 1/16. A constant gain changes no shape the pipeline finds
/// (thresholds scale with it) but keeps 12-bit data from being quantised to 16 gray levels.
/// Other depths, and 16-bit data using all 16 bits, are left as they are.
void scaleToSignificantBits(cv::Mat& image);

/// Read an image file as a run uses it: decoded unchanged (cv::IMREAD_UNCHANGED: 8/16-bit or
/// float, 1 to 4 channels, alpha kept), then turned upright by its EXIF orientation
/// (applyExifOrientation; OpenCV 4.6 ignores EXIF with IMREAD_UNCHANGED) and 16-bit data
/// scaled by its significant bits (scaleToSignificantBits). Before decoding: the file must exist,
/// be non-empty and have content some OpenCV image reader recognises (the format goes by content,
/// so a PNG named x.jpg is read as a PNG), and a PNG, JPEG, TIFF or WebP must not claim more than
/// `maxPixels` pixels in its header. Other formats (BMP, PNM, JPEG 2000, OpenEXR, ...) are checked
/// after decoding, and before that only against OpenCV's own limit (environment variable
/// OPENCV_IO_MAX_IMAGE_PIXELS, default 2^30, read when OpenCV is loaded). A JPEG whose last scan
/// has no end-of-image marker after it is refused as truncated (libjpeg would fill the missing rows
/// with gray and only print a warning).
/// @param maxPixels the pixel limit; <= 0 means no limit of roiclip's own.
/// @throws ImageTooLargeError naming the file, its size and the limit;
///         InvalidInputError naming the file and the problem (missing, empty, not an image,
///         truncated, corrupt).
cv::Mat readImage(const std::string& path, std::int64_t maxPixels = kDefaultMaxPixels);

}  // namespace roiclip::batch
