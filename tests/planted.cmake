# The checks of a planted file, for the cmake -P scripts of CTest's planted
# tests (tests/layer_link/run.cmake, tests/payload_compile/run.cmake): a
# command that must pass, and one that must fail for the planted reason.

# planted_must_pass(<why it failed> COMMAND <command>...): stops the test,
# with the command's output, unless the command succeeds.
function(planted_must_pass failed)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "COMMAND")
  execute_process(COMMAND ${arg_COMMAND} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${failed}:\n${out}")
  endif()
endfunction()

# planted_must_fail(<what> MATCHES <regex> PASSED <why passing is wrong>
#                   COMMAND <command>...): stops the test unless the command
# fails with output matching <regex>; then says "<what>, as it must".
function(planted_must_fail what)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "MATCHES;PASSED" "COMMAND")
  execute_process(COMMAND ${arg_COMMAND} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(status EQUAL 0)
    message(FATAL_ERROR "${arg_PASSED}")
  endif()
  if(NOT out MATCHES "${arg_MATCHES}")
    message(FATAL_ERROR "it failed, but not for the planted reason (${arg_MATCHES}):\n${out}")
  endif()
  message(STATUS "${what}, as it must:\n${out}")
endfunction()
