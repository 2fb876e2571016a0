# How the build finds its libraries, the same way on every system: each one
# through CMake's own search first (find_package with the library's CMake
# package or the module CMake ships, or find_path/find_library where a library
# ships neither), then through pkg-config. Nothing names a distribution's
# folders, so the same lines find Debian's packages, a vcpkg tree
# (CMAKE_TOOLCHAIN_FILE, CMakePresets.json) or Homebrew's (CMAKE_PREFIX_PATH).
#
# Each library becomes one target, Stoa::NAME, whichever way it was found; the
# configure step prints the way. STOA_DEPENDENCY_LOOKUP chooses:
#   AUTO          CMake's search, then pkg-config (the default)
#   FIND_PACKAGE  CMake's search only: what a vcpkg or Windows build has
#   PKG_CONFIG    pkg-config first, then CMake's search for a library with no .pc file
# A missing library stops the configure step naming the package that provides
# it on Debian, in vcpkg and in Homebrew (vcpkg.json lists the vcpkg ports).

set(STOA_DEPENDENCY_LOOKUP AUTO CACHE STRING "How to find libraries: AUTO, FIND_PACKAGE or PKG_CONFIG")
set_property(CACHE STOA_DEPENDENCY_LOOKUP PROPERTY STRINGS AUTO FIND_PACKAGE PKG_CONFIG)
if(NOT STOA_DEPENDENCY_LOOKUP MATCHES "^(AUTO|FIND_PACKAGE|PKG_CONFIG)$")
  message(FATAL_ERROR "STOA_DEPENDENCY_LOOKUP is '${STOA_DEPENDENCY_LOOKUP}'; expected AUTO, FIND_PACKAGE or PKG_CONFIG")
endif()
if(NOT STOA_DEPENDENCY_LOOKUP STREQUAL "FIND_PACKAGE")
  find_package(PkgConfig QUIET)
endif()

# The first of TARGETS that exists, in `out` (empty when none does).
function(_stoa_first_target out)
  foreach(candidate ${ARGN})
    if(TARGET ${candidate})
      set(${out} ${candidate} PARENT_SCOPE)
      return()
    endif()
  endforeach()
  set(${out} "" PARENT_SCOPE)
endfunction()

# CMake's search for one library: its package (PACKAGE, any of TARGETS), else a
# header (HEADER, under one of SUFFIXES) with, unless header-only, a library (LIBRARY).
function(_stoa_cmake_search name found)
  cmake_parse_arguments(D "" "HEADER;LIBRARY" "PACKAGE;TARGETS;SUFFIXES" ${ARGN})
  if(D_PACKAGE)
    find_package(${D_PACKAGE} QUIET)
    _stoa_first_target(target ${D_TARGETS})
    if(target)
      target_link_libraries(Stoa::${name} INTERFACE ${target})
      list(GET D_PACKAGE 0 package)
      set(${found} "find_package(${package}): ${target}" PARENT_SCOPE)
      return()
    endif()
  endif()
  if(D_HEADER)
    find_path(STOA_${name}_INCLUDE_DIR ${D_HEADER} PATH_SUFFIXES ${D_SUFFIXES})
    set(library "")
    if(D_LIBRARY)
      find_library(STOA_${name}_LIBRARY ${D_LIBRARY})
      set(library ${STOA_${name}_LIBRARY})
    endif()
    if(STOA_${name}_INCLUDE_DIR AND (NOT D_LIBRARY OR library))
      target_include_directories(Stoa::${name} SYSTEM INTERFACE ${STOA_${name}_INCLUDE_DIR})
      if(library)
        target_link_libraries(Stoa::${name} INTERFACE ${library})
      endif()
      set(${found} "find_path(${D_HEADER}) ${library}" PARENT_SCOPE)
      return()
    endif()
  endif()
  set(${found} "" PARENT_SCOPE)
endfunction()

