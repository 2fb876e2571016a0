// Lab 10's property checks; see checks.hpp. They call your heightAt() and
// blendMd2Frames() on data of their own and test a property the docs state.

#include "checks.hpp"
#include "lab10.hpp"

#include <stoa/crowd/CrowdLab.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace lab10 {

namespace {

std::string describe(glm::vec2 p) {
    char text[64];
    std::snprintf(text, sizeof text, "(%.3f, %.3f)", p.x, p.y);
    return text;
}

std::string describe3(const glm::vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.3f, %.3f, %.3f)", v.x, v.y, v.z);
    return text;
}

// A failed check says which section of the lab page states the rule.
stoa::CheckResult pointingToDocs(stoa::CheckResult result, const std::string& section) {
    if (!result.holds && result.message.find("(docs:") == std::string::npos)
        result.message += " (docs: " + section + ")";
    return result;
}

stoa::CheckResult heightsAtTexelCentresBody() {
    stoa::CheckRandom random(20261125u);
    stoa::HeightField field;
    field.grid.width = 9;
    field.grid.height = 6;
    field.grid.footprintMin = glm::vec2(-7.0f, 3.0f);
    field.grid.footprintMax = glm::vec2(11.0f, 15.0f);   // texels 2 m square
    field.heightMin = -1.0f;
    field.heightMax = 3.0f;
    for (int i = 0; i < field.grid.width * field.grid.height; ++i) field.values.push_back(random.next());
    const glm::vec2 cell = (field.grid.footprintMax - field.grid.footprintMin) /
                           glm::vec2(field.grid.width, field.grid.height);
    const auto metres = [&](int col, int row) {
        return field.heightMin + (field.heightMax - field.heightMin) *
                                     field.values[static_cast<std::size_t>(row * field.grid.width + col)];
    };
    const auto centre = [&](int col, int row) {
        return field.grid.footprintMin + (glm::vec2(col, row) + 0.5f) * cell;
    };
    for (int row = 0; row < field.grid.height; ++row) {
        for (int col = 0; col < field.grid.width; ++col) {
            const glm::vec2 at = centre(col, row);
            const float height = stoa::heightAt(field, at);
            if (std::fabs(height - metres(col, row)) > 1e-4f) {
                return stoa::CheckResult::fail(
                    "heightAt() at the centre " + describe(at) + " of texel (" + std::to_string(col) + ", " +
                    std::to_string(row) + ") is " + std::to_string(height) + " m; that texel's height is " +
                    std::to_string(metres(col, row)) + " m (the samples sit at the texel centres)");
            }
        }
    }
    for (int row = 0; row + 1 < field.grid.height; ++row) {
        for (int col = 0; col + 1 < field.grid.width; ++col) {
            const glm::vec2 at = 0.5f * (centre(col, row) + centre(col + 1, row + 1));
            const float mean = 0.25f * (metres(col, row) + metres(col + 1, row) + metres(col, row + 1) +
                                        metres(col + 1, row + 1));
            const float height = stoa::heightAt(field, at);
            if (std::fabs(height - mean) > 1e-4f) {
                return stoa::CheckResult::fail("heightAt() halfway between the centres of texels (" +
                                               std::to_string(col) + ", " + std::to_string(row) + ") and (" +
                                               std::to_string(col + 1) + ", " + std::to_string(row + 1) + "), at " +
                                               describe(at) + ", is " + std::to_string(height) +
                                               " m; the mean of the four is " + std::to_string(mean) + " m");
            }
        }
    }
    // Beyond the outermost centres, and outside the footprint, the edge's values hold
    // (the clamp). A guard row past the map's last row (values no sample has) shows a
    // read past the map: the field's grid still says 6 rows.
    for (int col = 0; col < field.grid.width; ++col) field.values.push_back(5.0f);
    const int lastCol = field.grid.width - 1, lastRow = field.grid.height - 1;
    for (const float beyond : {0.3f, 1.5f, 40.0f}) {   // in texels past the edge
        for (int col = 0; col <= lastCol; col += lastCol) {
            for (int row = 0; row <= lastRow; row += lastRow) {
                const glm::vec2 outward(col == 0 ? -1.0f : 1.0f, row == 0 ? -1.0f : 1.0f);
                const glm::vec2 corner(col == 0 ? field.grid.footprintMin.x : field.grid.footprintMax.x,
                                       row == 0 ? field.grid.footprintMin.y : field.grid.footprintMax.y);
                const glm::vec2 at = corner + outward * beyond * cell;
                const float height = stoa::heightAt(field, at);
                if (std::fabs(height - metres(col, row)) > 1e-4f) {
                    return stoa::CheckResult::fail(
                        "heightAt() at " + describe(at) + ", " + std::to_string(beyond) +
                        " texels outside the footprint's corner, is " + std::to_string(height) +
                        " m; the corner texel (" + std::to_string(col) + ", " + std::to_string(row) + ") is " +
                        std::to_string(metres(col, row)) + " m (clamp to [0, w - 1] x [0, h - 1]: outside the "
                        "footprint the edge's values hold, and no read may pass the last row or column)");
                }
            }
        }
    }
    return stoa::CheckResult::pass("heightAt() is each texel's height at its centre, the mean of four between them (" +
                                   std::to_string(field.grid.width * field.grid.height) + " centres, " +
                                   std::to_string((field.grid.width - 1) * (field.grid.height - 1)) +
                                   " midpoints), and the corner's height outside the footprint");
}

