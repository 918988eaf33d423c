# Chooses the Simbody library ("engine") milldyn is built against, and with
# it the NDEBUG setting of every translation unit (docs/building.md):
#
#   MILLDYN_ENGINE=release (default)  Simbody built from Debian's source
#       package in Release by scripts/build-engine.sh, installed under
#       MILLDYN_ENGINE_PREFIX; milldyn is compiled with NDEBUG.
#   MILLDYN_ENGINE=debian             Debian's binary libsimbody-dev (built
#       without NDEBUG: checked downcasts, asserts); milldyn is compiled
#       without NDEBUG (cmake/NoNDEBUG.cmake).
#
# Some Simbody classes change layout under NDEBUG (CacheEntryInfo in
# SimTKcommon/internal/StateImpl.h), so the library and every translation
# unit that includes its headers must agree: milldyn_engine_check() refuses
# any mix at configure time. Both defaults can come from the environment
# (MILLDYN_ENGINE, MILLDYN_ENGINE_PREFIX), so that a plugin built out of tree
# in the same shell (docs/new-layout.md) picks the same engine.
# Used by the top CMakeLists.txt and by out-of-tree plugins.

set(_milldyn_engine_default release)
if(NOT "$ENV{MILLDYN_ENGINE}" STREQUAL "")
  set(_milldyn_engine_default "$ENV{MILLDYN_ENGINE}")
endif()
set(MILLDYN_ENGINE "${_milldyn_engine_default}" CACHE STRING
  "Simbody engine: release (scripts/build-engine.sh, NDEBUG) or debian (libsimbody-dev, no NDEBUG)")
set_property(CACHE MILLDYN_ENGINE PROPERTY STRINGS release debian)

if(NOT "$ENV{MILLDYN_ENGINE_PREFIX}" STREQUAL "")
  set(_milldyn_prefix_default "$ENV{MILLDYN_ENGINE_PREFIX}")
elseif(NOT "$ENV{MILLDYN_ENGINE_ROOT}" STREQUAL "")
  set(_milldyn_prefix_default "$ENV{MILLDYN_ENGINE_ROOT}/simbody-current")
else()
  set(_milldyn_prefix_default "/opt/milldyn-engine/simbody-current")
endif()
set(MILLDYN_ENGINE_PREFIX "${_milldyn_prefix_default}" CACHE PATH
  "Where scripts/build-engine.sh installed the Release engine (MILLDYN_ENGINE=release)")

# Another engine than at the last configuration: find Simbody afresh.
set(_milldyn_engine_key "${MILLDYN_ENGINE}|${MILLDYN_ENGINE_PREFIX}")
if(DEFINED MILLDYN_ENGINE_LAST AND NOT MILLDYN_ENGINE_LAST STREQUAL _milldyn_engine_key)
  unset(Simbody_DIR CACHE)
endif()
set(MILLDYN_ENGINE_LAST "${_milldyn_engine_key}" CACHE INTERNAL "engine of the last configuration")

include(NoNDEBUG)   # NDEBUG comes only from MILLDYN_NDEBUG below, never from build-type flags
if(MILLDYN_ENGINE STREQUAL "release")
  if(NOT EXISTS "${MILLDYN_ENGINE_PREFIX}/.milldyn-engine-stamp")
    message(FATAL_ERROR "No Release engine at MILLDYN_ENGINE_PREFIX='${MILLDYN_ENGINE_PREFIX}' "
      "(no .milldyn-engine-stamp). Build it with scripts/build-engine.sh (scripts/build.sh does), "
      "or choose Debian's checked library explicitly: -DMILLDYN_ENGINE=debian (docs/building.md).")
  endif()
  find_package(Simbody CONFIG REQUIRED PATHS "${MILLDYN_ENGINE_PREFIX}" NO_DEFAULT_PATH)
  set(MILLDYN_NDEBUG ON)
elseif(MILLDYN_ENGINE STREQUAL "debian")
  find_package(Simbody CONFIG REQUIRED)
  set(MILLDYN_NDEBUG OFF)
else()
  message(FATAL_ERROR "MILLDYN_ENGINE='${MILLDYN_ENGINE}': expected release or debian (docs/building.md)")
endif()

