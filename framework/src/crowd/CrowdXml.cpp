#include <stoa/crowd/CrowdXml.hpp>

#include "XmlAttributes.hpp"
#include "XmlFile.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include <pugixml.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>

// The loader reads every file of a world in one pass, element by element, and
// checks each element as it goes: its attributes against the list it may
// carry, its numbers against their ranges, its children against the elements
// allowed there. Names that may be defined later in the pass (a type's
// behaviour, the types named in conditions and actions, a spawn's type and
// team) are remembered with their file and line and checked once every file
// has been read. Names are found through hash maps, so that a hostile file of
// 4 MB (a behaviour of 200,000 states) reads in linear time, and a list of
// names in a message stops after a dozen. docs/crowds-xml.md describes the format.
// This file is the format's one list of what is accepted, element by element;
// how an attribute is read and checked (XmlAttributes.hpp) and how a file's
// lines are counted (XmlFile.hpp) are the same for every element and live apart.

namespace stoa {

namespace fs = std::filesystem;

namespace {

using namespace xml;

/// "a, b, c" for a message: at most a dozen names, then how many more.
std::string joined(const std::vector<std::string>& names) {
    constexpr std::size_t shown = 12;
    std::string text;
    for (std::size_t i = 0; i < names.size() && i < shown; ++i) text += (i ? ", " : "") + quoteInput(names[i]);
    if (names.size() > shown) text += " and " + std::to_string(names.size() - shown) + " more";
    return text.empty() ? "(none)" : text;
}

/// Names to their index in a list, for lookups in constant time.
class NameIndex {
public:
    /// Adds `name` as the next index; returns the earlier index of the same name, or -1.
    int add(const std::string& name) {
        const auto [at, added] = m_indices.emplace(name, static_cast<int>(m_names.size()));
        if (!added) return at->second;
        m_names.push_back(name);
        return -1;
    }
    int find(const std::string& name) const {
        const auto at = m_indices.find(name);
        return at == m_indices.end() ? -1 : at->second;
    }
    const std::vector<std::string>& names() const { return m_names; }

private:
    std::unordered_map<std::string, int> m_indices;
    std::vector<std::string> m_names;
};

/// A path as written, after the folder of the file that names it (an absolute path stays as it is).
fs::path resolved(const XmlFile& file, const std::string& path) { return file.folder() / path; }

/// Where a type name is used, to check once every type is known.
struct TypeReference {
    std::string name;
    std::string file;
    int line;
    std::string user;   // "<sees>", "<seek>"
};

/// A file being read, for include loops.
struct OpenFile {
    fs::path identity;  // canonical when possible
    std::string name;
};

fs::path identity(const fs::path& path) {
    std::error_code error;
    fs::path canonical = fs::weakly_canonical(path, error);
    if (error) return fs::absolute(path, error).lexically_normal();
    return canonical;
}

class Loader {
public:
    CrowdWorld read(std::string text, const fs::path& name);

private:
    void readWorld(const XmlFile& file, pugi::xml_node world);
    void readAgentsChild(const XmlFile& file, pugi::xml_node node, int depth);
    void readInclude(const XmlFile& file, pugi::xml_node node, int depth);
    void readIncludedFile(std::string text, const fs::path& path, const fs::path& key, int depth);
    void readType(const XmlFile& file, pugi::xml_node node);
    void readBehaviour(const XmlFile& file, pugi::xml_node node);
    void readStateMachine(const XmlFile& file, pugi::xml_node node, Behaviour& behaviour);
    void readSubsumption(const XmlFile& file, pugi::xml_node node, Behaviour& behaviour);
    bool readAction(const XmlFile& file, pugi::xml_node node, std::vector<Action>& actions);
    Condition readCondition(const XmlFile& file, pugi::xml_node node);
    void readGround(const XmlFile& file, pugi::xml_node node);
    void checkNames();

    void useType(const XmlFile& file, pugi::xml_node node, const std::string& name) {
        m_typeReferences.push_back({name, file.name(), file.line(node), tag(node)});
    }

