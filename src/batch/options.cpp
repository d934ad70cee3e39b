// SPDX-License-Identifier: MIT
// Option and outcome texts (one table per enum, read both ways) and optionsKey().
#include <roiclip/batch/options.hpp>

#include <exception>
#include <sstream>
#include <utility>

namespace roiclip::batch {

namespace {

// The spelling of every value, in declaration order; toString and parse both read these.
constexpr std::pair<Status, const char*> kStatusNames[] = {
    {Status::Ok, "ok"},
    {Status::NoRoi, "no-roi"},
    {Status::Failed, "failed"},
    {Status::MaskMismatch, "mask-mismatch"},
};
constexpr std::pair<FailureKind, const char*> kFailureNames[] = {
    {FailureKind::None, "none"},
    {FailureKind::Unreadable, "unreadable"},
    {FailureKind::TooLarge, "too-large"},
    {FailureKind::NoTags, "no-tags"},
    {FailureKind::MissingTags, "missing-tags"},
    {FailureKind::InvalidInput, "invalid-input"},
    {FailureKind::Internal, "internal"},
    {FailureKind::Mismatch, "mismatch"},
};
constexpr std::pair<ContourMethod, const char*> kMethodNames[] = {
    {ContourMethod::Otsu, "otsu"},
    {ContourMethod::Adaptive, "adaptive"},
    {ContourMethod::Canny, "canny"},
    {ContourMethod::Threshold, "threshold"},
};
constexpr std::pair<Polarity, const char*> kPolarityNames[] = {
    {Polarity::Dark, "dark"},
    {Polarity::Light, "light"},
};

template <typename Enum, std::size_t N>
const char* nameOf(const std::pair<Enum, const char*> (&table)[N], Enum value,
                   const char* fallback) {
  for (const auto& [e, name] : table) {
    if (e == value) return name;
  }
  return fallback;  // only for a value outside the enum (a cast)
}

template <typename Enum, std::size_t N>
std::optional<Enum> valueOf(const std::pair<Enum, const char*> (&table)[N], std::string_view text) {
  for (const auto& [e, name] : table) {
    if (text == name) return e;
  }
  return std::nullopt;
}

}  // namespace

const char* toString(Status status) { return nameOf(kStatusNames, status, "failed"); }

std::optional<Status> parseStatus(std::string_view text) { return valueOf(kStatusNames, text); }

const char* toString(FailureKind kind) { return nameOf(kFailureNames, kind, "internal"); }

std::optional<FailureKind> parseFailureKind(std::string_view text) {
  return valueOf(kFailureNames, text);
}

const char* toString(ContourMethod method) { return nameOf(kMethodNames, method, "otsu"); }

const char* toString(Polarity polarity) { return nameOf(kPolarityNames, polarity, "dark"); }

void parseContourMethod(const std::string& text, ContourOptions& options) {
  const std::string prefix = std::string(toString(ContourMethod::Threshold)) + ":";
  if (text.rfind(prefix, 0) == 0) {
    const std::string value = text.substr(prefix.size());
    std::size_t used = 0;
    int t = -1;
    try {
      t = std::stoi(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != value.size() || t < 0 || t > 255) {
      throw InvalidInputError("contour method '" + text + "': threshold must be 0..255");
    }
    options.method = ContourMethod::Threshold;
    options.threshold = t;
    return;
  }
  const std::optional<ContourMethod> method = valueOf(kMethodNames, text);
  if (!method || *method == ContourMethod::Threshold) {  // a threshold needs its value
    throw InvalidInputError("contour method '" + text +
                            "': expected otsu, adaptive, canny or threshold:T");
  }
  options.method = *method;
}

Polarity parsePolarity(const std::string& text) {
  if (const std::optional<Polarity> p = valueOf(kPolarityNames, text)) return *p;
  throw InvalidInputError("polarity '" + text + "': expected dark or light");
}

std::string optionsKey(const RunOptions& o) {
  std::ostringstream os;
  os.precision(17);
  const ContourOptions& c = o.contours;
  // Enums as numbers: the key of existing outputs must not change when a name is reworded.
  std::string rois;
  for (const std::string& roi : o.rois) rois += (rois.empty() ? "" : "|") + roi;
  os << "roi=" << rois << ";tags=" << (o.keepTags ? "kept" : "excluded")
     << ",margin=" << o.tagMargin << ";hamming=" << o.detector.maxHamming
     << ";margin=" << o.detector.minDecisionMargin << ";board=" << o.boardFile
     << ";family=" << o.detector.family << ";decimate=" << o.detector.quadDecimate
     << ";sigma=" << o.detector.quadSigma << ";refine=" << o.detector.refineEdges
     << ";sharpen=" << o.detector.decodeSharpening << ";bits=" << o.detector.maxBitsCorrected
     << ";method=" << static_cast<int>(c.method) << ";polarity=" << static_cast<int>(c.polarity)
     << ";threshold=" << c.threshold << ";block=" << c.adaptiveBlock << ";c=" << c.adaptiveC
     << ";canny=" << c.cannyLow << "," << c.cannyHigh << ";approx=" << c.approxEpsilon
     << ";min_area=" << c.minArea << ";edges=" << c.openEdges
     << ";fill=" << toString(o.subjectFillRule) << ";roi_fill=" << toString(o.roiFillRule)
     << ";grid=" << o.grid.scale;
  return os.str();
}

}  // namespace roiclip::batch
