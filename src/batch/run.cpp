// SPDX-License-Identifier: MIT
// `roiclip run`: folders, files and videos through the per-image pipeline, in parallel,
// resumable (per image and per video frame), shardable.
#include <roiclip/batch/run.hpp>

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <opencv2/videoio/registry.hpp>

#include <roiclip/batch/process.hpp>
#include <roiclip/io/atomic_file.hpp>

#include "detail/coco.hpp"
#include "detail/folder.hpp"
#include "detail/image_file.hpp"
#include "detail/process.hpp"
#include "detail/report.hpp"
#include "detail/result_json.hpp"
#include "detail/shard.hpp"

namespace roiclip::batch {

namespace fs = std::filesystem;

namespace {

using detail::Clock;
using detail::Job;
using detail::secondsSince;
using io::writeFileAtomically;

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

// The files of one output NAME.
struct OutputFiles {
  fs::path json, overlay, mask;
  OutputFiles(const fs::path& folder, const std::string& name) {
    const std::string base = (folder / fs::path(name)).string();
    json = base + ".json";
    overlay = base + ".overlay.png";
    mask = base + ".mask.png";
  }
};

// "NAME.f000123": a video frame's output NAME.
std::string frameName(const std::string& videoName, int frame) {
  std::string digits = std::to_string(frame);
  if (digits.size() < 6) digits.insert(0, 6 - digits.size(), '0');
  return videoName + ".f" + digits;
}

// A failed result for a file that could not be read.
ImageResult unreadable(FailureKind kind, const std::string& reason) {
  ImageResult result;
  result.status = Status::Failed;
  result.failure = kind;
  result.reason = reason;
  return result;
}

class Runner {
 public:
  Runner(const BatchOptions& options, std::vector<Job> jobs)
      : options_(options), jobs_(std::move(jobs)), key_(optionsKey(options.process)) {}

  // Called with each finished row of a job (in order) and, for a video, with its frame count as
  // far as it is known (count() before and after reading it).
  struct Sink {
    std::function<void(ImageRecord)> row;
    std::function<void(std::size_t)> count;
    std::function<bool()> cancelled;
  };

  // The row of an up-to-date NAME (outputs complete, newer than the input, same options).
  std::optional<ImageRecord> upToDate(const OutputFiles& files,
                                      const std::optional<fs::file_time_type>& inputTime) const {
    if (options_.force || !inputTime) return std::nullopt;
    if (!notOlder(files.json, *inputTime) ||
        (options_.writeOverlays && !notOlder(files.overlay, *inputTime)) ||
        (options_.writeMasks && !notOlder(files.mask, *inputTime))) {
      return std::nullopt;
    }
    return detail::readRecord(files.json, key_);
  }

  // Process `image` (when not empty; else `result` says why not; `readSeconds` is what reading
  // or decoding it took) and write NAME's files.
  ImageRecord finish(const Processor& processor, const cv::Mat& image, ImageResult result,
                     const OutputFiles& files, const Job& job, int frame,
                     double readSeconds) const {
    const auto start = Clock::now();
    if (!image.empty()) result = processor.process(image);
    result.seconds.read = readSeconds;
    std::error_code ec;
    // An overlay only for images the pipeline could read (it sets the size then).
    std::string overlay, mask;
    auto t = Clock::now();
    if (result.width > 0) {
      if (options_.writeOverlays) {
        overlay = encodePng(renderOverlay(image, result), files.overlay.string());
      }
      if (options_.writeMasks && !result.roi.empty()) {
        mask = encodePng(renderMask(result, options_.process.grid), files.mask.string());
      }
    }
    result.seconds.overlay = secondsSince(t);
    t = Clock::now();
    if (!overlay.empty()) {
      writeFileAtomically(files.overlay, overlay);
    } else {
      fs::remove(files.overlay, ec);  // a stale overlay from an earlier run would mislead
    }
    if (!mask.empty()) writeFileAtomically(files.mask, mask);
    result.seconds.write = secondsSince(t);
    result.seconds.total = readSeconds + secondsSince(start);
    // NAME.json last: its presence with status ok is what marks the image as complete. Its own
    // write time is only in the summary's row (NAME.json cannot hold it).
    t = Clock::now();
    writeFileAtomically(files.json, resultToJson(result, job.rel, key_, frame));
    ImageRecord record = detail::recordOf(result);
    const double jsonWrite = secondsSince(t);
    record.stageSeconds.write += jsonWrite;
    record.stageSeconds.total += jsonWrite;
    record.seconds = record.stageSeconds.total;
    return record;
  }

