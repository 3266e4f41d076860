# Writes the header with psmpm's version and `git describe` of the
# checkout. Run at every build (the target psmpm_version), not only at
# configure time: otherwise a build after new commits or edits reported
# the commit it was configured at in `psmpm --version` and summary.json.
# The header is rewritten only when its text changes, so an unchanged
# checkout recompiles nothing.
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
# Through a file of this run's own and an atomic rename: ctest builds
# tests in parallel, each build runs this script, and configure_file()
# straight into OUTPUT shares its temporary file OUTPUT.tmp between the
# runs, so that one run could remove it under the other ("No such file or
# directory", a test that failed to build in CI).
string(RANDOM LENGTH 16 _tag)
set(_own ${OUTPUT}.${_tag})
configure_file(${SOURCE_DIR}/source/base/version_info.h.in ${_own} @ONLY)
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} _old)
  file(READ ${_own} _new)
  if(_old STREQUAL _new)
    file(REMOVE ${_own})
    return()
  endif()
endif()
file(RENAME ${_own} ${OUTPUT})
