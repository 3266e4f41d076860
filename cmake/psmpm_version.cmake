# Writes the header with psmpm's version and `git describe` of the
# checkout. Run at every build (the target psmpm_version), not only at
# configure time: otherwise a build after new commits or edits reported
# the commit it was configured at in `psmpm --version` and summary.json.
# configure_file() rewrites the header only when its text changes, so an
# unchanged checkout recompiles nothing.
#
# Inputs (-D): SOURCE_DIR, OUTPUT, PROJECT_VERSION, GIT_EXECUTABLE.
set(PSMPM_GIT_DESCRIBE "")
if(GIT_EXECUTABLE AND EXISTS ${SOURCE_DIR}/.git)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --tags
    WORKING_DIRECTORY ${SOURCE_DIR}
    OUTPUT_VARIABLE PSMPM_GIT_DESCRIBE OUTPUT_STRIP_TRAILING_WHITESPACE
    RESULT_VARIABLE _result ERROR_QUIET)
  if(NOT _result EQUAL 0)
    set(PSMPM_GIT_DESCRIBE "")
  endif()
endif()
configure_file(${SOURCE_DIR}/source/base/version_info.h.in ${OUTPUT} @ONLY)
