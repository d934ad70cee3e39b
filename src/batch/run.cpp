// `roiclip run`: a folder of images through the per-image pipeline, in parallel, resumable.
#include <roiclip/batch/run.hpp>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <exception>
#include <fstream>
#include <iomanip>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

namespace roiclip::batch {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const char* const kSummaryColumns =
    "image,status,failure,reason,skipped,width,height,tags_found,roi_area,contours_in,"
    "contours_out,clipped_area,iou,off_band_mismatches,seconds";

const std::vector<std::string>& imageExtensions() {
  static const std::vector<std::string> kExtensions = {
      ".png", ".jpg", ".jpeg", ".jpe", ".tif",  ".tiff", ".bmp", ".dib",
      ".pgm", ".ppm", ".pnm",  ".pbm", ".webp", ".jp2",  ".exr", ".hdr"};
  return kExtensions;
}

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool isImageFile(const fs::path& p) {
  const std::string ext = lower(p.extension().string());
  const auto& all = imageExtensions();
  return std::find(all.begin(), all.end(), ext) != all.end();
}

// True when `p` lies in folder `dir` (both weakly canonical).
bool isUnder(const fs::path& p, const fs::path& dir) {
  auto d = dir.begin();
  auto q = p.begin();
  for (; d != dir.end(); ++d, ++q) {
    if (d->empty()) continue;  // trailing separator
    if (q == p.end() || *q != *d) return false;
  }
  return true;
}

std::string encodePng(const cv::Mat& image, const std::string& what) {
  std::vector<uchar> buffer;
  if (!cv::imencode(".png", image, buffer)) throw Error("cannot encode " + what + " as PNG");
  return std::string(buffer.begin(), buffer.end());
}

// Newer-or-equal modification time: outputs written in the same clock tick count as newer.
bool notOlder(const fs::path& output, const fs::file_time_type& inputTime) {
  std::error_code ec;
  const auto t = fs::last_write_time(output, ec);
  return !ec && t >= inputTime;
}

std::optional<ImageRecord> readRecord(const fs::path& jsonFile, const std::string& key) {
  std::ifstream in(jsonFile, std::ios::binary);
  if (!in) return std::nullopt;
  const Json j = Json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  try {
    ImageRecord r;
    // ok and no-roi are final for these options; failed images (perhaps a file still being
    // copied) and mask mismatches are tried again.
    const std::string status = j.at("status").get<std::string>();
    if (status != "ok" && status != "no-roi") return std::nullopt;
    if (j.value("options", std::string()) != key) return std::nullopt;  // other options
    r.status = status == "ok" ? Status::Ok : Status::NoRoi;
    const std::string failure = j.at("failure").get<std::string>();
    r.failure = failure == "none"      ? FailureKind::None
                : failure == "no-tags" ? FailureKind::NoTags
                                       : FailureKind::MissingTags;
    r.reason = j.at("reason").get<std::string>();
    r.width = j.at("width").get<int>();
    r.height = j.at("height").get<int>();
    r.tagsFound = static_cast<int>(j.at("tags").size());
    r.roiArea = j.at("roi").at("area").get<double>();
    r.contoursIn = j.at("contours_in").get<int>();
    r.contoursOut = j.at("contours_out").get<int>();
    r.clippedArea = j.at("clipped_area").get<double>();
    r.iou = j.at("mask_check").at("exact").at("iou").get<double>();
    r.offBandMismatches = j.at("mask_check").at("off_band_mismatches").get<std::int64_t>();
    return r;
  } catch (const Json::exception&) {
    return std::nullopt;
  }
}

ImageRecord recordOf(const ImageResult& r) {
  ImageRecord rec;
  rec.status = r.status;
  rec.failure = r.failure;
  rec.reason = r.reason;
  rec.width = r.width;
  rec.height = r.height;
  rec.tagsFound = static_cast<int>(r.tags.size());
  rec.roiArea = r.roiArea;
  rec.contoursIn = r.contoursIn;
  rec.contoursOut = r.contoursOut;
  rec.clippedArea = r.clippedArea;
  rec.iou = r.vectorVsRaster.iou;
  rec.offBandMismatches = r.offBandMismatches();
  rec.seconds = r.seconds.total;
  return rec;
}

struct Job {
  fs::path image;    // absolute or as given
  std::string rel;   // relative to the input folder, '/' separated
  std::string name;  // output NAME
};

class Runner {
 public:
  Runner(const BatchOptions& options, std::vector<Job> jobs)
      : options_(options), jobs_(std::move(jobs)), key_(optionsKey(options.process)) {}

