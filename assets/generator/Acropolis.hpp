#pragma once
// The whole Acropolis asset set: what stoa-generate-assets writes, and what the
// tests regenerate to compare with the committed files in assets/acropolis/.

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::assets {

/// The committed statue's resolution: 2 * 200 * 100 = 40000 triangles.
constexpr int kStatueSlices = 200;
constexpr int kStatueRings = 100;

/// The files generateAcropolis() writes, by name, in the order it writes them.
const std::vector<std::string>& acropolisFileNames();

/// Writes every file of acropolisFileNames() into `folder` (created if needed).
/// Throws InputError naming the folder or file that cannot be created or written.
void generateAcropolis(const std::filesystem::path& folder);

/// Writes only `folder`/statue_dense.obj: the statue with about `triangles`
/// triangles (exactly 4 r^2 for r = round(sqrt(triangles / 4)), at least 4 * 2^2).
/// Returns its path. For benchmarks; not committed.
std::filesystem::path generateDenseStatue(const std::filesystem::path& folder, int triangles);

} // namespace stoa::assets
