# CTest's test_payload_compile (cmake -P): compiles, syntax only, the two
# payloads planted beside this file against model/step_payload.h. Passes when
# member.cpp (the geometry as the member `milling`) compiles and derived.cpp
# (a payload deriving from MillingGeometry) fails on StepPayload's
# static_assert, with its words.
include(${CMAKE_CURRENT_LIST_DIR}/../planted.cmake)
set(compile ${CXX_COMPILER} -std=c++20 -fsyntax-only -I${TAIWA_SOURCE_DIR}/core)
planted_must_pass("a payload holding its geometry as `milling` did not compile"
  COMMAND ${compile} ${CMAKE_CURRENT_LIST_DIR}/member.cpp)
planted_must_fail("a payload deriving from MillingGeometry fails to compile"
  MATCHES "a step payload holds its milling geometry as its member `milling`, not as a base"
  PASSED "a payload deriving from MillingGeometry compiled: StepPayload lets it through"
  COMMAND ${compile} ${CMAKE_CURRENT_LIST_DIR}/derived.cpp)
