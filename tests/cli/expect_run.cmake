# expect_run(CODE TEXT COMMAND...): runs COMMAND, requires exit code CODE and
# TEXT somewhere in its output.
function(expect_run expected_code expected_output)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL expected_code)
    message(FATAL_ERROR "${ARGN}\nexited ${code}, expected ${expected_code}\nstdout: ${out}\nstderr: ${err}")
  endif()
  string(FIND "${out}${err}" "${expected_output}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${ARGN}\noutput lacks '${expected_output}'\nstdout: ${out}\nstderr: ${err}")
  endif()
endfunction()
