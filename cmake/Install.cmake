# `cmake --install`: the libraries as the CMake package exactgeo (find_package(exactgeo),
# targets exactgeo::predicates, ::parallel, ::io, ::boxes, ::surface, ::mesh, ::ccd, ::inside,
# ::remesh and, where assimp is found, ::mesh_files), their headers, and the command-line
# tool. The libraries are static, so their private dependencies are part of the export;
# exactgeoConfig.cmake finds them again (tests/install/consumer uses it all). mesh_files is
# exported on its own, so that a consumer without assimp still gets every other target.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(EXACTGEO_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/exactgeo)

# A public usage requirement of predicates (consumers instantiate its templates), so it is
# exported too, as exactgeo::strict_fp. exactgeo_warnings is build-only and not exported.
set_target_properties(exactgeo_strict_fp PROPERTIES EXPORT_NAME strict_fp)

install(TARGETS exactgeo_predicates exactgeo_parallel exactgeo_io exactgeo_boxes exactgeo_surface
                exactgeo_mesh
                exactgeo_ccd exactgeo_ccd_files
                exactgeo_inside exactgeo_remesh exactgeo_strict_fp
        EXPORT exactgeoTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS exactgeo_mesh_files EXPORT exactgeoMeshFilesTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS exactgeo RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Every public header, internal/ included: the public templates include those.
foreach(folder predicates parallel io boxes surface mesh ccd inside remesh)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/include/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()

install(EXPORT exactgeoTargets NAMESPACE exactgeo:: DESTINATION ${EXACTGEO_INSTALL_CMAKEDIR})
install(EXPORT exactgeoMeshFilesTargets NAMESPACE exactgeo::
        DESTINATION ${EXACTGEO_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/exactgeoConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/exactgeoConfig.cmake
                              INSTALL_DESTINATION ${EXACTGEO_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/exactgeoConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/exactgeoConfig.cmake
              ${PROJECT_BINARY_DIR}/exactgeoConfigVersion.cmake
        DESTINATION ${EXACTGEO_INSTALL_CMAKEDIR})
