// Issue 14: loadObj never hangs, never accepts garbage and says exactly what
// is wrong. Each case of the "Why" list, on a file generated here
// (the same inputs are in the fuzzers' regression corpus,
// tests/fuzz/make-regression-corpus.py).

#include "catch.hpp"
#include "MeshChecks.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/geometry/ObjLoader.hpp>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

using namespace stoa;
using stoa::test::near;
using stoa::test::TempFolder;
namespace fs = std::filesystem;

namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// Loads `path` expecting an InputError at `file`:`line`; returns it.
InputError errorAt(const fs::path& path, const fs::path& file, int line) {
    try {
        std::ostringstream warnings;
        (void)loadObj(path, warnings);
    } catch (const InputError& error) {
        INFO(error.what());
        CHECK(error.file() == file.string());
        CHECK(error.line() == line);
        return error;
    }
    FAIL("loadObj(" << path << ") did not throw an InputError");
    return InputError("", 0, "");
}

/// A polygon of `corners` corners around the origin in the XY plane,
/// counter-clockwise seen from +Z; every other corner pulled in when `star`.
std::string polygon(int corners, bool star) {
    std::ostringstream text;
    text.precision(9);
    for (int i = 0; i < corners; ++i) {
        const double angle = 2.0 * M_PI * i / corners;
        const double radius = star && i % 2 ? 0.5 : 1.0;
        text << "v " << radius * std::cos(angle) << ' ' << radius * std::sin(angle) << " 0\n";
    }
    text << "f";
    for (int i = 1; i <= corners; ++i) text << ' ' << i;
    text << '\n';
    return text.str();
}

} // namespace

TEST_CASE("Issue 14: a convex face of 100,000 corners loads in linear time, as a fan", "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    const fs::path path = folder.write("circle.obj", polygon(100000, false));
    const auto start = std::chrono::steady_clock::now();
    const Model model = loadObj(path);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    REQUIRE(model.parts.size() == 1);
    const Mesh& mesh = model.parts[0].mesh;
    CHECK(mesh.triangleCount() == 99998);
    CHECK(mesh.vertices.size() == 100000);
    CHECK(near(test::surfaceArea(mesh), float(M_PI), 1e-3f));
    CHECK(near(mesh.vertices[0].normal, {0, 0, 1}));
    CHECK(seconds < 10.0);  // tinyobjloader's quadratic triangulation took 30 s in a release build
}

TEST_CASE("Issue 14: a non-convex face past the corner cap is an error naming its line", "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    SECTION("100,000 corners") {
        const fs::path path = folder.write("star.obj", polygon(100000, true));
        const InputError error = errorAt(path, path, 100001);
        CHECK(contains(error.message(), "100000 corners and is not convex"));
        CHECK(contains(error.message(), "at most " + std::to_string(maxNonConvexFaceCorners)));
    }
    SECTION("a face that winds twice around its centre, every corner turning the same way") {
        std::ostringstream text;
        for (int i = 0; i < 1000; ++i) {
            const double angle = 4.0 * M_PI * i / 1000;
            text << "v " << std::cos(angle) << ' ' << std::sin(angle) << " 0\n";
        }
        text << "f";
        for (int i = 1; i <= 1000; ++i) text << ' ' << i;
        const fs::path path = folder.write("twice.obj", text.str() + "\n");
        CHECK(contains(errorAt(path, path, 1001).message(), "1000 corners and is not convex"));
    }
    SECTION("a circle of 40,000 corners written with 4 decimals is convex enough for a fan") {
        std::ostringstream text;
        text.setf(std::ios::fixed);
        text.precision(4);
        for (int i = 0; i < 40000; ++i) {
            const double angle = 2.0 * M_PI * i / 40000;
            text << "v " << std::cos(angle) << ' ' << std::sin(angle) << " 0\n";
        }
        text << "f";
        for (int i = 1; i <= 40000; ++i) text << ' ' << i;
        const Model model = loadObj(folder.write("rounded.obj", text.str() + "\n"));
        CHECK(model.parts.at(0).mesh.triangleCount() == 39998);
    }
    SECTION("a star of 64 corners is still clipped into ears") {
        const fs::path path = folder.write("star64.obj", polygon(64, true));
        const Model model = loadObj(path);
        REQUIRE(model.parts.size() == 1);
        CHECK(model.parts[0].mesh.triangleCount() == 62);
        // Area of a star with 32 outer (r = 1) and 32 inner (r = 0.5) corners.
        const float area = float(64 * 0.5 * 1.0 * 0.5 * std::sin(2 * M_PI / 64));
        CHECK(near(test::surfaceArea(model.parts[0].mesh), area, 1e-4f));
    }
}