  OutputFiles prepare(const std::string& name) const {
    OutputFiles files(options_.output, name);
    std::error_code ec;
    fs::create_directories(files.json.parent_path(), ec);
    if (ec) {
      throw Error("cannot create output folder " + files.json.parent_path().string() + ": " +
                  ec.message());
    }
    return files;
  }

  static std::optional<fs::file_time_type> modified(const fs::path& file) {
    std::error_code ec;
    const auto t = fs::last_write_time(file, ec);
    if (ec) return std::nullopt;
    return t;
  }

  ImageRecord processImageFile(const Processor& processor, const Job& job) const {
    const OutputFiles files = prepare(job.name);
    std::optional<ImageRecord> rec = upToDate(files, modified(job.image));
    if (!rec) {
      const auto start = Clock::now();
      cv::Mat image;
      ImageResult result;
      try {
        image = readImage(job.image.string(), options_.process.maxPixels);
      } catch (const ImageTooLargeError& e) {
        result = unreadable(FailureKind::TooLarge, e.what());
      } catch (const InvalidInputError& e) {
        result = unreadable(FailureKind::Unreadable, e.what());
      }
      rec = finish(processor, image, std::move(result), files, job, -1, secondsSince(start));
    }
    rec->name = job.name;
    return *rec;
  }