  ImageRecord processOne(const Processor& processor, const Job& job) const {
    const fs::path base = options_.output / fs::path(job.name);
    const fs::path jsonFile = base.string() + ".json";
    const fs::path overlayFile = base.string() + ".overlay.png";
    const fs::path maskFile = base.string() + ".mask.png";
    std::error_code ec;
    fs::create_directories(jsonFile.parent_path(), ec);
    if (ec)
      throw Error("cannot create output folder " + jsonFile.parent_path().string() + ": " +
                  ec.message());

    if (!options_.force) {
      const auto inputTime = fs::last_write_time(job.image, ec);
      if (!ec && notOlder(jsonFile, inputTime) && notOlder(overlayFile, inputTime) &&
          (!options_.writeMasks || notOlder(maskFile, inputTime))) {
        if (auto rec = readRecord(jsonFile, key_)) {
          rec->skipped = true;
          return *rec;
        }
      }
    }

    ImageResult result;
    cv::Mat image;
    try {
      image = readImage(job.image.string(), options_.process.maxPixels);
    } catch (const ImageTooLargeError& e) {
      result.status = Status::Failed;
      result.failure = FailureKind::TooLarge;
      result.reason = e.what();
    } catch (const InvalidInputError& e) {
      result.status = Status::Failed;
      result.failure = FailureKind::Unreadable;
      result.reason = e.what();
    }
    if (!image.empty()) result = processor.process(image);
    // An overlay only for images the pipeline could read (it sets the size then).
    if (result.width > 0) {
      writeFileAtomic(overlayFile, encodePng(renderOverlay(image, result), overlayFile.string()));
      if (options_.writeMasks && !result.roi.empty()) {
        writeFileAtomic(maskFile,
                        encodePng(renderMask(result, options_.process.grid), maskFile.string()));
      }
    } else {
      fs::remove(overlayFile, ec);  // a stale overlay from an earlier run would mislead
    }
    // NAME.json last: its presence with status ok is what marks the image as complete.
    writeFileAtomic(jsonFile, resultToJson(result, job.rel, key_));
    return recordOf(result);
  }

  RunSummary run(const ProgressCallback& progress, const std::atomic<bool>* cancel) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = jobs_.size();
    int workers =
        options_.jobs > 0 ? options_.jobs : static_cast<int>(std::thread::hardware_concurrency());
    workers = std::max(1, std::min<int>(workers, static_cast<int>(std::max<std::size_t>(n, 1))));

    // The first worker's pipeline is set up here, so bad options fail before any file is
    // touched; the others set up theirs in their own thread (building a tag family's decode
    // table takes a good part of a second).
    const Processor first(options_.process);

    std::vector<std::optional<ImageRecord>> records(n);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    std::exception_ptr fatal;
    std::mutex mutex;
    Progress state;
    state.total = n;

