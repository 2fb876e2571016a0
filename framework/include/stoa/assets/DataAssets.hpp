#pragma once
// The asset kinds that need no OpenGL (stoa_core): MD2 models and crowd
// worlds. GlAssets.hpp has textures, programs and OBJ models.
//
//   AssetCache cache(paths::assetsDir());
//   addDataAssetLoaders(cache);
//   AssetRef<CrowdWorld> world = cache.get<CrowdWorld>("crowds/mars_explorers.xml");

#include <stoa/assets/AssetCache.hpp>
#include <stoa/crowd/CrowdWorld.hpp>
#include <stoa/geometry/Md2Model.hpp>

namespace stoa {

/// loadMd2(path); its one file.
AssetLoader<Md2Model> md2Loader();

/// loadCrowdWorld(path); its files are the world file, every file it
/// includes, and the ground maps it names (so that repainting a collision map
/// makes a new version of the world, and a program can rebuild its ground).
/// Models and skins are assets of their own (Md2Model, Texture2D).
AssetLoader<CrowdWorld> crowdWorldLoader();

/// Sets both loaders on `cache`.
void addDataAssetLoaders(AssetCache& cache);

} // namespace stoa
