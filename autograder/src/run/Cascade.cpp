#include "Cascade.hpp"

#include <map>
#include <string>

namespace stoa::grader {

void applyCascadePolicy(std::vector<GradeResult>& results) {
    struct Runs {
        double own = 0.0;
        double cascade = 0.0;
        bool hasCascade = false;
    };
    std::map<std::string, Runs> labs;
    for (const GradeResult& result : results) {
        Runs& runs = labs[result.lab];
        if (result.cascade) {
            runs.cascade += result.points;
            runs.hasCascade = true;
        } else {
            runs.own += result.points;
        }
    }
    for (GradeResult& result : results) {
        const Runs& runs = labs[result.lab];
        if (!runs.hasCascade) continue;
        bool cascadeCounts = runs.cascade > runs.own;
        result.counted = result.cascade == cascadeCounts;
    }
}

} // namespace stoa::grader
