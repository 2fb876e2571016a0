#include <stoa/render/CrowdRenderer.hpp>

#include <stoa/core/InputError.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/crowd/GroundMaps.hpp>
#include <stoa/geometry/DebugLines.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/scene/AcropolisScene.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

namespace {

constexpr int kTextureUnit = 0;
constexpr int kShadowUnit = 5;
constexpr int kFramesUnit = 6;
constexpr int kShadowMapSize = 2048;

/// Per agent type, a colour for its trail and markers (linear RGB).
glm::vec3 typeColour(std::size_t type) {
    static const glm::vec3 colours[] = {{0.15f, 0.45f, 1.0f}, {1.0f, 0.25f, 0.15f}, {0.2f, 0.85f, 0.3f},
                                        {0.95f, 0.8f, 0.1f},  {0.8f, 0.3f, 0.9f},   {0.1f, 0.85f, 0.85f}};
    return colours[type % (sizeof(colours) / sizeof(colours[0]))];
}

/// The model matrix of an agent: stand at (x, y, z), turned to its heading (0 faces +z), scaled.
glm::mat4 agentMatrix(const CrowdAgent& agent, float scale) {
    glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(agent.position.x, agent.y, agent.position.y));
    model = glm::rotate(model, agent.heading, glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::scale(model, glm::vec3(scale));
}

} // namespace

CrowdPrograms CrowdPrograms::load(const Loader& load) {
    CrowdPrograms programs;
    programs.scenery = &load("crowd/static.vert", "crowd/lit.frag");
    programs.agents = &load("crowd/md2.vert", "crowd/lit.frag");
    programs.sceneryDepth = &load("crowd/static.vert", "crowd/depth.frag");
    programs.agentsDepth = &load("crowd/md2.vert", "crowd/depth.frag");
    programs.markers = &load("instanced/instanced.vert", "instanced/instanced.frag");
    programs.lines = &load("debug/lines.vert", "debug/lines.frag");
    for (const Program* program : {programs.scenery, programs.agents, programs.sceneryDepth, programs.agentsDepth,
                                   programs.markers})
        program->bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);
    return programs;
}

CrowdView CrowdView::topDown(const GroundGrid& footprint, float aspect) {
    const glm::vec2 centre = 0.5f * (footprint.footprintMin + footprint.footprintMax);
    const glm::vec2 half = 0.5f * (footprint.footprintMax - footprint.footprintMin);
    // Fit the footprint: half-height covers z, and x once stretched by the aspect.
    const float halfHeight = std::max(half.y, half.x / aspect) * 1.02f;
    CrowdView view;
    view.eye = glm::vec3(centre.x, 60.0f, centre.y);
    view.view = glm::lookAt(view.eye, glm::vec3(centre.x, 0.0f, centre.y), glm::vec3(0.0f, 0.0f, -1.0f));
    view.projection = glm::ortho(-halfHeight * aspect, halfHeight * aspect, -halfHeight, halfHeight, 1.0f, 120.0f);
    return view;
}

std::unique_ptr<Md2GpuModel> uploadMd2(const std::filesystem::path& modelPath, const std::filesystem::path& skinPath,
                                       float scale) {
    auto gpu = std::make_unique<Md2GpuModel>();
    gpu->model = loadMd2(modelPath);
    gpu->scale = scale;
    const Md2Model& model = gpu->model;
    Mesh corners;
    for (const Md2Triangle& triangle : model.triangles) {
        for (int k = 0; k < 3; ++k) {
            Vertex vertex;
            vertex.position = glm::vec3(static_cast<float>(triangle.vertex[static_cast<std::size_t>(k)]), 0.0f, 0.0f);
            vertex.normal = glm::vec3(0.0f, 1.0f, 0.0f);
            vertex.uv = model.texCoords[triangle.texCoord[static_cast<std::size_t>(k)]];
            corners.indices.push_back(static_cast<std::uint32_t>(corners.vertices.size()));
            corners.vertices.push_back(vertex);
        }
    }
    gpu->corners = std::make_unique<InstancedMesh>(corners);
    std::vector<glm::vec4> texels;
    texels.reserve(model.frames.size() * model.vertexCount() * 2);
    for (const Md2Frame& frame : model.frames) {
        for (std::size_t v = 0; v < frame.positions.size(); ++v) {
            texels.emplace_back(frame.positions[v], 1.0f);
            texels.emplace_back(frame.normals[v], 0.0f);
        }
    }
    gpu->frames = BufferTexture(GL_RGBA32F);
    gpu->frames.upload(texels);
    gpu->skin = Texture2D::fromFile(skinPath);
    return gpu;
}

