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

    /// The mesh is shared: many objects may draw the same GpuMesh.
    explicit MeshObject(std::shared_ptr<const GpuMesh> mesh, Material material = {});

    Material material;

    /// Sets uModel, uNormalMatrix, uMaterial.{ambient,diffuse,specular,shininess},
    /// and for the maps:
    ///   uHasDiffuseMap  (bool)  material.diffuseMap is set;
    ///   uDiffuseMap     (int)   kDiffuseMapUnit, where that texture is bound;
    ///   uHasSpecularMap (bool)  material.specularMap is set;
    ///   uSpecularMap    (int)   kSpecularMapUnit, where that texture is bound;
    /// then draws. Textures are loaded through TextureCache::shared() at the
    /// first draw (and again when the material's path changes), so the
    /// objects that share a file share its texture. A shader that declares
    /// none of these uniforms is unaffected: unknown names are ignored, and
    /// nothing is bound for a material without maps. Throws InputError naming
    /// the image when a map is missing or does not decode.
    void draw(const Program& program) const override;

private:
    /// A texture and the path it was loaded from.
    struct BoundMap {
        std::string path;
        std::shared_ptr<const Texture2D> texture;
    };
    /// Loads `path` into `map` unless it holds that file already; empty path: no map.
    static void refreshMap(const std::string& path, BoundMap& map);
    static void bindMap(const Program& program, const BoundMap& map, int unit, const char* sampler,
                        const char* flag);

    std::shared_ptr<const GpuMesh> m_mesh;
    mutable BoundMap m_diffuseMap;   // loaded at the first draw that needs it
    mutable BoundMap m_specularMap;
};

} // namespace stoa