# The library's NDEBUG setting, from the configurations its CMake package was
# installed with: Simbody's CMakeLists.txt adds -DNDEBUG to Release,
# RelWithDebInfo and MinSizeRel only; Debian builds with CMAKE_BUILD_TYPE=None
# (imported configuration NONE), a plain build has NOCONFIG.
get_target_property(_milldyn_simbody_configs SimTKsimbody IMPORTED_CONFIGURATIONS)
if("${_milldyn_simbody_configs}" MATCHES "^(RELEASE|RELWITHDEBINFO|MINSIZEREL)(;(RELEASE|RELWITHDEBINFO|MINSIZEREL))*$")
  set(MILLDYN_SIMBODY_NDEBUG ON)
  set(MILLDYN_SIMBODY_BUILD "Release")
elseif("${_milldyn_simbody_configs}" MATCHES "^(NONE|NOCONFIG|DEBUG)(;(NONE|NOCONFIG|DEBUG))*$")
  set(MILLDYN_SIMBODY_NDEBUG OFF)
  set(MILLDYN_SIMBODY_BUILD "checked")
else()
  message(FATAL_ERROR "Simbody at '${Simbody_DIR}' was installed with configurations "
    "'${_milldyn_simbody_configs}': cannot tell whether it was built with NDEBUG (docs/building.md).")
endif()
if(NOT MILLDYN_SIMBODY_NDEBUG STREQUAL MILLDYN_NDEBUG)
  if(MILLDYN_NDEBUG)
    set(_milldyn_mix "milldyn would be compiled with NDEBUG (MILLDYN_ENGINE=${MILLDYN_ENGINE}) against a Simbody built without it")
  else()
    set(_milldyn_mix "milldyn would be compiled without NDEBUG (MILLDYN_ENGINE=${MILLDYN_ENGINE}) against a Simbody built with it")
  endif()
  message(FATAL_ERROR "Engine mix refused: ${_milldyn_mix} (Simbody_DIR='${Simbody_DIR}', "
    "configurations '${_milldyn_simbody_configs}'). Object layouts differ; see docs/building.md.")
endif()
if(MILLDYN_NDEBUG)
  add_compile_definitions(NDEBUG)
endif()
# Plugins must be built against the same Simbody version and NDEBUG setting
# (plugins/scene/EngineTag.h adds the latter from NDEBUG itself).
add_compile_definitions(MILLDYN_SIMBODY_VERSION="${Simbody_VERSION}")
# Where the library is: milldyn checks at start-up that the loaded
# libSimTKcommon comes from there (driver/EngineCheck.cpp; same soname as
# the other engine's).
foreach(_milldyn_cfg ${_milldyn_simbody_configs})
  get_target_property(_milldyn_simbody_location SimTKcommon IMPORTED_LOCATION_${_milldyn_cfg})
  if(_milldyn_simbody_location)
    get_filename_component(MILLDYN_SIMBODY_LIBDIR "${_milldyn_simbody_location}" DIRECTORY)
    break()
  endif()
endforeach()
message(STATUS "milldyn engine: Simbody ${Simbody_VERSION} ${MILLDYN_SIMBODY_BUILD} (${MILLDYN_ENGINE}, ${Simbody_DIR})")

# Called at the end of configuration: the NDEBUG setting came only from here.
function(milldyn_engine_check)
  get_directory_property(defs COMPILE_DEFINITIONS)
  if(MILLDYN_NDEBUG)
    if(NOT "${defs}" MATCHES "(^|;)NDEBUG(;|$)")
      message(FATAL_ERROR "MILLDYN_ENGINE=release but NDEBUG is not among the compile definitions; "
        "see docs/building.md.")
    endif()
    foreach(flag_var
        CMAKE_CXX_FLAGS CMAKE_CXX_FLAGS_RELEASE CMAKE_CXX_FLAGS_RELWITHDEBINFO
        CMAKE_CXX_FLAGS_MINSIZEREL CMAKE_CXX_FLAGS_DEBUG)
      if("${${flag_var}}" MATCHES "[-/]U *NDEBUG")
        message(FATAL_ERROR "${flag_var} undefines NDEBUG ('${${flag_var}}') against the Release engine; "
          "see docs/building.md.")
      endif()
    endforeach()
  else()
    milldyn_assert_no_ndebug()
  endif()
endfunction()
