#include "driver/PluginLoader.h"

#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/EngineTag.h"

#include <dlfcn.h>
#include <sys/stat.h>

#include <stdexcept>

namespace milldyn {

void loadPlugin(const std::string& given) {
    const SourceLocation where{"<--plugin " + given + ">", 1, 1};
    auto fail = [&](const std::string& reason) { return SpecError(where, "--plugin", reason); };
    // A name without a slash would make dlopen search the system's library
    // path, never the working directory: it means a file here.
    const std::string path = given.find('/') == std::string::npos ? "./" + given : given;
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw fail("cannot load: no such file " + path +
                   (given.find('/') == std::string::npos ? " (a name without a slash is looked for in the working directory)" : ""));
    if (!S_ISREG(st.st_mode)) throw fail("cannot load: " + path + " is not a regular file (a FIFO or device would block the load)");
    // RTLD_NOW: a missing symbol is an error here, not a crash mid-run. The
    // library stays loaded for the life of the process (its code builds
    // forces Simbody keeps).
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw fail(std::string("cannot load: ") + ::dlerror());
    using AbiFn = int (*)();
    using VersionFn = const char* (*)();
    using RegisterFn = void (*)(ElementRegistry&);
    auto abi = reinterpret_cast<AbiFn>(::dlsym(handle, "milldyn_plugin_abi_version"));
    auto simbody = reinterpret_cast<VersionFn>(::dlsym(handle, "milldyn_plugin_simbody_version"));
    auto reg = reinterpret_cast<RegisterFn>(::dlsym(handle, "milldyn_register_elements"));
    if (!abi || !simbody || !reg)
        throw fail("not a milldyn plugin (no milldyn_plugin_abi_version / milldyn_plugin_simbody_version / "
                   "milldyn_register_elements; see plugins/scene/PluginApi.h)");
    if (abi() != kPluginAbiVersion)
        throw fail("built against plugin ABI " + std::to_string(abi()) + ", this milldyn has ABI " +
                   std::to_string(kPluginAbiVersion) + ": rebuild the plugin");
    // The engine tag is the Simbody version and the NDEBUG setting ("3.7 Release",
    // "3.7 checked"): object layouts differ between the two settings.
    if (std::string(simbody()) != MILLDYN_ENGINE_TAG)
        throw fail(std::string("built against Simbody ") + simbody() + ", this milldyn uses Simbody " +
                   MILLDYN_ENGINE_TAG + ": rebuild the plugin against the same engine (docs/building.md)");
    try {
        reg(ElementRegistry::instance());
    } catch (const std::invalid_argument& e) {
        throw fail(e.what());
    }
}

}  // namespace milldyn
