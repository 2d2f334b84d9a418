# CTest's test_payload_compile (cmake -P): compiles, syntax only, the two
# payloads planted beside this file against model/step_payload.h. Passes when
# member.cpp (the geometry as the member `milling`) compiles and derived.cpp
# (a payload deriving from MillingGeometry) fails on StepPayload's
# static_assert, with its words.
set(flags -std=c++20 -fsyntax-only -I${TAIWA_SOURCE_DIR}/core)
execute_process(COMMAND ${CXX_COMPILER} ${flags} ${CMAKE_CURRENT_LIST_DIR}/member.cpp
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "a payload holding its geometry as `milling` did not compile:\n${out}")
endif()
execute_process(COMMAND ${CXX_COMPILER} ${flags} ${CMAKE_CURRENT_LIST_DIR}/derived.cpp
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(status EQUAL 0)
  message(FATAL_ERROR "a payload deriving from MillingGeometry compiled: StepPayload lets it through")
endif()
if(NOT out MATCHES "a step payload holds its milling geometry as its member `milling`, not as a base")
  message(FATAL_ERROR "a payload deriving from MillingGeometry failed, but not on StepPayload's static_assert:\n${out}")
endif()
message(STATUS "a payload deriving from MillingGeometry fails to compile, as it must")
