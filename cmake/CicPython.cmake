# The Python package `cic` (python/, docs/python.md): pybind11 bindings over the
# run layer's EvaluationSession, for Debian's /usr/bin/python3 with numpy and
# pandas from Debian. Built by default when pybind11, the Python headers and
# numpy are present (scripts/install-deps.sh all installs them).
#
# cic_python_detect(): before any library is defined, so that with the package
# every layer is compiled position-independent (a Python module is a shared
# object; cic_layer adds -fno-semantic-interposition, which keeps the inlining
# of a non-PIC build).
# cic_python_package(): the module, its pure-Python files, tests and install.

set(CIC_WITH_PYTHON AUTO CACHE STRING "Build the Python package (pybind11): AUTO, ON or OFF")

macro(cic_python_detect)
  set(_cic_py_why "")
  if(CIC_WITH_PYTHON STREQUAL "OFF")
    set(_cic_py_why "CIC_WITH_PYTHON=OFF")
  elseif(CIC_SANITIZE OR CIC_FUZZ)
    # A sanitized module cannot load into an uninstrumented interpreter.
    set(_cic_py_why "not in sanitizer or fuzzing builds")
  else()
    if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
      set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the package is built for (Debian's)")
    endif()
    set(PYBIND11_FINDPYTHON ON)
    find_package(Python QUIET COMPONENTS Interpreter Development.Module)
    find_package(pybind11 CONFIG QUIET)
    set(_cic_numpy 1)
    if(Python_FOUND)
      execute_process(COMMAND ${Python_EXECUTABLE} -c "import numpy" RESULT_VARIABLE _cic_numpy
                      OUTPUT_QUIET ERROR_QUIET)
    endif()
    if(NOT Python_FOUND)
      set(_cic_py_why "Python headers not found (python3-dev)")
    elseif(NOT pybind11_FOUND)
      set(_cic_py_why "pybind11 not found (pybind11-dev)")
    elseif(NOT _cic_numpy EQUAL 0)
      set(_cic_py_why "numpy not importable by ${Python_EXECUTABLE} (python3-numpy)")
    endif()
  endif()
  if(_cic_py_why STREQUAL "")
    set(CIC_HAVE_PYTHON ON)
    set(CIC_LAYER_PIC ON)   # cic_layer (CicHelpers.cmake) compiles every layer position-independent
    set_property(GLOBAL APPEND PROPERTY CIC_SUMMARY "  Python package (${Python_EXECUTABLE}): ON")
  else()
    set(CIC_HAVE_PYTHON OFF)
    if(CIC_WITH_PYTHON STREQUAL "ON" AND NOT CIC_SANITIZE AND NOT CIC_FUZZ)
      message(FATAL_ERROR "CIC_WITH_PYTHON=ON but ${_cic_py_why} (run scripts/install-deps.sh all)")
    endif()
    set_property(GLOBAL APPEND PROPERTY CIC_SUMMARY "  Python package: LEFT OUT (${_cic_py_why})")
  endif()
endmacro()

function(cic_python_package)
  if(NOT CIC_HAVE_PYTHON)
    # scripts/run.sh builds this target: without the package it only says why.
    if(NOT CIC_SANITIZE AND NOT CIC_FUZZ)
      add_custom_target(cic_python COMMAND ${CMAKE_COMMAND} -E echo "cic: the Python package was left out: ${_cic_py_why}"
                        VERBATIM)
    endif()
    return()
  endif()
  set(_pkg ${PROJECT_BINARY_DIR}/python/cic)
  pybind11_add_module(cic_python_core MODULE NO_EXTRAS ${PROJECT_SOURCE_DIR}/python/src/module.cpp)
  target_link_libraries(cic_python_core PRIVATE cic_run)
  set_target_properties(cic_python_core PROPERTIES OUTPUT_NAME _core LIBRARY_OUTPUT_DIRECTORY ${_pkg})
  # The build tree's package runs the build tree's cic as its worker.
  file(GENERATE OUTPUT ${_pkg}/_build.py CONTENT
"# Made by CMake for the build tree: the cic binary whose `cic worker` serves evaluations.
CIC_EXECUTABLE = \"$<TARGET_FILE:cic>\"
")
  # The package's files: its modules, their type stubs and py.typed (PEP 561).
  file(GLOB _py CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/python/cic/*.py ${PROJECT_SOURCE_DIR}/python/cic/*.pyi
       ${PROJECT_SOURCE_DIR}/python/cic/py.typed)
  set(_copies)
  foreach(_f IN LISTS _py)
    get_filename_component(_n ${_f} NAME)
    add_custom_command(OUTPUT ${_pkg}/${_n} COMMAND ${CMAKE_COMMAND} -E copy_if_different ${_f} ${_pkg}/${_n}
                       DEPENDS ${_f} VERBATIM)
    list(APPEND _copies ${_pkg}/${_n})
  endforeach()
  # A dist-info beside the package, so that importlib.metadata (and pip list) know
  # cic and its version, from the build tree as once installed.
  set(_dist cic-${PROJECT_VERSION}.dist-info)
  file(WRITE ${PROJECT_BINARY_DIR}/python/${_dist}/METADATA
"Metadata-Version: 2.1
Name: cic
Version: ${PROJECT_VERSION}
Summary: Evolve walking controllers for modular robots with HyperGP: cic's robots scored from Python
License: LGPL-3.0-or-later
Requires-Python: >=3.9
Requires-Dist: numpy
Requires-Dist: pandas
")
  file(WRITE ${PROJECT_BINARY_DIR}/python/${_dist}/INSTALLER "cmake\n")
  file(WRITE ${PROJECT_BINARY_DIR}/python/${_dist}/top_level.txt "cic\n")
  add_custom_target(cic_python ALL DEPENDS ${_copies} cic_python_core cic)

  # Installed beside Debian's own packages: /usr/lib/python3/dist-packages for
  # the .deb (prefix /usr), PREFIX/lib/python3.X/dist-packages otherwise (on
  # Debian's path for /usr/local). Decided at install time, when the prefix is known.
  set(_minor ${Python_VERSION_MINOR})
  file(WRITE ${PROJECT_BINARY_DIR}/generated/python_build_installed.py
"# Installed: the cic binary four folders up, in PREFIX/bin (lib/python3*/dist-packages/cic).
import os as _os

CIC_EXECUTABLE = _os.path.normpath(_os.path.join(_os.path.dirname(_os.path.abspath(__file__)), \"..\", \"..\", \"..\", \"..\", \"bin\", \"cic\"))
")
  install(CODE "
    if(\"\${CMAKE_INSTALL_PREFIX}\" STREQUAL \"/usr\")
      set(_cic_pydir \"\${CMAKE_INSTALL_PREFIX}/lib/python3/dist-packages/cic\")
    else()
      set(_cic_pydir \"\${CMAKE_INSTALL_PREFIX}/lib/python3.${_minor}/dist-packages/cic\")
    endif()
    file(INSTALL ${_py} \"$<TARGET_FILE:cic_python_core>\" DESTINATION \"\${_cic_pydir}\")
    file(INSTALL \"${PROJECT_BINARY_DIR}/generated/python_build_installed.py\" DESTINATION \"\${_cic_pydir}\"
         RENAME _build.py)
    file(INSTALL \"${PROJECT_BINARY_DIR}/python/${_dist}\" DESTINATION \"\${_cic_pydir}/..\")
  ")
  file(GLOB _examples CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/examples/python/*.py ${PROJECT_SOURCE_DIR}/examples/python/*.m)
  install(FILES ${_examples} DESTINATION ${CMAKE_INSTALL_DATADIR}/cic/examples/python)
endfunction()
