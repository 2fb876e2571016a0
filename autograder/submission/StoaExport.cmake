# Exports the built framework into <build>/stoa-config, so that a student's
# submission compiles only its own files against it (autograder/submission/,
# stoa-grade-class):
#
#   cmake -S autograder/submission -B <dir> -DStoa_DIR=<build>/stoa-config \
#         -DSTOA_TRACK_DIR=<the student's labs/>
#
# The exported targets keep their names (stoa_core, stoa, stoa_lab_app_NN_name,
# stoa_lab_hand_over_NN_name), so
# StoaLab.cmake works unchanged on both sides. Included from autograder/CMakeLists.txt, after the
# framework's targets exist.

set(STOA_EXPORT_DIR ${CMAKE_BINARY_DIR}/stoa-config)
# The lab apps (lab.cpp and its helpers, one static library per lab) and the
# labs' hand-overs (hand_over.cpp) go along: a submission compiles only the
# student's files.
set(stoa_export_targets stoa_core stoa)
get_property(stoa_export_labs GLOBAL PROPERTY STOA_LABS)
foreach(lab IN LISTS stoa_export_labs)
  foreach(library stoa_lab_app_${lab} stoa_lab_hand_over_${lab})
    if(TARGET ${library})
      list(APPEND stoa_export_targets ${library})
    endif()
  endforeach()
endforeach()
export(TARGETS ${stoa_export_targets} FILE ${STOA_EXPORT_DIR}/StoaTargets.cmake)
configure_file(${CMAKE_CURRENT_LIST_DIR}/StoaConfig.cmake.in ${STOA_EXPORT_DIR}/StoaConfig.cmake @ONLY)
