# The comparison benchmark as a user runs it: compute two features of a shared part with
# both methods, write JSON and SVG, then redraw the SVG from the JSON alone.
#   cmake -DCOMPARE=gvm_compare -DPART=file -DOUT=dir -P check_gvm_compare.cmake
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${COMPARE} ${PART} --largest 2 --json ${OUT}/cmp.json
                        --svg ${OUT}/computed.svg --csv ${OUT}/cmp.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE table)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gvm_compare exited with ${rc} (1 means the methods differ):\n${table}")
endif()
execute_process(COMMAND ${COMPARE} --from-json ${OUT}/cmp.json --svg ${OUT}/redrawn.svg
                RESULT_VARIABLE rc OUTPUT_VARIABLE redrawn_table)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gvm_compare --from-json exited with ${rc}")
endif()
if(NOT table STREQUAL redrawn_table)
  message(FATAL_ERROR "the table redrawn from JSON differs:\n${table}\n---\n${redrawn_table}")
endif()
file(READ ${OUT}/computed.svg computed)
file(READ ${OUT}/redrawn.svg redrawn)
if(NOT computed STREQUAL redrawn)
  message(FATAL_ERROR "the plot redrawn from JSON differs from the computed one")
endif()
# Two surfaces, two methods, two panels: four marks of each method (none is zero here).
foreach(colour 1f77b4 d62728)
  string(REGEX MATCHALL "fill='#${colour}' fill-opacity" marks "${computed}")
  list(LENGTH marks n)
  if(NOT n EQUAL 4)
    message(FATAL_ERROR "expected 4 marks of colour #${colour} in the plot, found ${n}")
  endif()
endforeach()
file(STRINGS ${OUT}/cmp.csv rows)
list(LENGTH rows n)
if(NOT n EQUAL 5)
  message(FATAL_ERROR "expected a header and 4 rows in the CSV, found ${n} lines")
endif()
# A file that is not a gvm.v1.Comparison is a clear error, not an empty plot.
file(WRITE ${OUT}/not-a-comparison.json "{\"surfaces\": 3}")
execute_process(COMMAND ${COMPARE} --from-json ${OUT}/not-a-comparison.json
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "not a gvm.v1.Comparison")
  message(FATAL_ERROR "a malformed JSON gave exit ${rc} and: ${err}")
endif()
