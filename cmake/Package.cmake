# Install rules and the package files, so a host finds the libraries with
#   find_package(RasterLiquids CONFIG REQUIRED)  ->  RasterLiquids::engine, RasterLiquids::liquid
# against an install prefix (cmake --install) or this build tree, and RasterLiquids::vdb where
# OpenVDB was found. Only the public headers are installed: the source tree's include/ folder,
# under include/rasterliquids/ with the same paths (#include "liquid/node.h"); the internals
# beside the sources stay out.
# The SPIR-V stays embedded in the (static) shader libraries, which are installed beside them.
include(CMakePackageConfigHelpers)
set(package_dir "${CMAKE_INSTALL_LIBDIR}/cmake/RasterLiquids")

install(TARGETS rasterliquids_engine rasterliquids_engine_shaders rasterliquids_liquid rasterliquids_liquid_shaders
        EXPORT RasterLiquidsTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${RASTERLIQUIDS_INCLUDE_DIR})
install(DIRECTORY include/ DESTINATION ${RASTERLIQUIDS_INCLUDE_DIR} FILES_MATCHING PATTERN "*.h")
install(EXPORT RasterLiquidsTargets NAMESPACE RasterLiquids:: DESTINATION ${package_dir})
# The OpenVDB export in a file of its own, loaded by the package only where OpenVDB is found again.
if(TARGET rasterliquids_vdb)
  install(TARGETS rasterliquids_vdb EXPORT RasterLiquidsVdbTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${RASTERLIQUIDS_INCLUDE_DIR})
  install(EXPORT RasterLiquidsVdbTargets NAMESPACE RasterLiquids:: DESTINATION ${package_dir})
  export(EXPORT RasterLiquidsVdbTargets NAMESPACE RasterLiquids:: FILE "${PROJECT_BINARY_DIR}/RasterLiquidsVdbTargets.cmake")
endif()

# The shipped scenes (assets/scenes/*.json), for hosts and tools: RasterLiquids_SCENES_DIR.
set(RASTERLIQUIDS_SCENES_DIR "${CMAKE_INSTALL_DATADIR}/rasterliquids/scenes")
install(DIRECTORY assets/scenes/ DESTINATION ${RASTERLIQUIDS_SCENES_DIR} FILES_MATCHING PATTERN "*.json" PATTERN "*.obj")

configure_package_config_file(cmake/RasterLiquidsConfig.cmake.in
  "${PROJECT_BINARY_DIR}/RasterLiquidsConfig.cmake" INSTALL_DESTINATION ${package_dir}
  PATH_VARS RASTERLIQUIDS_SCENES_DIR)
write_basic_package_version_file("${PROJECT_BINARY_DIR}/RasterLiquidsConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/RasterLiquidsConfig.cmake" "${PROJECT_BINARY_DIR}/RasterLiquidsConfigVersion.cmake"
              cmake/EmbedShaders.cmake
        DESTINATION ${package_dir})

# The build tree as a package too (find_package with RasterLiquids_DIR=<build>); its scenes are the
# source tree's (this file is not installed).
file(WRITE "${PROJECT_BINARY_DIR}/RasterLiquidsBuildTree.cmake"
     "set(RasterLiquids_SCENES_DIR \"${PROJECT_SOURCE_DIR}/assets/scenes\")\n")
export(EXPORT RasterLiquidsTargets NAMESPACE RasterLiquids:: FILE "${PROJECT_BINARY_DIR}/RasterLiquidsTargets.cmake")
file(COPY cmake/EmbedShaders.cmake DESTINATION "${PROJECT_BINARY_DIR}")
