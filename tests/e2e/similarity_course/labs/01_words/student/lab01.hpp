#pragma once
// Lab 01 of the made-up course: what the student writes.

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace course {

std::vector<std::string> splitWords(const std::string& text);
std::map<std::string, int> countWords(const std::vector<std::string>& words);
std::vector<std::pair<std::string, int>> mostFrequent(const std::map<std::string, int>& counts, int n);
double median(std::vector<double> values);
std::vector<int> histogram(const std::vector<double>& values, int bins, double low, double high);

} // namespace course
