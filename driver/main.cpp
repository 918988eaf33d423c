#include "driver/Cli.h"
#include "driver/EngineCheck.h"
#include "driver/outputs/OutputSet.h"

#include <cstdio>
#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    // Another Simbody than the one built against (same soname) must not run.
    const std::string mismatch = milldyn::engineMismatch();
    if (!mismatch.empty()) {
        std::cerr << "milldyn: error: " << mismatch << "\n";
        return 1;
    }
    // SIGINT/SIGTERM: remove temporaries, end non-zero (docs/reliability.md).
    milldyn::installSignalCleanup();
    int rc = 1;
    try {
        rc = milldyn::runCli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
    } catch (...) {  // runCli catches std::exception; anything else still ends in one line, not an abort
        std::fputs("milldyn: internal error: unknown exception\n", stderr);
        return 1;
    }
    // Output that did not reach its destination (info > /dev/full) is a failure.
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0) {
        std::fputs("milldyn: error: cannot write to standard output\n", stderr);
        return rc == 0 ? 1 : rc;
    }
    return rc;
}
