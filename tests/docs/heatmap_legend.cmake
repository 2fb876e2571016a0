# docs/images/heatmap-legend.png is what `stoa-grade --write-heatmap-legend` writes.
execute_process(COMMAND ${STOA_GRADE} --write-heatmap-legend ${OUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "stoa-grade --write-heatmap-legend failed (${status})")
endif()
file(SHA256 ${OUT} written)
file(SHA256 ${COMMITTED} committed)
if(NOT written STREQUAL committed)
  message(FATAL_ERROR "docs/images/heatmap-legend.png is not the grader's legend; regenerate it with "
                      "stoa-grade --write-heatmap-legend docs/images/heatmap-legend.png")
endif()