Mesh md2PoseMesh(const Md2Model& model, const Md2FramePair& frames, const CrowdFunctions& code) {
    STOA_ASSERT(frames.first >= 0 && frames.second >= 0 && frames.first < static_cast<int>(model.frames.size()) &&
                    frames.second < static_cast<int>(model.frames.size()),
                "md2PoseMesh(): a frame index is outside the model's frames");
    std::vector<glm::vec3> positions, normals;
    code.blendMd2Frames(model.frames[static_cast<std::size_t>(frames.first)],
                        model.frames[static_cast<std::size_t>(frames.second)], frames.t, positions, normals);
    Mesh mesh;
    for (const Md2Triangle& triangle : model.triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::size_t v = triangle.vertex[static_cast<std::size_t>(k)];
            Vertex vertex;
            vertex.position = v < positions.size() ? positions[v] : glm::vec3(0.0f);
            vertex.normal = v < normals.size() ? normals[v] : glm::vec3(0.0f, 1.0f, 0.0f);
            vertex.uv = model.texCoords[triangle.texCoord[static_cast<std::size_t>(k)]];
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
            mesh.vertices.push_back(vertex);
        }
    }
    return mesh;
}

CrowdRenderer::CrowdRenderer(const CrowdPrograms& programs, const CrowdSimulation& simulation)
    : m_programs(programs), m_lines(*programs.lines) {
    const CrowdWorld& world = simulation.world();
    for (const AgentType& type : world.types) {
        try {
            m_models.push_back(uploadMd2(type.model, type.skin, type.scale));
        } catch (const InputError& error) {   // the model's or skin's own message, after the line that named it
            throw InputError(type.file.string(), type.line, "the type '" + type.name + "' cannot be drawn: " + error.what());
        }
    }
    const GroundGrid& grid = simulation.maps().collision.grid;
    m_sceneMin = glm::vec3(grid.footprintMin.x, world.ground.heightMin, grid.footprintMin.y);
    m_sceneMax = glm::vec3(grid.footprintMax.x, std::max(world.ground.heightMax, world.ground.heightMin) + 3.0f,
                           grid.footprintMax.y);
    if (world.ground.scenery == "acropolis") {
        m_acropolis = std::make_unique<PieceDrawList>(acropolisPieces());
        m_sceneMax.y = std::max(m_sceneMax.y, 8.0f);
        for (const DrawItem& item : m_acropolis->items()) {
            glm::vec3 colour = item.material ? item.material->diffuse : glm::vec3(0.8f);
            if (item.material && !item.material->diffuseMap.empty()) {
                const Image texture = Image::load(item.material->diffuseMap, 3);
                glm::dvec3 sum(0.0);
                for (int y = 0; y < texture.height(); ++y)
                    for (int x = 0; x < texture.width(); ++x) sum += glm::dvec3(glm::vec3(texture.pixel(x, y)));
                // The mean of the texture's values, in the linear units the shader multiplies by.
                colour *= glm::vec3(sum / (255.0 * texture.width() * texture.height()));
            }
            m_flatColours.push_back(colour);
        }
    } else {
        m_terrain = std::make_unique<GpuMesh>(terrainMesh(simulation.maps().heights));
        m_terrainMaterial.diffuse = world.ground.scenery == "terrain" ? glm::vec3(0.62f, 0.45f, 0.3f) : glm::vec3(0.55f);
    }
    m_sampleMesh = std::make_unique<InstancedMesh>(shapes::cube(0.3f));
    m_crumbMesh = std::make_unique<InstancedMesh>(shapes::cylinder(0.12f, 0.04f, 8));
    m_baseMesh = std::make_unique<InstancedMesh>(shapes::cylinder(1.0f, 0.06f, 48));
    FramebufferOptions options;
    options.color = false;
    options.depthTexture = true;
    m_shadowMap = Framebuffer(kShadowMapSize, kShadowMapSize, options);
}

CrowdRenderer::~CrowdRenderer() = default;

FrameBlock CrowdRenderer::frameBlock(const CrowdView& view, const CrowdDrawOptions& options) {
    FrameBlock block{};
    block.view = view.view;
    block.projection = view.projection;
    block.cameraPosition = view.eye;
    block.ambient = options.ambient;
    block.directionalLightCount = 1;
    block.directionalLights[0].direction = glm::normalize(options.sunDirection);
    block.directionalLights[0].color = options.sunColor;
    return block;
}

