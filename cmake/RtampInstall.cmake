# What `cmake --install` puts under the prefix (docs/library.md, docs/design.md "Install layout"):
#   include/rtamp/<layer>/*.hpp            every layer's headers
#   lib/librtamp_<layer>.a                 the layer libraries (static, -fPIC)
#   lib/cmake/rtamp/                       rtampConfig.cmake, rtampConfigVersion.cmake,
#                                          rtampTargets.cmake (core), rtampMujocoTargets.cmake,
#                                          rtampDependencies.cmake
#   lib/pkgconfig/rtamp.pc, rtamp-mujoco.pc
#   bin/rtamp                              the command line (needs no data files at run time:
#                                          the built-in scenarios are compiled in)
#   share/rtamp/scenarios/*.yaml           the built-in scenarios as files, to copy and edit
#   share/rtamp/models/ur5.xml             the UR5's MuJoCo model (also compiled in)
#   share/rtamp/ros2/msg/PKG/TYPE.msg      the ROS 2 message definitions (src/rtamp/ros2/msg)
# Included by the top-level CMakeLists.txt after every layer and the CLI exist. Defines the
# umbrella targets rtamp::rtamp (every layer without MuJoCo) and rtamp::rtamp_mujoco.
include(CMakePackageConfigHelpers)

get_property(core_targets GLOBAL PROPERTY RTAMP_CORE_TARGETS)
get_property(mujoco_targets GLOBAL PROPERTY RTAMP_MUJOCO_TARGETS)

add_library(rtamp_all INTERFACE)
target_link_libraries(rtamp_all INTERFACE ${core_targets})
set_target_properties(rtamp_all PROPERTIES EXPORT_NAME rtamp)
add_library(rtamp::rtamp ALIAS rtamp_all)
install(TARGETS rtamp_all EXPORT rtampTargets)

add_library(rtamp_all_mujoco INTERFACE)
target_link_libraries(rtamp_all_mujoco INTERFACE rtamp_all ${mujoco_targets})
set_target_properties(rtamp_all_mujoco PROPERTIES EXPORT_NAME rtamp_mujoco)
add_library(rtamp::rtamp_mujoco ALIAS rtamp_all_mujoco)
install(TARGETS rtamp_all_mujoco EXPORT rtampMujocoTargets)

set(RTAMP_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/rtamp)
install(EXPORT rtampTargets NAMESPACE rtamp:: DESTINATION ${RTAMP_CMAKE_DIR} FILE rtampTargets.cmake)
install(EXPORT rtampMujocoTargets NAMESPACE rtamp:: DESTINATION ${RTAMP_CMAKE_DIR} FILE rtampMujocoTargets.cmake)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rtampConfig.cmake.in
  ${PROJECT_BINARY_DIR}/rtampConfig.cmake INSTALL_DESTINATION ${RTAMP_CMAKE_DIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rtampConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rtampConfig.cmake ${PROJECT_BINARY_DIR}/rtampConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/rtampDependencies.cmake
        DESTINATION ${RTAMP_CMAKE_DIR})

# Headers under a layer's detail/ are its internals (they may use the build-only
# dependencies, e.g. nlohmann_json) and are not installed.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/rtamp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" PATTERN "detail" EXCLUDE
        PATTERN "ros2/generator" EXCLUDE PATTERN "ros2/msg" EXCLUDE)
if(TARGET rtamp)
  install(TARGETS rtamp RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenarios/ DESTINATION ${CMAKE_INSTALL_DATADIR}/rtamp/scenarios
        FILES_MATCHING PATTERN "*.yaml")
install(FILES ${PROJECT_SOURCE_DIR}/models/ur5.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/rtamp/models)

# pkg-config: static libraries in link order (users before what they use).
set(core_order batch_core exec bt robot plan task automata ltl world ros2 util)
set(RTAMP_PC_CORE_LIBS "")
foreach(l IN LISTS core_order)
  if(TARGET rtamp_${l})
    string(APPEND RTAMP_PC_CORE_LIBS " -lrtamp_${l}")
  endif()
endforeach()
set(RTAMP_PC_MUJOCO_LIBS "")
foreach(l IN ITEMS serve batch episode sim)
  if(TARGET rtamp_${l})
    string(APPEND RTAMP_PC_MUJOCO_LIBS " -lrtamp_${l}")
  endif()
endforeach()
string(STRIP "${RTAMP_PC_CORE_LIBS}" RTAMP_PC_CORE_LIBS)
string(STRIP "${RTAMP_PC_MUJOCO_LIBS}" RTAMP_PC_MUJOCO_LIBS)
file(RELATIVE_PATH RTAMP_PC_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
set(RTAMP_PC_OMPL -lompl)
set(RTAMP_PC_MUJOCO -lmujoco)
set(RTAMP_PC_EGL "-lEGL -lzstd -llz4 -lz -lopencv_imgproc -lopencv_core")
configure_file(${PROJECT_SOURCE_DIR}/cmake/rtamp.pc.in ${PROJECT_BINARY_DIR}/rtamp.pc @ONLY)
configure_file(${PROJECT_SOURCE_DIR}/cmake/rtamp-mujoco.pc.in ${PROJECT_BINARY_DIR}/rtamp-mujoco.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/rtamp.pc ${PROJECT_BINARY_DIR}/rtamp-mujoco.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
