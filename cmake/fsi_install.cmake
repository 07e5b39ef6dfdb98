# `cmake --install build --prefix P`: the programs, the participant library with its
# headers, a pkg-config file and a CMake package, so that a solver written elsewhere
# builds against P (docs/participant_api.md, "Using the participant library from
# another project"). Nothing installed names the configure-time prefix: the .pc file
# and the CMake package find P from where they are, so --prefix at install time works.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Every program of these folders (fsi-run and the other front-end programs, the
# coupler, each solver, the example participants), found rather than listed so that a
# new solver is installed too. fsi-run starts the coupler, the recorder and the
# named solvers from its own folder (launch/run_plan.c), so they all go to bin/.
function(fsi_collect_programs dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  set(programs ${${out}})
  foreach(t ${targets})
    get_target_property(type ${t} TYPE)
    if(type STREQUAL "EXECUTABLE")
      list(APPEND programs ${t})
    endif()
  endforeach()
  set(${out} ${programs} PARENT_SCOPE)
  foreach(sub ${subdirs})
    fsi_collect_programs(${sub} ${out})
    set(${out} ${${out}} PARENT_SCOPE)
  endforeach()
endfunction()
set(FSI_PROGRAMS "")
foreach(dir coupler solid_solver fluid_solver launch examples)
  fsi_collect_programs(${CMAKE_SOURCE_DIR}/${dir} FSI_PROGRAMS)
endforeach()
install(TARGETS ${FSI_PROGRAMS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(PROGRAMS ${CMAKE_SOURCE_DIR}/launch/spy.sh DESTINATION ${CMAKE_INSTALL_BINDIR}
        RENAME fsi-spy)

# The library: one static archive with the message types inside.
install(TARGETS fsi_participant ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})

# Its headers, under include/fsi (the include path is P/include/fsi, so programs
# write #include "participant.h" in the tree and outside it alike). dim.h is
# installed with the build's dimension fixed: the library ignores interface
# messages of another one.
set(FSI_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/fsi)
foreach(h ${FSI_PARTICIPANT_HEADERS})
  if(NOT h STREQUAL "dim.h")
    install(FILES ${CMAKE_SOURCE_DIR}/core/${h} DESTINATION ${FSI_INSTALL_INCLUDEDIR})
  endif()
endforeach()
file(READ ${CMAKE_SOURCE_DIR}/core/dim.h dim_text)
string(REPLACE "#ifndef FSI_DIM\n#define FSI_DIM 2\n#endif"
               "/* Fixed by the build this copy was installed from. */\n#define FSI_DIM ${FSI_DIM}"
               installed_dim_text "${dim_text}")
if(installed_dim_text STREQUAL dim_text)
  message(FATAL_ERROR "cmake/fsi_install.cmake: core/dim.h no longer has the default it replaces")
endif()
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/install/dim.h CONTENT "${installed_dim_text}")
install(FILES ${CMAKE_BINARY_DIR}/install/dim.h DESTINATION ${FSI_INSTALL_INCLUDEDIR})

# pkg-config: fsi-participant.pc, relative to its own folder.
file(RELATIVE_PATH FSI_PC_TO_PREFIX
     /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
configure_file(${CMAKE_SOURCE_DIR}/cmake/fsi-participant.pc.in
               ${CMAKE_BINARY_DIR}/install/fsi-participant.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/install/fsi-participant.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# CMake: find_package(fsi) gives the imported target fsi::participant.
set(FSI_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/fsi)
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/fsiConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/install/fsiConfig.cmake
                              INSTALL_DESTINATION ${FSI_CMAKE_DIR}
                              PATH_VARS CMAKE_INSTALL_LIBDIR FSI_INSTALL_INCLUDEDIR
                                        CMAKE_INSTALL_BINDIR)
# The protocol version is checked on every message: a solver and the coupler it runs
# with must come from the same minor version.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/install/fsiConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/install/fsiConfig.cmake
              ${CMAKE_BINARY_DIR}/install/fsiConfigVersion.cmake
        DESTINATION ${FSI_CMAKE_DIR})

# The message types for Python (with python/fsi_traffic.py) and, when built, for
# lcm-spy. share/fsi/python rather than a dist-packages folder: the generated
# package is called `fsi`, too general a name to put on every program's sys.path.
install(DIRECTORY ${FSI_PYTHON_DIR}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/fsi/python
        PATTERN __pycache__ EXCLUDE)
if(FSI_LCMTYPES_JAR)
  install(FILES ${FSI_LCMTYPES_JAR} DESTINATION ${CMAKE_INSTALL_DATADIR}/fsi/java)
endif()
