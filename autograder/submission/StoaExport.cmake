# Exports the built framework into <build>/stoa-config, so that a student's
# submission compiles only its own files against it (autograder/submission/,
# stoa-grade-class):
#
#   cmake -S autograder/submission -B <dir> -DStoa_DIR=<build>/stoa-config \
#         -DSTOA_TRACK_DIR=<the student's labs/>
#
# The exported targets keep their names (stoa_core, stoa), so StoaLab.cmake works
# unchanged on both sides. Included from autograder/CMakeLists.txt, after the
# framework's targets exist.

set(STOA_EXPORT_DIR ${CMAKE_BINARY_DIR}/stoa-config)
export(TARGETS stoa_core stoa FILE ${STOA_EXPORT_DIR}/StoaTargets.cmake)
configure_file(${CMAKE_CURRENT_LIST_DIR}/StoaConfig.cmake.in ${STOA_EXPORT_DIR}/StoaConfig.cmake @ONLY)
