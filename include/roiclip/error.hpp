// roiclip: exception hierarchy. Every error the library throws derives from roiclip::Error.
#pragma once

#include <stdexcept>
#include <string>

namespace roiclip {

/// Root of all roiclip exceptions.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The caller passed input that cannot be processed: NaN or infinite coordinates, coordinates
/// outside the supported range, malformed files, wrong image types. The message names the input.
class InvalidInputError : public Error {
 public:
  using Error::Error;
};

/// An internal consistency check failed. This is a bug in roiclip; please report the input.
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace roiclip
