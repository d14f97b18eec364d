# Writes BuildInfo.h with the source tree's commit (git describe --always --dirty) at every
# build, touching the file only when the text changes (so only BenchContext.cpp recompiles).
execute_process(COMMAND git -C ${SRC} describe --always --dirty --abbrev=12
                OUTPUT_VARIABLE _commit OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE _rc ERROR_QUIET)
if(NOT _rc EQUAL 0 OR _commit STREQUAL "")
    set(_commit "unknown (not a git checkout)")
endif()
file(WRITE ${OUT}.tmp "#pragma once\n#define PB_GIT_COMMIT \"${_commit}\"\n")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUT}.tmp)
