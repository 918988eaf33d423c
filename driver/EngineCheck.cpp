#include "driver/EngineCheck.h"

#include "plugins/scene/EngineTag.h"

#include <link.h>

#include <filesystem>
#include <system_error>

#ifndef MILLDYN_SIMBODY_LIBDIR
#error "MILLDYN_SIMBODY_LIBDIR must be defined (cmake/Engine.cmake: the directory of libSimTKcommon)"
#endif

namespace milldyn {

std::string loadedSimbodyLibrary() {
    std::string found;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* data) {
            const std::string name = info->dlpi_name ? info->dlpi_name : "";
            if (name.find("/libSimTKcommon.so") != std::string::npos) {
                *static_cast<std::string*>(data) = name;
                return 1;
            }
            return 0;
        },
        &found);
    return found;
}

std::string engineMismatch() {
    const std::string loaded = loadedSimbodyLibrary();
    if (loaded.empty()) return "";  // statically linked or not loaded: nothing to compare
    std::error_code ec1, ec2;
    const auto dir = std::filesystem::weakly_canonical(std::filesystem::path(loaded).parent_path(), ec1);
    const auto expected = std::filesystem::weakly_canonical(MILLDYN_SIMBODY_LIBDIR, ec2);
    if (!ec1 && !ec2 && dir == expected) return "";
    return "loaded Simbody library " + loaded + ", but this milldyn was built against " + kSimbodyEngine + " in " +
           MILLDYN_SIMBODY_LIBDIR + " (object layouts differ; check LD_LIBRARY_PATH, docs/building.md)";
}

}  // namespace milldyn
