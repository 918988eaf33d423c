#include "driver/Cli.h"
#include "driver/outputs/OutputSet.h"

#include <cstdio>
#include <exception>
#include <iostream>

int main(int argc, char** argv) {
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
