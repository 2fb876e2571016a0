#pragma once
// Reading a crowd world from XML (pugixml). docs/crowds-xml.md is the format's
// reference and assets/crowds/*.xml are examples; in short:
//
//   <world seed="7" step="0.0333">
//     <include file="explorers.xml"/>              <!-- types and behaviours, relative to this file -->
//     <ground collision="acropolis_collision.png" height="" min="-15 -15" max="15 15"
//             height-min="0" height-max="0" scenery="acropolis"/>
//     <base x="0" z="10" radius="1.5"/>
//     <samples count="40" x="0" z="-8" radius="6"/>
//     <spawn type="explorer" count="20" x="0" z="10" radius="2" team="0"/>
//   </world>
//
// Every problem is an InputError naming the file, the line and what was
// expected: XML that is not well formed, an unknown element or attribute, a
// missing attribute, a number that is not one (or out of its range), a
// transition to a state that does not exist, a type or behaviour named twice
// or not at all, an include that loops.

#include <stoa/crowd/CrowdWorld.hpp>

#include <filesystem>
#include <string>

namespace stoa {

/// Limits that keep a hostile file from taking the machine.
struct CrowdXmlLimits {
    static constexpr std::size_t maxFileBytes = 4u << 20;   // per XML file
    static constexpr int maxIncludeDepth = 8;
    static constexpr int maxIncludes = 256;                 // <include> elements, all files together
    static constexpr std::size_t maxWorldBytes = 16u << 20; // the world file and its includes together
    /// All spawn counts together: what still steps in real time (30 steps a
    /// second, 33 ms a step) on one core of the reference machine (2 cores):
    /// 100,000 agents step in 15 to 20 ms of CPU time at the example worlds'
    /// density, 1,000,000 in 200 to 300 ms (crowd_benchmark; docs/crowds-xml.md).
    /// A denser crowd, or a longer sight, costs more per agent, and the window
    /// says so when a step is slow.
    static constexpr int maxAgents = 100000;
    /// The figure the error for a larger world gives.
    static constexpr const char* maxAgentsReason =
        "100,000 agents step in about 15 to 20 ms on one core, within a 33 ms step; 1,000,000 take 200 to 300 ms";
    static constexpr int maxSamples = 100000;
};

/// Reads the world file at `path` and the files it includes. Paths in the
/// files (maps, models, skins, includes) are resolved against the folder of
/// the file that names them; maps, models and skins are not opened here.
CrowdWorld loadCrowdWorld(const std::filesystem::path& path);

/// The same for a world file already in memory; `name` is the file named in
/// errors and the folder includes are resolved against is `name`'s. For tests
/// and fuzzers.
CrowdWorld parseCrowdWorld(const std::string& text, const std::filesystem::path& name);

} // namespace stoa
