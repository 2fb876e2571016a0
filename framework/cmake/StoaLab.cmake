# The lab mechanism.
#
# A lab is a folder labs/NN_name/ with its app (lab.cpp), its cases (cases.ini)
# and, in labs/NN_name/student/, the files a student edits and the header that
# declares them (labNN.hpp). solutions/NN_name/student/ holds the same student
# files, filled in. Every track keeps a lab's student files at
# <track root>/NN_name/student/, so a GLSL include names one ("05_shadows/student/
# shadows.glsl") the same way from every track. A "track" says where the student
# files come from:
#   main       labs/ by default, solutions/ with -DSTOA_USE_SOLUTIONS=ON  -> build/bin/
#   stubs      labs/, built beside a solutions build for the tests       -> build/bin/stubs/
#   mistake    a solution with one planted mistake (solutions/NN/mistakes/*.mistake)
#                                                                         -> build/bin/mistakes/NN_name.MISTAKE/
#   equivalent a solution rewritten another valid way (solutions/NN/equivalents/*.equivalent)
#                                                                         -> build/bin/equivalents/NN_name.NAME/
#   out of     a mistake kept outside the gallery, test data of stoa-grade --check-hints
#   gallery    (tests/data/out_of_gallery/NN/mistakes/*.mistake)          -> build/bin/out-of-gallery/NN_name.NAME/
#   variant    a solution the grader must report in its own words (tests/data/variants/NN/*.equivalent)
#                                                                         -> build/bin/variants/NN_name.NAME/
#
#   stoa_add_lab(NAME 01_transforms
#                STUDENT_FILES transforms.cpp cameras.cpp   # in student/, C++ and GLSL; twins in solutions/
#                APP_SOURCES lab.cpp
#                USES ...)                                          # earlier labs whose student code it links
#
# Student C++ becomes an OBJECT library per lab and track, so a later lab links the
# student's own earlier code. Student GLSL is read at run time through a search
# path baked into each program: [mistake overlay,] track root, shaders/.

# STOA_ROOT_DIR is the Stoa source tree: this project's, or the framework's when a
# submission is built against an exported framework (autograder/submission/).
if(NOT STOA_ROOT_DIR)
  set(STOA_ROOT_DIR ${CMAKE_SOURCE_DIR})
endif()
set(STOA_LABS_DIR ${STOA_ROOT_DIR}/labs)
set(STOA_SOLUTIONS_DIR ${STOA_ROOT_DIR}/solutions)
# STOA_TRACK_DIR builds the main track from a student's labs/ tree instead: only
# the student files each lab declares are copied from it (into <build>/track).
set(STOA_STUDENT_FOLDER student)
set(STOA_TRACK_DIR "" CACHE PATH "Build the labs from this folder (a student's labs/ tree) instead of labs/")
if(STOA_TRACK_DIR)
  set(STOA_MAIN_TRACK_DIR ${CMAKE_BINARY_DIR}/track)
  set(STOA_MAIN_TRACK_NAME submission)
elseif(STOA_USE_SOLUTIONS)
  set(STOA_MAIN_TRACK_DIR ${STOA_SOLUTIONS_DIR})
  set(STOA_MAIN_TRACK_NAME solutions)
else()
  set(STOA_MAIN_TRACK_DIR ${STOA_LABS_DIR})
  set(STOA_MAIN_TRACK_NAME labs)
endif()
# Extra tracks exist only where the solutions do and the tests are built.
if(STOA_USE_SOLUTIONS AND STOA_BUILD_TESTS)
  set(STOA_BUILD_EXTRA_TRACKS ON)
else()
  set(STOA_BUILD_EXTRA_TRACKS OFF)
endif()
# STOA_E2E_LAB narrows the extra tracks to one lab: its stubs, its first planted
# mistake and its first equivalent (the sanitizer build's end-to-end checks).
set(STOA_E2E_LAB "" CACHE STRING "Build the extra tracks (stubs, one mistake, one equivalent) for this lab only; empty: every lab, every variant")
# The mutation tool's build (autograder/mutation/mutate.py): one program per
# mutant in STOA_MUTANTS_DIR/NN_name/mistakes/*.mistake, built to bin/mutants/.
set(STOA_MUTANTS_DIR "" CACHE PATH "Build a program per mutant in this folder (the mutation tool sets it); empty: none")
# The reference pictures the window's comparison ('g') shows, one folder per lab
# (LabBuildInfo::referenceDirectory).
set(STOA_REFERENCES_DIR "${STOA_ROOT_DIR}/autograder/references" CACHE PATH
    "Where the lab programs find the reference pictures for the window's comparison")
