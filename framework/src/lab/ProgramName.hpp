#pragma once
// How a lab program names itself: "lab05_shadows" and "Stoa lab 05_shadows",
// or a tool's own name and title (LabBuildInfo::programName, windowTitle).

#include <stoa/lab/LabBuildInfo.hpp>

#include <string>

namespace stoa::detail {

inline std::string programName(const LabBuildInfo& info) {
    return info.programName ? info.programName : std::string("lab") + info.name;
}

inline std::string windowTitle(const LabBuildInfo& info) {
    return info.windowTitle ? info.windowTitle : std::string("Stoa lab ") + info.name;
}

} // namespace stoa::detail