  // Every `every`-th frame of a video, read in order by this one worker. Returns false when
  // cancelled before the video's end.
  bool processVideo(const Processor& processor, const Job& job, const Sink& sink) const {
    // One failed row for the whole video, under the video's NAME.
    const auto failed = [&](const std::string& reason, FailureKind kind = FailureKind::Unreadable) {
      ImageRecord rec =
          finish(processor, cv::Mat(), unreadable(kind, job.image.string() + ": " + reason),
                 prepare(job.name), job, -1, 0.0);
      rec.name = job.name;
      sink.count(1);
      sink.row(std::move(rec));
      return true;
    };
    std::error_code ec;
    const fs::file_status status = fs::status(job.image, ec);
    if (!fs::exists(status)) return failed("no such file");
    if (!fs::is_regular_file(status)) return failed("not a regular file");
    const std::optional<fs::file_time_type> videoTime = modified(job.image);
    // FFmpeg when OpenCV has it: the other backends (GStreamer, image sequences) would read
    // the same file differently, or a single image as a video.
    cv::VideoCapture capture(job.image.string(), cv::videoio_registry::hasBackend(cv::CAP_FFMPEG)
                                                     ? cv::CAP_FFMPEG
                                                     : cv::CAP_ANY);
    if (!capture.isOpened())
      return failed("cannot open video (no cv::VideoCapture backend reads it)");
    // The frame size from the container, before a frame is decoded (as an image's header).
    const auto width = static_cast<std::int64_t>(capture.get(cv::CAP_PROP_FRAME_WIDTH));
    const auto height = static_cast<std::int64_t>(capture.get(cv::CAP_PROP_FRAME_HEIGHT));
    const std::int64_t maxPixels = options_.process.maxPixels;
    if (maxPixels > 0 && width * height > maxPixels) {
      return failed("video frames " + std::to_string(width) + " x " + std::to_string(height) +
                        " = " + std::to_string(width * height) +
                        " pixels, more than the limit of " + std::to_string(maxPixels) +
                        " (--max-pixels); not decoded",
                    FailureKind::TooLarge);
    }
    const std::size_t every = static_cast<std::size_t>(options_.every);
    const double stated = capture.get(cv::CAP_PROP_FRAME_COUNT);
    if (stated >= 1 && stated < 1e9) {
      sink.count((static_cast<std::size_t>(stated) + every - 1) / every);
    }

    std::size_t rows = 0;
    cv::Mat frame;
    for (std::size_t k = 0;; ++k) {
      if (k % every == 0 && sink.cancelled()) return false;
      if (!capture.grab()) break;
      if (k % every != 0) continue;
      const int index = static_cast<int>(k);
      const std::string name = frameName(job.name, index);
      const OutputFiles files = prepare(name);
      std::optional<ImageRecord> rec = upToDate(files, videoTime);
      if (!rec) {
        const auto decode = Clock::now();
        ImageResult result;
        if (!capture.retrieve(frame) || frame.empty()) {
          result = unreadable(FailureKind::Unreadable, job.image.string() + ": frame " +
                                                           std::to_string(k) + ": cannot decode");
          frame.release();
        }
        rec = finish(processor, frame, std::move(result), files, job, index, secondsSince(decode));
      }
      rec->name = name;
      rec->frame = index;
      ++rows;
      sink.row(std::move(*rec));
    }
    if (rows == 0) return failed("no frame could be decoded");
    sink.count(rows);
    return true;
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

    // Per job: its rows, whether it was finished, and how many rows it counts for in the total
    // (1 until a video has been opened).
    std::vector<std::vector<ImageRecord>> records(n);
    std::vector<char> finished(n, 0);
    std::vector<std::size_t> counted(n, 1);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    std::exception_ptr fatal;
    std::mutex mutex;
    Progress state;
    state.total = n;
    const auto cancelled = [&] { return stop.load() || (cancel && cancel->load()); };
    const auto setCount = [&](std::size_t i, std::size_t c) {  // mutex held
      c = std::max(c, records[i].size());
      state.total = state.total - counted[i] + c;
      counted[i] = c;
    };

    const auto work = [&](const Processor& processor) {
      while (!cancelled()) {
        const std::size_t i = next.fetch_add(1);
        if (i >= n) break;
        const Job& job = jobs_[i];
        Sink sink;
        sink.cancelled = cancelled;
        sink.count = [&, i](std::size_t c) {
          const std::lock_guard<std::mutex> lock(mutex);
          setCount(i, c);
        };
        sink.row = [&, i](ImageRecord rec) {
          rec.image = job.rel;
          const std::lock_guard<std::mutex> lock(mutex);
          records[i].push_back(std::move(rec));
          const ImageRecord& last = records[i].back();
          setCount(i, counted[i]);
          ++state.done;
          if (last.skipped) ++state.skipped;
          if (last.status != Status::Ok) ++state.failed;
          state.elapsed =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          state.last = &last;
          if (progress) progress(state);
        };
        try {
          bool done = true;
          if (job.video) {
            done = processVideo(processor, job, sink);
          } else {
            sink.row(processImageFile(processor, job));
          }
          const std::lock_guard<std::mutex> lock(mutex);
          finished[i] = done ? 1 : 0;
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
    summary.total = state.total;
    for (std::size_t i = 0; i < n; ++i) {
      if (!finished[i]) summary.interrupted = true;
      for (ImageRecord& r : records[i]) {
        switch (r.status) {
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
        if (r.skipped) ++summary.skipped;
        summary.images.push_back(std::move(r));
      }
    }
    summary.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
  }

 private:
  const BatchOptions& options_;
  std::vector<Job> jobs_;
  std::string key_;
};

// The run's images. "in/" lists "in/x.png", which is not relative to "in/" element by element:
// the slash is dropped.
// The jobs of this run's shard. Names are given over all inputs, so every shard names an input
// alike.
std::vector<Job> listJobs(const BatchOptions& options) {
  if (options.every < 1) {
    throw InvalidInputError("every " + std::to_string(options.every) +
                            ": need a frame step of at least 1");
  }
  return detail::selectShard(detail::listJobs(options.inputs, options.output, options.recursive),
                             options.shard);
}

}  // namespace

std::size_t checkRun(const BatchOptions& options) {
  const std::size_t images = listJobs(options).size();
  const Processor check(options.process);
  return images;
}

RunSummary run(const BatchOptions& options, const ProgressCallback& progress,
               const std::atomic<bool>* cancel) {
  std::vector<Job> jobs = listJobs(options);
  detail::prepareOutputFolder(options.output);

  Runner runner(options, std::move(jobs));
  RunSummary summary = runner.run(progress, cancel);
  writeFileAtomically(options.output / "summary.csv", detail::summaryCsv(summary));
  writeFileAtomically(options.output / "summary.json", detail::summaryJson(summary, options));
  if (options.writeReport) {
    writeFileAtomically(options.output / "report.html", detail::reportHtml(summary, options));
  }
  if (!options.coco.empty()) {
    // A folder that cannot be made is reported by the write, naming the file.
    std::error_code ec;
    if (options.coco.has_parent_path()) fs::create_directories(options.coco.parent_path(), ec);
    writeFileAtomically(options.coco, detail::cocoJson(summary, options));
  }
  return summary;
}

}  // namespace roiclip::batch
