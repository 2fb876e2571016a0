#include <stoa/core/InputError.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <sstream>
#include <vector>

namespace stoa {

void CameraRig::toggle() {
    if (m_orbitActive) {
        const glm::vec3 eye = orbit.eyePosition();
        const glm::vec3 direction = glm::normalize(orbit.target() - eye);
        const float yaw = glm::degrees(std::atan2(-direction.x, -direction.z));
        const float pitch = glm::degrees(std::asin(glm::clamp(direction.y, -1.0f, 1.0f)));
        firstPerson = FirstPersonCamera(eye, yaw, pitch);
        firstPerson.setProjection(orbit.fovYDegrees(), orbit.nearPlane(), orbit.farPlane());
    } else {
        const glm::vec3 eye = firstPerson.eyePosition();
        const float distance = orbit.distance();
        const glm::vec3 target = eye + firstPerson.forward() * distance;
        orbit = OrbitCamera(target, distance, firstPerson.yawDegrees(), -firstPerson.pitchDegrees());
        orbit.setProjection(firstPerson.fovYDegrees(), firstPerson.nearPlane(), firstPerson.farPlane());
    }
    m_orbitActive = !m_orbitActive;
}

void CameraRig::loadCase(const CaseSpec& spec) {
    const std::string kind = spec.getChoice("camera", {"orbit", "first_person"}, std::string("orbit"));
    const float fov = static_cast<float>(spec.getNumberInRange("fov", 1.0, 179.0, 50.0));
    const float near = static_cast<float>(spec.getNumber("near", 0.1));
    const float far = static_cast<float>(spec.getNumber("far", 100.0));
    if (!(near > 0.0f)) spec.reject("near", "near must be greater than 0");
    if (!(far > near)) spec.reject("far", "far must be greater than near");
    if (kind == "orbit") {
        const float distance = static_cast<float>(spec.getNumber("distance", 6.0));
        if (!(distance > 0.0f)) spec.reject("distance", "distance must be greater than 0");
        const float pitch = static_cast<float>(spec.getNumberInRange("pitch", -89.0, 89.0, 20.0));
        orbit = OrbitCamera(spec.getVec3("target", glm::vec3(0.0f)), distance,
                            static_cast<float>(spec.getNumber("yaw", 30.0)), pitch);
        orbit.setProjection(fov, near, far);
        m_orbitActive = true;
    } else {
        firstPerson = FirstPersonCamera(spec.getVec3("position", glm::vec3(0.0f, 1.5f, 6.0f)),
                                        static_cast<float>(spec.getNumber("yaw", 0.0)),
                                        static_cast<float>(spec.getNumberInRange("pitch", -89.0, 89.0, 0.0)));
        firstPerson.setProjection(fov, near, far);
        m_orbitActive = false;
    }
    if (spec.has("input")) {
        try {
            applyInput(spec.getString("input"), spec.file, spec.line);
        } catch (const InputError& error) {
            spec.reject("input", error.message());  // at the line of the input key
        }
    }
}

void CameraRig::applyInput(const std::string& script, const std::string& file, int line) {
    std::stringstream commands(script);
    std::string command;
    while (std::getline(commands, command, ';')) {
        std::istringstream words(command);
        std::string verb;
        if (!(words >> verb)) continue;
        std::vector<float> numbers;
        std::string word;
        while (words >> word) {
            char* end = nullptr;
            const float value = std::strtof(word.c_str(), &end);
            if (end == word.c_str() || *end != '\0')
                throw InputError(file, line, "input: '" + word + "' in '" + command + "' is not a number");
            numbers.push_back(value);
        }
        auto expect = [&](std::size_t count, bool needsOrbit) {
            if (numbers.size() != count)
                throw InputError(file, line, "input: '" + verb + "' takes " + std::to_string(count) + " numbers");
            if (needsOrbit != m_orbitActive)
                throw InputError(file, line, "input: '" + verb + "' needs the " +
                                                 (needsOrbit ? "orbit" : "first_person") + " camera");
        };
        if (verb == "tumble") {
            expect(2, true);
            orbit.tumble(numbers[0], numbers[1]);
        } else if (verb == "track") {
            expect(2, true);
            orbit.track(numbers[0], numbers[1]);
        } else if (verb == "dolly") {
            expect(1, true);
            orbit.dolly(numbers[0]);
        } else if (verb == "look") {
            expect(2, false);
            firstPerson.look(numbers[0], numbers[1]);
        } else if (verb == "move") {
            expect(3, false);
            firstPerson.move({numbers[0], numbers[1], numbers[2]});
        } else {
            throw InputError(file, line,
                             "input: unknown command '" + verb + "' (valid: tumble, track, dolly, look, move)");
        }
    }
}

} // namespace stoa
