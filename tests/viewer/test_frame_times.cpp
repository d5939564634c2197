// FrameTimes: the median of the last N frame times.
#include <doctest/doctest.h>

#include "viewer/frame_times.h"

using facet::viewer::FrameTimes;

TEST_CASE("the median of the frame times added so far, 0 before any") {
  FrameTimes times(60);
  CHECK(times.median() == 0.0);
  times.add(30.0);
  CHECK(times.median() == 30.0);
  times.add(10.0);
  CHECK(times.median() == 20.0);  // an even count: the mean of the middle two
  times.add(1000.0);              // one slow frame does not move it far
  CHECK(times.median() == 30.0);
}

TEST_CASE("only the last N count") {
  FrameTimes times(3);
  for (double ms : {100.0, 100.0, 100.0, 5.0, 6.0}) times.add(ms);
  CHECK(times.count() == 3);
  CHECK(times.median() == 6.0);  // 100, 5, 6
  times.add(7.0);
  CHECK(times.median() == 6.0);  // 5, 6, 7
}
