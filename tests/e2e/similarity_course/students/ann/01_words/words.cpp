// Lab 01: words, counts and a histogram. Read the lab page first.

#include "lab01.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace course {

std::vector<std::string> splitWords(const std::string& text) {
    std::vector<std::string> result;
    std::string current;
    for (char c : text) {
        if (std::isalpha(static_cast<unsigned char>(c))) {
            current += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        } else if (!current.empty()) {
            result.push_back(current);
            current.clear();
        }
    }
    if (!current.empty()) result.push_back(current);
    return result;
}

std::map<std::string, int> countWords(const std::vector<std::string>& words) {
    std::map<std::string, int> counts;
    for (const std::string& word : words) ++counts[word];
    return counts;
}

std::vector<std::pair<std::string, int>> mostFrequent(const std::map<std::string, int>& counts, int n) {
    std::vector<std::pair<std::string, int>> sorted(counts.begin(), counts.end());
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    if (static_cast<int>(sorted.size()) > n) sorted.resize(static_cast<std::size_t>(std::max(0, n)));
    return sorted;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    std::size_t middle = values.size() / 2;
    if (values.size() % 2 == 1) return values[middle];
    return (values[middle - 1] + values[middle]) / 2.0;
}

std::vector<int> histogram(const std::vector<double>& values, int bins, double low, double high) {
    std::vector<int> counts(static_cast<std::size_t>(std::max(0, bins)), 0);
    if (bins <= 0 || !(high > low)) return counts;
    const double width = (high - low) / bins;
    for (double value : values) {
        if (value < low || value > high) continue;
        int bin = static_cast<int>((value - low) / width);
        if (bin >= bins) bin = bins - 1;
        ++counts[static_cast<std::size_t>(bin)];
    }
    return counts;
}

} // namespace course
