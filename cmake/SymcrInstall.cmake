# Install and export rules: the runtime library and headers, symcr-gen, the symcr CLI (which
# symcr_add_compatibility_test runs), the CMake package (symcrConfig.cmake with
# symcr_add_checkpointing) and, for other build systems, pkg-config's symcr.pc (the compiler
# wrappers symcr-c++ and symcr-cc are installed by wrapper/). All in the component "sdk", so
# `cmake --install <build> --component sdk` installs what a consuming project needs.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS symcr_runtime symcr_device EXPORT symcrTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT sdk
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT sdk)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/include/symcr
                  ${PROJECT_SOURCE_DIR}/runtime/device/include/symcr
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT sdk)
if(TARGET symcr-gen)
  set_target_properties(symcr-gen PROPERTIES EXPORT_NAME gen)
  install(TARGETS symcr-gen EXPORT symcrTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
          COMPONENT sdk)
endif()
if(TARGET symcr-cli)
  set_target_properties(symcr-cli PROPERTIES EXPORT_NAME cli)
  install(TARGETS symcr-cli EXPORT symcrTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
          COMPONENT sdk)
endif()
install(EXPORT symcrTargets NAMESPACE symcr:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/symcr
        COMPONENT sdk)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/symcrConfig.cmake.in
  ${PROJECT_BINARY_DIR}/symcrConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/symcr)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/symcrConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/symcrConfig.cmake
              ${PROJECT_BINARY_DIR}/symcrConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/SymcrCheckpointing.cmake
              ${PROJECT_SOURCE_DIR}/cmake/SymcrCompatibility.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/symcr COMPONENT sdk)

# pkg-config (symcr.pc) for builds outside CMake: the runtime's flags and the tools' paths. Its
# prefix is found from where the file is (pkg-config's ${pcfiledir}), so the installed tree may
# move, as the CMake package may.
file(RELATIVE_PATH SYMCR_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig
     ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" SYMCR_PC_TO_PREFIX "${SYMCR_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/symcr.pc.in ${PROJECT_BINARY_DIR}/symcr.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/symcr.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT sdk)
