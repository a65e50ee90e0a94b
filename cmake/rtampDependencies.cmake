# The libraries rtamp links that have no usable CMake package on Debian 12, as
# imported targets with the same names in the build tree and for users of the
# installed package (rtampConfig.cmake includes this file):
#   rtamp_deps::ompl    OMPL 1.5 — its config lists Boost's unversioned .so files,
#                       which Debian ships only with the -dev packages; libompl.so
#                       carries its own Boost dependencies, so it is linked alone.
#   rtamp_deps::mujoco  MuJoCo 2.2.2 — no pkg-config, no CMake package usable without qhull.
#   rtamp_deps::egl     EGL (Mesa), for MuJoCo's offscreen rendering.
#   rtamp_deps::zstd, rtamp_deps::lz4  the compressions of the MCAP writer (no CMake package on Debian 12).
#
#   rtamp_import_library(<target> <library name> [GLOBAL])
#     Finds lib<name> (cache variable RTAMP_<NAME>_LIBRARY) and defines <target> as an
#     UNKNOWN IMPORTED library; does nothing if <target> exists already. Sets
#     <target>_FOUND in the caller's scope (TRUE/FALSE).
function(rtamp_import_library target libname)
  cmake_parse_arguments(I "GLOBAL" "" "" ${ARGN})
  if(TARGET ${target})
    set(${target}_FOUND TRUE PARENT_SCOPE)
    return()
  endif()
  string(TOUPPER "RTAMP_${libname}_LIBRARY" var)
  string(MAKE_C_IDENTIFIER "${var}" var)
  find_library(${var} NAMES ${libname})
  if(NOT ${var})
    set(${target}_FOUND FALSE PARENT_SCOPE)
    return()
  endif()
  if(I_GLOBAL)
    add_library(${target} UNKNOWN IMPORTED GLOBAL)
  else()
    add_library(${target} UNKNOWN IMPORTED)
  endif()
  set_target_properties(${target} PROPERTIES IMPORTED_LOCATION "${${var}}")
  set(${target}_FOUND TRUE PARENT_SCOPE)
endfunction()
