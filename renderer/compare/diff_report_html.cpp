#include "compare/diff_report_html.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "common/markup_text.h"
#include "compare/diff_format.h"
#include "compare/diff_text.h"
#include "compare/heat_map.h"

namespace facet {
namespace {

// Small images are shown enlarged by a whole factor (pixels stay square and
// sharp), so a 10x10 test image is not a speck.
constexpr int kSmallImageTarget = 256;  // CSS pixels

constexpr const char* kStyle = R"(
body { margin: 0; padding: 1.5em; background: #1d1f21; color: #d8d8d8; font: 14px/1.45 system-ui, sans-serif; }
h1 { margin: 0 0 .3em; font-size: 1.6em; }
h2 { margin: 0 0 .6em; font-size: 1.2em; }
code { font: 12px ui-monospace, monospace; color: #b8c4d0; word-break: break-all; }
a { color: #8cb4ff; }
table { border-collapse: collapse; }
td, th { padding: .15em .8em .15em 0; text-align: left; vertical-align: top; }
th { font-weight: 600; color: #a0a0a0; }
td.n { text-align: right; font-variant-numeric: tabular-nums; }
header, nav, section { max-width: 1400px; margin: 0 auto 1.5em; }
nav ol { padding-left: 2em; columns: 2 22em; }
section { border-top: 1px solid #444; padding-top: 1.2em; }
.verdict { display: inline-block; padding: 0 .5em; border-radius: 3px; font-size: .8em; font-weight: 700; color: #111; vertical-align: middle; }
.v0 { background: #7fc97f; } .v1 { background: #f0c75e; } .v2 { background: #f07060; } .v3, .v4 { background: #d070e0; }
.problem { color: #ffb0a0; }
.images { display: grid; grid-template-columns: repeat(3, minmax(0, max-content)); gap: 1em; margin-bottom: 1em; }
figure { margin: 0; }
figure img { display: block; max-width: 100%; height: auto; image-rendering: pixelated;
  background: repeating-conic-gradient(#555 0 25%, #777 0 50%) 0 0 / 16px 16px; }
figure .none { display: flex; align-items: center; justify-content: center; width: 256px; height: 128px; border: 1px dashed #666; color: #999; }
figcaption { margin-top: .3em; color: #a0a0a0; }
.swatch { display: inline-block; width: 1em; height: 1em; border: 1px solid #888; vertical-align: -.15em; margin-right: .3em; }
.legend span { margin-right: 1em; white-space: nowrap; }
)";


std::string badge(Verdict v) {
  return "<span class=\"verdict v" + std::to_string(static_cast<int>(v)) + "\">" + std::string(verdictName(v)) + "</span>";
}

std::string swatch(Rgba8 c) {
  char css[48];
  std::snprintf(css, sizeof css, "rgba(%d,%d,%d,%.3f)", c.r, c.g, c.b, c.a / 255.0);
  return "<span class=\"swatch\" style=\"background:" + std::string(css) + "\"></span>";
}

void writeFigure(std::ostringstream& out, const ReportImage& image, const std::string& caption, const std::string& detail) {
  out << "<figure>";
  if (image.path.empty()) {
    out << "<div class=\"none\">no image</div>";
  } else {
    const int scale = std::max(1, kSmallImageTarget / std::max(image.width, image.height));
    out << "<a href=\"" << markupEscaped(image.path) << "\"><img src=\"" << markupEscaped(image.path) << "\" width=\"" << image.width * scale
        << "\" height=\"" << image.height * scale << "\" alt=\"" << markupEscaped(caption) << "\"></a>";
  }
  out << "<figcaption>" << markupEscaped(caption);
  if (!detail.empty()) out << "<br><code>" << markupEscaped(detail) << "</code>";
  out << "</figcaption></figure>\n";
}

void writeFigures(std::ostringstream& out, const DiffResult& r, const DiffThresholds& t) {
  constexpr const char* kChannels[4] = {"R", "G", "B", "A"};
  out << "<table class=\"figures\">\n<tr><th></th>";
  for (const char* c : kChannels) out << "<th>" << c << "</th>";
  out << "<th></th></tr>\n<tr><th>max difference</th>";
  for (const ChannelDiff& c : r.channels) out << "<td class=\"n\">" << c.max << "</td>";
  out << "<td>8-bit levels</td></tr>\n<tr><th>mean difference</th>";
  for (const ChannelDiff& c : r.channels) out << "<td class=\"n\">" << formatNumber(c.mean) << "</td>";
  out << "<td></td></tr>\n</table>\n<table class=\"figures\">\n";
  out << "<tr><th>mean error, RMS error, PSNR</th><td>" << formatIdiffNumber(r.meanError / 255.0) << ", " << formatIdiffNumber(r.rmse / 255.0)
      << ", " << formatIdiffNumber(r.psnr) << " dB (" << formatChannels(r.storedChannels) << "; fractions of full scale, as idiff)</td></tr>\n";
  out << "<tr><th>failing pixels</th><td>" << formatPixels(r.failingPixels) << " (" << formatNumber(r.failingPercent)
      << "%) over " << formatThreshold(t.failThreshold) << "; allowed " << formatAllowed(t.failPercent, t.allowFailures) << "</td></tr>\n";
  out << "<tr><th>warning pixels</th><td>" << formatPixels(r.warningPixels) << " (" << formatNumber(r.warningPercent)
      << "%) over " << formatThreshold(t.warnThreshold) << "; allowed " << formatAllowed(t.warnPercent) << "</td></tr>\n";
  out << "<tr><th>differing pixels</th><td>" << formatPixels(r.differingPixels) << " in " << formatBox(r.differing, r.height)
      << "</td></tr>\n";
  out << "<tr><th>failing box</th><td>" << formatBox(r.failing, r.height) << "</td></tr>\n";
  if (r.worst.x >= 0)
    out << "<tr><th>max error</th><td>" << formatIdiffNumber(r.worst.difference / 255.0) << " (" << r.worst.difference << " of 255) at "
        << formatPosition(r.worst.x, r.worst.y, r.height) << " " << formatChannel(r.worst.channel, r.storedChannels) << ": expected "
        << swatch(r.worst.expected) << "<code>" << formatColor(r.worst.expected) << "</code>, actual " << swatch(r.worst.actual) << "<code>"
        << formatColor(r.worst.actual) << "</code></td></tr>\n";
  out << "</table>\n";
}

void writeCase(std::ostringstream& out, const ReportCase& rc, int rank, const DiffThresholds& t) {
  const DiffCase& c = rc.diffCase;
  out << "<section id=\"case-" << rank << "\" data-name=\"" << markupEscaped(c.name) << "\">\n<h2>" << rank << ". " << markupEscaped(c.name) << " "
      << badge(c.verdict) << "</h2>\n";
  if (!c.problem.empty()) out << "<p class=\"problem\">" << markupEscaped(c.problem) << "</p>\n";
  out << "<div class=\"images\">\n";
  writeFigure(out, rc.expected, "expected", c.expectedPath);
  writeFigure(out, rc.actual, "actual", c.actualPath);
  writeFigure(out, rc.heatMap, "difference", c.result ? "largest channel difference per pixel" : "");
  out << "</div>\n";
  if (c.result) writeFigures(out, *c.result, t);
  out << "</section>\n";
}

void writeLegend(std::ostringstream& out, const DiffThresholds& t) {
  const int tolerated = toleratedLevels(t.failThreshold);
  std::vector<int> levels = {1, tolerated, tolerated + 1, 8, 32, 128, 255};
  levels.erase(std::remove_if(levels.begin(), levels.end(), [](int d) { return d < 1 || d > 255; }), levels.end());
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  out << "<p class=\"legend\">heat map, by a pixel's largest channel difference (8-bit levels): <span>" << swatch(heatMapColor(0, t))
      << "0 equal</span>";
  for (const int d : levels)
    out << "<span>" << swatch(heatMapColor(d, t)) << d << (d > tolerated ? " fails" : " passes") << "</span>";
  out << "</p>\n";
}

void writeThresholds(std::ostringstream& out, const DiffThresholds& t) {
  out << "<table class=\"thresholds\">\n<tr><th></th><th>threshold</th><th>pixels allowed over it</th><th>hard limit</th></tr>\n";
  out << "<tr><th>fail</th><td>" << formatThreshold(t.failThreshold) << "</td><td>" << formatAllowed(t.failPercent, t.allowFailures) << "</td><td>"
      << formatThreshold(t.hardFail) << "</td></tr>\n";
  out << "<tr><th>warn</th><td>" << formatThreshold(t.warnThreshold) << "</td><td>" << formatAllowed(t.warnPercent) << "</td><td>"
      << formatThreshold(t.hardWarn) << "</td></tr>\n</table>\n";
}

std::string tocEntry(const DiffCase& c) {
  if (!c.result) return markupEscaped(c.problem);
  const DiffResult& r = *c.result;
  return formatNumber(r.failingPercent) + "% failing, max difference " + std::to_string(r.maxDifference) + ", PSNR " + formatNumber(r.psnr) +
         " dB";
}

}  // namespace

std::string reportHtml(std::vector<ReportCase> cases, const ReportContext& context) {
  std::stable_sort(cases.begin(), cases.end(), [](const ReportCase& a, const ReportCase& b) { return worseThan(a.diffCase, b.diffCase); });
  std::vector<DiffCase> plain;
  for (const ReportCase& rc : cases) plain.push_back(rc.diffCase);
  const Verdict worst = worstVerdict(plain);

  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>facet diff: " << verdictName(worst) << ", "
      << cases.size() << (cases.size() == 1 ? " case" : " cases") << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<header>\n";
  out << "<h1>facet diff " << badge(worst) << "</h1>\n";
  out << "<p>expected <code>" << markupEscaped(context.expectedSource) << "</code> &middot; actual <code>" << markupEscaped(context.actualSource)
      << "</code></p>\n";
  out << "<p>" << markupEscaped(summaryLine(plain)) << "</p>\n";
  writeThresholds(out, context.thresholds);
  writeLegend(out, context.thresholds);
  out << "</header>\n<nav>\n<h2>Cases, worst first</h2>\n<ol>\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const DiffCase& c = cases[i].diffCase;
    out << "<li><a href=\"#case-" << i + 1 << "\">" << markupEscaped(c.name) << "</a> " << badge(c.verdict) << " " << tocEntry(c) << "</li>\n";
  }
  out << "</ol>\n</nav>\n";
  for (std::size_t i = 0; i < cases.size(); ++i) writeCase(out, cases[i], static_cast<int>(i + 1), context.thresholds);
  out << "</body>\n</html>\n";
  return out.str();
}

}  // namespace facet
