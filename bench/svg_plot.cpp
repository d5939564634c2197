#include "svg_plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "common/markup_text.h"

namespace facet {
namespace {

// A panel's cell: the plot area and the room around it for titles, ticks and labels.
constexpr double kAreaWidth = 300, kAreaHeight = 200;
constexpr double kLeft = 64, kRight = 18, kTop = 30, kBottom = 46;
constexpr double kCellWidth = kLeft + kAreaWidth + kRight, kCellHeight = kTop + kAreaHeight + kBottom;
constexpr double kHeader = 80, kMargin = 12;

constexpr std::array<const char*, 6> kColours = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};


std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

// 1000 as "1k", 2e6 as "2M": tick labels stay short.
std::string shortNumber(double v) {
  char text[32];
  const double a = std::fabs(v);
  if (a >= 1e6) std::snprintf(text, sizeof text, "%gM", v / 1e6);
  else if (a >= 1e4) std::snprintf(text, sizeof text, "%gk", v / 1e3);
  else std::snprintf(text, sizeof text, "%g", v);
  return text;
}

bool drawable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

// An axis' range in plotted units (log10 of the value on a log axis) and its ticks.
struct Scale {
  bool log = false;
  double lo = 0, hi = 1;
  std::vector<std::pair<double, std::string>> ticks;
  double toUnit(double v) const { return log ? std::log10(v) : v; }
  double fraction(double v) const { return (toUnit(v) - lo) / (hi - lo); }
};

Scale scaleFor(const PlotAxis& axis, const std::vector<double>& values) {
  Scale s;
  s.log = axis.log;
  double lo = INFINITY, hi = -INFINITY;
  for (const double v : values)
    if (drawable(v, axis.log)) lo = std::min(lo, s.toUnit(v)), hi = std::max(hi, s.toUnit(v));
  for (const auto& tick : axis.ticks)
    if (drawable(tick.first, axis.log)) lo = std::min(lo, s.toUnit(tick.first)), hi = std::max(hi, s.toUnit(tick.first));
  if (!std::isfinite(lo)) lo = 0, hi = 1;
  if (axis.fromZero && !axis.log) lo = std::min(lo, 0.0);
  if (hi - lo <= 0) {
    const double half = axis.log ? 0.5 : std::max(1.0, std::fabs(lo) * 0.1);
    lo -= half, hi += half;
  }
  const double pad = 0.06 * (hi - lo);
  s.lo = axis.fromZero && !axis.log && lo == 0 ? 0 : lo - pad;
  s.hi = hi + pad;

  if (!axis.ticks.empty()) {
    for (const auto& tick : axis.ticks)
      if (drawable(tick.first, axis.log)) s.ticks.push_back(tick);
    return s;
  }
  if (axis.log) {
    // Powers of ten when the range holds three; else 1, 2 and 5 of each decade.
    for (const std::vector<double>& steps : {std::vector<double>{1}, std::vector<double>{1, 2, 5}, std::vector<double>{1, 1.5, 2, 3, 5, 7}}) {
      s.ticks.clear();
      for (int k = static_cast<int>(std::floor(s.lo)); k <= static_cast<int>(std::ceil(s.hi)); ++k)
        for (const double m : steps) {
          const double v = m * std::pow(10.0, k);
          if (std::log10(v) >= s.lo && std::log10(v) <= s.hi) s.ticks.emplace_back(v, shortNumber(v));
        }
      if (s.ticks.size() >= 3) break;
    }
    return s;
  }
  // A step of 1, 2 or 5 times a power of ten giving four to eight ticks.
  const double raw = (s.hi - s.lo) / 5;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade;
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= raw * 0.75) {
      step = m * decade;
      break;
    }
  for (double v = std::ceil(s.lo / step) * step; v <= s.hi + 1e-9 * step; v += step)
    s.ticks.emplace_back(std::fabs(v) < 1e-9 * step ? 0.0 : v, shortNumber(std::fabs(v) < 1e-9 * step ? 0.0 : v));
  return s;
}

std::string marker(int kind, double x, double y, const char* colour) {
  const std::string fill = std::string(" fill=\"") + colour + "\"";
  switch (kind % 4) {
    case 0:
      return "<circle cx=\"" + number(x) + "\" cy=\"" + number(y) + "\" r=\"3.5\"" + fill + "/>";
    case 1:
      return "<rect x=\"" + number(x - 3.2) + "\" y=\"" + number(y - 3.2) + "\" width=\"6.4\" height=\"6.4\"" + fill + "/>";
    case 2:
      return "<path d=\"M" + number(x) + " " + number(y - 4.2) + "L" + number(x + 4) + " " + number(y + 3) + "L" + number(x - 4) + " " +
             number(y + 3) + "Z\"" + fill + "/>";
    default:
      return "<path d=\"M" + number(x) + " " + number(y - 4.5) + "L" + number(x + 4) + " " + number(y) + "L" + number(x) + " " + number(y + 4.5) +
             "L" + number(x - 4) + " " + number(y) + "Z\"" + fill + "/>";
  }
}

