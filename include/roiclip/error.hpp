// SPDX-License-Identifier: MIT
// roiclip: exception hierarchy. Every error the library throws derives from roiclip::Error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace roiclip {

/// Root of all roiclip exceptions.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The input of a call an error concerns: the subject and clip operands of simplify() and clip(),
/// the polylines of clipLines() (its region is the clip operand).
enum class Operand : std::uint8_t { None, Subject, Clip, Line };

/// "subject", "clip", "line" (as the messages name them), or "" for Operand::None.
inline const char* toString(Operand operand) {
  switch (operand) {
    case Operand::Subject:
      return "subject";
    case Operand::Clip:
      return "clip";
    case Operand::Line:
      return "line";
    case Operand::None:
      break;
  }
  return "";
}

/// The coordinate of a vertex an error concerns.
enum class Axis : std::uint8_t { None, X, Y };

/// Where in the input an InvalidInputError lies. Every field may be unset.
struct InputLocation {
  /// The name of the input (a file name); when set, messages name it instead of the operand.
  std::string source;
  Operand operand = Operand::None;    ///< which operand the path belongs to
  std::optional<std::size_t> path;    ///< index of the path within its operand
  std::optional<std::size_t> vertex;  ///< index of the vertex within its path
  Axis axis = Axis::None;             ///< which coordinate of the vertex is wrong
};

/// The caller passed input that cannot be processed: NaN or infinite coordinates, coordinates
/// outside the supported range, malformed files, wrong image types. The message names the input.
///
/// Errors the core finds at a vertex carry their location as fields (location()), and what() is
/// formatted from them, as cv::Exception does:
///   "OPERAND path P, vertex V: AXIS PROBLEM"   e.g. "clip path 1, vertex 1: y is not a finite
///   number" "SOURCE: path P, vertex V: AXIS PROBLEM"   once a source is attached (withSource()).
/// Code that wants to know which input is wrong reads the fields, never the message.
class InvalidInputError : public Error {
 public:
  /// An error with no location fields: what() is `message` as given (it names the input itself).
  explicit InvalidInputError(const std::string& message) : Error(message), problem_(message) {}

  /// An error at `location`; what() is format(location, problem).
  InvalidInputError(InputLocation location, std::string problem)
      : Error(format(location, problem)),
        location_(std::move(location)),
        problem_(std::move(problem)) {}

  /// Where the error lies (every field unset for an error made from a message alone).
  [[nodiscard]] const InputLocation& location() const noexcept { return location_; }
  /// The message without its location ("y is not a finite number" is AXIS + " " + problem()).
  [[nodiscard]] const std::string& problem() const noexcept { return problem_; }

  /// The same error with `source` as the location's source: the message names it in place of
  /// the operand ("FILE: path 1, vertex 1: ..."; "FILE: PROBLEM" when there is no location).
  [[nodiscard]] InvalidInputError withSource(std::string source) const {
    InputLocation location = location_;
    location.source = std::move(source);
    return {std::move(location), problem_};
  }

  /// "[SOURCE: | OPERAND ][path P[, vertex V]: ][AXIS ]PROBLEM".
  static std::string format(const InputLocation& location, const std::string& problem) {
    std::string where;
    if (!location.source.empty()) {
      where = location.source + ": ";
    } else if (location.operand != Operand::None) {
      where = std::string(toString(location.operand)) + " ";
    }
    if (location.path) {
      where += "path " + std::to_string(*location.path);
      if (location.vertex) where += ", vertex " + std::to_string(*location.vertex);
      where += ": ";
    }
    if (location.axis != Axis::None) where += location.axis == Axis::X ? "x " : "y ";
    return where + problem;
  }

 private:
  InputLocation location_;
  std::string problem_;
};

/// A call reached one of its work limits (roiclip::Limits) and gave up before taking the memory
/// the rest of the work would need. Nothing is returned; the caller may retry with a larger limit.
/// what() is formatted from the fields: "more than 1000 crossings (the limit maxCrossings)".
class ResourceLimitError : public Error {
 public:
  /// The limit named `limit` (a Limits member, "maxCrossings") of `value` was exceeded by work
  /// counted as `what` ("crossings").
  ResourceLimitError(std::string limit, std::uint64_t value, const std::string& what)
      : Error("more than " + std::to_string(value) + " " + what + " (the limit " + limit + ")"),
        limit_(std::move(limit)),
        value_(value) {}
  /// The name of the limit that was reached ("maxCrossings").
  [[nodiscard]] const std::string& limit() const noexcept { return limit_; }
  /// Its value.
  [[nodiscard]] std::uint64_t value() const noexcept { return value_; }

 private:
  std::string limit_;
  std::uint64_t value_ = 0;
};

/// An internal consistency check failed. This is a bug in roiclip; please report the input.
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace roiclip
