#pragma once
// The median and spread of timed samples, as benchmarks print them.
#include <vector>

namespace facet {

struct Summary {
  double median = 0, min = 0, max = 0, q1 = 0, q3 = 0;
};

// q in [0, 1] of sorted values, interpolated linearly between neighbours.
double quantile(const std::vector<double>& sorted, double q);

Summary summarize(std::vector<double> values);

}  // namespace facet
