#pragma once
// stoa-editor's deferred pipeline: the scene's objects with its wide field
// (lab 06's culling and levels of detail), its wandering lights (lab 08), its
// crowd (lab 10) and a ball thrown into it that bounces off the triangles of a
// BVH and throws sparks (lab 07), drawn by stoa::CourseRenderer with the
// students' code of labs 04-10 (your own, when you build your track). Not one
// of lab 11's exercises: EditorLabApp (editor_app.hpp) uses it when the
// renderer panel's "deferred" is on, and the showcase (docs/showcase.md) is
// drawn by it.

#include "lab01.hpp"
#include "lab05.hpp"
#include "lab06.hpp"
#include "lab07.hpp"

#include <stoa/camera/Camera.hpp>
#include <stoa/core/HashRandom.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/crowd/CrowdLab.hpp>
#include <stoa/crowd/CrowdSimulation.hpp>
#include <stoa/crowd/CrowdXml.hpp>
#include <stoa/crowd/GroundMaps.hpp>
#include <stoa/editor/EditorAssets.hpp>
#include <stoa/editor/EditorScene.hpp>
#include <stoa/geometry/LevelOfDetail.hpp>
#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/VertexArray.hpp>
#include <stoa/render/AmbientOcclusion.hpp>
#include <stoa/render/CourseRenderer.hpp>
#include <stoa/scene/WanderingLights.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stoa {

class EditorPipeline {
public:
    using Log = std::function<void(const std::string&)>;

    /// `searchPath`: the lab's GLSL search path (the students' GLSL of labs 04-09 on it).
    EditorPipeline(std::vector<std::filesystem::path> searchPath, Log log)
        : m_searchPath(std::move(searchPath)), m_log(std::move(log)) {}

    /// Builds what `scene` needs that differs from the last scene's: the field's
    /// meshes and levels, the crowd. `folder`: the scene file's folder (assets
    /// are looked for there first, then in assets/). Bad assets go to the log.
    void prepare(const EditorScene& scene, const std::filesystem::path& folder, EditorAssets& assets) {
        if (!m_renderer) makeRenderer();
        if (scene.field.meshes != m_fieldMeshNames) buildFieldMeshes(scene.field.meshes, folder);
        // The crowd's world is an asset: a new version (its XML or a ground map saved) starts the crowd again.
        const AssetRef<CrowdWorld>* world = assets.crowdWorld(scene.crowdWorld);
        const int version = world ? world->version() : 0;
        if (scene.crowdWorld != m_crowdName || version != m_crowdVersion) {
            if (scene.crowdWorld == m_crowdName && m_crowdVersion != 0)
                m_log("crowd: " + scene.crowdWorld + " changed, the crowd starts again");
            loadCrowd(scene.crowdWorld, world);
            m_crowdVersion = version;
        }
    }

    /// Moves the crowd and the wandering lights on by `seconds` of wall time.
    void advance(double seconds) {
        m_seconds += seconds;
        advanceBall(static_cast<float>(seconds));
        if (!m_crowd) return;
        m_crowdDebt += seconds;
        const double step = m_crowd->world().step;
        int steps = 0;
        while (m_crowdDebt >= step && steps < 8) {   // at most 8 steps a frame: a slow frame slows the crowd
            m_crowd->step();
            m_crowdDebt -= step;
            ++steps;
        }
        if (m_crowdDebt > step) m_crowdDebt = 0.0;
        noteFootsteps();
    }

