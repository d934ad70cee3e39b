// `roiclip run`: a folder of images through the per-image pipeline, in parallel, resumable.
#include <roiclip/batch/run.hpp>

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

#include <roiclip/batch/process.hpp>
#include <roiclip/io/atomic_file.hpp>

#include "detail/folder.hpp"
#include "detail/image_file.hpp"
#include "detail/report.hpp"
#include "detail/result_json.hpp"

namespace roiclip::batch {

namespace fs = std::filesystem;

namespace {

using detail::Job;
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
        if (auto rec = detail::readRecord(jsonFile, key_)) return *rec;
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
      writeFileAtomically(overlayFile,
                          encodePng(renderOverlay(image, result), overlayFile.string()));
      if (options_.writeMasks && !result.roi.empty()) {
        writeFileAtomically(
            maskFile, encodePng(renderMask(result, options_.process.grid), maskFile.string()));
      }
    } else {
      fs::remove(overlayFile, ec);  // a stale overlay from an earlier run would mislead
    }
    // NAME.json last: its presence with status ok is what marks the image as complete.
    writeFileAtomically(jsonFile, detail::resultToJson(result, job.rel, key_));
    return detail::recordOf(result);
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

// The run's images. "in/" lists "in/x.png", which is not relative to "in/" element by element:
// the slash is dropped.
std::vector<Job> listJobs(const BatchOptions& options) {
  fs::path input = options.input;
  while (!input.has_filename() && input.has_relative_path()) input = input.parent_path();
  return detail::listJobs(input, options.output, options.recursive);
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
  std::error_code ec;
  fs::create_directories(options.output, ec);
  if (ec || !fs::is_directory(options.output)) {
    throw Error("cannot create output folder " + options.output.string() +
                (ec ? ": " + ec.message() : ""));
  }
  // A run killed hard (second Ctrl-C, SIGKILL) can leave hidden temporaries; never final files.
  io::removeStaleTemporaries(options.output);

  Runner runner(options, std::move(jobs));
  RunSummary summary = runner.run(progress, cancel);
  writeFileAtomically(options.output / "summary.csv", detail::summaryCsv(summary));
  writeFileAtomically(options.output / "summary.json", detail::summaryJson(summary, options));
  if (options.writeReport) {
    writeFileAtomically(options.output / "report.html", detail::reportHtml(summary, options));
  }
  return summary;
}

}  // namespace roiclip::batch
