# Layers.UpwardIncludeFailsTheCheck: scripts/check-layers.py (which the build
# runs before any layer compiles) accepts the real tree and refuses a copy of a
# layer that includes a header of a layer above it.
#   cmake -DSOURCE_DIR=... -DWORK_DIR=... -P upward_include_test.cmake
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(check ${SOURCE_DIR}/scripts/check-layers.py)

execute_process(COMMAND ${Python3_EXECUTABLE} ${check} ${SOURCE_DIR} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the source tree breaks the layer order:\n${err}")
endif()

file(REMOVE_RECURSE ${WORK_DIR})

# The application's rooms keep their order too: report < run < study < cli.
foreach(pair "report;run/run.hpp" "run;study/sweep.hpp" "study;cli/cli.hpp")
  list(GET pair 0 low)
  list(GET pair 1 high)
  file(REMOVE_RECURSE ${WORK_DIR})
  file(MAKE_DIRECTORY ${WORK_DIR}/src/${low})
  file(WRITE ${WORK_DIR}/src/${low}/bad.cpp "#include \"cic/experiments/experiment.hpp\"\n#include \"cic/${high}\"\n")
  execute_process(COMMAND ${Python3_EXECUTABLE} ${check} ${WORK_DIR} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "an upward include (${low} -> cic/${high}) passed the check")
  endif()
  if(NOT err MATCHES "src/${low}/bad.cpp:2: layer ${low} includes cic/${high}")
    message(FATAL_ERROR "the refusal of ${low} -> cic/${high} does not name the file, line and layers:\n${err}")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/include/cic/sim ${WORK_DIR}/src/sim)
file(WRITE ${WORK_DIR}/src/sim/ok.cpp "#include \"cic/core/rng.hpp\"\n#include \"world.hpp\"\n")
file(WRITE ${WORK_DIR}/include/cic/sim/bad.hpp "#pragma once\n#include \"cic/io/settings.hpp\"\n")
execute_process(COMMAND ${Python3_EXECUTABLE} ${check} ${WORK_DIR} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "an upward include (sim -> io) passed the check")
endif()
if(NOT err MATCHES "include/cic/sim/bad.hpp:2: layer sim includes cic/io/settings.hpp from layer io")
  message(FATAL_ERROR "the refusal does not name the file, line and layers:\n${err}")
endif()
if(err MATCHES "ok.cpp")
  message(FATAL_ERROR "a downward and a private include were refused:\n${err}")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
