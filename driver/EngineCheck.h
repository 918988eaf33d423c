#pragma once
// The Simbody library actually loaded must be the engine milldyn was built
// against: Debian's checked libSimTKcommon.so.3.7 and the Release engine's
// share one soname, so a LD_LIBRARY_PATH (or a lost RUNPATH) could load the
// other one into this process, whose objects then disagree about layout
// (docs/building.md).

#include <string>

namespace milldyn {

/// The path of the loaded libSimTKcommon, or "" if none is loaded.
std::string loadedSimbodyLibrary();

/// "" when the loaded libSimTKcommon lies in the directory milldyn was built
/// against (MILLDYN_SIMBODY_LIBDIR); otherwise one line saying both.
std::string engineMismatch();

}  // namespace milldyn
