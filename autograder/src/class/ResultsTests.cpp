#include "ResultsTests.hpp"

#include "GradeResult.hpp"

#include <cctype>

namespace stoa::grader {

std::string labOfTest(const JsonValue& test) {
    if (const JsonValue* tags = test.find("tags"))
        for (const JsonValue& tag : tags->items())
            if (tag.asString().size() > 3 && std::isdigit(static_cast<unsigned char>(tag.asString()[0])))
                return tag.asString();
    std::string name = stringMember(test, "name");
    return name.substr(0, name.find('/'));
}

std::string caseOfTest(const JsonValue& test) {
    std::string name = stringMember(test, "name");
    std::size_t slash = name.find('/');
    std::string caseName = slash == std::string::npos ? name : name.substr(slash + 1);
    const std::string cascadeMark = " [cascade]";
    if (caseName.size() > cascadeMark.size() &&
        caseName.compare(caseName.size() - cascadeMark.size(), cascadeMark.size(), cascadeMark) == 0)
        caseName.resize(caseName.size() - cascadeMark.size());
    return caseName;
}

bool hasTag(const JsonValue& test, const std::string& wanted) {
    if (const JsonValue* tags = test.find("tags"))
        for (const JsonValue& tag : tags->items())
            if (tag.asString() == wanted) return true;
    return false;
}

std::string testStatus(const JsonValue& test) {
    if (const JsonValue* tags = test.find("tags"))
        for (const JsonValue& tag : tags->items())
            if (statusFromName(tag.asString())) return tag.asString();
    const JsonValue* status = test.find("status");
    return status && !status->asString().empty() ? status->asString() : "unknown";
}

double numberMember(const JsonValue& object, const std::string& name, double fallback) {
    const JsonValue* member = object.find(name);
    return member ? member->asNumber(fallback) : fallback;
}

std::string stringMember(const JsonValue& object, const std::string& name) {
    const JsonValue* member = object.find(name);
    return member ? member->asString() : std::string();
}

} // namespace stoa::grader