TEST_CASE("Issue 14: FIFOs, devices and folders are refused without blocking", "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    const fs::path fifo = folder / "pipe.obj";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    SECTION("a FIFO named .obj") {
        const InputError error = errorAt(fifo, fifo, 0);
        CHECK(contains(error.message(), "FIFO"));
    }
    SECTION("a FIFO named by mtllib") {
        const fs::path path = folder.write("model.obj", "mtllib pipe.obj\n" + kTriangle + "f 1 2 3\n");
        const InputError error = errorAt(path, path, 1);
        CHECK(contains(error.message(), "mtllib names 'pipe.obj'"));
        CHECK(contains(error.message(), "FIFO"));
    }
    SECTION("/dev/zero, as the OBJ and as its mtllib") {
        if (!fs::exists("/dev/zero")) return;
        InputError error = errorAt("/dev/zero", "/dev/zero", 0);
        CHECK(contains(error.message(), "character device"));
        const fs::path path = folder.write("zero.obj", "mtllib /dev/zero\n" + kTriangle + "f 1 2 3\n");
        error = errorAt(path, path, 1);
        CHECK(contains(error.message(), "character device"));
    }
    SECTION("a folder") {
        const InputError error = errorAt(folder.path(), folder.path(), 0);
        CHECK(contains(error.message(), "this is a folder, not an OBJ file"));
    }
    SECTION("a symbolic link loop and a name too long") {
        const fs::path loop = folder / "loop.obj";
        fs::create_symlink(loop, loop);
        InputError error = errorAt(loop, loop, 0);
        CHECK(contains(error.message(), "loop of symbolic links"));
        CHECK_FALSE(contains(error.message(), "does not exist"));
        const fs::path longName = folder / (std::string(256, 'a') + ".obj");
        error = errorAt(longName, longName, 0);
        CHECK(contains(error.message(), "too long"));
    }
}

TEST_CASE("Issue 14: normals stay unit length whatever the numbers", "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    SECTION("vn 3e38 3e38 3e38") {
        const Model model = loadObj(folder.write("huge-normal.obj", kTriangle + "vn 3e38 3e38 3e38\nf 1//1 2//1 3//1\n"));
        for (const Vertex& vertex : model.parts.at(0).mesh.vertices) {
            CHECK(near(vertex.normal, glm::vec3(1.0f / std::sqrt(3.0f))));
        }
    }
    SECTION("vn 0 0 0 is recomputed from the face") {
        const Model model = loadObj(folder.write("zero-normal.obj", kTriangle + "vn 0 0 0\nf 1//1 2//1 3//1\n"));
        for (const Vertex& vertex : model.parts.at(0).mesh.vertices) CHECK(near(vertex.normal, {0, 0, 1}));
    }
    SECTION("a huge triangle without normals gets +Z, not +Y") {
        const Model model = loadObj(folder.write("huge.obj", "v -3e38 -3e38 0\nv 3e38 -3e38 0\nv 0 3e38 0\nf 1 2 3\n"));
        for (const Vertex& vertex : model.parts.at(0).mesh.vertices) CHECK(near(vertex.normal, {0, 0, 1}));
    }
    SECTION("a tiny triangle without normals gets +Z too") {
        const Model model = loadObj(folder.write("tiny.obj", "v 0 0 0\nv 1e-30 0 0\nv 0 1e-30 0\nf 1 2 3\n"));
        for (const Vertex& vertex : model.parts.at(0).mesh.vertices) CHECK(near(vertex.normal, {0, 0, 1}));
    }
}

TEST_CASE("Issue 14: a face that repeats its corners is an error, never silently dropped", "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    const fs::path path = folder.write("repeat.obj", kTriangle + "f 1 2 3\nf 1 2 3 1 2 3\n");
    const InputError error = errorAt(path, path, 5);
    CHECK(contains(error.message(), "uses vertex 1 more than once"));
}

TEST_CASE("Issue 14: material values out of range are clamped with a warning naming the line",
          "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    folder.write("m.mtl", "newmtl m\nKd 5 -3 1e30\nKa 0.1 0.1 0.1\nNs -50\n");
    const fs::path path = folder.write("m.obj", "mtllib m.mtl\n" + kTriangle + "usemtl m\nf 1 2 3\n");
    std::ostringstream warnings;
    const Model model = loadObj(path, warnings);
    const Material& material = model.parts.at(0).material;
    CHECK(near(material.diffuse, {1, 0, 1}));
    CHECK(near(material.ambient, glm::vec3(0.1f)));
    CHECK(material.shininess == 0.0f);
    const std::string mtl = (folder / "m.mtl").string();
    INFO(warnings.str());
    CHECK(contains(warnings.str(), mtl + ":2: Kd"));
    CHECK(contains(warnings.str(), "clamped to (1, 0, 1)"));
    CHECK(contains(warnings.str(), mtl + ":4: Ns -50 is negative"));
    CHECK_FALSE(contains(warnings.str(), ":3:"));  // Ka is within [0, 1]
}

