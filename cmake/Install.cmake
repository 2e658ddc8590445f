# `cmake --install BUILD --prefix P` installs the hpcontact executable, the static library with its
# public headers (P/include/hpcontact/<module>/...), a CMake package (find_package(hpcontact):
# the target hpcontact::hpcontact carrying its dependencies) and a pkg-config file (hpcontact.pc).
include(CMakePackageConfigHelpers)

install(TARGETS hpcontact_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The interface targets defined in cmake/Dependencies.cmake travel with the library: a static
# library's private dependencies are link dependencies of whoever links it.
install(TARGETS hpcontact hpcontact_cholmod hpcontact_ptscotch hpcontact_gmsh hpcontact_warnings
        EXPORT hpcontactTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY lib/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hpcontact FILES_MATCHING PATTERN "*.hpp")
install(EXPORT hpcontactTargets NAMESPACE hpcontact:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hpcontact)

configure_package_config_file(cmake/hpcontactConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/hpcontactConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hpcontact)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/hpcontactConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hpcontactConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/hpcontactConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hpcontact)

file(RELATIVE_PATH HPCONTACT_PC_TO_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
configure_file(cmake/hpcontact.pc.in ${CMAKE_CURRENT_BINARY_DIR}/hpcontact.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hpcontact.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
