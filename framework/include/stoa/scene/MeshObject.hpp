#pragma once
// An Object drawn as a triangle mesh with a Blinn-Phong material, and the
// material's diffuse and specular maps when it names them.

#include <stoa/geometry/Material.hpp>
#include <stoa/scene/Object.hpp>

#include <memory>
#include <string>

namespace stoa {

class GpuMesh;
class Texture2D;

class MeshObject : public Object {
public:
    /// Texture units the maps are bound to; units from kFirstFreeTextureUnit
    /// on are left to the lab (normal maps, shadow maps, ...).
    static constexpr int kDiffuseMapUnit = 0;
    static constexpr int kSpecularMapUnit = 1;
    static constexpr int kFirstFreeTextureUnit = 2;

    /// The mesh is shared: many objects may draw the same GpuMesh. The
    /// material's maps are loaded here, through TextureCache::shared() (the
    /// objects that share a file share its texture): needs a current context,
    /// and throws InputError naming the image when a map is missing or does
    /// not decode.
    explicit MeshObject(std::shared_ptr<const GpuMesh> mesh, Material material = {});

    /// The coefficients may change at any time; after changing a map's path,
    /// call resolveMaps() (drawing asserts that the maps match the paths).
    Material material;
    /// Loads the maps `material` names now (those it loaded already are kept).
    void resolveMaps();

    const GpuMesh& mesh() const { return *m_mesh; }
    /// The mesh's bounds (object space).
    std::optional<Bounds> localBounds() const override;
    /// One item: the mesh, the matrices, the material and its maps. The
    /// uniforms it sets (ObjectUniforms): uModel, uNormalMatrix,
    /// uMaterial.{ambient,diffuse,specular,shininess}, and for the maps
    ///   uHasDiffuseMap  (bool)  material.diffuseMap is set;
    ///   uDiffuseMap     (int)   kDiffuseMapUnit, where that texture is bound;
    ///   uHasSpecularMap (bool)  material.specularMap is set;
    ///   uSpecularMap    (int)   kSpecularMapUnit, where that texture is bound.
    /// A shader that declares none of these uniforms is unaffected.
    void addDraws(DrawList& list) const override;

private:
    /// A texture and the path it was loaded from.
    struct ResolvedMap {
        std::string path;
        std::shared_ptr<const Texture2D> texture;
    };
    /// Loads `path` into `map` unless it holds that file already; empty path: no map.
    static void resolve(const std::string& path, ResolvedMap& map);

    std::shared_ptr<const GpuMesh> m_mesh;
    ResolvedMap m_diffuseMap;
    ResolvedMap m_specularMap;
};

} // namespace stoa