TEST_CASE("Issue 14: byte-order marks, UTF-16 and line endings", "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    SECTION("a UTF-8 BOM before the first v") {
        const Model model = loadObj(folder.write("bom.obj", "\xEF\xBB\xBF" + kTriangle + "f 1 2 3\n"));
        CHECK(model.parts.at(0).mesh.vertices.size() == 3);
    }
    SECTION("CR-only line endings, with the right line numbers") {
        const Model model = loadObj(folder.write("cr.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r"));
        CHECK(model.parts.at(0).mesh.triangleCount() == 1);
        const fs::path broken = folder.write("cr-broken.obj", "v 0 0 0\rv 1 0 0\r\rf 1 2 3\r");
        CHECK(contains(errorAt(broken, broken, 4).message(), "vertex 3 but only 2 vertices"));
    }
    SECTION("UTF-16, with and without its byte-order mark") {
        std::string utf16 = "\xFF\xFE";
        for (char c : kTriangle + "f 1 2 3\n") utf16 += std::string(1, c) + '\0';
        const fs::path marked = folder.write("utf16.obj", utf16);
        CHECK(errorAt(marked, marked, 0).message() == "UTF-16 is not supported; save the file as UTF-8");
        const fs::path bare = folder.write("utf16-bare.obj", utf16.substr(2));
        CHECK(contains(errorAt(bare, bare, 0).message(), "UTF-16 is not supported"));
    }
}

TEST_CASE("Issue 14: material names with spaces are the whole rest of the line", "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    folder.write("m.mtl", "newmtl old wood\nKd 0.5 0.4 0.3\nnewmtl old\nKd 1 1 1\n");
    const Model model = loadObj(folder.write("wood.obj", "mtllib m.mtl\n" + kTriangle + "usemtl old wood\nf 1 2 3\n"));
    CHECK(model.parts.at(0).material.name == "old wood");
    CHECK(near(model.parts.at(0).material.diffuse, {0.5f, 0.4f, 0.3f}));
    const fs::path path = folder.write("missing.obj", "mtllib m.mtl\n" + kTriangle + "usemtl old oak\nf 1 2 3\n");
    CHECK(contains(errorAt(path, path, 5).message(), "usemtl names material 'old oak'"));
}

TEST_CASE("Issue 14: messages name the real cause", "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    SECTION("an index too large for any file is about its size, not its form") {
        const fs::path path = folder.write("big.obj", kTriangle + "f 1 2 99999999999\n");
        CHECK(contains(errorAt(path, path, 4).message(),
                       "face refers to vertex 99999999999 but only 3 vertices (v) are defined so far"));
        const fs::path huger = folder.write("huger.obj", kTriangle + "f 1 2 -999999999999999999999999\n");
        CHECK(contains(errorAt(huger, huger, 4).message(), "(counting back) but only 3 vertices"));
    }
    SECTION("a NUL byte does not cut what() short") {
        const fs::path path = folder.write("nul.obj", std::string("v 0 0 0\nv 1 0\0tail 0\n", 21));
        const InputError error = errorAt(path, path, 2);
        const std::string what = error.what();
        CHECK(contains(what, "\\x00tail"));
        CHECK(what.find('\0') == std::string::npos);
    }
    SECTION("control bytes and invalid UTF-8 are escaped, valid UTF-8 kept") {
        const fs::path path = folder.write("esc.obj", "v 0 0 \x1b[31m\xff\xc3\xa9\n");
        const std::string what = errorAt(path, path, 1).what();
        CHECK(contains(what, "\\x1b[31m\\xff\xc3\xa9"));
    }
    SECTION("no faces: the message counts the lines") {
        const fs::path path = folder.write("points.obj", kTriangle);
        CHECK(contains(errorAt(path, path, 0).message(), "none of its 3 lines is an f line"));
    }
}

TEST_CASE("Issue 14: an MTL file past its size cap is refused before it is read", "[geometry][obj][issue14]") {
    TempFolder folder("obj-hardening");
    const fs::path mtl = folder / "big.mtl";
    {
        std::ofstream out(mtl, std::ios::binary);
        out.seekp(static_cast<std::streamoff>(maxMtlFileBytes));  // a sparse file one byte past the cap
        out.put('\n');
    }
    const fs::path path = folder.write("big.obj", "mtllib big.mtl\n" + kTriangle + "f 1 2 3\n");
    const InputError error = errorAt(path, path, 1);
    CHECK(contains(error.message(), "too large"));
    CHECK(contains(error.message(), "16 MiB) for an MTL file"));
}