void CrowdRenderer::drawScenery(const Program& program, bool depthOnly, bool flat) {
    program.use();
    program.set("uLightSpace", m_lightSpace);
    if (m_terrain) {
        program.set("uModel", glm::mat4(1.0f));
        program.set("uNormalMatrix", glm::mat3(1.0f));
        if (!depthOnly) {
            program.set("uDiffuse", m_terrainMaterial.diffuse);
            program.set("uHasTexture", false);
        }
        m_terrain->draw();
    }
    if (m_acropolis) {
        for (std::size_t i = 0; i < m_acropolis->items().size(); ++i) {
            const DrawItem& item = m_acropolis->items()[i];
            program.set("uModel", item.model);
            program.set("uNormalMatrix", item.normalMatrix);
            if (!depthOnly && flat) {
                program.set("uDiffuse", m_flatColours[i]);
                program.set("uHasTexture", false);
            } else if (!depthOnly) {
                program.set("uDiffuse", item.material ? item.material->diffuse : glm::vec3(0.8f));
                program.set("uHasTexture", item.diffuseMap != nullptr);
                if (item.diffuseMap) item.diffuseMap->bind(kTextureUnit);
                program.set("uTexture", kTextureUnit);
            }
            item.mesh->draw();
        }
    }
}

void CrowdRenderer::uploadAgents(const CrowdSimulation& simulation, const CrowdDrawOptions& options) {
    const CrowdFunctions& code = simulation.code();
    const std::vector<CrowdAgent>& agents = simulation.agents();
    std::vector<Instance> instances;
    for (std::size_t type = 0; type < m_models.size(); ++type) {
        Md2GpuModel& gpu = *m_models[type];
        instances.clear();
        for (std::size_t i = 0; i < agents.size(); ++i) {
            const CrowdAgent& agent = agents[i];
            if (!agent.alive || agent.type != static_cast<int>(type)) continue;
            const Md2Animation* animation = gpu.model.findAnimation(simulation.animationName(agent.animation));
            if (!animation) animation = &gpu.model.animations.front();
            const Md2FramePair frames = code.md2FramesAt(*animation, agent.animationTime, options.framesPerSecond);
            const int frameCount = static_cast<int>(gpu.model.frames.size());
            if (frames.first < 0 || frames.first >= frameCount || frames.second < 0 || frames.second >= frameCount) {
                throw std::out_of_range("md2FramesAt() returned frames " + std::to_string(frames.first) + " and " +
                                        std::to_string(frames.second) + " for animation '" + animation->name +
                                        "', whose frames are " + std::to_string(animation->first) + ".." +
                                        std::to_string(animation->first + animation->count - 1));
            }
            Instance instance;
            instance.model = agentMatrix(agent, gpu.scale);
            instance.color = glm::vec4(static_cast<float>(frames.first), static_cast<float>(frames.second), frames.t,
                                       static_cast<int>(i) == options.selected ? 1.0f : 0.0f);
            instances.push_back(instance);
        }
        gpu.corners->setInstances(instances);
    }
}

void CrowdRenderer::drawAgents(const Program& program) {
    program.use();
    program.set("uLightSpace", m_lightSpace);
    program.set("uFrames", kFramesUnit);
    program.set("uDiffuse", glm::vec3(1.0f));
    program.set("uHasTexture", true);
    program.set("uTexture", kTextureUnit);
    for (const std::unique_ptr<Md2GpuModel>& gpu : m_models) {
        program.set("uVertexCount", static_cast<int>(gpu->model.vertexCount()));
        gpu->frames.bind(kFramesUnit);
        gpu->skin.bind(kTextureUnit);
        gpu->corners->draw();
    }
}

void CrowdRenderer::drawAgentsWith(const CrowdSimulation& simulation, const Program& program,
                                   const CrowdDrawOptions& options) {
    uploadAgents(simulation, options);
    drawAgents(program);
}

