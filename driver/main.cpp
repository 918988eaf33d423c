#include "driver/Cli.h"
#include "driver/EngineCheck.h"

#include <iostream>

int main(int argc, char** argv) {
    // Another Simbody than the one built against (same soname) must not run.
    const std::string mismatch = milldyn::engineMismatch();
    if (!mismatch.empty()) {
        std::cerr << "milldyn: error: " << mismatch << "\n";
        return 1;
    }
    return milldyn::runCli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
