# CTest's test_layer_link (cmake -P): configures tests/layer_link/ in a folder
# of the build and builds its two link checks. Passes when the planted call
# to the model links and the planted call to the post fails with an undefined
# reference to it; also when every layer of the core has its link check built
# (LINK_CHECKS, the executables of core/layers.cmake).
string(REPLACE "|" ";" LINK_CHECKS "${LINK_CHECKS}")
list(LENGTH LINK_CHECKS count)
if(count LESS 10)
  message(FATAL_ERROR "only ${count} layer link checks: ${LINK_CHECKS}")
endif()
foreach(check ${LINK_CHECKS})
  if(NOT EXISTS ${check})
    message(FATAL_ERROR "the layer's link check ${check} was not built")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${TAIWA_SOURCE_DIR}/tests/layer_link -B ${WORK} -G ${GENERATOR}
  -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  -DTAIWA_SOURCE_DIR=${TAIWA_SOURCE_DIR} -DTAIWA_MODEL_ARCHIVE=${MODEL_ARCHIVE}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "configuring tests/layer_link failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK} --target planted_right_links
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the model calling the model did not link:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK} --target planted_wrong_links
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(status EQUAL 0)
  message(FATAL_ERROR "the model calling the post linked: the layer link check lets a wrong-way call through")
endif()
if(NOT out MATCHES "undefined reference to [`']taiwa::dialectNames")
  message(FATAL_ERROR "the model calling the post failed, but not on the wrong-way call:\n${out}")
endif()
message(STATUS "the model calling the post fails to link, as it must:\n${out}")
