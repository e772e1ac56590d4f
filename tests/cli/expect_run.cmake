# The CLI tests' expectations. Each runs COMMAND and requires its exit code.
#   expect_run(CODE TEXT COMMAND...)          TEXT somewhere in stdout or stderr
#   expect_run_without(CODE TEXT COMMAND...)  TEXT nowhere in stdout or stderr
#   expect_stdout(CODE REGEX COMMAND...)      REGEX matched on stdout alone
#   expect_run_input(CODE TEXT INPUT COMMAND...)  expect_run with INPUT as standard input

# Runs COMMAND (INPUT as standard input unless empty), requires exit code
# CODE, and sets RUN_OUT, RUN_ERR and RUN_SAID (the command, for messages)
# in the caller.
function(run_expecting_code expected_code input)
  if(input)
    execute_process(COMMAND ${ARGN} INPUT_FILE ${input} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    set(said "${ARGN} < ${input}")
  else()
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    set(said "${ARGN}")
  endif()
  if(NOT code EQUAL expected_code)
    message(FATAL_ERROR "${said}\nexited ${code}, expected ${expected_code}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(RUN_OUT "${out}" PARENT_SCOPE)
  set(RUN_ERR "${err}" PARENT_SCOPE)
  set(RUN_SAID "${said}" PARENT_SCOPE)
endfunction()

function(expect_run expected_code expected_output)
  run_expecting_code(${expected_code} "" ${ARGN})
  string(FIND "${RUN_OUT}${RUN_ERR}" "${expected_output}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${RUN_SAID}\noutput lacks '${expected_output}'\nstdout: ${RUN_OUT}\nstderr: ${RUN_ERR}")
  endif()
endfunction()

function(expect_run_without expected_code absent)
  run_expecting_code(${expected_code} "" ${ARGN})
  string(FIND "${RUN_OUT}${RUN_ERR}" "${absent}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${RUN_SAID}\noutput has '${absent}'\nstdout: ${RUN_OUT}\nstderr: ${RUN_ERR}")
  endif()
endfunction()

function(expect_stdout expected_code pattern)
  run_expecting_code(${expected_code} "" ${ARGN})
  if(NOT RUN_OUT MATCHES "${pattern}")
    message(FATAL_ERROR "${RUN_SAID}\nstdout does not match '${pattern}'\nstdout: ${RUN_OUT}\nstderr: ${RUN_ERR}")
  endif()
endfunction()

function(expect_run_input expected_code expected_output input)
  run_expecting_code(${expected_code} ${input} ${ARGN})
  string(FIND "${RUN_OUT}${RUN_ERR}" "${expected_output}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${RUN_SAID}\noutput lacks '${expected_output}'\nstdout: ${RUN_OUT}\nstderr: ${RUN_ERR}")
  endif()
endfunction()
