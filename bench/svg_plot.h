#pragma once
// Line plots as an SVG document, written by facet itself (no plotting
// library): a grid of panels, each with its own axes (linear or
// logarithmic), one polyline with markers per series, and one legend for
// all panels. What `facet bench --sweep --plot` draws.
#include <string>
#include <utility>
#include <vector>

namespace facet {

struct PlotAxis {
  std::string label;
  bool log = false;  // base 10; values not above 0 are left out
  // Ticks as (value, label); empty: round values chosen from the data.
  std::vector<std::pair<double, std::string>> ticks;
  bool fromZero = false;  // a linear axis that starts at 0 whatever the data
};

struct PlotSeries {
  std::string name;          // the legend's entry; the same name keeps its colour and marker in every panel
  std::vector<double> x, y;  // a point whose value is not finite (or not above 0 on a log axis) breaks the line
};

struct PlotPanel {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;
};

struct Plot {
  std::string title;
  std::string note;  // a line under the title (what was measured, where)
  int columns = 3;
  std::vector<PlotPanel> panels;  // row by row
};

// The whole SVG document (UTF-8). Text is escaped; a panel without any
// point to draw shows its axes and "no data".
std::string plotSvg(const Plot& plot);

}  // namespace facet
