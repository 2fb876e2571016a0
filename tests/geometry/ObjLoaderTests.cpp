#include "catch.hpp"
#include "MeshChecks.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/geometry/ObjLoader.hpp>

#include <fstream>
#include <random>

using namespace stoa;
using stoa::test::near;
namespace fs = std::filesystem;

namespace {

const fs::path dataDir = fs::path(STOA_TEST_DATA_DIR) / "geometry";

/// A folder under the system's temporary directory, removed with its
/// contents when the object goes away. Bad-input files are written here, so
/// their text (and line numbers) sit next to the test that checks them.
class TemporaryFolder {
public:
    TemporaryFolder() {
        std::random_device random;
        m_path = fs::temp_directory_path() / ("stoa-geometry-tests-" + std::to_string(random()));
        fs::create_directories(m_path);
    }
    ~TemporaryFolder() {
        std::error_code ignored;
        fs::remove_all(m_path, ignored);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;

    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path path = m_path / name;
        fs::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }
    const fs::path& path() const { return m_path; }

private:
    fs::path m_path;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// Loads `path`, expecting an InputError about `file` at `line`, and returns its message.
std::string loadError(const fs::path& path, const fs::path& file, int line) {
    try {
        (void)loadObj(path);
    } catch (const InputError& error) {
        const std::string what = error.what();
        INFO(what);
        CHECK(error.file() == file.string());
        CHECK(error.line() == line);
        CHECK(contains(what, file.filename().string()));
        if (line > 0) CHECK(contains(what, ":" + std::to_string(line) + ": "));
        return error.message();
    }
    FAIL("loadObj(" << path << ") did not throw an InputError");
    return "";
}

/// Checks the promises every loaded part keeps.
void checkPart(const ModelPart& part) {
    CHECK_NOTHROW(part.mesh.validate("part"));
    const std::string nonUnit = test::firstNonUnitNormal(part.mesh);
    INFO(nonUnit);
    CHECK(nonUnit.empty());
}

} // namespace

TEST_CASE("loadObj reads a cube with two materials from its MTL file", "[geometry][obj]") {
    const Model model = loadObj(dataDir / "cube.obj");
    CHECK(model.source == (dataDir / "cube.obj").string());
    REQUIRE(model.parts.size() == 2);
    CHECK(model.parts[0].material.name == "crate");  // in the order the file first uses them
    CHECK(model.parts[1].material.name == "lid");

    const ModelPart& crate = model.parts[0];
    checkPart(crate);
    CHECK(crate.mesh.vertices.size() == 5 * 4);  // each face's corners differ by normal
    CHECK(crate.mesh.triangleCount() == 5 * 2);
    const std::string againstNormals = test::firstTriangleAgainstNormals(crate.mesh);
    INFO(againstNormals);
    CHECK(againstNormals.empty());
    const auto [lower, upper] = crate.mesh.bounds();
    CHECK(near(lower, glm::vec3(-0.5f)));
    CHECK(near(upper, glm::vec3(0.5f)));

    CHECK(near(crate.material.ambient, {0.05f, 0.04f, 0.03f}));
    CHECK(near(crate.material.diffuse, {0.6f, 0.4f, 0.2f}));
    CHECK(near(crate.material.specular, {0.3f, 0.3f, 0.3f}));
    CHECK(crate.material.shininess == 64.0f);
    // Texture paths are absolute, relative to the MTL file's folder.
    CHECK(fs::path(crate.material.diffuseMap).is_absolute());
    CHECK(crate.material.diffuseMap == (dataDir / "textures" / "crate.png").lexically_normal().string());
    CHECK(crate.material.specularMap == (dataDir / "textures" / "crate_specular.png").lexically_normal().string());

    // The lid's MTL entry sets only "Kd 0.5", a grey; the rest keeps the defaults.
    const ModelPart& lid = model.parts[1];
    checkPart(lid);
    CHECK(lid.mesh.vertices.size() == 4);
    CHECK(lid.mesh.triangleCount() == 2);
    const Material defaults;
    CHECK(near(lid.material.diffuse, glm::vec3(0.5f)));
    CHECK(near(lid.material.ambient, defaults.ambient));
    CHECK(near(lid.material.specular, defaults.specular));
    CHECK(lid.material.shininess == defaults.shininess);
    CHECK(lid.material.diffuseMap.empty());
    CHECK(lid.material.specularMap.empty());
    for (const Vertex& v : lid.mesh.vertices) {
        CHECK(near(v.normal, {0, 1, 0}));
        CHECK(near(v.position.y, 0.5f));
    }

    // Both parts together enclose the unit cube, counter-clockwise from outside.
    CHECK(near(test::signedVolume(crate.mesh) + test::signedVolume(lid.mesh), 1.0f, 1e-5f));
}

TEST_CASE("loadObj splits a quad into two triangles and keeps uvs", "[geometry][obj]") {
    const Model model = loadObj(dataDir / "quad.obj");
    REQUIRE(model.parts.size() == 1);
    const ModelPart& part = model.parts[0];
    CHECK(part.material.name == "default");  // no usemtl: the default Material
    checkPart(part);
    CHECK(part.mesh.vertices.size() == 4);
    CHECK(part.mesh.triangleCount() == 2);
    const std::string againstNormals = test::firstTriangleAgainstNormals(part.mesh);
    INFO(againstNormals);
    CHECK(againstNormals.empty());
    CHECK(near(test::surfaceArea(part.mesh), 1.0f));
    for (const Vertex& v : part.mesh.vertices) {
        CHECK(near(v.uv, {v.position.x, v.position.y}));
        CHECK(near(v.normal, {0, 0, 1}));
    }
}

TEST_CASE("loadObj triangulates a concave polygon without flipping it", "[geometry][obj]") {
    TemporaryFolder folder;
    // An L-shaped hexagon in the XZ plane, counter-clockwise seen from +Y; a
    // fan from its first corner would cover the notch.
    const fs::path path = folder.write("ell.obj", "v 2 0 0\n"
                                                  "v 2 0 -1\n"
                                                  "v 1 0 -1\n"
                                                  "v 1 0 -2\n"
                                                  "v 0 0 -2\n"
                                                  "v 0 0 0\n"
                                                  "vn 0 1 0\n"
                                                  "f 1//1 2//1 3//1 4//1 5//1 6//1\n");
    const Model model = loadObj(path);
    REQUIRE(model.parts.size() == 1);
    const Mesh& mesh = model.parts[0].mesh;
    CHECK(mesh.vertices.size() == 6);
    CHECK(mesh.triangleCount() == 4);
    CHECK(near(test::surfaceArea(mesh), 3.0f));  // the L covers 3 unit squares
    const std::string againstNormals = test::firstTriangleAgainstNormals(mesh);
    INFO(againstNormals);
    CHECK(againstNormals.empty());
}

TEST_CASE("loadObj resolves negative (relative) indices", "[geometry][obj]") {
    const Model relative = loadObj(dataDir / "negative_indices.obj");

    TemporaryFolder folder;
    const fs::path absolutePath = folder.write("absolute.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                                               "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                                               "vn 0 0 1\n"
                                                               "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
                                                               "v 0 0 1\nv 1 0 1\nv 0 1 1\n"
                                                               "f 5 6 7\n");
    const Model absolute = loadObj(absolutePath);

    REQUIRE(relative.parts.size() == 1);
    REQUIRE(absolute.parts.size() == 1);
    const Mesh& mesh = relative.parts[0].mesh;
    const Mesh& expected = absolute.parts[0].mesh;
    checkPart(relative.parts[0]);
    CHECK(mesh.vertices.size() == 7);
    CHECK(mesh.triangleCount() == 3);
    REQUIRE(mesh.vertices.size() == expected.vertices.size());
    CHECK(mesh.indices == expected.indices);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        CHECK(near(mesh.vertices[i].position, expected.vertices[i].position));
        CHECK(near(mesh.vertices[i].normal, expected.vertices[i].normal));
        CHECK(near(mesh.vertices[i].uv, expected.vertices[i].uv));
    }
    // The last triangle has no normals in the file: they are computed, facing +Z.
    for (std::size_t i = 4; i < 7; ++i) CHECK(near(mesh.vertices[i].normal, {0, 0, 1}));
}