    /// The frame: `objects` (the editor's, built from the scene) with the
    /// field, the wandering lights and the crowd.
    void render(const EditorScene& scene, std::vector<CourseItem> objects, std::vector<PointLight> lights,
                const Material* fieldMaterial, const Texture2D* fieldDiffuse, const Camera& camera, glm::ivec2 size,
                const CourseSettings& settings) {
        appendField(scene.field, fieldMaterial, fieldDiffuse, objects);
        if (scene.lightSwarm.count > 0) {
            WanderingLightsOptions options;
            options.count = scene.lightSwarm.count;
            options.seed = static_cast<std::uint32_t>(scene.lightSwarm.seed);
            options.regionMin = {-scene.lightSwarm.radius, 0.3f, -scene.lightSwarm.radius};
            options.regionMax = {scene.lightSwarm.radius, scene.lightSwarm.height, scene.lightSwarm.radius};
            options.brightness = scene.lightSwarm.brightness;
            const std::vector<PointLight> swarm = wanderingLights(options, static_cast<float>(m_seconds));
            lights.insert(lights.end(), swarm.begin(), swarm.end());
        }
        CourseLighting lighting;
        lighting.ambient = scene.ambient;
        lighting.sunDirection = scene.sunDirection;
        lighting.sunColor = scene.sunColor;
        lighting.pointLights = std::move(lights);
        const float extent = std::max(20.0f, 0.5f * scene.field.spacing * static_cast<float>(scene.field.rows) + 10.0f);
        lighting.sceneMin = {-extent, -1.0f, -extent};
        lighting.sceneMax = {extent, 12.0f, extent};
        CourseCrowd crowd;
        if (m_crowd) {
            crowd.simulation = m_crowd.get();
            crowd.renderer = m_crowdRenderer.get();
            crowd.options.markers = true;   // the samples the explorers look for, their crumbs, the base
            crowd.options.selected = m_selectedAgent;   // drawn highlighted
        }
        if (m_ballFlying) {
            CourseItem ball;
            ball.levels = {m_ballMesh.get()};
            ball.model = glm::scale(glm::translate(glm::mat4(1.0f), m_bounce.ball.position), glm::vec3(m_bounce.ball.radius));
            ball.material = &m_ballMaterial;
            objects.push_back(ball);
        }
        m_renderer->render(objects, lighting, camera, size, settings, m_crowd ? &crowd : nullptr,
                           [this](const Framebuffer& lightBuffer) { drawSparks(lightBuffer); });
        // A lab still unfinished switches its own pass off: said once.
        for (const std::string& part : m_renderer->stats().switchedOff)
            if (m_saidOff.insert(part).second) m_log(part + " is still a stub in this build: drawn without it");
    }

    /// Throws lab 07's ball from `from` along `direction` (12 m/s) into the
    /// scene's objects: their triangles in world space go into a BVH (the
    /// student's buildBvh()); the ball bounces off them (advanceSimulation()).
    void throwBall(const EditorScene& scene, const std::filesystem::path& folder, const glm::vec3& from,
                   const glm::vec3& direction) {
        std::vector<Triangle> triangles;
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const EditorObject& object = scene.objects[i];
            const glm::mat4 model = modelMatrix(object.position, object.rotationDegrees, object.scale);
            for (const Mesh& mesh : cpuMeshes(object.mesh, folder))
                for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
                    Triangle triangle;
                    triangle.p0 = glm::vec3(model * glm::vec4(mesh.vertices[mesh.indices[t]].position, 1.0f));
                    triangle.p1 = glm::vec3(model * glm::vec4(mesh.vertices[mesh.indices[t + 1]].position, 1.0f));
                    triangle.p2 = glm::vec3(model * glm::vec4(mesh.vertices[mesh.indices[t + 2]].position, 1.0f));
                    triangle.object = static_cast<int>(i);
                    triangles.push_back(triangle);
                }
        }
        m_bvh = buildBvh(std::move(triangles));   // the student's (lab 07)
        const SparkRandom random = m_bounce.random;   // each throw's sparks differ
        m_bounce = Simulation{};
        m_bounce.random = random;
        m_bounce.ball.position = from;
        m_bounce.ball.velocity = glm::normalize(direction) * 12.0f;
        m_ballFlying = true;
    }

    /// Where sparks flew since the last call (for their sound).
    std::vector<glm::vec3> takeSparkBursts() {
        std::vector<glm::vec3> bursts;
        bursts.swap(m_bursts);
        return bursts;
    }

    const CourseStats& stats() const { return m_renderer->stats(); }
    /// The crowd's agent drawn highlighted (-1: none).
    void selectAgent(int agent) { m_selectedAgent = agent; }
    const CrowdSimulation* crowd() const { return m_crowd.get(); }
    /// Where agents set a foot down since the last call (for the footsteps' sound).
    std::vector<glm::vec3> takeFootsteps() {
        std::vector<glm::vec3> steps;
        steps.swap(m_footsteps);
        return steps;
    }
    double seconds() const { return m_seconds; }
    void setSeconds(double seconds) { m_seconds = seconds; }

