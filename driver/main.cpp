#include "driver/Cli.h"

#include <cstdio>
#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        return milldyn::runCli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
    } catch (...) {  // runCli catches std::exception; anything else still ends in one line, not an abort
        std::fputs("milldyn: internal error: unknown exception\n", stderr);
        return 1;
    }
}