TEST_CASE("loadObj computes smooth normals when the file has none", "[geometry][obj]") {
    const Model model = loadObj(dataDir / "pyramid_no_normals.obj");
    REQUIRE(model.parts.size() == 1);
    const Mesh& mesh = model.parts[0].mesh;
    checkPart(model.parts[0]);
    CHECK(mesh.vertices.size() == 5);  // shared corners stay shared
    CHECK(mesh.triangleCount() == 4);
    const std::string againstNormals = test::firstTriangleAgainstNormals(mesh);
    INFO(againstNormals);
    CHECK(againstNormals.empty());
    for (const Vertex& v : mesh.vertices) {
        CHECK(near(v.uv, {0, 0}));  // no vt in the file
        if (near(v.position, {0, 1, 0})) {
            CHECK(near(v.normal, {0, 1, 0}));  // the apex: four equal sides cancel sideways
        } else {
            // A base corner averages its two sides, (1, 1, 0) and (0, 1, 1) for the corner (1, 0, 1).
            const glm::vec3 expected = glm::normalize(glm::vec3(v.position.x, 2.0f, v.position.z));
            CHECK(near(v.normal, expected));
        }
    }
}

TEST_CASE("loadObj smooths normals across uv seams", "[geometry][obj]") {
    TemporaryFolder folder;
    // Two triangles folded along the edge 1-2; the shared corners have
    // different uvs on each side, so they become separate vertices.
    const fs::path path = folder.write("fold.obj", "v 0 0 0\nv 0 0 -1\nv 1 0 0\nv -1 1 0\n"
                                                   "vt 0 0\nvt 1 1\n"
                                                   "f 1/1 3/1 2/1\n"
                                                   "f 1/2 2/2 4/2\n");
    const Model model = loadObj(path);
    REQUIRE(model.parts.size() == 1);
    const Mesh& mesh = model.parts[0].mesh;
    CHECK(mesh.vertices.size() == 6);
    glm::vec3 firstNormal(0.0f);
    int copies = 0;
    for (const Vertex& v : mesh.vertices) {
        if (!near(v.position, {0, 0, 0})) continue;
        if (copies++ == 0) firstNormal = v.normal;
        CHECK(near(v.normal, firstNormal));  // both copies of corner 1 share one smooth normal
    }
    CHECK(copies == 2);
    // The faces' cross products are (0, 1, 0) and (1, 1, 0).
    CHECK(near(firstNormal, glm::normalize(glm::vec3(1, 2, 0))));
}

