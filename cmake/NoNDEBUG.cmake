# NDEBUG changes the layout of some Simbody classes (e.g. CacheEntryInfo in
# SimTKcommon/internal/StateImpl.h): a translation unit and the Simbody
# library must agree on it, or realizeTopology() crashes. So NDEBUG must never
# come from CMake's build-type flags (Release and RelWithDebInfo add it):
# this strips it from every configuration's flags, keeping the optimisation,
# and cmake/Engine.cmake defines it exactly when the engine was built with it.
foreach(flag_var
    CMAKE_CXX_FLAGS CMAKE_CXX_FLAGS_RELEASE CMAKE_CXX_FLAGS_RELWITHDEBINFO
    CMAKE_CXX_FLAGS_MINSIZEREL CMAKE_CXX_FLAGS_DEBUG)
  string(REGEX REPLACE "(^| )[-/]D *NDEBUG($| )" " " ${flag_var} "${${flag_var}}")
  set(${flag_var} "${${flag_var}}" CACHE STRING "" FORCE)
endforeach()

# Called at the end of configuration: fails loudly if NDEBUG came back
# through any flag variable or directory definition.
function(milldyn_assert_no_ndebug)
  foreach(flag_var
      CMAKE_CXX_FLAGS CMAKE_CXX_FLAGS_RELEASE CMAKE_CXX_FLAGS_RELWITHDEBINFO
      CMAKE_CXX_FLAGS_MINSIZEREL CMAKE_CXX_FLAGS_DEBUG)
    if("${${flag_var}}" MATCHES "NDEBUG")
      message(FATAL_ERROR "${flag_var} contains NDEBUG ('${${flag_var}}'). "
        "Simbody code must not be compiled with -DNDEBUG against Debian's checked "
        "Simbody (MILLDYN_ENGINE=debian): see docs/building.md.")
    endif()
  endforeach()
  get_directory_property(defs COMPILE_DEFINITIONS)
  if("${defs}" MATCHES "NDEBUG")
    message(FATAL_ERROR "COMPILE_DEFINITIONS contain NDEBUG; see docs/building.md.")
  endif()
endfunction()
