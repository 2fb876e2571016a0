#pragma once
// What every benchmark program here measures with: wall-clock time in
// milliseconds, and the median of several runs (the machines are shared and
// noisy; a median is what the docs and notes quote).

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

namespace stoa::benchmark {

using Clock = std::chrono::steady_clock;

inline double milliseconds(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double, std::milli>(to - from).count();
}

/// The median of `values` (not empty): the middle value, or the mean of the two middle ones.
inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

} // namespace stoa::benchmark
