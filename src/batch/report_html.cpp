// SPDX-License-Identifier: MIT
// report.html: the counts, a sortable summary table (failures first) and a grid of overlays.
#include "detail/report_html.hpp"

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <numeric>
#include <optional>
#include <sstream>

#include "detail/overlay.hpp"
#include "detail/report.hpp"

namespace roiclip::batch::detail {

namespace {

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

std::string fixed(double v, int precision) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(precision) << v;
  return os.str();
}

// Failures first: the order of the status groups in the table and the grid.
int statusRank(Status status) {
  switch (status) {
    case Status::Failed:
      return 0;
    case Status::MaskMismatch:
      return 1;
    case Status::NoRoi:
      return 2;
    case Status::Ok:
      return 3;
  }
  return 0;
}

// Whether the pipeline got as far as clipping, so contours, areas and the mask check mean
// something.
bool clipped(const ImageRecord& r) {
  return r.status == Status::Ok || r.status == Status::MaskMismatch;
}

// The IoU to show: none for images the pipeline did not clip. (Written so it also compiles once
// ImageRecord::iou is a std::optional<double>.)
std::optional<double> shownIou(const ImageRecord& r) {
  if (!clipped(r)) return std::nullopt;
  return r.iou;
}

constexpr const char* kDash = "&ndash;";

const char* const kStyle = R"(
body{font-family:system-ui,sans-serif;margin:1em 2em;background:#f4f4f4;color:#222}
h1{margin:.2em 0}h2{margin:1.2em 0 .4em}
.facts code{background:#e4e4e4;padding:0 .3em;border-radius:3px}
.counts span{display:inline-block;margin:.2em .6em .2em 0;padding:.15em .6em;border-radius:1em;
background:#ddd}
.counts .ok{background:#cdeccd}.counts .bad{background:#f6caca}
table{border-collapse:collapse;background:#fff;font-size:90%;width:100%}
th,td{padding:.25em .6em;border-bottom:1px solid #e0e0e0;text-align:right;white-space:nowrap}
th{background:#333;color:#fff;position:sticky;top:0}
th button{font:inherit;color:inherit;background:none;border:0;cursor:pointer;padding:0}
th button::after{content:" \2195";opacity:.6}
th[aria-sort=ascending] button::after{content:" \25B2"}
th[aria-sort=descending] button::after{content:" \25BC"}
td.text,th.text{text-align:left}td.reason{white-space:normal;min-width:12em;overflow-wrap:anywhere}
.scroll{overflow-x:auto}
tr.bad td{background:#fdeaea}.sub{font-size:85%;color:#555}.status-bad{color:#b00;font-weight:bold}.status-ok{color:#070}
.grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(260px,1fr));gap:12px}
figure{margin:0;padding:6px;background:#fff;border:1px solid #ddd;border-radius:4px}
figure.bad{border-color:#e88}
figure img{width:100%;height:auto;display:block}
figcaption{font-size:85%;margin-top:4px;overflow-wrap:anywhere}
.noimage{aspect-ratio:4/3;display:flex;align-items:center;justify-content:center;
background:#eee;color:#b00;text-align:center;padding:1em;overflow:hidden;overflow-wrap:anywhere}
)";

// Sort the table by a th's data-key: numbers read from each row's data-* attribute; rows without
// a value (no IoU) stay last; ties keep the page's own order (data-order).
const char* const kScript = R"(
(function () {
  var heads = document.querySelectorAll('#summary th[data-key]');
  heads.forEach(function (th) {
    th.querySelector('button').addEventListener('click', function () {
      var key = th.getAttribute('data-key');
      var asc = th.getAttribute('aria-sort') !== 'ascending';
      heads.forEach(function (h) { h.removeAttribute('aria-sort'); });
      th.setAttribute('aria-sort', asc ? 'ascending' : 'descending');
      var body = document.querySelector('#summary tbody');
      var rows = Array.prototype.slice.call(body.rows);
      rows.sort(function (a, b) {
        var x = a.getAttribute('data-' + key), y = b.getAttribute('data-' + key);
        var d = 0;
        if (x === '' || y === '') d = (x === '') - (y === '');
        else d = (asc ? 1 : -1) * (parseFloat(x) - parseFloat(y));
        return d || a.getAttribute('data-order') - b.getAttribute('data-order');
      });
      rows.forEach(function (r) { body.appendChild(r); });
    });
  });
  // report.html#sort=iou opens sorted by IoU, ascending; #sort=-iou descending.
  var m = /^#sort=(-?)([a-z-]+)$/.exec(location.hash);
  var th = m && document.querySelector('#summary th[data-key="' + m[2] + '"]');
  if (th) {
    th.querySelector('button').click();
    if (m[1]) th.querySelector('button').click();
  }
})();
)";

void writeCounts(std::ostringstream& os, const RunSummary& summary) {
  const auto count = [&os](std::size_t n, const char* what, bool bad) {
    os << "<span class=\""
       << (bad && n > 0 ? "bad"
           : n > 0      ? "ok"
                        : "")
       << "\">" << n << ' ' << what << "</span>";
  };
  os << "<p class=\"counts\" id=\"counts\"><span><b>" << summary.images.size() << " of "
     << summary.total << " images</b></span>";
  count(summary.ok, "ok", false);
  count(summary.failed, "failed", true);
  count(summary.mismatched, "mask-mismatch", true);
  count(summary.noRoi, "no-roi", true);
  os << "<span>" << summary.skipped << " up to date</span>";
  if (summary.interrupted) os << "<span class=\"bad\">interrupted</span>";
  os << "</p>\n";
}

void writeRow(std::ostringstream& os, const ImageRecord& r, std::size_t order, bool overlays) {
  const bool ok = r.status == Status::Ok;
  const bool measured = clipped(r);
  const std::optional<double> iou = shownIou(r);
  const std::string name = urlEncode(r.name);
  os << "<tr id=\"row-" << order << "\"" << (ok ? "" : " class=\"bad\"") << " data-order=\""
     << order << "\" data-status=\"" << statusRank(r.status) << "\" data-roi-area=\""
     << (measured ? fixed(r.roiArea, 3) : "") << "\" data-area=\""
     << (measured ? fixed(r.clippedArea, 3) : "") << "\" data-iou=\"" << (iou ? fixed(*iou, 6) : "")
     << "\" data-time=\"" << fixed(r.seconds, 4) << "\">";
  os << "<td class=\"text\"><a href=\"#img-" << order << "\">" << htmlEscape(r.image)
     << "</a></td><td class=\"text " << (ok ? "status-ok" : "status-bad") << "\">"
     << toString(r.status) << "</td><td class=\"text reason\">" << htmlEscape(r.reason)
     << "</td><td>" << r.tagsFound;
  if (r.tagsRejected > 0) os << " (" << r.tagsRejected << " rejected)";
  os << "</td>";
  if (measured) {
    // With several ROIs, each one's figures in a line of its own under the image's.
    const bool several = r.rois.size() > 1;
    const auto cell = [&](const std::string& total, const auto& perRoi) {
      os << "<td>" << total;
      if (several) {
        for (const RoiRecord& roi : r.rois) {
          os << "<div class=\"sub\">" << htmlEscape(roi.name) << ": " << perRoi(roi) << "</div>";
        }
      }
      os << "</td>";
    };
    cell(fixed(r.roiArea, 1), [](const RoiRecord& roi) { return fixed(roi.roiArea, 1); });
    cell(contoursInsideText(r.contoursOut, r.contoursIn),
         [](const RoiRecord& roi) { return std::to_string(roi.contoursOut) + " inside"; });
    cell(fixed(r.clippedArea, 1), [](const RoiRecord& roi) { return fixed(roi.clippedArea, 1); });
  } else {
    os << "<td>" << kDash << "</td><td>" << kDash << "</td><td>" << kDash << "</td>";
  }
  os << "<td>" << (iou ? fixed(*iou, 4) : kDash) << "</td><td>"
     << (measured ? std::to_string(r.offBandMismatches) : kDash) << "</td><td>"
     << (r.skipped ? std::string("up to date") : fixed(r.seconds, 3)) << "</td><td class=\"text\">";
  if (r.width > 0 && overlays) os << "<a href=\"" << name << ".overlay.png\">overlay</a> ";
  os << "<a href=\"" << name << ".json\">JSON</a></td></tr>\n";
}

void writeFigure(std::ostringstream& os, const ImageRecord& r, std::size_t order, bool overlays) {
  const bool ok = r.status == Status::Ok;
  const std::string name = urlEncode(r.name);
  os << "<figure id=\"img-" << order << "\"" << (ok ? "" : " class=\"bad\"") << ">";
  if (r.width > 0 && !overlays) {
    os << "<div class=\"noimage\">no overlay (--no-overlay)</div>";
  } else if (r.width > 0) {
    os << "<a href=\"" << name << ".overlay.png\"><img loading=\"lazy\" src=\"" << name
       << ".overlay.png\" alt=\"overlay of " << htmlEscape(r.image) << "\"></a>";
  } else {
    os << "<div class=\"noimage\">no overlay: " << htmlEscape(r.reason) << "</div>";
  }
  os << "<figcaption><a href=\"#row-" << order << "\"><b>" << htmlEscape(r.image)
     << "</b></a> <span class=\"" << (ok ? "status-ok" : "status-bad") << "\">"
     << toString(r.status) << "</span>";
  if (clipped(r)) os << ", contours " << contoursInsideText(r.contoursOut, r.contoursIn);
  os << " &middot; <a href=\"" << name << ".json\">JSON</a></figcaption></figure>\n";
}

}  // namespace

std::vector<std::size_t> reportOrder(const RunSummary& summary) {
  std::vector<std::size_t> order(summary.images.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return statusRank(summary.images[a].status) < statusRank(summary.images[b].status);
  });
  return order;
}

std::string reportHtml(const RunSummary& summary, const ReportPage& page) {
  std::ostringstream os;
  os << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
     << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>"
     << htmlEscape(page.title);
  if (!page.facts.empty()) os << ": " << htmlEscape(page.facts.front().second);
  os << "</title>\n<style>" << kStyle << "</style></head><body>\n<h1>" << htmlEscape(page.title)
     << "</h1>\n<p class=\"facts\">";
  for (std::size_t i = 0; i < page.facts.size(); ++i) {
    os << (i == 0 ? "" : ", ") << htmlEscape(page.facts[i].first) << " <code>"
       << htmlEscape(page.facts[i].second) << "</code>";
  }
  os << "</p>\n";
  writeCounts(os, summary);

  const std::vector<std::size_t> order = reportOrder(summary);
  os << "<div class=\"scroll\"><table id=\"summary\"><thead><tr><th class=\"text\">image</th>"
     << "<th class=\"text\" data-key=\"status\"><button type=\"button\">status</button></th>"
     << "<th class=\"text\">reason</th><th>tags</th>"
     << "<th data-key=\"roi-area\"><button type=\"button\">ROI px&sup2;</button></th>"
     << "<th>contours</th>"
     << "<th data-key=\"area\"><button type=\"button\">clipped px&sup2;</button></th>"
     << "<th data-key=\"iou\"><button type=\"button\">IoU</button></th><th>off-band</th>"
     << "<th data-key=\"time\"><button type=\"button\">s</button></th>"
     << "<th class=\"text\">files</th></tr></thead>\n<tbody>\n";
  for (std::size_t k = 0; k < order.size(); ++k)
    writeRow(os, summary.images[order[k]], k, page.overlays);
  os << "</tbody></table></div>\n<h2>Overlays</h2>\n<div class=\"grid\" id=\"overlays\">\n";
  for (std::size_t k = 0; k < order.size(); ++k)
    writeFigure(os, summary.images[order[k]], k, page.overlays);
  os << "</div>\n<script>" << kScript << "</script>\n</body></html>\n";
  return os.str();
}

std::string reportHtml(const RunSummary& summary, const BatchOptions& options) {
  std::string rois;
  for (const std::string& roi : options.process.rois) rois += (rois.empty() ? "" : " + ") + roi;
  ReportPage page{"roiclip run",
                  {{"input", inputList(options)},
                   {"ROI", rois},
                   {"contours", toString(options.process.contours.method)},
                   {"fill rule", toString(options.process.subjectFillRule)}}};
  page.overlays = options.writeOverlays;
  return reportHtml(summary, page);
}

}  // namespace roiclip::batch::detail