# pkg-config's search for one library: its modules (ARGN), when pkg-config is there.
function(_stoa_pkg_config_search name found)
  set(${found} "" PARENT_SCOPE)
  if(NOT ARGN OR NOT PKG_CONFIG_FOUND)
    return()
  endif()
  pkg_check_modules(STOA_PC_${name} QUIET IMPORTED_TARGET ${ARGN})
  if(STOA_PC_${name}_FOUND)
    target_link_libraries(Stoa::${name} INTERFACE PkgConfig::STOA_PC_${name})
    set(${found} "pkg-config ${ARGN}" PARENT_SCOPE)
  endif()
endfunction()

# stoa_dependency(NAME [PACKAGE find_package-arguments...] [TARGETS ...]
#                 [HEADER file [SUFFIXES ...]] [LIBRARY name] [PKG module...]
#                 PROVIDERS "Debian: ...; vcpkg: ...; Homebrew: ...")
# Defines Stoa::NAME as the library found, the ways tried in the order above.
function(stoa_dependency name)
  cmake_parse_arguments(D "" "HEADER;LIBRARY;PROVIDERS" "PACKAGE;TARGETS;SUFFIXES;PKG" ${ARGN})
  # Imported, as find_package's targets are: a target that links it is
  # exported with the name (autograder/submission/), which the submission's
  # build defines again by including this file.
  add_library(Stoa::${name} INTERFACE IMPORTED GLOBAL)
  set(cmake_args PACKAGE ${D_PACKAGE} TARGETS ${D_TARGETS} HEADER ${D_HEADER} SUFFIXES ${D_SUFFIXES} LIBRARY ${D_LIBRARY})
  set(found "")
  if(STOA_DEPENDENCY_LOOKUP STREQUAL "PKG_CONFIG")
    _stoa_pkg_config_search(${name} found ${D_PKG})
  endif()
  if(NOT found)
    _stoa_cmake_search(${name} found ${cmake_args})
  endif()
  if(NOT found AND STOA_DEPENDENCY_LOOKUP STREQUAL "AUTO")
    _stoa_pkg_config_search(${name} found ${D_PKG})
  endif()
  if(NOT found)
    message(FATAL_ERROR "Stoa needs ${name} and did not find it (looked up as ${STOA_DEPENDENCY_LOOKUP}). "
                        "It comes from ${D_PROVIDERS}. On Debian or Ubuntu, .ci/install-deps.sh installs everything; "
                        "elsewhere it prints the commands for your system.")
  endif()
  message(STATUS "Stoa: ${name} through ${found}")
  set(STOA_${name}_FOUND_BY "${found}" PARENT_SCOPE)
endfunction()

find_package(OpenGL REQUIRED COMPONENTS OpenGL)
find_package(OpenGL QUIET COMPONENTS EGL)   # headless rendering on Linux; absent on Windows and macOS
find_package(Threads REQUIRED)

stoa_dependency(GLEW PACKAGE GLEW TARGETS GLEW::GLEW HEADER GL/glew.h LIBRARY GLEW PKG glew
                PROVIDERS "Debian: libglew-dev; vcpkg: glew; Homebrew: glew")
# CMake's FindGLUT rather than freeglut's own package: Debian's FreeGLUTConfig
# names libXxf86vm.so, which freeglut3-dev does not install.
stoa_dependency(GLUT PACKAGE GLUT TARGETS GLUT::GLUT HEADER GL/freeglut.h LIBRARY glut PKG glut
                PROVIDERS "Debian: freeglut3-dev; vcpkg: freeglut; Homebrew: freeglut")
# stb: headers, and on Debian a library with the implementations (libstb); where
# there is none (vcpkg, Homebrew) StbImplementation.cpp compiles them.
stoa_dependency(STB HEADER stb_image.h SUFFIXES stb PKG stb
                PROVIDERS "Debian: libstb-dev; vcpkg: stb; Homebrew: stb (or the headers on the include path)")
find_library(STOA_STB_LIBRARY stb)
set(stoa_stb_headers_only OFF)
if(STOA_STB_FOUND_BY MATCHES "^pkg-config")
  # pkg-config's stb.pc links the library already.
elseif(STOA_STB_LIBRARY)
  target_link_libraries(Stoa::STB INTERFACE ${STOA_STB_LIBRARY})
else()
  set(stoa_stb_headers_only ON)
