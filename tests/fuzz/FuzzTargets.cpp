#include "FuzzTargets.hpp"

#include <stoa/audio/SoundClip.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/crowd/CrowdXml.hpp>
#include <stoa/editor/EditorSceneFile.hpp>
#include <stoa/geometry/Md2Model.hpp>
#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/image/HeightMap.hpp>
#include <stoa/image/Image.hpp>

#include <set>
#include <sstream>

namespace stoa::fuzz {

bool obj(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t split = input.find(mtlSeparator);
    const std::string objText = input.substr(0, split);
    const std::string mtlText = split == std::string::npos ? std::string() : input.substr(split + mtlSeparator.size());
    const MtlReader readMtl = [&](const std::filesystem::path&) { return mtlText; };
    std::ostringstream warnings;
    try {
        const Model model = parseObj(objText, "/nonexistent-fuzz-folder/model.obj", readMtl, warnings);
        (void)model;
        return true;
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
}

bool image(const std::uint8_t* data, std::size_t size) {
    try {
        const Image decoded = Image::decode(data, size, "fuzz-image");
        // Each decoded image keeps its promise: the size its header gave, all its bytes.
        if (decoded.sizeInBytes() != static_cast<std::size_t>(decoded.width()) * decoded.height() * decoded.channels())
            __builtin_trap();
        return true;
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
}

bool heightMap(const std::uint8_t* data, std::size_t size) {
    std::ostringstream warnings;
    try {
        const Image height = decodeHeightMap(data, size, "fuzz-height-map", warnings);
        if (height.channels() != 1) __builtin_trap();
        return true;
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
}

bool md2(const std::uint8_t* data, std::size_t size) {
    try {
        const Md2Model model = decodeMd2(data, size, "fuzz-model.md2");
        // Each decoded model keeps its promises: every frame has every vertex, every
        // triangle indexes what exists, the animations cover the frames in order.
        const std::size_t vertices = model.vertexCount();
        for (const Md2Frame& frame : model.frames)
            if (frame.positions.size() != vertices || frame.normals.size() != vertices) __builtin_trap();
        for (const Md2Triangle& triangle : model.triangles)
            for (int corner = 0; corner < 3; ++corner)
                if (triangle.vertex[corner] >= vertices || triangle.texCoord[corner] >= model.texCoords.size()) __builtin_trap();
        int next = 0;
        for (const Md2Animation& animation : model.animations) {
            if (animation.first != next || animation.count < 1) __builtin_trap();
            next += animation.count;
        }
        if (next != static_cast<int>(model.frames.size())) __builtin_trap();
        return true;
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
}

bool crowdXml(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const CrowdWorld world = parseCrowdWorld(text, "/nonexistent-fuzz-folder/fuzz.xml");
        // Each world read keeps its promises: every index the loader set points at something.
        const auto within = [](int index, std::size_t count) { return index >= 0 && static_cast<std::size_t>(index) < count; };
        for (const AgentType& type : world.types)
            if (!within(type.behaviourIndex, world.behaviours.size())) __builtin_trap();
        for (const SpawnArea& spawn : world.spawns)
            if (!within(spawn.typeIndex, world.types.size()) || spawn.count < 0) __builtin_trap();
        for (const Behaviour& behaviour : world.behaviours) {
            const std::vector<MachineState>& states = behaviour.machine.states;
            if (behaviour.kind == Behaviour::Kind::StateMachine && !within(behaviour.machine.initial, states.size()))
                __builtin_trap();
            for (const MachineState& state : states)
                for (const Transition& transition : state.transitions)
                    if (!within(transition.target, states.size())) __builtin_trap();
        }
        if (world.spawns.empty() || !(world.step > 0.0f && world.step <= 1.0f)) __builtin_trap();
        return true;
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
}

bool editorScene(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    EditorScene scene;
    try {
        scene = editorSceneFromJson(text, "fuzz.json");
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
    // Each scene read keeps its promises: ids from 1 and unique, every object's
    // material exists, the ranges the reader checks hold.
    std::set<std::uint32_t> ids;
    for (const EditorObject& object : scene.objects) {
        if (object.id == 0 || !ids.insert(object.id).second || !scene.findMaterial(object.material)) __builtin_trap();
    }
    for (const EditorLight& light : scene.lights) {
        if (light.id == 0 || !ids.insert(light.id).second || !(light.radius > 0.0f)) __builtin_trap();
    }
    for (const EditorMaterial& material : scene.materials)
        if (!(material.shininess > 0.0f)) __builtin_trap();
    const int pcf = scene.renderer.pcfSize;
    if (pcf < 1 || pcf > 3) __builtin_trap();
    // And it saves, and the saved text reads back to itself: what the editor
    // opened, it can write, and reopen.
    try {
        const std::string saved = editorSceneToJson(scene);
        if (editorSceneToJson(editorSceneFromJson(saved, "fuzz-saved.json")) != saved) __builtin_trap();
    } catch (...) {
        __builtin_trap();
    }
    return true;
}

bool sound(const std::uint8_t* data, std::size_t size) {
    try {
        const SoundClip clip = SoundClip::decode(data, size, "fuzz.ogg");
        if (clip.channels() < 1 || clip.channels() > 2) __builtin_trap();
        if (clip.sampleRate() < SoundClip::minSampleRate || clip.sampleRate() > SoundClip::maxSampleRate) __builtin_trap();
        if (clip.durationSeconds() > SoundClip::maxSeconds + 1.0 || clip.empty()) __builtin_trap();
        return true;
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
}

} // namespace stoa::fuzz