set_property(GLOBAL PROPERTY STOA_LABS "")
set_property(GLOBAL PROPERTY STOA_MISTAKES "")
set_property(GLOBAL PROPERTY STOA_EQUIVALENTS "")
set_property(GLOBAL PROPERTY STOA_OUT_OF_GALLERY "")
set_property(GLOBAL PROPERTY STOA_MUTANTS "")

# The lab's header (labs/NN_name/student/lab03.hpp), which is no student file,
# is reachable from every track's student files, wherever the track is: an
# `#include "lab03.hpp"` looks first next to the including file, then here. A
# submission's track (<build>/track) holds only its student files, so a header
# the student changed in their own tree is not used: the student code compiles
# against the header the lab's app compiles against.
function(_stoa_lab_folder_includes target lab)
  # The lab's folder and its student/ folder (its header, labNN.hpp), and the
  # student/ folders of the labs it uses, whose functions it may call.
  get_property(uses GLOBAL PROPERTY STOA_LAB_${lab}_USES)
  target_include_directories(${target} PRIVATE ${STOA_LABS_DIR}/${lab} ${STOA_LABS_DIR}/${lab}/student)
  foreach(used IN LISTS uses)
    target_include_directories(${target} PRIVATE ${STOA_LABS_DIR}/${used}/student)
  endforeach()
  # NotImplemented records which lab a stub belongs to (stoa/core/NotImplemented.hpp).
  # _GLIBCXX_ASSERTIONS: an index past the end of a std::vector or std::array in
  # student code stops the program with the line and the index (libstdc++), which
  # the grader reports as a crash, instead of reading whatever lies beyond.
  target_compile_definitions(${target} PRIVATE STOA_STUDENT_LAB="${lab}" _GLIBCXX_ASSERTIONS)
endfunction()

# The student C++ of `lab` for one track, one OBJECT library per file, so that a
# variant that changes one file (a planted mistake, an equivalent) compiles that
# file alone and links the track's objects of the others. Returns the targets in
# `out` (empty for a lab whose student files are all GLSL).
function(_stoa_student_objects out lab track_suffix source_dir)
  get_property(cpp_files GLOBAL PROPERTY STOA_LAB_${lab}_CPP)
  set(targets "")
  foreach(file IN LISTS cpp_files)
    _stoa_student_file_target(target ${file} "${track_suffix}")
    if(NOT TARGET ${target})
      add_library(${target} OBJECT ${source_dir}/${file})
      target_link_libraries(${target} PUBLIC stoa)
      _stoa_lab_folder_includes(${target} ${lab})
    endif()
    list(APPEND targets ${target})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# The target name of one student file (`lab/file.cpp`) in a track.
function(_stoa_student_file_target out file track_suffix)
  string(MAKE_C_IDENTIFIER "${file}" id)
  set(${out} stoa_student_${id}${track_suffix} PARENT_SCOPE)
endfunction()

