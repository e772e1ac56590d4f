# cmake -DSOURCE_DIR=... -DOUT=.../build_stamp.h -P write_build_stamp.cmake
# The commit the build is made from and whether the tree differs from it
# (changed or untracked files; build folders are ignored by .gitignore)
# (the test-set ledger refuses a binary that cannot name its code). The
# ledger itself is left out: a run appending to it does not make the tree
# another tree. OUT is rewritten only when its text changes, so a build
# recompiles one file, and only after a commit or an edit.
execute_process(COMMAND git -C "${SOURCE_DIR}" rev-parse HEAD
                OUTPUT_VARIABLE commit RESULT_VARIABLE commit_failed
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
execute_process(COMMAND git --no-optional-locks -C "${SOURCE_DIR}" status --porcelain --untracked-files=normal -- .
                        ":(exclude)benchmarks/test_set_ledger.jsonl"
                OUTPUT_VARIABLE changes RESULT_VARIABLE status_failed ERROR_QUIET)
if(commit_failed OR status_failed)
  set(commit "unknown")
  set(dirty "true")
elseif(changes STREQUAL "")
  set(dirty "false")
else()
  set(dirty "true")
endif()
file(WRITE "${OUT}.new"
     "// Written by cmake/write_build_stamp.cmake at build time.\n"
     "#pragma once\n"
     "#define ALPLAN_BUILD_COMMIT \"${commit}\"\n"
     "#define ALPLAN_BUILD_DIRTY ${dirty}\n")
file(COPY_FILE "${OUT}.new" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.new")
