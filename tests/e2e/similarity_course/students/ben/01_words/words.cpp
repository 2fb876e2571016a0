// Lab 01: words, counts and a histogram. Read the lab page first.

#include "lab01.hpp"

#include <algorithm>
#include <stdexcept>

namespace course {

namespace {
bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
char lower(char c) { return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c; }
}

std::vector<std::string> splitWords(const std::string& text) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && !isLetter(text[i])) i++;
        std::size_t start = i;
        while (i < text.size() && isLetter(text[i])) i++;
        if (i > start) {
            std::string word = text.substr(start, i - start);
            std::transform(word.begin(), word.end(), word.begin(), lower);
            words.push_back(word);
        }
    }
    return words;
}

std::map<std::string, int> countWords(const std::vector<std::string>& words) {
    std::map<std::string, int> result;
    for (auto it = words.begin(); it != words.end(); it++) {
        auto found = result.find(*it);
        if (found == result.end()) result.insert({*it, 1});
        else found->second += 1;
    }
    return result;
}

std::vector<std::pair<std::string, int>> mostFrequent(const std::map<std::string, int>& counts, int n) {
    std::vector<std::pair<std::string, int>> all;
    for (auto& entry : counts) all.push_back(entry);
    std::sort(all.begin(), all.end(), [](const std::pair<std::string, int>& x, const std::pair<std::string, int>& y) {
        if (x.second != y.second) return x.second > y.second;
        return x.first < y.first;
    });
    std::vector<std::pair<std::string, int>> top;
    for (int k = 0; k < n && k < (int)all.size(); k++) top.push_back(all[k]);
    return top;
}

double median(std::vector<double> values) {
    const std::size_t count = values.size();
    if (count == 0) return 0;
    std::nth_element(values.begin(), values.begin() + count / 2, values.end());
    double upper = values[count / 2];
    if (count & 1) return upper;
    double lowerHalfMax = *std::max_element(values.begin(), values.begin() + count / 2);
    return 0.5 * (lowerHalfMax + upper);
}

std::vector<int> histogram(const std::vector<double>& values, int bins, double low, double high) {
    std::vector<int> result;
    if (bins < 1) return result;
    result.assign(bins, 0);
    for (std::size_t k = 0; k < values.size(); k++) {
        double t = (values[k] - low) / (high - low);
        if (t < 0 || t > 1) continue;
        int index = std::min(bins - 1, (int)std::floor(t * bins));
        result[index]++;
    }
    return result;
}

} // namespace course
