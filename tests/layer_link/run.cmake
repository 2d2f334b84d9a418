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
include(${CMAKE_CURRENT_LIST_DIR}/../planted.cmake)
file(REMOVE_RECURSE ${WORK})
planted_must_pass("configuring tests/layer_link failed"
  COMMAND ${CMAKE_COMMAND} -S ${TAIWA_SOURCE_DIR}/tests/layer_link -B ${WORK} -G ${GENERATOR}
  -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  -DTAIWA_SOURCE_DIR=${TAIWA_SOURCE_DIR} -DTAIWA_MODEL_ARCHIVE=${MODEL_ARCHIVE})
planted_must_pass("the model calling the model did not link"
  COMMAND ${CMAKE_COMMAND} --build ${WORK} --target planted_right_links)
planted_must_fail("the model calling the post fails to link"
  MATCHES "undefined reference to [`']taiwa::dialectNames"
  PASSED "the model calling the post linked: the layer link check lets a wrong-way call through"
  COMMAND ${CMAKE_COMMAND} --build ${WORK} --target planted_wrong_links)
