# scripts/bench-gp-tricks.sh undoes each GP-loop trick with a patch in
# benchmarks/variants/. A patch that no longer applies to src/gp/evolution.cpp
# would leave the trick unmeasured: this test fails first. Outside a git
# checkout (a source tarball) there is nothing to apply against: it passes.
find_program(GIT git)
if(NOT GIT OR NOT EXISTS "${SOURCE_DIR}/.git")
  message(STATUS "not a git checkout: skipped")
  return()
endif()
file(GLOB patches "${SOURCE_DIR}/benchmarks/variants/*.patch")
if(NOT patches)
  message(FATAL_ERROR "no patches in benchmarks/variants/")
endif()
foreach(p IN LISTS patches)
  # safe.directory: CI may check out as another user than the one running the tests.
  execute_process(COMMAND ${GIT} -c safe.directory=* -C "${SOURCE_DIR}" apply --check "${p}"
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${p} no longer applies to the sources:\n${err}")
  endif()
endforeach()
