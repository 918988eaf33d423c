# Debian's libSimTK* are built without NDEBUG, and some Simbody classes
# (e.g. CacheEntryInfo in SimTKcommon/internal/StateImpl.h) change layout
# under NDEBUG. Any translation unit that includes Simbody headers with
# -DNDEBUG disagrees with the library and crashes in realizeTopology().
# We keep optimisation and strip NDEBUG from every configuration's flags.
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
        "Simbody code must not be compiled with -DNDEBUG: see "
        "docs/building.md (Debian's Simbody is built without it).")
    endif()
  endforeach()
  get_directory_property(defs COMPILE_DEFINITIONS)
  if("${defs}" MATCHES "NDEBUG")
    message(FATAL_ERROR "COMPILE_DEFINITIONS contain NDEBUG; see docs/building.md.")
  endif()
endfunction()
