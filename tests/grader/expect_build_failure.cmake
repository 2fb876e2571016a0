# cmake -DBUILD_DIR=... -DTARGET=... -DEXPECTED=TEXT -P expect_build_failure.cmake
# Passes when building TARGET fails and the compiler's output names TEXT (the
# header the layer may not include), so that a failure for another reason
# (a broken build tree) does not pass for the one this test is about.
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${TARGET}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(result EQUAL 0)
  message(FATAL_ERROR "${TARGET} built: a layer included a header it must not see")
endif()
if(NOT output MATCHES "${EXPECTED}")
  message(FATAL_ERROR "${TARGET} failed to build, but not on ${EXPECTED}:\n${output}")
endif()
string(REGEX MATCH "[^\n]*${EXPECTED}[^\n]*" line "${output}")
message(STATUS "refused as expected: ${line}")