# One lab program: the lab's app (a static library compiled once per lab, and
# exported with the framework so that a submission build links it instead of
# compiling it again: autograder/submission/StoaExport.cmake), the student
# objects of its track, and a generated source with its build info (labBuildInfo()
# in stoa/lab/LabBuildInfo.hpp): name, track, lab folder and the GLSL search path
# (track roots first, shaders/ last).
function(_stoa_lab_program lab target output_dir track_name search_path objects)
  get_property(uses GLOBAL PROPERTY STOA_LAB_${lab}_USES)
  set(app stoa_lab_app_${lab})
  if(NOT TARGET ${app})
    get_property(app_sources GLOBAL PROPERTY STOA_LAB_${lab}_APP)
    add_library(${app} STATIC ${app_sources})   # holds main(), which the linker takes from it
    target_link_libraries(${app} PUBLIC stoa)
    _stoa_lab_folder_includes(${app} ${lab})
  endif()
  string(REPLACE ";" "|" search_path_joined "${search_path}")
  set(info_source ${CMAKE_BINARY_DIR}/lab-build-info/${target}.cpp)
  string(CONCAT info_text "// Generated by framework/cmake/StoaLab.cmake for ${target}.\n#include <stoa/lab/LabBuildInfo.hpp>\n\n"
                "stoa::LabBuildInfo stoa::labBuildInfo() {\n"
                "    return {\"${lab}\", \"${track_name}\", \"${STOA_LABS_DIR}/${lab}\",\n"
                "            \"${search_path_joined}\",\n"
                "            \"${STOA_REFERENCES_DIR}/${lab}\"};\n}\n")
  _stoa_write_if_changed(${info_source} "${info_text}")
  add_executable(${target} ${info_source})
  target_link_libraries(${target} PRIVATE ${app})
  _stoa_link_hand_overs(${target} "${uses};${lab}")
  string(REGEX REPLACE "^([0-9]+)_.*" "\\1" number ${lab})
  string(REGEX REPLACE "^[0-9]+_" "" short ${lab})
  set_target_properties(${target} PROPERTIES OUTPUT_NAME lab${number}_${short}
                                             RUNTIME_OUTPUT_DIRECTORY ${output_dir})
  foreach(object IN LISTS objects)
    target_link_libraries(${target} PRIVATE ${object})
  endforeach()
  target_link_libraries(${target} PRIVATE stoa)
endfunction()