TEST_CASE("loadObj resolves texture paths relative to the MTL file's folder", "[geometry][obj]") {
    TemporaryFolder folder;
    folder.write("materials/wood.mtl", "newmtl wood\n"
                                       "map_Kd ../textures/wood.png\n"
                                       "map_Ks maps\\wood_specular.png\n");
    folder.write("textures/wood.png", "");   // the loader checks that maps exist, never reads them
    folder.write("materials/maps/wood_specular.png", "");
    const fs::path path = folder.write("table.obj", "mtllib materials/wood.mtl\n"
                                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                    "usemtl wood\n"
                                                    "f 1 2 3\n");
    const Model model = loadObj(path);
    REQUIRE(model.parts.size() == 1);
    const Material& wood = model.parts[0].material;
    CHECK(wood.name == "wood");
    CHECK(wood.diffuseMap == (folder.path() / "textures" / "wood.png").lexically_normal().string());
    CHECK(wood.specularMap == (folder.path() / "materials" / "maps" / "wood_specular.png").lexically_normal().string());
    CHECK(near(wood.diffuse, Material().diffuse));  // no Kd: the default
}

TEST_CASE("loadObj reads files with Windows line endings", "[geometry][obj]") {
    TemporaryFolder folder;
    const fs::path path = folder.write("crlf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nvn 0 0 1\r\nf 1//1 2//1 3//1\r\n");
    const Model model = loadObj(path);
    REQUIRE(model.parts.size() == 1);
    CHECK(model.parts[0].mesh.triangleCount() == 1);
    CHECK(near(model.parts[0].mesh.vertices[1].position, {1, 0, 0}));

    const fs::path broken = folder.write("crlf_broken.obj", "v 0 0 0\r\nv 1 0 0\r\n\r\nf 1 2 3\r\n");
    const std::string message = loadError(broken, broken, 4);
    CHECK(contains(message, "vertex 3 but only 2 vertices"));
}