    const auto work = [&](const Processor& processor) {
      while (!stop.load() && !(cancel && cancel->load())) {
        const std::size_t i = next.fetch_add(1);
        if (i >= n) break;
        try {
          ImageRecord rec = processOne(processor, jobs_[i]);
          rec.image = jobs_[i].rel;
          rec.name = jobs_[i].name;
          const std::lock_guard<std::mutex> lock(mutex);
          records[i] = std::move(rec);
          ++state.done;
          if (records[i]->skipped) ++state.skipped;
          if (records[i]->status != Status::Ok) ++state.failed;
          state.elapsed =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          state.last = &*records[i];
          if (progress) progress(state);
        } catch (...) {
          // Writing failed (or worse): the output folder is unusable, stop the run.
          const std::lock_guard<std::mutex> lock(mutex);
          if (!fatal) fatal = std::current_exception();
          stop = true;
        }
      }
    };

    // OpenCV's own thread pool would compete with our workers for the same cores.
    const int cvThreads = cv::getNumThreads();
    if (workers > 1) cv::setNumThreads(1);
    if (workers == 1) {
      work(first);
    } else {
      std::vector<std::thread> threads;
      threads.emplace_back(work, std::cref(first));
      for (int w = 1; w < workers; ++w) {
        threads.emplace_back([&] {
          std::optional<Processor> own;
          try {
            own.emplace(options_.process);
          } catch (...) {
            const std::lock_guard<std::mutex> lock(mutex);
            if (!fatal) fatal = std::current_exception();
            stop = true;
            return;
          }
          work(*own);
        });
      }
      for (auto& t : threads) t.join();
    }
    cv::setNumThreads(cvThreads);
    if (fatal) std::rethrow_exception(fatal);

    RunSummary summary;
    summary.total = n;
    for (auto& r : records) {
      if (!r) continue;
      switch (r->status) {
        case Status::Ok:
          ++summary.ok;
          break;
        case Status::NoRoi:
          ++summary.noRoi;
          break;
        case Status::Failed:
          ++summary.failed;
          break;
        case Status::MaskMismatch:
          ++summary.mismatched;
          break;
      }
      if (r->skipped) ++summary.skipped;
      summary.images.push_back(std::move(*r));
    }
    summary.interrupted = summary.images.size() < n;
    summary.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
  }

 private:
  const BatchOptions& options_;
  std::vector<Job> jobs_;
  std::string key_;
};

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

std::string htmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Percent-encode everything but unreserved characters and '/', for relative URLs.
std::string urlEncode(const std::string& s) {
  std::ostringstream os;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' || c == '/') {
      os << c;
    } else {
      os << '%' << std::uppercase << std::hex << std::setw(2) << std::setfill('0')
         << static_cast<int>(c) << std::dec;
    }
  }
  return os.str();
}

std::string fmt(double v, int precision) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(precision) << v;
  return os.str();
}

std::string ruleName(FillRule r) { return toString(r); }

const char* methodName(ContourMethod m) {
  switch (m) {
    case ContourMethod::Otsu:
      return "otsu";
    case ContourMethod::Adaptive:
      return "adaptive";
    case ContourMethod::Canny:
      return "canny";
    case ContourMethod::Threshold:
      return "threshold";
  }
  return "otsu";
}

}  // namespace

std::vector<fs::path> findImages(const fs::path& input, bool recursive) {
  std::error_code ec;
  if (!fs::is_directory(input, ec)) {
    throw InvalidInputError(input.string() + ": not a folder (or not readable)");
  }
  std::vector<fs::path> found;
  const auto consider = [&](const fs::directory_entry& e) {
    const std::string fname = e.path().filename().string();
    if (!fname.empty() && fname[0] == '.') return;  // hidden files and our own temp files
    std::error_code fe;
    if (e.is_regular_file(fe) && isImageFile(e.path())) found.push_back(e.path());
  };
  try {
    if (recursive) {
      for (const auto& e :
           fs::recursive_directory_iterator(input, fs::directory_options::skip_permission_denied)) {
        consider(e);
      }
    } else {
      for (const auto& e : fs::directory_iterator(input)) consider(e);
    }
  } catch (const fs::filesystem_error& e) {
    throw InvalidInputError(input.string() + ": cannot list folder: " + e.what());
  }
  std::sort(found.begin(), found.end());
  return found;
}