private:
    struct FieldMesh {
        std::vector<std::unique_ptr<GpuMesh>> levels;
        BoundingSphere sphere;   // object space
    };

    void advanceBall(float seconds) {
        if (!m_ballFlying || !m_bvh) return;
        const int before = m_bounce.contacts;
        advanceSimulation(m_bounce, *m_bvh, std::min(seconds, 0.5f));   // the student's (lab 07); a stall skips ahead
        if (m_bounce.contacts > before && !m_bounce.particles.empty()) m_bursts.push_back(m_bounce.particles.back().position);
        // Fallen off the world, or resting with its sparks gone: put away.
        const bool resting = glm::length(m_bounce.ball.velocity) < 0.05f && m_bounce.particles.empty();
        if (m_bounce.ball.position.y < -30.0f || resting) m_ballFlying = false;
    }

    // The sparks: additive billboards (lab 07's particles.glsl), depth-tested
    // against the G-buffer's copy, not written.
    void drawSparks(const Framebuffer& lightBuffer) {
        if (!m_ballFlying || m_bounce.particles.empty()) return;
        std::vector<float> sparks;
        sparks.reserve(4 * m_bounce.particles.size());
        for (const Particle& spark : m_bounce.particles)
            sparks.insert(sparks.end(), {spark.position.x, spark.position.y, spark.position.z, spark.age / spark.lifetime});
        m_sparkBuffer->upload(sparks, GL_STREAM_DRAW);
        RenderState state;
        state.depth.write = false;
        state.cull = CullMode::None;
        state.blend = BlendMode::Additive;
        beginPass(passInto(lightBuffer, state));
        m_sparkProgram->use();
        m_sparkProgram->set("uHalfSize", 0.07f);
        m_sparkArray->bind();
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(m_bounce.particles.size()));
    }

    // The CPU meshes of a scene object's mesh name (for the BVH), loaded once.
    const std::vector<Mesh>& cpuMeshes(const std::string& name, const std::filesystem::path& folder) {
        auto found = m_cpuMeshes.find(name);
        if (found != m_cpuMeshes.end()) return found->second;
        std::vector<Mesh>& meshes = m_cpuMeshes[name];
        if (std::optional<Mesh> shape = EditorAssets::shapeMesh(name)) meshes.push_back(std::move(*shape));
        else if (const std::filesystem::path path = resolve(name, folder, paths::assetsDir()); !path.empty()) {
            try {
                for (ModelPart& part : loadObj(path).parts) meshes.push_back(std::move(part.mesh));
            } catch (const InputError& error) {
                m_log(std::string("the ball goes through ") + name + ": " + error.what());
            }
        }
        return meshes;
    }

    void makeRenderer() {
        const auto load = [&](const std::string& vertex, const std::string& fragment) -> const Program& {
            m_programs.push_back(std::make_unique<Program>(Program::fromFiles(vertex, fragment, m_searchPath)));
            return *m_programs.back();
        };
        m_crowdPrograms = CrowdPrograms::load(load);
        m_renderer = std::make_unique<CourseRenderer>(CoursePrograms::load(load));
        m_sparkProgram = &load("picking/sparks.vert", "picking/sparks.frag");
        m_sparkProgram->bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);
        m_sparkBuffer = std::make_unique<Buffer>(GL_ARRAY_BUFFER);
        m_sparkArray = std::make_unique<VertexArray>();
        m_sparkArray->attribute(0, *m_sparkBuffer, 4, GL_FLOAT, 4 * sizeof(float), 0);
        m_sparkArray->divisor(0, 1);
        m_ballMesh = std::make_unique<GpuMesh>(shapes::sphere(1.0f, 24, 12));
        m_ballMaterial.diffuse = m_ballMaterial.ambient = glm::vec3(0.85f, 0.3f, 0.12f);
        m_ballMaterial.specular = glm::vec3(0.6f);
    }

    std::filesystem::path resolve(const std::string& name, const std::filesystem::path& folder,
                                  const std::filesystem::path& assets) const {
        std::error_code error;
        for (const std::filesystem::path& candidate : {folder / name, assets / name})
            if (std::filesystem::is_regular_file(candidate, error)) return candidate;
        return {};
    }

    void buildFieldMeshes(const std::vector<std::string>& names, const std::filesystem::path& folder) {
        m_fieldMeshNames = names;
        m_fieldMeshes.clear();
        for (const std::string& name : names) {
            try {
                Mesh mesh;
                if (std::optional<Mesh> shape = EditorAssets::shapeMesh(name)) {
                    mesh = std::move(*shape);
                } else {
                    const std::filesystem::path path = resolve(name, folder, paths::assetsDir());
                    if (path.empty()) throw InputError(name, 0, "no such file next to the scene file or in assets/");
                    mesh = loadObj(path).parts.front().mesh;
                }
                FieldMesh field;
                try {
                    field.sphere = meshBoundingSphere(mesh);   // the student's (lab 06)
                } catch (const NotImplemented&) {
                    field.sphere = BoundingSphere{};   // radius 0: never culled, always full detail
                }
                for (const LodLevel& level : buildLevelsOfDetail(mesh, {1.0f, 0.5f, 0.25f, 0.1f}, 0.2f))
                    field.levels.push_back(std::make_unique<GpuMesh>(level.mesh));
                m_fieldMeshes.push_back(std::move(field));
            } catch (const InputError& error) {
                m_log(std::string("field: cannot use the mesh ") + name + ": " + error.what());
            }
        }
        m_placements.clear();
    }

    // Rows x rows jittered places, each with a mesh, a turn and a size; the
    // ground near the origin left to the scene's own objects.
    void appendField(const EditorField& field, const Material* material, const Texture2D* diffuse,
                     std::vector<CourseItem>& items) {
        if (m_fieldMeshes.empty()) return;
        if (m_placements.empty() || m_placedFor.rows != field.rows || m_placedFor.spacing != field.spacing ||
            m_placedFor.clearRadius != field.clearRadius || m_placedFor.seed != field.seed) {
            m_placedFor = field;
            m_placements.clear();
            HashRandom random(static_cast<std::uint32_t>(field.seed));
            const float half = 0.5f * field.spacing * static_cast<float>(field.rows - 1);
            for (int i = 0; i < field.rows; ++i)
                for (int j = 0; j < field.rows; ++j) {
                    const float jitter = 0.3f * field.spacing;
                    const glm::vec3 position(-half + field.spacing * i + random.between(-jitter, jitter), 0.0f,
                                             -half + field.spacing * j + random.between(-jitter, jitter));
                    const float yaw = random.between(0.0f, 360.0f);
                    const float size = random.between(0.8f, 1.6f);
                    const auto mesh = static_cast<std::size_t>(random.next() * m_fieldMeshes.size()) % m_fieldMeshes.size();
                    if (std::abs(position.x) < field.clearRadius && std::abs(position.z) < field.clearRadius) continue;
                    Placement placement;
                    placement.mesh = mesh;
                    placement.model = modelMatrix(position, {0.0f, yaw, 0.0f}, glm::vec3(size));
                    try {   // the student's (lab 06); a stub: radius 0, never culled
                        if (m_fieldMeshes[mesh].sphere.radius > 0.0f)
                            placement.sphere = worldBoundingSphere(m_fieldMeshes[mesh].sphere, placement.model);
                    } catch (const NotImplemented&) {
                    }
                    m_placements.push_back(placement);
                }
        }
        for (std::size_t i = 0; i < m_placements.size(); ++i) {
            const Placement& placement = m_placements[i];
            CourseItem item;
            item.id = kFirstFieldId + static_cast<std::uint32_t>(i);
            for (const std::unique_ptr<GpuMesh>& level : m_fieldMeshes[placement.mesh].levels) item.levels.push_back(level.get());
            item.model = placement.model;
            item.normalMatrix = glm::inverseTranspose(glm::mat3(placement.model));
            item.material = material;
            item.diffuseMap = diffuse;
            item.sphere = placement.sphere;
            items.push_back(item);
        }
    }

    void loadCrowd(const std::string& name, const AssetRef<CrowdWorld>* world) {
        m_crowdName = name;
        m_crowdRenderer.reset();
        m_crowd.reset();
        m_walked.clear();
        if (!world) return;   // none, or it did not load (EditorAssets logged why)
        try {
            const std::shared_ptr<const CrowdWorld> held = world->current();   // this version, however the file changes
            const CrowdWorld& loaded = *held;
            m_crowd = std::make_unique<CrowdSimulation>(loaded, loadGroundMaps(loaded.ground, loaded.file));
            m_crowd->advance(static_cast<int>(std::lround(3.0 / loaded.step)));   // three seconds: the agents on their way
            m_crowdRenderer = std::make_unique<CrowdRenderer>(m_crowdPrograms, *m_crowd);
            m_walked.assign(m_crowd->agents().size(), {glm::vec2(0.0f), 0.0f});
            for (std::size_t i = 0; i < m_walked.size(); ++i) m_walked[i].first = m_crowd->agents()[i].position;
        } catch (const InputError& error) {
            m_crowdRenderer.reset();
            m_crowd.reset();
            m_log(std::string("crowd: ") + error.what());
        }
    }

    // A footstep each stride an agent walks.
    void noteFootsteps() {
        constexpr float kStride = 1.6f;
        const std::vector<CrowdAgent>& agents = m_crowd->agents();
        m_walked.resize(agents.size(), {glm::vec2(0.0f), 0.0f});
        for (std::size_t i = 0; i < agents.size(); ++i) {
            auto& [last, distance] = m_walked[i];
            const float moved = glm::length(agents[i].position - last);
            last = agents[i].position;
            if (!agents[i].alive || moved > 2.0f) continue;   // respawned: no step
            distance += moved;
            if (distance < kStride) continue;
            distance -= kStride;
            m_footsteps.emplace_back(agents[i].position.x, agents[i].y, agents[i].position.y);
        }
    }

    // Past any scene's ids (a scene file's are at most kMaxId): every copy its own colour.
    static constexpr std::uint32_t kFirstFieldId = EditorScene::kMaxId + 1;

    struct Placement {
        std::size_t mesh = 0;
        glm::mat4 model{1.0f};
        BoundingSphere sphere;
    };

    std::vector<std::filesystem::path> m_searchPath;
    Log m_log;
    std::set<std::string> m_saidOff;   // the passes said to be switched off (CourseStats::switchedOff)
    std::vector<std::unique_ptr<Program>> m_programs;
    CrowdPrograms m_crowdPrograms;
    std::unique_ptr<CourseRenderer> m_renderer;
    std::vector<std::string> m_fieldMeshNames;
    std::vector<FieldMesh> m_fieldMeshes;
    EditorField m_placedFor;
    std::vector<Placement> m_placements;
    std::string m_crowdName;
    int m_crowdVersion = 0;     // of the world asset the crowd was made from
    std::unique_ptr<CrowdSimulation> m_crowd;
    std::unique_ptr<CrowdRenderer> m_crowdRenderer;
    std::vector<std::pair<glm::vec2, float>> m_walked;   // per agent: last position, distance since its last footstep
    std::vector<glm::vec3> m_footsteps;
    double m_crowdDebt = 0.0;
    int m_selectedAgent = -1;
    double m_seconds = 0.0;
    // Lab 07's ball and sparks.
    std::map<std::string, std::vector<Mesh>> m_cpuMeshes;
    std::optional<Bvh> m_bvh;
    Simulation m_bounce;
    bool m_ballFlying = false;
    std::vector<glm::vec3> m_bursts;
    const Program* m_sparkProgram = nullptr;
    std::unique_ptr<Buffer> m_sparkBuffer;
    std::unique_ptr<VertexArray> m_sparkArray;
    std::unique_ptr<GpuMesh> m_ballMesh;
    Material m_ballMaterial;
};

} // namespace stoa
