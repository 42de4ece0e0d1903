# Installation (`cmake --install`) and the Debian package (`cpack -G DEB`); docs/install.md.
#
#   bin/cic
#   share/cic/settings/*.xml, *.xsd     the shipped settings (cic --settings NAME.xml finds them)
#   share/cic/settings/robots/*.xml     robot files the settings name
#   share/cic/examples/*.xml            example sweep files (their <base> rewritten for this layout)
#   share/doc/cic/                      README.md, docs/*.md, docs/img/*
#   share/man/man1/cic.1                made by `cic man` at build time
#   share/bash-completion/completions/cic   made by `cic completion` at build time
#   lib/libcic_*.a, include/cic/<layer>/   every library layer, the command line's included
#   lib/cmake/cic/cicConfig*.cmake      find_package(cic): targets cic::core ... cic::cli
#
# This file is also a script (cmake -P) for the build steps below: with CIC_RUN it
# runs `CIC_RUN CIC_ARG` into CIC_OUT; with CIC_EXAMPLE_IN it writes the installed
# form of an example sweep file to CIC_EXAMPLE_OUT.

if(CMAKE_SCRIPT_MODE_FILE)
  if(DEFINED CIC_RUN)
    # A sanitizer build (CIC_SANITIZE, CIC_FUZZ) must not fail here on a leak report.
    if(DEFINED ENV{ASAN_OPTIONS})
      set(ENV{ASAN_OPTIONS} "$ENV{ASAN_OPTIONS}:detect_leaks=0")
    else()
      set(ENV{ASAN_OPTIONS} "detect_leaks=0")
    endif()
    execute_process(COMMAND "${CIC_RUN}" ${CIC_ARG} OUTPUT_FILE "${CIC_OUT}.tmp" RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      file(REMOVE "${CIC_OUT}.tmp")
      message(FATAL_ERROR "`${CIC_RUN} ${CIC_ARG}` failed (${rc})")
    endif()
    file(RENAME "${CIC_OUT}.tmp" "${CIC_OUT}")
  elseif(DEFINED CIC_EXAMPLE_IN)
    # In the source tree examples sit in experiments/examples/ and name
    # ../../settings/X; installed they sit in share/cic/examples/ next to share/cic/settings/.
    file(READ "${CIC_EXAMPLE_IN}" text)
    string(REPLACE "../../settings/" "../settings/" text "${text}")
    file(WRITE "${CIC_EXAMPLE_OUT}" "${text}")
  endif()
  return()
endif()

include(GNUInstallDirs)

set(CIC_INSTALL_SHAREDIR ${CMAKE_INSTALL_DATADIR}/cic)
set(_cic_gen ${PROJECT_BINARY_DIR}/generated)
set(_cic_this ${CMAKE_CURRENT_LIST_FILE})

# --- generated at build time: man page, bash completion, installed examples --
add_custom_command(OUTPUT ${_cic_gen}/cic.1
  COMMAND ${CMAKE_COMMAND} -E make_directory ${_cic_gen}
  COMMAND ${CMAKE_COMMAND} -DCIC_RUN=$<TARGET_FILE:cic> -DCIC_ARG=man -DCIC_OUT=${_cic_gen}/cic.1 -P ${_cic_this}
  DEPENDS cic ${_cic_this}
  COMMENT "Generating cic.1 (cic man)"
  VERBATIM)
add_custom_command(OUTPUT ${_cic_gen}/cic.bash-completion
  COMMAND ${CMAKE_COMMAND} -E make_directory ${_cic_gen}
  COMMAND ${CMAKE_COMMAND} -DCIC_RUN=$<TARGET_FILE:cic> -DCIC_ARG=completion
          -DCIC_OUT=${_cic_gen}/cic.bash-completion -P ${_cic_this}
  DEPENDS cic ${_cic_this}
  COMMENT "Generating the bash completion (cic completion)"
  VERBATIM)

file(GLOB _cic_examples CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/experiments/examples/*.xml)
set(_cic_installed_examples)
foreach(_ex IN LISTS _cic_examples)
  get_filename_component(_name ${_ex} NAME)
  set(_out ${_cic_gen}/examples/${_name})
  add_custom_command(OUTPUT ${_out}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${_cic_gen}/examples
    COMMAND ${CMAKE_COMMAND} -DCIC_EXAMPLE_IN=${_ex} -DCIC_EXAMPLE_OUT=${_out} -P ${_cic_this}
    DEPENDS ${_ex} ${_cic_this}
    VERBATIM)
  list(APPEND _cic_installed_examples ${_out})
endforeach()

add_custom_target(cic_install_files ALL
  DEPENDS ${_cic_gen}/cic.1 ${_cic_gen}/cic.bash-completion ${_cic_installed_examples})

# --- install rules ------------------------------------------------------------
install(TARGETS cic RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Videos and screenshot strips from an installed cic: the two scripts, beside it.
install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/render-video.sh DESTINATION ${CMAKE_INSTALL_BINDIR} RENAME cic-render-video)
install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/screenshot-strip.sh DESTINATION ${CMAKE_INSTALL_BINDIR}
        RENAME cic-screenshot-strip)

file(GLOB _cic_settings CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/settings/*.xml)
install(FILES ${_cic_settings}
              ${PROJECT_SOURCE_DIR}/settings/cic-settings.xsd
              ${PROJECT_SOURCE_DIR}/settings/cic-sweep.xsd
              ${PROJECT_SOURCE_DIR}/settings/cic-robot.xsd
              ${PROJECT_SOURCE_DIR}/settings/cic-population.xsd
              ${PROJECT_SOURCE_DIR}/settings/cic-gait.xsd
              ${PROJECT_SOURCE_DIR}/settings/cic-archive.xsd
        DESTINATION ${CIC_INSTALL_SHAREDIR}/settings)
file(GLOB _cic_robots CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/settings/robots/*.xml)
install(FILES ${_cic_robots} DESTINATION ${CIC_INSTALL_SHAREDIR}/settings/robots)
install(FILES ${_cic_installed_examples} DESTINATION ${CIC_INSTALL_SHAREDIR}/examples)

file(GLOB _cic_docs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/COPYING
              ${PROJECT_SOURCE_DIR}/CITATION.cff ${_cic_docs} DESTINATION ${CMAKE_INSTALL_DOCDIR})
file(GLOB _cic_doc_images CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/img/*)
install(FILES ${_cic_doc_images} DESTINATION ${CMAKE_INSTALL_DOCDIR}/img)

install(FILES ${_cic_gen}/cic.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${_cic_gen}/cic.bash-completion
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME cic)

# --- cic as a CMake package: find_package(cic) gives cic::core ... cic::cli
# (docs/install.md, "Building on cic"; docs/extending.md): the library layers
# and the application's, so that a project outside cic can register an
# experiment type and run it through cic's own command line (examples/plugin).
include(CMakePackageConfigHelpers)
set(CIC_PACKAGE_LAYERS core tree gp nn sim io experiments report search run study cli)
if(CIC_WITH_VIEWER)
  list(APPEND CIC_PACKAGE_LAYERS viz)
endif()
set(CIC_LIBRARY_LAYERS)
foreach(_layer IN LISTS CIC_PACKAGE_LAYERS)
  list(APPEND CIC_LIBRARY_LAYERS cic_${_layer})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/cic/${_layer} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cic)
endforeach()
install(TARGETS ${CIC_LIBRARY_LAYERS} EXPORT cicTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# What cicConfig.cmake must find again for the layers this build has.
set(CIC_PACKAGE_WITH_MPI ${CIC_WITH_MPI})
set(CIC_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/cic)
install(EXPORT cicTargets NAMESPACE cic:: DESTINATION ${CIC_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/cicConfig.cmake.in ${_cic_gen}/cicConfig.cmake
  INSTALL_DESTINATION ${CIC_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the library's API (docs/install.md).
write_basic_package_version_file(${_cic_gen}/cicConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${_cic_gen}/cicConfig.cmake ${_cic_gen}/cicConfigVersion.cmake DESTINATION ${CIC_INSTALL_CMAKEDIR})

# --- Debian package: cpack -G DEB (in the build folder) -----------------------
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME cic)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "cic")
set(CPACK_PACKAGE_CONTACT "cic maintainers <cic@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "evolutionary robotics with HyperGP, and symbolic regression")
set(CPACK_PACKAGE_DESCRIPTION
  "cic evolves walking controllers for simulated modular robots with HyperGP (hypercube-encoded
genetic programming evolving recurrent neural networks; ODE physics), and runs symbolic
regression with the same GP core. One settings file describes an experiment; each run
writes its effective settings, log, statistics and resumable population checkpoints.
Includes the thesis's settings files, robot files, example sweeps, the documentation,
a man page and bash completion.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)           # the .deb installs into /usr
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)            # cic_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)

# Libraries: dpkg-shlibdeps (dpkg-dev) reads them off the binary, with versions.
# Without it, the list it gives on Debian 12 (bookworm) for this configuration.
# Tools: cic runs gnuplot for its plots (Depends). POV-Ray and ffmpeg turn the scenes of
# `cic render` into videos (Recommends); xvfb-run (offscreen `cic view --screenshot`) and
# mpirun (docs/mpi.md) are Suggests.
set(_cic_tool_depends "gnuplot-nox | gnuplot")
# CPackDeb's shlibdeps also needs the `file` program (found missing on a fresh
# minimal Debian, where `cpack -G DEB` then failed): without either, the list below.
find_program(CIC_DPKG_SHLIBDEPS dpkg-shlibdeps)
find_program(CIC_FILE_PROGRAM file)
mark_as_advanced(CIC_DPKG_SHLIBDEPS CIC_FILE_PROGRAM)
if(CIC_DPKG_SHLIBDEPS AND CIC_FILE_PROGRAM)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)           # CPack appends them to the list below
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${_cic_tool_depends}")
else()
  set(_cic_lib_depends "libc6 (>= 2.35), libfmt9 (>= 9.1.0+ds1), libgcc-s1 (>= 3.0), libode8 (>= 2:0.16.2), libpagmo8 (>= 2.18.0), libstdc++6 (>= 11), libxml2 (>= 2.7.4)")
  if(CIC_WITH_VIEWER)
    string(APPEND _cic_lib_depends ", libopenscenegraph161 (>= 3.6.5+dfsg1)")
  endif()
  if(CIC_WITH_MPI)
    string(APPEND _cic_lib_depends ", libopenmpi3 (>= 4.1.4)")
  endif()
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${_cic_lib_depends}, ${_cic_tool_depends}")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "povray, ffmpeg")
set(_cic_suggests "xvfb")
if(CIC_WITH_MPI)
  string(APPEND _cic_suggests ", openmpi-bin")
endif()
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "${_cic_suggests}")

include(CPack)

# tests/cli/install_test.cpp installs and packages this build: it needs the
# generated files, and the cmake/cpack of this build.
if(TARGET cic_test_cli)
  add_dependencies(cic_test_cli cic_install_files)
  # An out-of-tree build against sanitized libraries needs the same runtime.
  set(_cic_example_flags "")
  if(CIC_SANITIZE)
    set(_cic_example_flags "-fsanitize=address,undefined -DEIGEN_MALLOC_ALREADY_ALIGNED=1")
  endif()
  target_compile_definitions(cic_test_cli PRIVATE
    CIC_CMAKE_COMMAND="${CMAKE_COMMAND}" CIC_CPACK_COMMAND="${CMAKE_CPACK_COMMAND}"
    CIC_EXAMPLE_CXX_FLAGS="${_cic_example_flags}")
endif()
