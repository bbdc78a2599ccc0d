# Writes OUT, the header of granmc's build identity: the project version and, in a git checkout, the commit
# (12 hex digits) with "-dirty" when tracked files differ from it; "unknown commit" elsewhere. Run at every
# build (the granmc_build_id target); the header is rewritten only when the identity changes, so an
# unchanged checkout recompiles nothing (io/build_id.hpp says who reads it).
execute_process(COMMAND git -C "${SOURCE_DIR}" rev-parse --short=12 HEAD
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE no_commit ERROR_QUIET)
if(no_commit EQUAL 0 AND NOT commit STREQUAL "")
  execute_process(COMMAND git -C "${SOURCE_DIR}" update-index -q --refresh OUTPUT_QUIET ERROR_QUIET)
  execute_process(COMMAND git -C "${SOURCE_DIR}" diff-index --quiet HEAD -- RESULT_VARIABLE dirty ERROR_QUIET)
  set(GRANMC_BUILD_ID "${VERSION}+${commit}")
  if(NOT dirty EQUAL 0)
    string(APPEND GRANMC_BUILD_ID "-dirty")
  endif()
else()
  set(GRANMC_BUILD_ID "${VERSION}+unknown commit")
endif()
configure_file("${SOURCE_DIR}/kernel/core/build_id.hpp.in" "${OUT}" @ONLY)
