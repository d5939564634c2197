#pragma once
// A progress bar on a terminal: `facet render --backend ray` draws one on
// stderr while it traces, and nothing when stderr is not a terminal (a pipe,
// a file, CI's log), so that logs hold only the lines they always held.
#include <chrono>
#include <cstdio>
#include <string>

namespace facet {

class ProgressBar {
 public:
  // `label` leads the bar: "ray tracing".
  explicit ProgressBar(std::string label);
  ~ProgressBar();  // clears the bar's line, if one was drawn
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // done in [0, 1]; redraws when the whole percentage changed.
  void update(double done);
  // The same with `detail` after the bar ("12/500, 1 failed, 8.3 jobs/s"),
  // redrawn when the percentage or the detail changed.
  void update(double done, const std::string& detail);
  // Clears the bar's line; nothing is drawn after.
  void finish();

 private:
  std::string label_;
  bool terminal_;
  int shown_ = -1;  // the percentage on screen; -1: nothing drawn
  std::string detail_;  // the detail on screen
  std::chrono::steady_clock::time_point start_;
};

}  // namespace facet