    CrowdWorld m_world;
    std::vector<OpenFile> m_open;              // the world file, then each include being read
    std::vector<std::string> m_typeFiles;      // the file of each of m_world.types
    std::vector<std::string> m_behaviourFiles; // the file of each of m_world.behaviours
    std::vector<TypeReference> m_typeReferences;
    NameIndex m_types;                         // m_world.types by name
    NameIndex m_behaviours;                    // m_world.behaviours by name
    std::vector<OpenFile> m_included;          // every file included so far, named by where it was
    std::size_t m_bytes = 0;                   // XML read, all files together
};

CrowdWorld Loader::read(std::string text, const fs::path& name) {
    m_bytes = text.size();
    const XmlFile file(std::move(text), name);
    m_world.file = name;
    m_open.push_back({identity(name), file.name()});
    const pugi::xml_node root = file.document().document_element();
    if (std::string(root.name()) != "world") {
        file.fail(root, "the root element is " + tag(root) + "; a crowd world file holds one <world> element");
    }
    for (pugi::xml_node other = root.next_sibling(); other; other = other.next_sibling()) {
        if (other.type() == pugi::node_element) file.fail(other, "a second root element " + tag(other) + " after <world>");
    }
    readWorld(file, root);
    checkNames();
    return std::move(m_world);
}

void Loader::readWorld(const XmlFile& file, pugi::xml_node world) {
    checkAttributes(file, world, {"seed", "step"});
    m_world.seed = static_cast<std::uint32_t>(wholeNumber(file, world, "seed", 1, 0, 0xFFFFFFFFll));
    m_world.step = number(file, world, "step", 1.0f / 30.0f, Range::Step);
    bool ground = false;
    std::int64_t agents = 0, samples = 0;
    for (pugi::xml_node node : childElements(file, world)) {
        const std::string name = node.name();
        if (name == "include" || name == "type" || name == "behaviour") {
            readAgentsChild(file, node, 0);
        } else if (name == "ground") {
            if (ground) file.fail(node, "a second <ground>; a world has exactly one");
            readGround(file, node);
            ground = true;
        } else if (name == "base") {
            checkLeaf(file, node, {"x", "z", "radius"});
            Base base;
            base.position = {number(file, node, "x", std::nullopt, Range::Metres), number(file, node, "z", std::nullopt, Range::Metres)};
            base.radius = number(file, node, "radius", 1.5f, Range::Positive);
            base.line = file.line(node);
            m_world.bases.push_back(base);
        } else if (name == "samples") {
            checkLeaf(file, node, {"count", "x", "z", "radius"});
            SampleArea area;
            area.count = static_cast<int>(wholeNumber(file, node, "count", std::nullopt, 0, CrowdXmlLimits::maxSamples));
            area.centre = {number(file, node, "x", std::nullopt, Range::Metres), number(file, node, "z", std::nullopt, Range::Metres)};
            area.radius = number(file, node, "radius", 1.0f, Range::NonNegative);
            area.line = file.line(node);
            samples += area.count;
            if (samples > CrowdXmlLimits::maxSamples) {
                file.fail(node, "the <samples> elements place " + std::to_string(samples) + " samples in all; at most " +
                                    std::to_string(CrowdXmlLimits::maxSamples) + " are allowed");
            }
            m_world.samples.push_back(area);
        } else if (name == "spawn") {
            checkLeaf(file, node, {"type", "count", "x", "z", "radius", "team"});
            SpawnArea spawn;
            spawn.type = requiredText(file, node, "type");
            spawn.count = static_cast<int>(wholeNumber(file, node, "count", std::nullopt, 0, CrowdXmlLimits::maxAgents));
            spawn.centre = {number(file, node, "x", std::nullopt, Range::Metres), number(file, node, "z", std::nullopt, Range::Metres)};
            spawn.radius = number(file, node, "radius", 1.0f, Range::NonNegative);
            spawn.team = static_cast<int>(wholeNumber(file, node, "team", 0, 0, std::numeric_limits<int>::max()));
            spawn.line = file.line(node);
            agents += spawn.count;
            if (agents > CrowdXmlLimits::maxAgents) {
                file.fail(node, "the <spawn> elements place " + std::to_string(agents) + " agents in all; at most " +
                                    std::to_string(CrowdXmlLimits::maxAgents) + " are allowed (" +
                                    CrowdXmlLimits::maxAgentsReason + ", too slow to watch)");
            }
            m_world.spawns.push_back(spawn);
        } else {
            file.fail(node, "unknown element " + tag(node) +
                                " in <world>; expected one of: include, type, behaviour, ground, base, samples, spawn");
        }
    }
    if (!ground) file.fail(world, "the world has no <ground> element; it needs exactly one");
    if (m_world.spawns.empty()) file.fail(world, "the world has no <spawn> element; it needs at least one");
    for (SpawnArea& spawn : m_world.spawns) {
        spawn.typeIndex = -1;  // set by checkNames(), once the included types are known
        const int bases = static_cast<int>(m_world.bases.size());
        if (bases == 0 && spawn.team != 0) {
            throw InputError(file.name(), spawn.line, "<spawn> team=\"" + std::to_string(spawn.team) +
                                                          "\", but the world has no <base>; without bases the team is 0");
        }
        if (bases > 0 && spawn.team >= bases) {
            throw InputError(file.name(), spawn.line, "<spawn> team=\"" + std::to_string(spawn.team) +
                                                          "\" names no base; the world has " + std::to_string(bases) +
                                                          " (teams 0 to " + std::to_string(bases - 1) + ")");
        }
        m_typeReferences.push_back({spawn.type, file.name(), spawn.line, "<spawn>"});
    }
}

void Loader::readGround(const XmlFile& file, pugi::xml_node node) {
    checkLeaf(file, node, {"collision", "height", "min", "max", "height-min", "height-max", "scenery"});
    GroundDescription& ground = m_world.ground;
    ground.collisionMap = resolved(file, requiredText(file, node, "collision"));
    const std::string height = node.attribute("height").value();
    ground.heightMap = height.empty() ? fs::path() : resolved(file, height);
    ground.footprintMin = coordinates(file, node, "min", glm::vec2(-15.0f));
    ground.footprintMax = coordinates(file, node, "max", glm::vec2(15.0f));
    if (!(ground.footprintMin.x < ground.footprintMax.x && ground.footprintMin.y < ground.footprintMax.y)) {
        file.fail(node, "<ground> min must be less than max on both axes (x and z)");
    }
    ground.heightMin = number(file, node, "height-min", 0.0f, Range::Metres);
    ground.heightMax = number(file, node, "height-max", 0.0f, Range::Metres);
    if (ground.heightMax < ground.heightMin) file.fail(node, "<ground> height-max must be at least height-min");
    ground.scenery = optionalText(file, node, "scenery", "none");
    if (ground.scenery != "acropolis" && ground.scenery != "terrain" && ground.scenery != "none") {
        file.fail(node, "<ground> scenery=\"" + quoteInput(ground.scenery) + "\" is unknown; expected one of: acropolis, terrain, none");
    }
    ground.line = file.line(node);
}

/// An element of <agents> (or the same elements directly in <world>).
void Loader::readAgentsChild(const XmlFile& file, pugi::xml_node node, int depth) {
    const std::string name = node.name();
    if (name == "include") return readInclude(file, node, depth);
    if (name == "type") return readType(file, node);
    if (name == "behaviour") return readBehaviour(file, node);
    file.fail(node, "unknown element " + tag(node) + " in <agents>; expected one of: include, type, behaviour");
}

void Loader::readInclude(const XmlFile& file, pugi::xml_node node, int depth) {
    checkLeaf(file, node, {"file"});
    const std::string written = requiredText(file, node, "file");
    const fs::path path = resolved(file, written);
    if (depth + 1 > CrowdXmlLimits::maxIncludeDepth) {
        file.fail(node, "<include> nests deeper than " + std::to_string(CrowdXmlLimits::maxIncludeDepth) + " files");
    }
    const fs::path key = identity(path);
    // Only the world's own folder tree: an include of /etc/passwd or ../../secret.xml
    // would otherwise read any file the user can, and quote it in its errors.
    const fs::path worldFolder = identity(fs::path(m_world.file).parent_path());
    const fs::path inside = key.lexically_relative(worldFolder);
    if (inside.empty() || *inside.begin() == "..") {
        file.fail(node, "<include> file=\"" + quoteInput(written) + "\" lies outside the world's folder " + worldFolder.string() +
                            "; a world includes files from its own folder and the folders below it");
    }
    for (std::size_t i = 0; i < m_open.size(); ++i) {
        if (m_open[i].identity != key) continue;
        std::string chain;
        for (std::size_t j = i; j < m_open.size(); ++j) chain += m_open[j].name + " -> ";
        file.fail(node, "include loop: " + chain + path.string());
    }
    // A file's types and behaviours are defined once: a second include of it
    // would define them again (and 4 files that include the next 1000 times each
    // would have the loader read 10^9 files).
    for (const OpenFile& earlier : m_included)
        if (earlier.identity == key)
            file.fail(node, "<include> file=\"" + quoteInput(written) + "\" is included already, at " + earlier.name +
                                "; include each file once");
    if (m_included.size() >= static_cast<std::size_t>(CrowdXmlLimits::maxIncludes))
        file.fail(node, "more than " + std::to_string(CrowdXmlLimits::maxIncludes) + " <include> elements in one world");
    m_included.push_back({key, file.name() + ":" + std::to_string(file.line(node))});
    std::string text;
    try {
        text = readInputFile(path, CrowdXmlLimits::maxFileBytes, "crowd XML file");
    } catch (const InputError& error) {
        file.fail(node, "<include> file=\"" + quoteInput(written) + "\" cannot be read: " + error.message());
    }
    m_bytes += text.size();
    if (m_bytes > CrowdXmlLimits::maxWorldBytes)
        file.fail(node, "<include> file=\"" + quoteInput(written) + "\" takes the world past " +
                            std::to_string(CrowdXmlLimits::maxWorldBytes >> 20) + " MiB of XML, all files together");
    try {
        readIncludedFile(std::move(text), path, key, depth);
    } catch (const InputError& error) {
        // Where the file was included from, after what is wrong in it: "(included from
        // world.xml:5)", and for a file included by an included file ", from ...".
        std::string message = error.message();
        const std::string from = file.name() + ":" + std::to_string(file.line(node));
        if (message.size() > 1 && message.back() == ')' && message.find(" (included from ") != std::string::npos)
            message.insert(message.size() - 1, ", from " + from);
        else
            message += " (included from " + from + ")";
        throw InputError(error.file(), error.line(), message);
    }
}

void Loader::readIncludedFile(std::string text, const fs::path& path, const fs::path& key, int depth) {
    const XmlFile included(std::move(text), path);
    const pugi::xml_node root = included.document().document_element();
    if (std::string(root.name()) != "agents") {
        included.fail(root, "the root element of an included file is " + tag(root) + "; expected <agents>");
    }
    for (pugi::xml_node other = root.next_sibling(); other; other = other.next_sibling()) {
        if (other.type() == pugi::node_element) included.fail(other, "a second root element " + tag(other) + " after <agents>");
    }
    checkAttributes(included, root, {});
    m_open.push_back({key, included.name()});
    for (pugi::xml_node child : childElements(included, root)) readAgentsChild(included, child, depth + 1);
    m_open.pop_back();
}

void Loader::readType(const XmlFile& file, pugi::xml_node node) {
    checkLeaf(file, node, {"name", "model", "skin", "scale", "speed", "sight", "radius", "behaviour"});
    AgentType type;
    type.name = requiredText(file, node, "name");
    type.model = resolved(file, requiredText(file, node, "model"));
    type.skin = resolved(file, requiredText(file, node, "skin"));
    type.scale = number(file, node, "scale", type.scale, Range::Positive);
    type.speed = number(file, node, "speed", type.speed, Range::Positive);
    type.sightRadius = number(file, node, "sight", type.sightRadius, Range::Positive);
    type.radius = number(file, node, "radius", type.radius, Range::Positive);
    type.behaviour = requiredText(file, node, "behaviour");
    type.line = file.line(node);
    type.file = file.name();
    const int earlier = m_types.add(type.name);
    if (earlier >= 0) {
        file.fail(node, "the type '" + quoteInput(type.name) + "' is defined twice; the first is at " + m_typeFiles[earlier] +
                            ":" + std::to_string(m_world.types[earlier].line));
    }
    m_world.types.push_back(type);
    m_typeFiles.push_back(file.name());
}

void Loader::readBehaviour(const XmlFile& file, pugi::xml_node node) {
    Behaviour behaviour;
    behaviour.line = file.line(node);
    const std::string kind = node.attribute("kind").value();
    if (kind == "fsm") {
        checkAttributes(file, node, {"name", "kind", "initial"});
        behaviour.kind = Behaviour::Kind::StateMachine;
    } else if (kind == "subsumption") {
        checkAttributes(file, node, {"name", "kind"});
        behaviour.kind = Behaviour::Kind::Subsumption;
    } else {
        requiredText(file, node, "kind");
        file.fail(node, "<behaviour> kind=\"" + quoteInput(kind) + "\" is unknown; expected fsm or subsumption");
    }
    behaviour.name = requiredText(file, node, "name");
    const int earlier = m_behaviours.add(behaviour.name);
    if (earlier >= 0) {
        file.fail(node, "the behaviour '" + quoteInput(behaviour.name) + "' is defined twice; the first is at " +
                            m_behaviourFiles[earlier] + ":" + std::to_string(m_world.behaviours[earlier].line));
    }
    if (behaviour.kind == Behaviour::Kind::StateMachine) readStateMachine(file, node, behaviour);
    else readSubsumption(file, node, behaviour);
    m_world.behaviours.push_back(std::move(behaviour));
    m_behaviourFiles.push_back(file.name());
}

void Loader::readStateMachine(const XmlFile& file, pugi::xml_node node, Behaviour& behaviour) {
    std::vector<MachineState>& states = behaviour.machine.states;
    std::vector<std::pair<pugi::xml_node, std::string>> targets;  // each transition's element and `to`
    NameIndex names;
    for (pugi::xml_node stateNode : childElements(file, node)) {
        if (std::string(stateNode.name()) != "state") {
            file.fail(stateNode, "unknown element " + tag(stateNode) + " in <behaviour kind=\"fsm\">; expected <state>");
        }
        checkAttributes(file, stateNode, {"name", "animation", "speed"});
        MachineState state;
        state.name = requiredText(file, stateNode, "name");
        state.animation = optionalText(file, stateNode, "animation", "run");
        state.speedScale = number(file, stateNode, "speed", 1.0f, Range::NonNegative);
        state.line = file.line(stateNode);
        const int earlier = names.add(state.name);
        if (earlier >= 0) {
            file.fail(stateNode, "the state '" + quoteInput(state.name) + "' is defined twice in the behaviour '" +
                                     quoteInput(behaviour.name) + "'; the first is at line " + std::to_string(states[earlier].line));
        }
        for (pugi::xml_node child : childElements(file, stateNode)) {
            if (readAction(file, child, state.actions)) continue;
            if (std::string(child.name()) != "transition") {
                file.fail(child, "unknown element " + tag(child) + " in <state>; expected an action (wander, seek, flee, "
                                 "follow-crumbs, pick-up, drop, drop-crumb, pick-up-crumb, stop, send, attack) or <transition>");
            }
            checkAttributes(file, child, {"to"});
            Transition transition;
            transition.line = file.line(child);
            targets.emplace_back(child, requiredText(file, child, "to"));
            for (pugi::xml_node condition : childElements(file, child)) transition.when.push_back(readCondition(file, condition));
            state.transitions.push_back(std::move(transition));
        }
        states.push_back(std::move(state));
    }
    if (states.empty()) file.fail(node, "the behaviour '" + quoteInput(behaviour.name) + "' has no <state>; it needs at least one");
    std::size_t next = 0;
    for (MachineState& state : states) {
        for (Transition& transition : state.transitions) {
            const auto& [element, to] = targets[next++];
            transition.target = names.find(to);
            if (transition.target < 0) {
                file.fail(element, "<transition> to=\"" + quoteInput(to) + "\" names no state of the behaviour '" +
                                       quoteInput(behaviour.name) + "'; its states are: " + joined(names.names()));
            }
        }
    }
    const std::string initial = optionalText(file, node, "initial", states[0].name);
    behaviour.machine.initial = names.find(initial);
    if (behaviour.machine.initial < 0) {
        file.fail(node, "<behaviour> initial=\"" + quoteInput(initial) + "\" names no state of the behaviour '" +
                            quoteInput(behaviour.name) + "'; its states are: " + joined(names.names()));
    }
}

void Loader::readSubsumption(const XmlFile& file, pugi::xml_node node, Behaviour& behaviour) {
    std::vector<Layer>& layers = behaviour.stack.layers;
    NameIndex names;
    for (pugi::xml_node layerNode : childElements(file, node)) {
        if (std::string(layerNode.name()) != "layer") {
            file.fail(layerNode, "unknown element " + tag(layerNode) + " in <behaviour kind=\"subsumption\">; expected <layer>");
        }
        checkAttributes(file, layerNode, {"name", "animation", "speed"});
        Layer layer;
        layer.name = requiredText(file, layerNode, "name");
        layer.animation = optionalText(file, layerNode, "animation", "run");
        layer.speedScale = number(file, layerNode, "speed", 1.0f, Range::NonNegative);
        layer.line = file.line(layerNode);
        const int earlier = names.add(layer.name);
        if (earlier >= 0) {
            file.fail(layerNode, "the layer '" + quoteInput(layer.name) + "' is defined twice in the behaviour '" +
                                     quoteInput(behaviour.name) + "'; the first is at line " + std::to_string(layers[earlier].line));
        }
        bool when = false;
        for (pugi::xml_node child : childElements(file, layerNode)) {
            if (readAction(file, child, layer.actions)) continue;
            if (std::string(child.name()) != "when") {
                file.fail(child, "unknown element " + tag(child) + " in <layer>; expected <when> or an action (wander, seek, "
                                 "flee, follow-crumbs, pick-up, drop, drop-crumb, pick-up-crumb, stop, send, attack)");
            }
            if (when) file.fail(child, "a second <when> in the layer '" + quoteInput(layer.name) + "'; a layer has at most one");
            when = true;
            checkAttributes(file, child, {});
            for (pugi::xml_node condition : childElements(file, child)) layer.when.push_back(readCondition(file, condition));
        }
        layers.push_back(std::move(layer));
    }
    if (layers.empty()) file.fail(node, "the behaviour '" + quoteInput(behaviour.name) + "' has no <layer>; it needs at least one");
}

/// Reads `node` into `actions` when it is an action; false when it is not one.
bool Loader::readAction(const XmlFile& file, pugi::xml_node node, std::vector<Action>& actions) {
    const std::string name = node.name();
    Action action;
    action.line = file.line(node);
    using Kind = Action::Kind;
    if (name == "wander") {
        checkLeaf(file, node, {"turn"});
        action.kind = Kind::Wander;
        action.value = number(file, node, "turn", 90.0f, Range::NonNegative);
    } else if (name == "seek") {
        checkLeaf(file, node, {"target"});
        action.kind = Kind::Seek;
        action.target = requiredText(file, node, "target");
        if (action.target != "base" && action.target != "sample" && action.target != "crumb") useType(file, node, action.target);
    } else if (name == "flee") {
        checkLeaf(file, node, {"from"});
        action.kind = Kind::Flee;
        action.target = requiredText(file, node, "from");
        useType(file, node, action.target);
    } else if (name == "send") {
        checkLeaf(file, node, {"message", "radius"});
        action.kind = Kind::Send;
        action.target = requiredText(file, node, "message");
        action.value = number(file, node, "radius", 8.0f, Range::Positive);
    } else if (name == "attack") {
        checkLeaf(file, node, {"type"});
        action.kind = Kind::Attack;
        action.target = requiredText(file, node, "type");
        useType(file, node, action.target);
    } else {
        static const std::pair<const char*, Kind> plain[] = {
            {"follow-crumbs", Kind::FollowCrumbs}, {"pick-up", Kind::PickUp},   {"drop", Kind::Drop},
            {"drop-crumb", Kind::DropCrumb},       {"pick-up-crumb", Kind::PickUpCrumb}, {"stop", Kind::Stop},
        };
        const auto found = std::find_if(std::begin(plain), std::end(plain), [&](const auto& p) { return name == p.first; });
        if (found == std::end(plain)) return false;
        checkLeaf(file, node, {});
        action.kind = found->second;
    }
    actions.push_back(std::move(action));
    return true;
}

Condition Loader::readCondition(const XmlFile& file, pugi::xml_node node) {
    using Kind = Condition::Kind;
    Condition condition;
    // Each <not> toggles: <not><not><carrying/></not></not> is <carrying/>. A loop, not
    // recursion, so that 800,000 nested <not> elements cannot overflow the stack.
    while (std::string(node.name()) == "not") {
        checkAttributes(file, node, {});
        const std::vector<pugi::xml_node> inner = childElements(file, node);
        if (inner.size() != 1) {
            file.fail(node, "<not> holds exactly one condition; found " + std::to_string(inner.size()));
        }
        condition.negated = !condition.negated;
        node = inner[0];
    }
    const std::string name = node.name();
    condition.line = file.line(node);
    if (name == "always") {
        checkLeaf(file, node, {});
        condition.kind = Kind::Always;
    } else if (name == "sees") {
        checkLeaf(file, node, {"type"});
        condition.kind = Kind::Sees;
        condition.type = requiredText(file, node, "type");
        useType(file, node, condition.type);
    } else if (name == "near") {
        checkLeaf(file, node, {"type", "distance"});
        condition.kind = Kind::Near;
        condition.type = requiredText(file, node, "type");
        condition.value = number(file, node, "distance", std::nullopt, Range::Positive);
        useType(file, node, condition.type);
    } else if (name == "carrying") {
        checkLeaf(file, node, {});
        condition.kind = Kind::Carrying;
    } else if (name == "at-base") {
        checkLeaf(file, node, {"distance"});
        condition.kind = Kind::AtBase;
        condition.value = number(file, node, "distance", 1.5f, Range::Positive);
    } else if (name == "sees-sample") {
        checkLeaf(file, node, {});
        condition.kind = Kind::SeesSample;
    } else if (name == "smells-crumb") {
        checkLeaf(file, node, {});
        condition.kind = Kind::SmellsCrumb;
    } else if (name == "blocked") {
        checkLeaf(file, node, {"ahead"});
        condition.kind = Kind::Blocked;
        condition.value = number(file, node, "ahead", 1.0f, Range::Positive);
    } else if (name == "time-in-state") {
        checkLeaf(file, node, {"seconds"});
        condition.kind = Kind::TimeInState;
        condition.value = number(file, node, "seconds", std::nullopt, Range::NonNegative);
    } else if (name == "message") {
        checkLeaf(file, node, {"name"});
        condition.kind = Kind::Message;
        condition.type = requiredText(file, node, "name");
    } else if (name == "chance") {
        checkLeaf(file, node, {"per-step"});
        condition.kind = Kind::Chance;
        condition.value = number(file, node, "per-step", std::nullopt, Range::UnitInterval);
    } else {
        file.fail(node, "unknown condition " + tag(node) + "; expected one of: always, sees, near, carrying, at-base, "
                        "sees-sample, smells-crumb, blocked, time-in-state, message, chance, not");
    }
    return condition;
}

/// The names that may be defined in any file: each type's behaviour and every use of a type.
void Loader::checkNames() {
    for (std::size_t i = 0; i < m_world.types.size(); ++i) {
        AgentType& type = m_world.types[i];
        type.behaviourIndex = m_behaviours.find(type.behaviour);
        if (type.behaviourIndex < 0) {
            throw InputError(m_typeFiles[i], type.line, "the type '" + quoteInput(type.name) + "' has behaviour=\"" +
                                                            quoteInput(type.behaviour) + "\", which is not defined; behaviours: " +
                                                            joined(m_behaviours.names()));
        }
    }
    for (const TypeReference& reference : m_typeReferences) {
        if (m_types.find(reference.name) < 0) {
            throw InputError(reference.file, reference.line, reference.user + " names the type '" + quoteInput(reference.name) +
                                                                 "', which is not defined; types: " + joined(m_types.names()));
        }
    }
    for (SpawnArea& spawn : m_world.spawns) spawn.typeIndex = m_types.find(spawn.type);
}

} // namespace

CrowdWorld loadCrowdWorld(const fs::path& path) {
    return Loader().read(readInputFile(path, CrowdXmlLimits::maxFileBytes, "crowd XML file"), path);
}

CrowdWorld parseCrowdWorld(const std::string& text, const fs::path& name) {
    return Loader().read(text, name);
}

} // namespace stoa
