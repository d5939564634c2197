#include "viewer/frame_times.h"

#include <algorithm>

namespace facet::viewer {

FrameTimes::FrameTimes(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) { samples_.reserve(capacity_); }

void FrameTimes::add(double milliseconds) {
  if (samples_.size() < capacity_) {
    samples_.push_back(milliseconds);
    return;
  }
  samples_[next_] = milliseconds;
  next_ = (next_ + 1) % capacity_;
}

double FrameTimes::median() const {
  if (samples_.empty()) return 0.0;
  std::vector<double> sorted = samples_;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  if (sorted.size() % 2 == 1) return *middle;
  const double below = *std::max_element(sorted.begin(), middle);  // the larger of the lower half
  return 0.5 * (below + *middle);
}

}  // namespace facet::viewer
