# `cmake --install build --prefix P` (README, "Install"): a relocatable tree
#   P/bin/morphcut-city, P/bin/morphcut           the tools (our libraries are static: nothing to find)
#   P/lib/libmc_core.a, P/lib/cmake/morphcut/     MorphCut as a library: find_package(morphcut) gives
#                                                 morphcut::core (geometry and the algorithm, core/)
#   P/include/morphcut/core/*.hpp                 its headers, included as "core/decompose.hpp"
#   P/share/morphcut/                             config/lod.yaml, the docs, the demo tile
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# No RPATH: our libraries are static and every shared one is the system's. An install RPATH
# made CMake pad the build tree's binaries with an empty RUNPATH (":::…", to be rewritten at
# install), and an empty entry is the current directory: every start looked for its dozen shared
# libraries in the caller's directory first (about 150 failed opens, and a library planted there
# would have been loaded). Test `binaries_search_no_relative_library_path`.
install(TARGETS morphcut_city morphcut RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

target_include_directories(mc_core PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/morphcut>)
set_target_properties(mc_core PROPERTIES EXPORT_NAME core)
add_library(morphcut::core ALIAS mc_core)
install(TARGETS mc_core EXPORT morphcutTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY core/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/morphcut/core FILES_MATCHING PATTERN "*.hpp" PATTERN "*.def")
install(EXPORT morphcutTargets NAMESPACE morphcut:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/morphcut)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/morphcutConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/morphcutConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/morphcut)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/morphcutConfigVersion.cmake VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/morphcutConfig.cmake ${CMAKE_BINARY_DIR}/morphcutConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/morphcut)

install(FILES config/lod.yaml README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/morphcut)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/morphcut/docs)
install(FILES datasets/3dbag/3dbag_5910.city.json DESTINATION ${CMAKE_INSTALL_DATADIR}/morphcut/datasets)