void CrowdRenderer::renderShadowMap(const CrowdDrawOptions& options) {
    // An orthographic box around the footprint, seen from the sun.
    const glm::vec3 centre = 0.5f * (m_sceneMin + m_sceneMax);
    const float radius = 0.5f * glm::length(m_sceneMax - m_sceneMin);
    const glm::vec3 direction = glm::normalize(options.sunDirection);
    const glm::vec3 up = std::fabs(direction.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    CrowdView sun;
    sun.eye = centre - direction * (radius + 1.0f);
    sun.view = glm::lookAt(sun.eye, centre, up);
    sun.projection = glm::ortho(-radius, radius, -radius, radius, 0.5f, 2.0f * radius + 2.0f);
    const glm::mat4 toUnit = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    m_lightSpace = toUnit * sun.projection * sun.view;
    m_frame.update(frameBlock(sun, options));
    m_frame.bind();
    const GLuint previous = StateCache::current().drawFramebuffer();
    PassDescription pass = passInto(m_shadowMap);
    pass.clear.depth = true;
    pass.state.cull = CullMode::None;
    beginPass(pass);
    drawScenery(*m_programs.sceneryDepth, true);
    drawAgents(*m_programs.agentsDepth);
    StateCache::current().bindFramebuffer(previous);
}

void CrowdRenderer::drawMarkers(const CrowdSimulation& simulation, const CrowdView& view,
                                const CrowdDrawOptions& options) {
    const CrowdWorld& world = simulation.world();
    const HeightField& heights = simulation.maps().heights;
    const auto groundAt = [&](glm::vec2 xz) { return simulation.code().heightAt(heights, xz); };
    std::vector<Instance> instances;
    m_programs.markers->use();
    // One instanced draw of `mesh` at each point, `lift` metres above the ground.
    const auto drawAt = [&](const std::vector<glm::vec2>& points, float lift, const glm::vec4& colour,
                            InstancedMesh& mesh) {
        instances.clear();
        for (const glm::vec2& point : points) {
            Instance instance;
            instance.model = glm::translate(glm::mat4(1.0f), glm::vec3(point.x, groundAt(point) + lift, point.y));
            instance.color = colour;
            instances.push_back(instance);
        }
        mesh.setInstances(instances);
        mesh.draw();
    };
    drawAt(simulation.samples(), 0.15f, glm::vec4(1.0f, 0.55f, 0.1f, 1.0f), *m_sampleMesh);
    drawAt(simulation.crumbs(), 0.03f, glm::vec4(0.95f, 0.95f, 0.9f, 1.0f), *m_crumbMesh);
    instances.clear();
    for (const Base& base : world.bases) {
        Instance instance;
        instance.model = glm::scale(
            glm::translate(glm::mat4(1.0f), glm::vec3(base.position.x, groundAt(base.position) + 0.03f, base.position.y)),
            glm::vec3(base.radius, 1.0f, base.radius));
        instance.color = glm::vec4(0.3f, 0.3f, 0.35f, 1.0f);
        instances.push_back(instance);
    }
    m_baseMesh->setInstances(instances);
    m_baseMesh->draw();
    if (!options.trails) return;
    DebugLines lines;
    for (std::size_t i = 0; i < simulation.agents().size(); ++i) {
        const std::vector<glm::vec2> trail = simulation.trail(i);
        const glm::vec3 colour = typeColour(static_cast<std::size_t>(simulation.agents()[i].type));
        for (std::size_t k = 1; k < trail.size(); ++k) {
            const glm::vec2 a = trail[k - 1], b = trail[k];
            lines.line({a.x, groundAt(a) + 0.05f, a.y}, {b.x, groundAt(b) + 0.05f, b.y}, colour);
        }
    }
    m_lines.draw(lines, view.projection * view.view);
}

void CrowdRenderer::render(const CrowdSimulation& simulation, const CrowdView& view, glm::ivec2 size,
                           const CrowdDrawOptions& options) {
    uploadAgents(simulation, options);   // once for both passes
    if (options.shadows) renderShadowMap(options);
    m_frame.update(frameBlock(view, options));
    m_frame.bind();
    PassDescription pass = passInto(size);
    pass.clear.color = true;
    pass.clear.colorValue = glm::vec4(options.sky, 1.0f);
    pass.clear.depth = true;
    pass.state.cull = CullMode::None;   // the MD2 characters and the terrain are seen from any side
    beginPass(pass);
    m_shadowMap.bindDepthTexture(kShadowUnit);
    for (const Program* program : {m_programs.scenery, m_programs.agents}) {
        program->use();
        program->set("uShadows", options.shadows);
        program->set("uShadowMap", kShadowUnit);
        program->set("uShadowBias", 0.0015f);
    }
    drawScenery(*m_programs.scenery, false, options.flatScenery);
    drawAgents(*m_programs.agents);
    if (options.markers) drawMarkers(simulation, view, options);
}

} // namespace stoa
