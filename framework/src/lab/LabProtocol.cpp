#include <stoa/lab/LabProtocol.hpp>

namespace stoa {

namespace {

const char* const kNotImplemented = "not implemented: ";
const char* const kProgramPrefix = "stoa: ";
const char* const kCheckPrefix = "check ";

const char* verdictText(CheckVerdict verdict) {
    switch (verdict) {
    case CheckVerdict::Holds: return "holds";
    case CheckVerdict::DoesNotHold: return "does not hold";
    case CheckVerdict::NotAttempted: return "not attempted";
    }
    return "holds";
}

bool startsWith(const std::string& text, const std::string& prefix, std::size_t at = 0) {
    return text.compare(at, prefix.size(), prefix) == 0;
}

} // namespace

std::string notImplementedText(const std::string& what) { return kNotImplemented + what; }

std::string notImplementedLine(const std::string& what) { return kProgramPrefix + notImplementedText(what); }

std::optional<std::string> parseNotImplementedLine(const std::string& line) {
    const std::size_t at = line.find(kNotImplemented);
    if (at == std::string::npos) return std::nullopt;
    std::string what = line.substr(at + std::char_traits<char>::length(kNotImplemented));
    if (what.empty()) return std::nullopt;
    return what;
}

std::string checkVerdictLine(const std::string& name, CheckVerdict verdict, const std::string& message) {
    return kCheckPrefix + name + ": " + verdictText(verdict) + ": " + message;
}

std::optional<CheckVerdictLine> parseCheckVerdictLine(const std::string& line) {
    if (!startsWith(line, kCheckPrefix)) return std::nullopt;
    const std::size_t nameStart = std::char_traits<char>::length(kCheckPrefix);
    const std::size_t nameEnd = line.find(": ", nameStart);
    if (nameEnd == std::string::npos || nameEnd == nameStart) return std::nullopt;
    CheckVerdictLine parsed;
    parsed.name = line.substr(nameStart, nameEnd - nameStart);
    const std::size_t verdictStart = nameEnd + 2;
    // "does not hold" before "holds"? No prefix of one is the other, but test the longest first.
    for (CheckVerdict verdict : {CheckVerdict::DoesNotHold, CheckVerdict::NotAttempted, CheckVerdict::Holds}) {
        const std::string text = std::string(verdictText(verdict)) + ": ";
        if (startsWith(line, text, verdictStart)) {
            parsed.verdict = verdict;
            parsed.message = line.substr(verdictStart + text.size());
            return parsed;
        }
    }
    return std::nullopt;
}

} // namespace stoa
