# `cmake --install`: the core library, its public headers, and a package config so that another
# project finds it with find_package(penumbra CONFIG REQUIRED) and links penumbra::core. The
# command-line tool is installed too; the reference renderer and the viewer stay in the tree.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(PENUMBRA_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/penumbra)
install(TARGETS penumbra_core EXPORT penumbraTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS penumbra RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/include/penumbra DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PENUMBRA_TECHNIQUE_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/penumbra)
install(EXPORT penumbraTargets NAMESPACE penumbra:: DESTINATION ${PENUMBRA_CMAKE_DIR})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/penumbraConfig.cmake.in
  ${CMAKE_BINARY_DIR}/penumbraConfig.cmake INSTALL_DESTINATION ${PENUMBRA_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/penumbraConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/penumbraConfig.cmake ${CMAKE_BINARY_DIR}/penumbraConfigVersion.cmake
  DESTINATION ${PENUMBRA_CMAKE_DIR})
