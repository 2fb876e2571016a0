// Lab 01: words, counts and a histogram. Read the lab page first.

#include "lab01.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace course {

std::vector<std::string> splitWords(const std::string& text) {
    std::string cleaned = text;
    for (char& c : cleaned)
        c = std::isalpha((unsigned char)c) ? (char)std::tolower((unsigned char)c) : ' ';
    std::istringstream stream(cleaned);
    std::vector<std::string> out;
    for (std::string w; stream >> w;) out.push_back(w);
    return out;
}

std::map<std::string, int> countWords(const std::vector<std::string>& words) {
    std::map<std::string, int> m;
    std::vector<std::string> sorted = words;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t a = 0, b = 0; a < sorted.size(); a = b) {
        while (b < sorted.size() && sorted[b] == sorted[a]) ++b;
        m[sorted[a]] = (int)(b - a);
    }
    return m;
}

std::vector<std::pair<std::string, int>> mostFrequent(const std::map<std::string, int>& counts, int n) {
    std::multimap<int, std::string, std::greater<int>> byCount;
    for (const auto& [word, count] : counts) byCount.emplace(count, word);
    std::vector<std::pair<std::string, int>> answer;
    for (const auto& [count, word] : byCount) {
        if ((int)answer.size() == n) break;
        answer.emplace_back(word, count);
    }
    return answer;
}

double median(std::vector<double> values) {
    double result = 0;
    std::sort(values.begin(), values.end());
    const int size = (int)values.size();
    if (size > 0)
        result = size % 2 ? values[size / 2] : 0.5 * (values[size / 2 - 1] + values[size / 2]);
    return result;
}

std::vector<int> histogram(const std::vector<double>& values, int bins, double low, double high) {
    std::vector<int> h(bins > 0 ? bins : 0);
    const double scale = bins / (high - low);
    for (double v : values)
        if (v >= low && v <= high && bins > 0)
            h[std::min<int>(bins - 1, (int)((v - low) * scale))] += 1;
    return h;
}

} // namespace course
