# Writes build_info.hpp with the current git revision. Run at every build (not only at
# configure time) so that provenance records never name a stale revision; the header
# is rewritten only when its content changes, so nothing recompiles needlessly.
execute_process(COMMAND git rev-parse --short=12 HEAD
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE RBCAL_GIT_REVISION OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT RBCAL_GIT_REVISION)
  set(RBCAL_GIT_REVISION "unknown")
endif()
execute_process(COMMAND git status --porcelain --untracked-files=no
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE RBCAL_GIT_DIRTY OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(RBCAL_GIT_DIRTY)
  string(APPEND RBCAL_GIT_REVISION "-dirty")
endif()
configure_file(${SOURCE_DIR}/cmake/build_info.hpp.in ${OUTPUT} @ONLY)
