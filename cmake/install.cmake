# `cmake --install`: the stage libraries, their headers, the freestand executable and a CMake
# package, so another project does find_package(freestand) and links freestand::freestand
# (README, "Use as a CMake package"; tests/package checks it).
#
# Installed tree (GNUInstallDirs):
#   bin/freestand
#   include/freestand/<stage>/*.hpp          one folder per stage, as in src/ (not *_detail.hpp,
#                                            which only the stage's sources include)
#   lib/libfreestand_<stage>.a
#   lib/cmake/freestand/freestandConfig.cmake, freestandConfigVersion.cmake,
#                       freestandTargets.cmake, freestandTargets-<config>.cmake
#
# The headers include each other as "core/record.hpp", so include/freestand is on the installed
# targets' include path as well as include/, where a consumer writes <freestand/core/record.hpp>.
# The command line's own libraries (freestand_cli_options, freestand_cli_support) are not
# installed: they are the executable's parsing and printing, not the library's API.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(FREESTAND_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/freestand)

# freestand::freestand links every stage. The executable already owns the name `freestand`,
# so the target is freestand_package, exported as `freestand`; the alias lets a project that
# adds this tree with add_subdirectory() link the same name.
add_library(freestand_package INTERFACE)
set_target_properties(freestand_package PROPERTIES EXPORT_NAME freestand)
add_library(freestand::freestand ALIAS freestand_package)

set(FREESTAND_INSTALLED_TARGETS freestand_package)
foreach(stage IN LISTS FREESTAND_STAGES)
  if(TARGET freestand_${stage})
    target_link_libraries(freestand_package INTERFACE freestand_${stage})
    # freestand::core, freestand::spectra, ... for a consumer that needs one stage only.
    set_target_properties(freestand_${stage} PROPERTIES EXPORT_NAME ${stage})
    add_library(freestand::${stage} ALIAS freestand_${stage})
    list(APPEND FREESTAND_INSTALLED_TARGETS freestand_${stage})
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/${stage}/
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/freestand/${stage}
            FILES_MATCHING PATTERN "*.hpp" PATTERN "*_detail.hpp" EXCLUDE)
  endif()
endforeach()

# The headers are C++20: a consumer compiles them as such whatever its own default.
target_compile_features(freestand_core INTERFACE cxx_std_20)

# Static libraries compiled with the sanitizers need their runtimes wherever they are linked;
# the build tree gets them from freestand_options, which is not installed.
if(FREESTAND_SANITIZE OR FREESTAND_FUZZ)
  target_link_options(freestand_core INTERFACE $<INSTALL_INTERFACE:-fsanitize=address,undefined>)
endif()

install(TARGETS ${FREESTAND_INSTALLED_TARGETS} EXPORT freestandTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} ${CMAKE_INSTALL_INCLUDEDIR}/freestand)
install(TARGETS freestand RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT freestandTargets NAMESPACE freestand:: DESTINATION ${FREESTAND_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/freestandConfig.cmake.in
  ${PROJECT_BINARY_DIR}/freestandConfig.cmake
  INSTALL_DESTINATION ${FREESTAND_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the API, so 0.1 accepts 0.1.* only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/freestandConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/freestandConfig.cmake
              ${PROJECT_BINARY_DIR}/freestandConfigVersion.cmake
        DESTINATION ${FREESTAND_INSTALL_CMAKEDIR})
