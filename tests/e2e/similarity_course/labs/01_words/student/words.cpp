// Lab 01: words, counts and a histogram. Read the lab page first.

#include "lab01.hpp"

#include <stdexcept>

namespace course {

std::vector<std::string> splitWords(const std::string& text) {
    // TODO(lab01): the words of the text in order, lower case; a word is a run of letters.
    (void)text;
    throw std::logic_error("splitWords() is not implemented");
}

std::map<std::string, int> countWords(const std::vector<std::string>& words) {
    // TODO(lab01): how many times each word occurs.
    (void)words;
    throw std::logic_error("countWords() is not implemented");
}

std::vector<std::pair<std::string, int>> mostFrequent(const std::map<std::string, int>& counts, int n) {
    // TODO(lab01): the n most frequent words, most frequent first, ties in alphabetical order.
    (void)counts;
    (void)n;
    throw std::logic_error("mostFrequent() is not implemented");
}

double median(std::vector<double> values) {
    // TODO(lab01): the middle value, or the mean of the two middle values; 0 for none.
    (void)values;
    throw std::logic_error("median() is not implemented");
}

std::vector<int> histogram(const std::vector<double>& values, int bins, double low, double high) {
    // TODO(lab01): how many values fall in each of `bins` equal bins from low to high;
    // values outside [low, high] are not counted, high goes in the last bin.
    (void)values;
    (void)bins;
    (void)low;
    (void)high;
    throw std::logic_error("histogram() is not implemented");
}

} // namespace course
