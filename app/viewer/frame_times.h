#pragma once
// Frame times for the panel: the median of the last few, which holds still
// when now and then a frame waits for the window system or a shader compile.
#include <cstddef>
#include <vector>

namespace facet::viewer {

class FrameTimes {
 public:
  explicit FrameTimes(std::size_t capacity = 60);

  void add(double milliseconds);
  double median() const;  // of the last `capacity` added; 0 before the first
  std::size_t count() const { return samples_.size(); }

 private:
  std::vector<double> samples_;  // a ring once full
  std::size_t next_ = 0;         // where the next sample goes once full
  std::size_t capacity_;
};

}  // namespace facet::viewer