void drawPanel(std::string& svg, const PlotPanel& panel, double left, double top, const std::vector<std::string>& names) {
  std::vector<double> xs, ys;
  for (const PlotSeries& s : panel.series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (drawable(s.x[i], panel.x.log) && drawable(s.y[i], panel.y.log)) xs.push_back(s.x[i]), ys.push_back(s.y[i]);
  }
  const Scale sx = scaleFor(panel.x, xs), sy = scaleFor(panel.y, ys);
  const double x0 = left + kLeft, y0 = top + kTop, x1 = x0 + kAreaWidth, y1 = y0 + kAreaHeight;
  const auto px = [&](double v) { return x0 + sx.fraction(v) * kAreaWidth; };
  const auto py = [&](double v) { return y1 - sy.fraction(v) * kAreaHeight; };

  svg += "<g>\n<text x=\"" + number(left + kCellWidth / 2) + "\" y=\"" + number(top + 18) + "\" text-anchor=\"middle\" font-weight=\"bold\">" +
         markupEscaped(panel.title) + "</text>\n";
  svg += "<rect x=\"" + number(x0) + "\" y=\"" + number(y0) + "\" width=\"" + number(kAreaWidth) + "\" height=\"" + number(kAreaHeight) +
         "\" fill=\"#ffffff\" stroke=\"#444444\"/>\n";
  for (const auto& [value, label] : sx.ticks) {
    const double x = px(value);
    svg += "<line x1=\"" + number(x) + "\" y1=\"" + number(y0) + "\" x2=\"" + number(x) + "\" y2=\"" + number(y1) + "\" stroke=\"#e4e4e4\"/>";
    svg += "<line x1=\"" + number(x) + "\" y1=\"" + number(y1) + "\" x2=\"" + number(x) + "\" y2=\"" + number(y1 + 4) + "\" stroke=\"#444444\"/>";
    svg += "<text x=\"" + number(x) + "\" y=\"" + number(y1 + 16) + "\" text-anchor=\"middle\">" + markupEscaped(label) + "</text>\n";
  }
  for (const auto& [value, label] : sy.ticks) {
    const double y = py(value);
    svg += "<line x1=\"" + number(x0) + "\" y1=\"" + number(y) + "\" x2=\"" + number(x1) + "\" y2=\"" + number(y) + "\" stroke=\"#e4e4e4\"/>";
    svg += "<line x1=\"" + number(x0 - 4) + "\" y1=\"" + number(y) + "\" x2=\"" + number(x0) + "\" y2=\"" + number(y) + "\" stroke=\"#444444\"/>";
    svg += "<text x=\"" + number(x0 - 7) + "\" y=\"" + number(y + 4) + "\" text-anchor=\"end\">" + markupEscaped(label) + "</text>\n";
  }
  svg += "<text x=\"" + number((x0 + x1) / 2) + "\" y=\"" + number(y1 + 36) + "\" text-anchor=\"middle\">" + markupEscaped(panel.x.label) + "</text>\n";
  svg += "<text transform=\"translate(" + number(left + 16) + " " + number((y0 + y1) / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
         markupEscaped(panel.y.label) + "</text>\n";

  if (xs.empty())
    svg += "<text x=\"" + number((x0 + x1) / 2) + "\" y=\"" + number((y0 + y1) / 2) + "\" text-anchor=\"middle\" fill=\"#888888\">no data</text>\n";
  for (const PlotSeries& s : panel.series) {
    const int index = static_cast<int>(std::find(names.begin(), names.end(), s.name) - names.begin());
    const char* colour = kColours[static_cast<std::size_t>(index) % kColours.size()];
    std::string path, marks;
    bool pen = false;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!drawable(s.x[i], panel.x.log) || !drawable(s.y[i], panel.y.log)) {
        pen = false;
        continue;
      }
      path += pen ? 'L' : 'M';
      path += number(px(s.x[i])) + " " + number(py(s.y[i]));
      pen = true;
      marks += marker(index, px(s.x[i]), py(s.y[i]), colour);
    }
    if (!path.empty()) svg += "<path d=\"" + path + "\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"1.8\"/>\n";
    svg += marks + "\n";
  }
  svg += "</g>\n";
}

}  // namespace

std::string plotSvg(const Plot& plot) {
  const int columns = std::max(1, plot.columns);
  const int rows = static_cast<int>((plot.panels.size() + static_cast<std::size_t>(columns) - 1) / static_cast<std::size_t>(columns));
  const double width = 2 * kMargin + columns * kCellWidth, height = kHeader + rows * kCellHeight + kMargin;
  // Each name once, in order of first appearance: its colour and marker in every panel.
  std::vector<std::string> names;
  for (const PlotPanel& panel : plot.panels)
    for (const PlotSeries& s : panel.series)
      if (std::find(names.begin(), names.end(), s.name) == names.end()) names.push_back(s.name);

  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" + number(height) + "\" viewBox=\"0 0 " +
         number(width) + " " + number(height) + "\" font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"11\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
  svg += "<text x=\"" + number(kMargin) + "\" y=\"24\" font-size=\"16\" font-weight=\"bold\">" + markupEscaped(plot.title) + "</text>\n";
  if (!plot.note.empty()) svg += "<text x=\"" + number(kMargin) + "\" y=\"43\" fill=\"#444444\">" + markupEscaped(plot.note) + "</text>\n";
  for (std::size_t i = 0; i < names.size(); ++i) {
    const double x = kMargin + static_cast<double>(i) * 120;
    const char* colour = kColours[i % kColours.size()];
    svg += "<line x1=\"" + number(x) + "\" y1=\"64\" x2=\"" + number(x + 28) + "\" y2=\"64\" stroke=\"" + colour + "\" stroke-width=\"1.8\"/>";
    svg += marker(static_cast<int>(i), x + 14, 64, colour);
    svg += "<text x=\"" + number(x + 34) + "\" y=\"68\">" + markupEscaped(names[i]) + "</text>\n";
  }
  for (std::size_t p = 0; p < plot.panels.size(); ++p) {
    const double left = kMargin + static_cast<double>(p % static_cast<std::size_t>(columns)) * kCellWidth;
    const double top = kHeader + static_cast<double>(p / static_cast<std::size_t>(columns)) * kCellHeight;
    drawPanel(svg, plot.panels[p], left, top, names);
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace facet
