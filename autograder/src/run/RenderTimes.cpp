#include "RenderTimes.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace stoa::grader {

CaseTimeouts caseTimeouts(double referenceSeconds, bool sanitized) {
    CaseTimeouts timeouts;
    if (referenceSeconds > 0.0) {
        timeouts.first = std::max(kTimeoutFloorSeconds, kTimeoutFactor * referenceSeconds);
        timeouts.afterTimeout = std::max(kShortTimeoutFloorSeconds, kShortTimeoutFactor * referenceSeconds);
    }
    if (sanitized) {
        timeouts.first *= kSanitizerSlowdown;
        timeouts.afterTimeout *= kSanitizerSlowdown;
    }
    return timeouts;
}

std::filesystem::path renderTimesPath(const std::filesystem::path& referencesFolder) {
    return referencesFolder / "render-times.txt";
}

std::map<std::string, double> readRenderTimes(const std::filesystem::path& file) {
    std::map<std::string, double> times;
    std::ifstream in(file);
    if (!in) return times;
    int lineNumber = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        std::istringstream words(line);
        words.imbue(std::locale::classic());
        std::string name, rest;
        double seconds = 0.0;
        if (!(words >> name >> seconds) || (words >> rest) || !(seconds > 0.0) || !std::isfinite(seconds))
            throw InputError(file.string(), lineNumber,
                             "expected a case name and its render time in seconds (\"orbit_front 0.4\"), got '" +
                                 line + "'");
        times[name] = seconds;
    }
    return times;
}

bool updateRenderTimes(const std::filesystem::path& file, const std::map<std::string, double>& measured) {
    std::map<std::string, double> recorded;
    try {
        recorded = readRenderTimes(file);
    } catch (const InputError&) {
        recorded.clear();   // a broken file is rewritten from the measurements
    }
    std::map<std::string, double> updated = recorded;
    for (const auto& [name, seconds] : measured) {
        double rounded = std::max(0.1, std::ceil(seconds * 10.0 - 1e-9) / 10.0);
        auto old = recorded.find(name);
        if (old == recorded.end() || rounded > 2.0 * old->second || rounded < 0.5 * old->second)
            updated[name] = rounded;
    }
    std::error_code error;
    if (updated == recorded && std::filesystem::exists(file, error)) return false;

    std::ostringstream text;
    text << "# The solution's render time of each case, in seconds, rounded up to a tenth; written by\n"
            "# stoa-grade --update-references, which changes a time only when it more than doubles or\n"
            "# halves. Each case's timeout is derived from it (autograder/src/run/RenderTimes.hpp).\n";
    for (const auto& [name, seconds] : updated) {
        char value[32];
        std::snprintf(value, sizeof value, "%.1f", seconds);
        text << name << " " << value << "\n";
    }
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << text.str();
    if (!out) throw InputError(file.string(), 0, "cannot write the render times");
    return true;
}

} // namespace stoa::grader