endif()
option(STOA_STB_FROM_HEADERS "Compile stb's code into stoa_core (on where no stb library is found)" ${stoa_stb_headers_only})
# Dear ImGui with its GLUT and OpenGL 3 backends (framework/src/app/ImGuiLayer.cpp).
stoa_dependency(IMGUI PACKAGE imgui TARGETS imgui::imgui HEADER imgui.h SUFFIXES imgui LIBRARY imgui PKG imgui
                PROVIDERS "Debian: libimgui-dev; vcpkg: imgui[glut-binding,opengl3-binding]")
# OpenAL Soft plays positional sound (audio/SoundDevice.cpp; stb_vorbis decodes the clips).
stoa_dependency(OPENAL PACKAGE OpenAL TARGETS OpenAL::OpenAL HEADER AL/al.h LIBRARY openal PKG openal
                PROVIDERS "Debian: libopenal-dev; vcpkg: openal-soft; Homebrew: openal-soft")
# libvorbis's encoder writes the generated sounds (assets/generator/Sounds.cpp).
stoa_dependency(VORBISENC PACKAGE Vorbis TARGETS Vorbis::vorbisenc HEADER vorbis/vorbisenc.h LIBRARY vorbisenc PKG vorbisenc
                PROVIDERS "Debian: libvorbis-dev; vcpkg: libvorbis; Homebrew: libvorbis")
stoa_dependency(VORBIS PACKAGE Vorbis TARGETS Vorbis::vorbis HEADER vorbis/codec.h LIBRARY vorbis PKG vorbis
                PROVIDERS "Debian: libvorbis-dev; vcpkg: libvorbis; Homebrew: libvorbis")
stoa_dependency(OGG PACKAGE Ogg TARGETS Ogg::ogg HEADER ogg/ogg.h LIBRARY ogg PKG ogg
                PROVIDERS "Debian: libogg-dev; vcpkg: libogg; Homebrew: libogg")
stoa_dependency(TINYOBJLOADER PACKAGE tinyobjloader TARGETS tinyobjloader::tinyobjloader PKG tinyobjloader
                PROVIDERS "Debian: libtinyobjloader-dev; vcpkg: tinyobjloader; Homebrew: tinyobjloader")
# meshoptimizer's simplifier makes lab 06's levels of detail (geometry/LevelOfDetail.cpp).
stoa_dependency(MESHOPTIMIZER PACKAGE meshoptimizer TARGETS meshoptimizer::meshoptimizer
                HEADER meshoptimizer.h LIBRARY meshoptimizer
                PROVIDERS "Debian: libmeshoptimizer-dev; vcpkg: meshoptimizer; Homebrew: meshoptimizer")
# pugixml reads lab 10's crowd worlds (crowd/CrowdXml.cpp).
stoa_dependency(PUGIXML PACKAGE pugixml TARGETS pugixml::pugixml pugixml::static pugixml PKG pugixml
                PROVIDERS "Debian: libpugixml-dev; vcpkg: pugixml; Homebrew: pugixml")
# nlohmann-json (header only) reads and writes the editor's scene files (editor/EditorSceneFile.cpp).
stoa_dependency(NLOHMANN_JSON PACKAGE nlohmann_json 3 TARGETS nlohmann_json::nlohmann_json
                HEADER nlohmann/json.hpp PKG nlohmann_json
                PROVIDERS "Debian: nlohmann-json3-dev; vcpkg: nlohmann-json; Homebrew: nlohmann-json")
stoa_dependency(GLM PACKAGE glm TARGETS glm::glm HEADER glm/glm.hpp PKG glm
                PROVIDERS "Debian: libglm-dev; vcpkg: glm; Homebrew: glm")

# OSMesa is loaded at run time (dlopen, framework/src/app/HeadlessContext.cpp), so
# one binary runs on machines with and without it (Mesa 25.1 dropped OSMesa).

if(STOA_BUILD_TESTS)
  find_package(Catch2 QUIET)
  if(NOT Catch2_FOUND)
    message(FATAL_ERROR "The tests need Catch2 (Debian: catch2; vcpkg: catch2; Homebrew: catch2). "
                        "Run .ci/install-deps.sh, or configure with -DSTOA_BUILD_TESTS=OFF.")
  endif()
endif()