stoa::CheckResult walkableAtTexelsBody() {
    // A map that is not square, with texels that are not square either, over a
    // footprint away from the origin: rows and columns must not be confused.
    stoa::CheckRandom random(20261125u);
    stoa::CollisionMap map;
    map.grid.width = 7;
    map.grid.height = 4;
    map.grid.footprintMin = glm::vec2(-5.0f, 2.0f);
    map.grid.footprintMax = glm::vec2(9.0f, 14.0f);   // texels 2 m by 3 m
    for (int i = 0; i < map.grid.width * map.grid.height; ++i) map.walkable.push_back(random.next() < 0.5f ? 0 : 255);
    const glm::vec2 cell = (map.grid.footprintMax - map.grid.footprintMin) / glm::vec2(map.grid.width, map.grid.height);
    for (int row = 0; row < map.grid.height; ++row) {
        for (int col = 0; col < map.grid.width; ++col) {
            const bool white = map.walkable[static_cast<std::size_t>(row * map.grid.width + col)] != 0;
            // The texel's centre and two points just inside its near and far corners.
            for (const glm::vec2 within : {glm::vec2(0.5f), glm::vec2(0.02f), glm::vec2(0.98f)}) {
                const glm::vec2 at = map.grid.footprintMin + (glm::vec2(col, row) + within) * cell;
                if (stoa::walkableAt(map, at) != white) {
                    return stoa::CheckResult::fail(
                        "walkableAt() at " + describe(at) + ", in texel (" + std::to_string(col) + ", " +
                        std::to_string(row) + ") of a 7 x 4 map, says " + (white ? "no" : "yes") +
                        "; that texel is " + (white ? "white" : "black") +
                        " (col from x and the width, row from z and the height)");
                }
            }
        }
    }
    // Outside every edge, including the far ones, nothing is walkable.
    for (const float t : {0.1f, 0.5f, 0.9f}) {
        const glm::vec2 along = map.grid.footprintMin + t * (map.grid.footprintMax - map.grid.footprintMin);
        const glm::vec2 outside[] = {{map.grid.footprintMin.x - 0.01f, along.y}, {map.grid.footprintMax.x, along.y},
                                     {along.x, map.grid.footprintMin.y - 0.01f}, {along.x, map.grid.footprintMax.y}};
        for (const glm::vec2 at : outside) {
            if (stoa::walkableAt(map, at)) {
                return stoa::CheckResult::fail("walkableAt() at " + describe(at) +
                                               ", on or outside the footprint's edge, says yes; "
                                               "nothing outside the map is walkable, nor its far edges");
            }
        }
    }
    return stoa::CheckResult::pass("walkableAt() reads the texel that holds each point of a 7 x 4 map (84 points) "
                                   "and refuses 12 points on or outside its edges");
}

