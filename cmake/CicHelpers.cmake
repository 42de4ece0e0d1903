# Helpers shared by the top-level CMakeLists.txt.
include(GNUInstallDirs)   # CMAKE_INSTALL_INCLUDEDIR for the layers' installed include path

# cic_layer(NAME DIR): a static library from every .cpp below DIR.
# Globbing keeps one layer = one folder; CONFIGURE_DEPENDS re-globs on build.
function(cic_layer name dir)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
  if(NOT sources)
    set(sources ${PROJECT_SOURCE_DIR}/cmake/empty.cpp)
  endif()
  add_library(${name} STATIC ${sources})
  # Public headers only (include/cic/<layer>/); private ones sit beside their
  # sources. Which layer may include which is checked by scripts/check-layers.py.
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
                                            $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # Installed as cic::<layer> (cmake/CicInstall.cmake, cicConfig.cmake).
  string(REGEX REPLACE "^cic_" "" _export ${name})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${_export})
  add_dependencies(${name} cic_layer_check)   # an upward include fails the build
  if(CIC_LAYER_PIC)   # linked into the Python module too (cmake/CicPython.cmake)
    set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_compile_options(${name} PRIVATE -fno-semantic-interposition)
  endif()
  set_property(GLOBAL APPEND PROPERTY CIC_LAYERS ${name})
endfunction()

# cic_optional_feature(OPTION DESCRIPTION PACKAGE pkg [COMPONENTS ...]):
# AUTO turns the option ON when the package is found and says what was left out.
# A macro, so the package's variables (e.g. OPENSCENEGRAPH_LIBRARIES) reach the caller.
macro(cic_optional_feature _cof_opt _cof_desc)
  cmake_parse_arguments(_COF "" "PACKAGE" "COMPONENTS" ${ARGN})
  set(_cof_wanted ${${_cof_opt}})
  if(_cof_wanted STREQUAL "OFF")
    set_property(GLOBAL APPEND PROPERTY CIC_SUMMARY "  ${_cof_desc}: off (${_cof_opt}=OFF)")
  else()
    if(_COF_COMPONENTS)
      find_package(${_COF_PACKAGE} QUIET COMPONENTS ${_COF_COMPONENTS})
    else()
      find_package(${_COF_PACKAGE} QUIET)
    endif()
    string(TOUPPER ${_COF_PACKAGE} _cof_upper)
    if(${_COF_PACKAGE}_FOUND OR ${_cof_upper}_FOUND)
      set(${_cof_opt} ON)
      set_property(GLOBAL APPEND PROPERTY CIC_SUMMARY "  ${_cof_desc}: ON")
    elseif(_cof_wanted STREQUAL "ON")
      message(FATAL_ERROR "${_cof_opt}=ON but ${_COF_PACKAGE} was not found (run scripts/install-deps.sh)")
    else()
      set(${_cof_opt} OFF)
      set_property(GLOBAL APPEND PROPERTY CIC_SUMMARY
        "  ${_cof_desc}: LEFT OUT (${_COF_PACKAGE} not found; run scripts/install-deps.sh)")
    endif()
  endif()
endmacro()

function(cic_print_summary)
  get_property(lines GLOBAL PROPERTY CIC_SUMMARY)
  message(STATUS "cic ${PROJECT_VERSION} optional parts:")
  foreach(l IN LISTS lines)
    message(STATUS "${l}")
  endforeach()
endfunction()