std::string outputName(const fs::path& relative, bool keepExtension) {
  if (relative.empty() || relative.is_absolute() || relative.has_root_name()) {
    throw InvalidInputError("'" + relative.string() + "': not a relative path");
  }
  std::string out;
  for (auto it = relative.begin(); it != relative.end(); ++it) {
    const std::string part = it->string();
    if (part.empty() || part == "." || part == "..") {
      throw InvalidInputError("'" + relative.string() + "': path leaves or names its folder");
    }
    if (!out.empty()) out += '/';
    out += (std::next(it) == relative.end() && !keepExtension) ? it->stem().string() : part;
  }
  if (out.empty() || out.back() == '/') {
    throw InvalidInputError("'" + relative.string() + "': empty file name");
  }
  return out;
}

void writeFileAtomic(const fs::path& file, const std::string& bytes) {
  static std::atomic<unsigned> counter{0};
  const fs::path tmp =
      file.parent_path() / ("." + file.filename().string() + ".tmp." + std::to_string(::getpid()) +
                            "." + std::to_string(counter.fetch_add(1)));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw Error("cannot write " + file.string() + ": " + std::strerror(errno));
    }
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw Error("cannot write " + file.string() + ": write failed");
    }
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw Error("cannot write " + file.string() + ": " + ec.message());
  }
}

std::size_t removeStaleTemporaries(const fs::path& output) {
  std::size_t removed = 0;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(output, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string f = it->path().filename().string();
    // ".NAME.tmp.PID.N", as writeFileAtomic names them.
    const std::size_t tmp = f.rfind(".tmp.");
    if (f.empty() || f[0] != '.' || tmp == std::string::npos) continue;
    const std::string rest = f.substr(tmp + 5);
    const std::size_t dot = rest.find('.');
    if (dot == std::string::npos || dot == 0) continue;
    const std::string pidText = rest.substr(0, dot);
    if (pidText.find_first_not_of("0123456789") != std::string::npos ||
        rest.substr(dot + 1).find_first_not_of("0123456789") != std::string::npos ||
        pidText.size() > 9) {
      continue;
    }
    const auto pid = static_cast<pid_t>(std::stol(pidText));
    // A live process (another run into the same folder) still owns its temporaries.
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code rm;
    if (fs::remove(it->path(), rm)) ++removed;
  }
  return removed;
}

RunSummary run(const BatchOptions& options, const ProgressCallback& progress,
               const std::atomic<bool>* cancel) {
  // "in/" lists "in/x.png", which is not relative to "in/" element by element: drop the slash.
  fs::path input = options.input;
  while (!input.has_filename() && input.has_relative_path()) input = input.parent_path();
  std::vector<fs::path> images = findImages(input, options.recursive);
  std::error_code ec;
  fs::create_directories(options.output, ec);
  if (ec || !fs::is_directory(options.output)) {
    throw Error("cannot create output folder " + options.output.string() +
                (ec ? ": " + ec.message() : ""));
  }
  // A run killed hard (second Ctrl-C, SIGKILL) can leave hidden temporaries; never final files.
  removeStaleTemporaries(options.output);
  // An output folder inside the input folder must not feed our own overlays back in.
  const fs::path outCanon = fs::weakly_canonical(options.output);
  const fs::path inCanon = fs::weakly_canonical(input);
  const auto isOurOutput = [&](const fs::path& p) {
    if (outCanon != inCanon) {
      // Only an output folder inside the input folder can hold outputs we would list.
      return isUnder(outCanon, inCanon) && isUnder(fs::weakly_canonical(p), outCanon);
    }
    const std::string f = lower(p.filename().string());
    const auto endsWith = [&f](const std::string& s) {
      return f.size() >= s.size() && f.compare(f.size() - s.size(), s.size(), s) == 0;
    };
    return endsWith(".overlay.png") || endsWith(".mask.png");
  };
  images.erase(std::remove_if(images.begin(), images.end(), isOurOutput), images.end());

  std::vector<Job> jobs;
  std::map<std::string, int> stems;
  for (const auto& p : images) {
    Job j;
    j.image = p;
    // Relative to the folder as listed, symlinks not resolved: a link to a file elsewhere still
    // gets its name inside the output folder.
    const fs::path rel = p.lexically_relative(input);
    j.rel = rel.generic_string();
    j.name = outputName(rel, false);
    ++stems[j.name];
    jobs.push_back(std::move(j));
  }
  for (auto& j : jobs) {
    if (stems[j.name] > 1) j.name = outputName(fs::path(j.rel), true);
  }

  Runner runner(options, std::move(jobs));
  RunSummary summary = runner.run(progress, cancel);
  writeFileAtomic(options.output / "summary.csv", summaryCsv(summary));
  writeFileAtomic(options.output / "summary.json", summaryJson(summary, options));
  if (options.writeReport) {
    writeFileAtomic(options.output / "report.html", reportHtml(summary, options));
  }
  return summary;
}