# Beside the main track's program, <bin>/labNN_name.sources: the build folder and
# the compiled student files it was built from (the lab's and those of the labs
# it uses; GLSL is read at run time). stoa-grade refuses a program older than one
# of them: the student changed a file and did not rebuild.
function(_stoa_list_compiled_sources lab uses)
  string(REGEX REPLACE "^([0-9]+)_.*" "\\1" number ${lab})
  string(REGEX REPLACE "^[0-9]+_" "" short ${lab})
  set(text "# Written by framework/cmake/StoaLab.cmake: what bin/lab${number}_${short} is built from.\n")
  string(APPEND text "build ${CMAKE_BINARY_DIR}\n")
  foreach(used IN LISTS uses lab)
    file(GLOB files ${STOA_MAIN_TRACK_DIR}/${used}/${STOA_STUDENT_FOLDER}/*.cpp
                    ${STOA_MAIN_TRACK_DIR}/${used}/${STOA_STUDENT_FOLDER}/*.hpp)
    list(SORT files)
    foreach(file IN LISTS files)
      string(APPEND text "source ${file}\n")
    endforeach()
  endforeach()
  _stoa_write_if_changed(${CMAKE_BINARY_DIR}/bin/lab${number}_${short}.sources "${text}")
endfunction()

function(stoa_add_lab)
  cmake_parse_arguments(ARG "" "NAME" "STUDENT_FILES;APP_SOURCES;USES" ${ARGN})
  set(lab ${ARG_NAME})
  set(cpp "")
  set(student ${lab}/${STOA_STUDENT_FOLDER})
  foreach(file IN LISTS ARG_STUDENT_FILES)
    if(NOT EXISTS ${STOA_LABS_DIR}/${student}/${file})
      message(FATAL_ERROR "stoa_add_lab(${lab}): student file labs/${student}/${file} does not exist")
    endif()
    if(EXISTS ${STOA_SOLUTIONS_DIR} AND NOT EXISTS ${STOA_SOLUTIONS_DIR}/${student}/${file})
      message(FATAL_ERROR "stoa_add_lab(${lab}): labs/${student}/${file} has no twin in solutions/${student}/")
    endif()
    if(STOA_TRACK_DIR)
      _stoa_stage_student_file(${lab} ${file})
    endif()
    if(file MATCHES "\\.cpp$")
      list(APPEND cpp ${student}/${file})
    endif()
  endforeach()
  set(app "")
  foreach(file IN LISTS ARG_APP_SOURCES)
    list(APPEND app ${STOA_LABS_DIR}/${lab}/${file})
  endforeach()
  # Student C++, relative to the track root (labs/ or solutions/).
  set_property(GLOBAL PROPERTY STOA_LAB_${lab}_CPP ${cpp})
  set_property(GLOBAL PROPERTY STOA_LAB_${lab}_APP ${app})
  set_property(GLOBAL PROPERTY STOA_LAB_${lab}_USES ${ARG_USES})
  set_property(GLOBAL PROPERTY STOA_LAB_${lab}_FILES ${ARG_STUDENT_FILES})
  set_property(GLOBAL APPEND PROPERTY STOA_LABS ${lab})
  # A lab whose functions the framework calls hands them over (hand_over.cpp):
  # one small library per lab, whichever track's student code it is linked with.
  if(EXISTS ${STOA_LABS_DIR}/${lab}/hand_over.cpp)
    set_property(GLOBAL PROPERTY STOA_LAB_${lab}_HANDS_OVER ON)
    if(NOT TARGET stoa_lab_hand_over_${lab})
      add_library(stoa_lab_hand_over_${lab} STATIC ${STOA_LABS_DIR}/${lab}/hand_over.cpp)
      target_link_libraries(stoa_lab_hand_over_${lab} PUBLIC stoa)
      _stoa_lab_folder_includes(stoa_lab_hand_over_${lab} ${lab})
    endif()
  endif()

  # The main track.
  set(objects "")
  foreach(used IN LISTS ARG_USES lab)
    _stoa_student_objects(object ${used} "" ${STOA_MAIN_TRACK_DIR})
    list(APPEND objects ${object})
  endforeach()
  _stoa_lab_program(${lab} ${lab} ${CMAKE_BINARY_DIR}/bin ${STOA_MAIN_TRACK_NAME}
                    "${STOA_MAIN_TRACK_DIR};${STOA_ROOT_DIR}/shaders" "${objects}")
  _stoa_list_compiled_sources(${lab} "${ARG_USES}")

  if(ARG_USES AND EXISTS ${STOA_SOLUTIONS_DIR} AND NOT STOA_MAIN_TRACK_NAME STREQUAL "solutions")
    _stoa_cascade_program(${lab} "${ARG_USES}")
  endif()

  # Mutants (autograder/mutation/): variants of the solutions, as planted mistakes are.
  if(STOA_MUTANTS_DIR AND STOA_MAIN_TRACK_NAME STREQUAL "solutions")
    file(GLOB mutants ${STOA_MUTANTS_DIR}/${lab}/mistakes/*.mistake)
    foreach(mutant_file IN LISTS mutants)
      _stoa_variant_program(${lab} ${mutant_file} mutant mutants "${ARG_USES}")
    endforeach()
  endif()

  if(NOT STOA_BUILD_EXTRA_TRACKS OR (STOA_E2E_LAB AND NOT STOA_E2E_LAB STREQUAL lab))
    return()
  endif()

  # The stubs, beside the solutions.
  set(objects "")
  foreach(used IN LISTS ARG_USES lab)
    _stoa_student_objects(object ${used} "-stubs" ${STOA_LABS_DIR})
    list(APPEND objects ${object})
  endforeach()
  _stoa_lab_program(${lab} ${lab}-stubs ${CMAKE_BINARY_DIR}/bin/stubs labs
                    "${STOA_LABS_DIR};${STOA_ROOT_DIR}/shaders" "${objects}")

  # One program per planted mistake, and one per equivalent rewrite (solutions/NN/
  # equivalents/*.equivalent: the solution written another valid way, which must pass;
  # the calibration of the compare).
  file(GLOB mistakes ${STOA_SOLUTIONS_DIR}/${lab}/mistakes/*.mistake)
  file(GLOB equivalents ${STOA_SOLUTIONS_DIR}/${lab}/equivalents/*.equivalent)
  if(STOA_E2E_LAB)
    list(SORT mistakes)
    list(SORT equivalents)
    list(SUBLIST mistakes 0 1 mistakes)
    list(SUBLIST equivalents 0 1 equivalents)
  endif()
  foreach(mistake_file IN LISTS mistakes)
    _stoa_variant_program(${lab} ${mistake_file} mistake mistakes "${ARG_USES}")
  endforeach()
  foreach(equivalent_file IN LISTS equivalents)
    _stoa_variant_program(${lab} ${equivalent_file} equivalent equivalents "${ARG_USES}")
  endforeach()
  # Mistakes kept outside the gallery, so that they never become hints: the test
  # that hints are right or silent (e2e.hints_right_or_silent). Each compiles its
  # one patched file and links the solutions' objects, like a planted mistake.
  # Not in the narrowed (STOA_E2E_LAB) build.
  if(NOT STOA_E2E_LAB)
    file(GLOB out_of_gallery ${STOA_ROOT_DIR}/tests/data/out_of_gallery/${lab}/mistakes/*.mistake)
    foreach(mistake_file IN LISTS out_of_gallery)
      _stoa_variant_program(${lab} ${mistake_file} probe out-of-gallery "${ARG_USES}")
    endforeach()
    # Solutions changed in a way the grader must report as such, not as a wrong
    # picture (tests/data/variants/NN/*.equivalent): far too slow, not hanging
    # (e2e.slow_is_not_a_hang); GL state set behind RenderState (e2e.raw_gl_state_named).
    file(GLOB variants ${STOA_ROOT_DIR}/tests/data/variants/${lab}/*.equivalent)
    foreach(variant_file IN LISTS variants)
      _stoa_variant_program(${lab} ${variant_file} variant variants "${ARG_USES}")
    endforeach()
  endif()
endfunction()

# A variant of a lab's solution: a .mistake or .equivalent file (same format; an
# equivalent has `why:` instead of `hint:` and no `fails:`) applied to one solution
# file. Builds build/bin/<folder>/NN_name.NAME/labNN_name, with the earlier labs'
# solutions linked in, and records NN_name.NAME in STOA_MISTAKES or STOA_EQUIVALENTS.
function(_stoa_variant_program lab variant_file kind folder uses)
  get_filename_component(name ${variant_file} NAME_WE)
  set(id ${lab}.${name})
  set(overlay ${CMAKE_BINARY_DIR}/${folder}/${id})
  _stoa_apply_mistake(${variant_file} ${lab} ${overlay} patched_file)
  set(objects "")
  foreach(used IN LISTS uses)
    _stoa_student_objects(object ${used} "" ${STOA_SOLUTIONS_DIR})
    list(APPEND objects ${object})
  endforeach()
  # The lab's own student code: the solutions' objects, but for the patched file,
  # which alone is compiled (a GLSL variant compiles nothing: its overlay is read
  # at run time through the program's search path).
  get_property(lab_cpp GLOBAL PROPERTY STOA_LAB_${lab}_CPP)
  foreach(file IN LISTS lab_cpp)
    if(patched_file STREQUAL "${overlay}/${file}")
      set(target stoa_student_${kind}_${id})
      add_library(${target} OBJECT ${overlay}/${file})
      target_link_libraries(${target} PUBLIC stoa)
      _stoa_lab_folder_includes(${target} ${lab})
    else()
      _stoa_student_file_target(target ${file} "")   # variants exist where the main track is solutions/
    endif()
    list(APPEND objects ${target})
  endforeach()
  _stoa_lab_program(${lab} ${lab}-${kind}-${name} ${CMAKE_BINARY_DIR}/bin/${folder}/${id} ${kind}:${name}
                    "${overlay};${STOA_SOLUTIONS_DIR};${STOA_ROOT_DIR}/shaders" "${objects}")
  string(TOUPPER ${folder} property)
  string(MAKE_C_IDENTIFIER ${property} property)
  set_property(GLOBAL APPEND PROPERTY STOA_${property} ${id})
endfunction()

# The cascade program of a lab that uses earlier labs: the main track's code for
# this lab with the earlier labs' solutions linked in (C++) and found first (GLSL),
# so that a broken earlier lab does not sink this one. Built where solutions/
# exists and the main track is not the solutions themselves (a student's or the
# stubs' tree); build/bin/cascade/labNN_name. The lab's own GLSL is reached
# through links in build/cascade/NN_name/, so edits show without reconfiguring.
function(_stoa_cascade_program lab uses)
  set(overlay ${CMAKE_BINARY_DIR}/cascade/${lab})
  set(student ${lab}/${STOA_STUDENT_FOLDER})
  get_property(files GLOBAL PROPERTY STOA_LAB_${lab}_FILES)
  file(MAKE_DIRECTORY ${overlay}/${student})
  foreach(file IN LISTS files)
    if(NOT file MATCHES "\\.cpp$")
      get_filename_component(parent ${overlay}/${student}/${file} DIRECTORY)
      file(MAKE_DIRECTORY ${parent})
      file(CREATE_LINK ${STOA_MAIN_TRACK_DIR}/${student}/${file} ${overlay}/${student}/${file} SYMBOLIC)
    endif()
  endforeach()
  set(objects "")
  foreach(used IN LISTS uses)
    _stoa_student_objects(object ${used} "-solutions" ${STOA_SOLUTIONS_DIR})
    list(APPEND objects ${object})
  endforeach()
  # The earlier labs' solutions alone, as a target of their own: stoa-grade-class
  # builds it first, where solutions/ may be read, and then the student's files
  # where it may not, so that a student's file cannot #include a solution
  # (ClassGrader.cpp).
  add_custom_target(${lab}-cascade-solutions)
  if(objects)
    add_dependencies(${lab}-cascade-solutions ${objects})
  endif()
  _stoa_student_objects(object ${lab} "" ${STOA_MAIN_TRACK_DIR})   # the main program's objects
  list(APPEND objects ${object})
  _stoa_lab_program(${lab} ${lab}-cascade ${CMAKE_BINARY_DIR}/bin/cascade cascade
                    "${overlay};${STOA_SOLUTIONS_DIR};${STOA_ROOT_DIR}/shaders" "${objects}")
endfunction()

# Copies one student file of a submission (STOA_TRACK_DIR) into the staged track.
# The file is looked for at NN_name/student/FILE, then where releases before the
# student/ folders kept it (NN_name/FILE). A file the submission lacks is taken
# from labs/ (the stub): that lab grades "not attempted" instead of failing to
# configure.
function(_stoa_stage_student_file lab file)
  set(student ${lab}/${STOA_STUDENT_FOLDER})
  set(from ${STOA_TRACK_DIR}/${student}/${file})
  if(NOT EXISTS ${from} AND NOT IS_SYMLINK ${from} AND (EXISTS ${STOA_TRACK_DIR}/${lab}/${file} OR IS_SYMLINK ${STOA_TRACK_DIR}/${lab}/${file}))
    message(STATUS "the submission has ${lab}/${file} where older releases kept it; grading it as ${student}/${file}")
    set(from ${STOA_TRACK_DIR}/${lab}/${file})
  endif()
  if(IS_SYMLINK ${from})
    # The grader's configure may read only the submission's own files.
    file(READ_SYMLINK ${from} link_target)
    file(RELATIVE_PATH shown ${STOA_TRACK_DIR} ${from})
    message(FATAL_ERROR "error: the submission's ${shown} is a symbolic link (to ${link_target}); "
                        "hand in the file itself")
  endif()
  if(NOT EXISTS ${from})
    message(WARNING "the submission has no ${student}/${file}; using the stub from labs/")
    set(from ${STOA_LABS_DIR}/${student}/${file})
  endif()
  configure_file(${from} ${STOA_MAIN_TRACK_DIR}/${student}/${file} COPYONLY)
endfunction()

# A .mistake file:
#   hint: what the student sees when their image looks like this mistake
#   docs: labs/01_transforms.md#the-view-matrix
#   fails: case_a case_b            (cases this mistake must fail)
#   file: transforms.cpp            (a student file of the lab, in its student/ folder)
#   --- find
#   <exact lines of the solution>
#   --- replace
#   <the lines with the mistake>
#   --- end
# The text between the markers must occur exactly once in the solution file.
function(_stoa_apply_mistake mistake_file lab overlay out)
  file(READ ${mistake_file} text)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${mistake_file})
  string(REGEX MATCH "(^|\n)file:[ \t]*([^\n]+)" _ "${text}")
  set(file "${CMAKE_MATCH_2}")
  string(STRIP "${file}" file)
  if(file STREQUAL "")
    message(FATAL_ERROR "${mistake_file}: missing 'file:' line naming the student file to change")
  endif()
  set(student ${lab}/${STOA_STUDENT_FOLDER})
  set(original ${STOA_SOLUTIONS_DIR}/${student}/${file})
  if(NOT EXISTS ${original})
    message(FATAL_ERROR "${mistake_file}: file: ${file} is not in solutions/${student}/")
  endif()
  string(FIND "${text}" "--- find\n" find_at)
  string(FIND "${text}" "--- replace\n" replace_at)
  string(FIND "${text}" "--- end" end_at)
  if(find_at LESS 0 OR replace_at LESS find_at OR end_at LESS replace_at)
    message(FATAL_ERROR "${mistake_file}: expected '--- find', '--- replace' and '--- end' blocks, in that order")
  endif()
  string(FIND "${text}" "--- find\n" last_find_at REVERSE)
  if(NOT last_find_at EQUAL find_at)
    message(FATAL_ERROR "${mistake_file}: more than one '--- find' block; a mistake changes one place "
                        "(make the find text longer to cover several lines, or plant two mistakes)")
  endif()
  math(EXPR find_begin "${find_at} + 9")
  math(EXPR find_length "${replace_at} - ${find_begin}")
  math(EXPR replace_begin "${replace_at} + 12")
  math(EXPR replace_length "${end_at} - ${replace_begin}")
  string(SUBSTRING "${text}" ${find_begin} ${find_length} find)
  string(SUBSTRING "${text}" ${replace_begin} ${replace_length} replace)
  file(READ ${original} source)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${original})
  string(FIND "${source}" "${find}" first)
  if(first LESS 0)
    message(FATAL_ERROR "${mistake_file}: the '--- find' text does not occur in solutions/${student}/${file}; "
                        "update the mistake to match the solution")
  endif()
  string(FIND "${source}" "${find}" last REVERSE)
  if(NOT first EQUAL last)
    message(FATAL_ERROR "${mistake_file}: the '--- find' text occurs more than once in solutions/${student}/${file}")
  endif()
  string(REPLACE "${find}" "${replace}" patched "${source}")
  file(MAKE_DIRECTORY ${overlay}/${student})
  # Write only on change, so a reconfigure does not rebuild every mistake.
  set(target_file ${overlay}/${student}/${file})
  if(EXISTS ${target_file})
    file(READ ${target_file} previous)
  else()
    set(previous "")
  endif()
  if(NOT previous STREQUAL patched)
    file(WRITE ${target_file} "${patched}")
  endif()
  set(${out} ${target_file} PARENT_SCOPE)
endfunction()

# Links the student code of every lab of the main track into `target` (the
# tests of the labs' functions, the benchmarks), with the labs' headers and
# their hand-overs.
function(stoa_link_lab_code target)
  get_property(labs GLOBAL PROPERTY STOA_LABS)
  foreach(lab IN LISTS labs)
    _stoa_student_objects(objects ${lab} "" ${STOA_MAIN_TRACK_DIR})
    foreach(object IN LISTS objects)
      target_link_libraries(${target} PRIVATE ${object})
    endforeach()
    target_include_directories(${target} PRIVATE ${STOA_LABS_DIR}/${lab}/student)
  endforeach()
  _stoa_link_hand_overs(${target} "${labs}")
endfunction()

# The hand-overs of `labs` (each lab's hand_over.cpp, where the framework calls
# the lab's functions) linked into `target`, and called when the program starts
# (before main(), so that even a lab's constructor finds them): a generated
# source fills the framework's student-code table (stoa/core/StudentCode.hpp)
# with the student functions the program links.
function(_stoa_link_hand_overs target labs)
  set(declarations "")
  set(calls "")
  foreach(lab IN LISTS labs)
    get_property(hands_over GLOBAL PROPERTY STOA_LAB_${lab}_HANDS_OVER)
    if(hands_over)
      string(REGEX REPLACE "^([0-9]+)_.*" "lab\\1" namespace ${lab})
      string(APPEND declarations "namespace ${namespace} {\nvoid handOver(stoa::StudentCode& code);\n}\n")
      string(APPEND calls "    ${namespace}::handOver(code);\n")
      target_link_libraries(${target} PRIVATE stoa_lab_hand_over_${lab})
    endif()
  endforeach()
  if(calls STREQUAL "")
    return()
  endif()
  set(source ${CMAKE_BINARY_DIR}/lab-hand-over/${target}.cpp)
  string(CONCAT text "// Generated by framework/cmake/StoaLab.cmake for ${target}.\n"
                "namespace stoa {\nstruct StudentCode;\nStudentCode& studentCode();\n}\n${declarations}\n"
                "namespace {\nbool handOverStudentCode() {\n    stoa::StudentCode& code = stoa::studentCode();\n"
                "${calls}    return true;\n}\n[[maybe_unused]] const bool handedOver = handOverStudentCode();\n}\n")
  _stoa_write_if_changed(${source} "${text}")
  target_sources(${target} PRIVATE ${source})
endfunction()

# Writes a generated source only when its text changed, so that a reconfigure
# does not recompile and relink every program.
function(_stoa_write_if_changed file text)
  set(previous "")
  if(EXISTS ${file})
    file(READ ${file} previous)
  endif()
  if(NOT previous STREQUAL text)
    file(WRITE ${file} "${text}")
  endif()
endfunction()
