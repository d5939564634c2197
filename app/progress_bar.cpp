#include "progress_bar.h"

#include <algorithm>
#include <cmath>

#include <unistd.h>

namespace facet {

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), terminal_(isatty(fileno(stderr)) == 1), start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::finish() {
  if (terminal_ && shown_ >= 0) std::fprintf(stderr, "\r\033[K");  // the bar's line cleared, the cursor at its start
  terminal_ = false;
}

void ProgressBar::update(double done) { update(done, detail_); }

void ProgressBar::update(double done, const std::string& detail) {
  if (!terminal_) return;
  const int percent = static_cast<int>(std::floor(std::clamp(done, 0.0, 1.0) * 100.0));
  if (percent == shown_ && detail == detail_) return;
  shown_ = percent;
  detail_ = detail;
  constexpr int kWidth = 30;
  const int filled = percent * kWidth / 100;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::string bar = std::string(static_cast<std::size_t>(filled), '#') + std::string(static_cast<std::size_t>(kWidth - filled), '-');
  const std::string prefix = detail_.empty() ? std::string() : detail_ + ", ";
  if (percent > 0 && percent < 100)
    std::fprintf(stderr, "\r%s [%s] %3d%%  %s%.1f s, about %.1f s left\033[K", label_.c_str(), bar.c_str(), percent, prefix.c_str(), seconds,
                 seconds * (100.0 - percent) / percent);
  else
    std::fprintf(stderr, "\r%s [%s] %3d%%  %s%.1f s\033[K", label_.c_str(), bar.c_str(), percent, prefix.c_str(), seconds);
  std::fflush(stderr);
}

}  // namespace facet
