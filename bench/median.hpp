#pragma once
// The median of timing samples (the timing harnesses report medians, not means: a sample
// disturbed by the machine does not move them).

#include <algorithm>
#include <vector>

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
