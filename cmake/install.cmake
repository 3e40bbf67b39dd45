# `cmake --install BUILD --prefix P` (docs/architecture.md, "Package"): the rearm program in
# P/bin, its plotting scripts in P/share/rearm/plot (found relative to the program), every
# module's library with its headers (P/include/rearm/<module>/, the internal ones left out) and
# the package files P/lib/cmake/rearm/, so that a downstream project writes
#   find_package(rearm 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE rearm::experiment)
# (examples/downstream).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

get_property(rearm_modules GLOBAL PROPERTY REARM_MODULES)
set(rearm_libraries rearm_warnings)
foreach(m ${rearm_modules})
  list(APPEND rearm_libraries rearm_${m})
  install(DIRECTORY framework/${m}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rearm/${m}
          FILES_MATCHING PATTERN "*.h" PATTERN "*_internal.h" EXCLUDE)
endforeach()
list(APPEND rearm_libraries rearm_baselines)
install(DIRECTORY baselines/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rearm/baselines
        FILES_MATCHING PATTERN "*.h")
install(TARGETS ${rearm_libraries} EXPORT rearmTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS rearm RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY experiments/plot/ DESTINATION ${CMAKE_INSTALL_DATADIR}/rearm/plot
        FILES_MATCHING PATTERN "*.py")

set(rearm_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/rearm)
install(EXPORT rearmTargets NAMESPACE rearm:: DESTINATION ${rearm_cmake_dir})
configure_package_config_file(cmake/rearmConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/generated/rearmConfig.cmake
                              INSTALL_DESTINATION ${rearm_cmake_dir})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/generated/rearmConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/generated/rearmConfig.cmake
              ${CMAKE_BINARY_DIR}/generated/rearmConfigVersion.cmake
        DESTINATION ${rearm_cmake_dir})