stoa::CheckResult blendedNormalsUnitBody() {
    stoa::CheckRandom random(20261125u);
    stoa::Md2Frame first, second;
    const auto unit = [&]() {
        for (;;) {
            const glm::vec3 v(2.0f * random.next() - 1.0f, 2.0f * random.next() - 1.0f, 2.0f * random.next() - 1.0f);
            const float length = glm::length(v);
            if (length > 0.2f && length <= 1.0f) return v / length;
        }
    };
    for (int i = 0; i < 200; ++i) {
        first.positions.emplace_back(random.next(), random.next(), random.next());
        second.positions.emplace_back(random.next(), random.next(), random.next());
        first.normals.push_back(unit());
        glm::vec3 other = unit();
        if (glm::dot(other, first.normals.back()) < -0.9f) other = -other;   // not opposite: their blend never vanishes
        second.normals.push_back(other);
    }
    std::vector<glm::vec3> positions, normals;
    for (const float t : {0.0f, 0.25f, 0.5f, 0.8f}) {
        stoa::blendMd2Frames(first, second, t, positions, normals);
        if (positions.size() != first.positions.size() || normals.size() != first.normals.size()) {
            return stoa::CheckResult::fail("blendMd2Frames() gave " + std::to_string(positions.size()) + " positions and " +
                                           std::to_string(normals.size()) + " normals for frames of " +
                                           std::to_string(first.positions.size()) + " vertices");
        }
        for (std::size_t i = 0; i < normals.size(); ++i) {
            const glm::vec3 line = first.positions[i] + t * (second.positions[i] - first.positions[i]);
            if (glm::length(positions[i] - line) > 1e-4f) {
                return stoa::CheckResult::fail("blendMd2Frames() at t = " + std::to_string(t) + " put vertex " +
                                               std::to_string(i) + " off the straight line between its two frames");
            }
            if (std::fabs(glm::length(normals[i]) - 1.0f) > 1e-3f) {
                return stoa::CheckResult::fail("blendMd2Frames() at t = " + std::to_string(t) + " gave vertex " +
                                               std::to_string(i) + " a normal of length " +
                                               std::to_string(glm::length(normals[i])) +
                                               "; normals must be unit length (a blend of two is shorter: normalize it)");
            }
            const glm::vec3 between = glm::normalize(first.normals[i] + t * (second.normals[i] - first.normals[i]));
            if (glm::length(normals[i] - between) > 1e-3f) {
                return stoa::CheckResult::fail("blendMd2Frames() at t = " + std::to_string(t) + " gave vertex " +
                                               std::to_string(i) + " a normal that is not the normalized blend "
                                               "n1 + t (n2 - n1) of its two frames' normals");
            }
            if (t == 0.0f && glm::length(normals[i] - first.normals[i]) > 1e-4f) {
                return stoa::CheckResult::fail("blendMd2Frames() at t = 0 gave vertex " + std::to_string(i) +
                                               " a normal other than the first frame's");
            }
        }
    }
    // Exactly opposite normals halfway: the blend is 0, with no direction, and the
    // first frame's normal stays.
    stoa::Md2Frame up, down;
    up.positions = down.positions = {glm::vec3(0.0f, 1.0f, 0.0f)};
    up.normals = {glm::vec3(0.0f, 0.6f, 0.8f)};
    down.normals = {-up.normals[0]};
    stoa::blendMd2Frames(up, down, 0.5f, positions, normals);
    if (normals.size() != 1 || !(glm::length(normals[0] - up.normals[0]) <= 1e-4f))
        return stoa::CheckResult::fail("blendMd2Frames() at t = 0.5 between the normals (0, 0.6, 0.8) and (0, -0.6, -0.8), "
                                       "whose blend is 0, gave " +
                                       (normals.empty() ? std::string("no normal") : describe3(normals[0])) +
                                       "; keep the first frame's normal where the blend has no length");
    return stoa::CheckResult::pass("blendMd2Frames() keeps 200 vertices on the line between their frames with unit normals at t = 0, 0.25, 0.5 and 0.8, and the first frame's normal where opposite normals cancel");
}

