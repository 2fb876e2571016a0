# Every dependency comes from the distribution's packages (see .ci/install-deps.sh).
# A missing one stops the configure step with the package that provides it.

find_package(PkgConfig REQUIRED)
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
find_package(Threads REQUIRED)

function(stoa_require_pkg target module package)
  pkg_check_modules(${target} IMPORTED_TARGET ${module})
  if(NOT ${target}_FOUND)
    message(FATAL_ERROR "Stoa needs ${module} (Debian package: ${package}). "
                        "Run .ci/install-deps.sh, or install it by hand.")
  endif()
endfunction()

stoa_require_pkg(GLEW glew libglew-dev)
stoa_require_pkg(GLUT glut freeglut3-dev)
stoa_require_pkg(STB stb libstb-dev)
# Dear ImGui with its GLUT and OpenGL 3 backends, built into Debian's static
# libimgui.a: the window's UI panel (F1; framework/src/app/ImGuiLayer.cpp).
stoa_require_pkg(IMGUI imgui libimgui-dev)
# OpenAL Soft plays positional sound (audio/SoundDevice.cpp; stb_vorbis, in libstb,
# decodes the clips). libvorbis's encoder writes the generated sounds (assets/generator/Sounds.cpp).
stoa_require_pkg(OPENAL openal libopenal-dev)
stoa_require_pkg(VORBISENC vorbisenc libvorbis-dev)
stoa_require_pkg(VORBIS vorbis libvorbis-dev)
stoa_require_pkg(OGG ogg libogg-dev)

find_package(tinyobjloader CONFIG QUIET)
if(NOT tinyobjloader_FOUND)
  message(FATAL_ERROR "Stoa needs tinyobjloader (Debian package: libtinyobjloader-dev). Run .ci/install-deps.sh.")
endif()

# meshoptimizer's simplifier makes lab 06's levels of detail (geometry/LevelOfDetail.cpp).
find_package(meshoptimizer CONFIG QUIET)
if(NOT meshoptimizer_FOUND)
  message(FATAL_ERROR "Stoa needs meshoptimizer (Debian package: libmeshoptimizer-dev). Run .ci/install-deps.sh.")
endif()

# pugixml reads lab 10's crowd worlds (crowd/CrowdXml.cpp).
find_package(pugixml CONFIG QUIET)
if(NOT pugixml_FOUND)
  message(FATAL_ERROR "Stoa needs pugixml (Debian package: libpugixml-dev). Run .ci/install-deps.sh.")
endif()

# nlohmann-json (header only) reads and writes the editor's scene files (editor/EditorSceneFile.cpp).
find_package(nlohmann_json 3 CONFIG QUIET)
if(NOT nlohmann_json_FOUND)
  message(FATAL_ERROR "Stoa needs nlohmann-json 3 (Debian package: nlohmann-json3-dev). Run .ci/install-deps.sh.")
endif()

find_path(GLM_INCLUDE_DIR glm/glm.hpp)
if(NOT GLM_INCLUDE_DIR)
  message(FATAL_ERROR "Stoa needs GLM (Debian package: libglm-dev). Run .ci/install-deps.sh.")
endif()

# OSMesa is loaded at run time (dlopen, framework/src/app/HeadlessContext.cpp), so
# one binary runs on machines with and without it (Mesa 25.1 dropped OSMesa).

if(STOA_BUILD_TESTS)
  find_package(Catch2 QUIET)
  if(NOT Catch2_FOUND)
    message(FATAL_ERROR "The tests need Catch2 (Debian package: catch2). "
                        "Run .ci/install-deps.sh, or configure with -DSTOA_BUILD_TESTS=OFF.")
  endif()
endif()