TEST_CASE("loadObj reads numbers too small for a float as zero", "[geometry][obj]") {
    TemporaryFolder folder;
    const fs::path path = folder.write("tiny.obj", "v 0 0 1e-999\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Model model = loadObj(path);
    REQUIRE(model.parts.size() == 1);
    CHECK(model.parts[0].mesh.vertices[0].position.z == 0.0f);
}

TEST_CASE("loadObj reports a file it cannot read", "[geometry][obj][errors]") {
    const fs::path path = dataDir / "no_such_model.obj";
    const std::string message = loadError(path, path, 0);
    CHECK(contains(message, "does not exist"));
}

TEST_CASE("loadObj reports face indices out of range with their line", "[geometry][obj][errors]") {
    TemporaryFolder folder;
    const std::string header = "# a triangle with a bad corner\n"  // line 1
                               "v 0 0 0\n"                         // line 2
                               "v 1 0 0\n"                         // line 3
                               "v 0 1 0\n"                         // line 4
                               "vt 0 0\n"                          // line 5
                               "vn 0 0 1\n"                        // line 6
                               "f 1 2 3\n";                        // line 7

    SECTION("a position index past the end") {
        const fs::path path = folder.write("bad_position.obj", header + "f 1 2 12\n");
        const std::string message = loadError(path, path, 8);
        CHECK(contains(message, "face refers to vertex 12 but only 3 vertices (v) are defined so far"));
    }
    SECTION("a position that is defined only later") {
        const fs::path path = folder.write("forward.obj", header + "f 1 2 4\nv 1 1 0\n");
        const std::string message = loadError(path, path, 8);
        CHECK(contains(message, "vertex 4 but only 3 vertices"));
    }
    SECTION("a negative index counting back too far") {
        const fs::path path = folder.write("bad_negative.obj", header + "f -1 -2 -4\n");
        const std::string message = loadError(path, path, 8);
        CHECK(contains(message, "vertex -4 (counting back) but only 3 vertices"));
    }
    SECTION("a texture coordinate index past the end") {
        const fs::path path = folder.write("bad_uv.obj", header + "f 1/1 2/1 3/2\n");
        const std::string message = loadError(path, path, 8);
        CHECK(contains(message, "texture coordinate 2 but only 1 texture coordinates (vt)"));
    }
    SECTION("a normal index past the end") {
        const fs::path path = folder.write("bad_normal.obj", header + "\n\nf 1//1 2//1 3//-2\n");
        const std::string message = loadError(path, path, 10);
        CHECK(contains(message, "normal -2 (counting back) but only 1 normals (vn)"));
    }
    SECTION("index zero") {
        const fs::path path = folder.write("zero.obj", header + "f 0 1 2\n");
        const std::string message = loadError(path, path, 8);
        CHECK(contains(message, "start at 1"));
    }
    SECTION("a face with two corners") {
        const fs::path path = folder.write("two_corners.obj", header + "f 1 2\n");
        const std::string message = loadError(path, path, 8);
        CHECK(contains(message, "at least 3 corners, found 2"));
    }
    SECTION("a malformed corner") {
        const fs::path path = folder.write("malformed.obj", header + "f 1 2 3/\n");
        const std::string message = loadError(path, path, 8);
        CHECK(contains(message, "found '3/'"));
    }
    SECTION("a comment after a face") {
        const fs::path path = folder.write("comment.obj", header + "f 1 2 3 # the same again\n");
        const std::string message = loadError(path, path, 8);
        CHECK(contains(message, "comments must be on a line of their own"));
    }
}

TEST_CASE("loadObj reports numbers that are not finite or not numbers", "[geometry][obj][errors]") {
    TemporaryFolder folder;
    SECTION("NaN in a position") {
        const fs::path path = folder.write("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
        const std::string message = loadError(path, path, 2);
        CHECK(contains(message, "'nan' is not finite"));
    }
    SECTION("infinity in a normal") {
        const fs::path path = folder.write("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -inf\nf 1//1 2//1 3//1\n");
        const std::string message = loadError(path, path, 4);
        CHECK(contains(message, "'-inf' is not finite"));
    }
    SECTION("a number too large for a float in a uv") {
        const fs::path path = folder.write("huge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 1e999 0\nf 1/1 2/1 3/1\n");
        const std::string message = loadError(path, path, 4);
        CHECK(contains(message, "'1e999' is not finite"));
    }
    SECTION("a word where a number belongs") {
        const fs::path path = folder.write("word.obj", "v 0 0 0\nv 1 0 zero\nv 0 1 0\nf 1 2 3\n");
        const std::string message = loadError(path, path, 2);
        CHECK(contains(message, "expected a number, found 'zero'"));
    }
    SECTION("a position with two numbers") {
        const fs::path path = folder.write("short.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n");
        const std::string message = loadError(path, path, 2);
        CHECK(contains(message, "needs 3 numbers (x y z), found 2"));
    }
    SECTION("NaN in the MTL file names the MTL file and its line") {
        const fs::path mtl = folder.write("paint.mtl", "newmtl red\nKd 1 0 0\n\nnewmtl broken\nKs 0.5 nan 0.5\n");
        const fs::path path = folder.write("painted.obj", "mtllib paint.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        const std::string message = loadError(path, mtl, 5);
        CHECK(contains(message, "'nan' is not finite"));
    }
    SECTION("a comment after the numbers is fine") {
        const fs::path path = folder.write("commented.obj", "v 0 0 0 # origin\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        const Model model = loadObj(path);
        CHECK(model.parts.size() == 1);
    }
}

TEST_CASE("loadObj reports missing MTL files and unknown materials", "[geometry][obj][errors]") {
    TemporaryFolder folder;
    SECTION("an mtllib file that does not exist") {
        const fs::path path = folder.write("lost.obj", "# materials are elsewhere\n"
                                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                       "mtllib lost.mtl\n"  // line 5
                                                       "usemtl paint\nf 1 2 3\n");
        const std::string message = loadError(path, path, 5);
        CHECK(contains(message, "lost.mtl"));
        CHECK(contains(message, "does not exist"));
    }
    SECTION("a usemtl that no MTL file defines") {
        folder.write("paint.mtl", "newmtl red\nKd 1 0 0\n");
        const fs::path path = folder.write("typo.obj", "mtllib paint.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                       "usemtl rde\n"  // line 5
                                                       "f 1 2 3\n");
        const std::string message = loadError(path, path, 5);
        CHECK(contains(message, "usemtl names material 'rde'"));
    }
    SECTION("a usemtl without any mtllib") {
        const fs::path path = folder.write("bare.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
        const std::string message = loadError(path, path, 4);
        CHECK(contains(message, "no mtllib line comes before it"));
    }
}

TEST_CASE("loadObj checks the indices of lines and points too, with their line", "[geometry][obj][errors]") {
    TemporaryFolder folder;
    // A polyline with index 0: not drawn, but as wrong as a face with one.
    const fs::path path = folder.write("polyline.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 0\n");
    const std::string message = loadError(path, path, 5);
    CHECK(contains(message, "vertex 0, but OBJ indices start at 1"));
}

TEST_CASE("loadObj reports a model without faces", "[geometry][obj][errors]") {
    TemporaryFolder folder;
    const fs::path path = folder.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    const std::string message = loadError(path, path, 0);
    CHECK(contains(message, "no faces"));
}