std::string summaryCsv(const RunSummary& summary) {
  std::ostringstream os;
  os << kSummaryColumns << "\n";
  for (const auto& r : summary.images) {
    os << csvField(r.image) << ',' << toString(r.status) << ',' << toString(r.failure) << ','
       << csvField(r.reason) << ',' << (r.skipped ? 1 : 0) << ',' << r.width << ',' << r.height
       << ',' << r.tagsFound << ',' << fmt(r.roiArea, 3) << ',' << r.contoursIn << ','
       << r.contoursOut << ',' << fmt(r.clippedArea, 3) << ',' << fmt(r.iou, 6) << ','
       << r.offBandMismatches << ',' << fmt(r.seconds, 4) << "\n";
  }
  return os.str();
}

std::string summaryJson(const RunSummary& summary, const BatchOptions& options) {
  Json rows = Json::array();
  for (const auto& r : summary.images) {
    rows.push_back({{"image", r.image},
                    {"name", r.name},
                    {"status", toString(r.status)},
                    {"failure", toString(r.failure)},
                    {"reason", r.reason},
                    {"skipped", r.skipped},
                    {"width", r.width},
                    {"height", r.height},
                    {"tags_found", r.tagsFound},
                    {"roi_area", r.roiArea},
                    {"contours_in", r.contoursIn},
                    {"contours_out", r.contoursOut},
                    {"clipped_area", r.clippedArea},
                    {"iou", r.iou},
                    {"off_band_mismatches", r.offBandMismatches},
                    {"seconds", r.seconds}});
  }
  const RunOptions& p = options.process;
  Json j = {{"input", options.input.string()},
            {"output", options.output.string()},
            {"options",
             {{"roi", p.roi},
              {"board", p.boardFile},
              {"family", p.detector.family},
              {"method", methodName(p.contours.method)},
              {"polarity", p.contours.polarity == Polarity::Dark ? "dark" : "light"},
              {"approx_epsilon", p.contours.approxEpsilon},
              {"min_area", p.contours.minArea},
              {"fill_rule", ruleName(p.subjectFillRule)},
              {"roi_fill_rule", ruleName(p.roiFillRule)}}},
            {"total", summary.total},
            {"processed", summary.images.size()},
            {"ok", summary.ok},
            {"no_roi", summary.noRoi},
            {"failed", summary.failed},
            {"mask_mismatch", summary.mismatched},
            {"skipped", summary.skipped},
            {"interrupted", summary.interrupted},
            {"seconds", summary.seconds},
            {"images", std::move(rows)}};
  return j.dump(1) + "\n";
}