// Senses in which exactly the listed kinds of condition hold.
class FixedSenses : public stoa::CrowdSenses {
public:
    explicit FixedSenses(std::vector<stoa::Condition::Kind> holding) : m_holding(std::move(holding)) {}
    bool holds(const stoa::Condition& condition) const override {
        bool found = false;
        for (const stoa::Condition::Kind kind : m_holding) found = found || kind == condition.kind;
        return found != condition.negated;
    }

private:
    std::vector<stoa::Condition::Kind> m_holding;
};

stoa::Layer layerWhen(const char* name, std::vector<stoa::Condition::Kind> kinds) {
    stoa::Layer layer;
    layer.name = name;
    for (const stoa::Condition::Kind kind : kinds) {
        stoa::Condition condition;
        condition.kind = kind;
        layer.when.push_back(condition);
    }
    return layer;
}

stoa::CheckResult layersFirstThatFiresBody() {
    using Kind = stoa::Condition::Kind;
    // A goat's stack with a default layer at the bottom, and a stack whose every
    // layer has conditions: there nothing may fire, and the answer is -1.
    stoa::SubsumptionStack herd;
    herd.layers = {layerWhen("flee", {Kind::Sees}), layerWhen("drink", {Kind::Near, Kind::Carrying}),
                   layerWhen("graze", {Kind::Chance}), layerWhen("amble", {})};
    stoa::SubsumptionStack guard;
    guard.layers = {layerWhen("attack", {Kind::Near, Kind::Sees}), layerWhen("return", {Kind::Carrying}),
                    layerWhen("rest", {Kind::AtBase})};
    struct Row {
        const stoa::SubsumptionStack* stack;
        const char* stackName;
        std::vector<Kind> holding;
        const char* sensesName;
        int expected;
    };
    const Row rows[] = {
        {&herd, "flee / drink (two conditions) / graze / amble (none)", {}, "nothing", 3},
        {&herd, "flee / drink (two conditions) / graze / amble (none)", {Kind::Near}, "only the first of drink's two", 3},
        {&herd, "flee / drink (two conditions) / graze / amble (none)", {Kind::Near, Kind::Carrying, Kind::Chance},
         "drink's two and graze's", 1},
        {&herd, "flee / drink (two conditions) / graze / amble (none)", {Kind::Sees, Kind::Chance}, "flee's and graze's", 0},
        {&guard, "attack (two conditions) / return / rest", {}, "nothing", -1},
        {&guard, "attack (two conditions) / return / rest", {Kind::Sees}, "only one of attack's two", -1},
        {&guard, "attack (two conditions) / return / rest", {Kind::AtBase}, "rest's", 2},
        {&guard, "attack (two conditions) / return / rest", {Kind::Near, Kind::Sees, Kind::AtBase}, "attack's two and rest's", 0},
    };
    for (const Row& row : rows) {
        const FixedSenses senses(row.holding);
        const int layer = stoa::arbitrateLayers(*row.stack, senses);
        if (layer != row.expected)
            return stoa::CheckResult::fail(
                "arbitrateLayers() of the layers " + std::string(row.stackName) + ", when " + row.sensesName +
                " holds, returned " + std::to_string(layer) + "; expected " + std::to_string(row.expected) +
                ": the first layer from the top whose conditions all hold runs, a layer without conditions "
                "always fires, and when none fires the answer is -1");
    }
    return stoa::CheckResult::pass("arbitrateLayers() picks the first layer whose conditions all hold, in 8 "
                                   "situations, -1 when none fires");
}

} // namespace

stoa::CheckResult checkLayersFirstThatFires() { return pointingToDocs(layersFirstThatFiresBody(), "Subsumption"); }

stoa::CheckResult checkHeightsAtTexelCentres() {
    return pointingToDocs(heightsAtTexelCentresBody(), "Bilinear height");
}

stoa::CheckResult checkWalkableAtTexels() {
    return pointingToDocs(walkableAtTexelsBody(), "From a point to a texel");
}

stoa::CheckResult checkBlendedNormalsUnit() { return pointingToDocs(blendedNormalsUnitBody(), "Blending two frames"); }

} // namespace lab10