std::string reportHtml(const RunSummary& summary, const BatchOptions& options) {
  std::ostringstream os;
  os << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
     << "<title>roiclip run: " << htmlEscape(options.input.string()) << "</title>\n"
     << "<style>body{font-family:sans-serif;margin:1em;background:#f4f4f4}"
     << "figure{display:inline-block;vertical-align:top;margin:.5em;padding:.5em;"
     << "background:#fff;max-width:48%}figure img{max-width:100%}"
     << "table{border-collapse:collapse;font-size:90%}td,th{padding:.1em .5em;text-align:right}"
     << ".bad{color:#b00}</style></head><body>\n"
     << "<h1>roiclip run</h1>\n<p>Input <code>" << htmlEscape(options.input.string())
     << "</code>, ROI <code>" << htmlEscape(options.process.roi) << "</code>, contours <code>"
     << methodName(options.process.contours.method) << "</code>, fill rule <code>"
     << ruleName(options.process.subjectFillRule) << "</code>. " << summary.images.size() << " of "
     << summary.total << " images: " << summary.ok << " ok, " << summary.noRoi << " no-roi, "
     << summary.failed << " failed, " << summary.mismatched << " mask-mismatch"
     << (summary.interrupted ? " (interrupted)" : "") << ".</p>\n";
  for (const auto& r : summary.images) {
    const bool ok = r.status == Status::Ok;
    os << "<figure>";
    if (r.status != Status::Failed || r.width > 0) {
      os << "<a href=\"" << urlEncode(r.name) << ".overlay.png\"><img loading=\"lazy\" src=\""
         << urlEncode(r.name) << ".overlay.png\" alt=\"" << htmlEscape(r.image) << "\"></a>";
    }
    os << "<figcaption><b>" << htmlEscape(r.image) << "</b> <span" << (ok ? "" : " class=\"bad\"")
       << ">" << toString(r.status) << "</span>";
    if (!r.reason.empty()) os << ": " << htmlEscape(r.reason);
    os << "<table><tr><th>tags</th><th>ROI px&sup2;</th><th>contours in/out</th>"
       << "<th>clipped px&sup2;</th><th>IoU</th><th>off-band</th><th>s</th></tr><tr><td>"
       << r.tagsFound << "</td><td>" << fmt(r.roiArea, 1) << "</td><td>" << r.contoursIn << "/"
       << r.contoursOut << "</td><td>" << fmt(r.clippedArea, 1) << "</td><td>" << fmt(r.iou, 4)
       << "</td><td>" << r.offBandMismatches << "</td><td>"
       << (r.skipped ? std::string("skipped") : fmt(r.seconds, 3)) << "</td></tr></table>"
       << "<a href=\"" << urlEncode(r.name) << ".json\">JSON</a></figcaption></figure>\n";
  }
  os << "</body></html>\n";
  return os.str();
}

std::vector<std::string> configToArguments(const std::string& jsonText, const std::string& source) {
  const Json j = Json::parse(jsonText, nullptr, false);
  if (j.is_discarded()) throw InvalidInputError(source + ": not valid JSON");
  if (!j.is_object()) throw InvalidInputError(source + ": expected a JSON object of options");
  std::vector<std::string> args;
  const auto scalar = [&](const std::string& key, const Json& v) -> std::string {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number_integer()) return std::to_string(v.get<long long>());
    if (v.is_number()) return v.dump();
    throw InvalidInputError(source + ": option '" + key + "' must be a string, number or boolean");
  };
  for (const auto& [key, value] : j.items()) {
    const std::string flag = "--" + key;
    if (value.is_null()) continue;
    if (value.is_boolean()) {
      if (value.get<bool>()) args.push_back(flag);
    } else if (value.is_array()) {
      for (const auto& v : value) {
        args.push_back(flag);
        args.push_back(scalar(key, v));
      }
    } else {
      args.push_back(flag);
      args.push_back(scalar(key, value));
    }
  }
  return args;
}

}  // namespace roiclip::batch
