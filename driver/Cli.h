#pragma once
// The command line: `milldyn run|info|validate`. Exit codes: 0 ok,
// 1 the analysis (or an output) failed, 2 bad input.

#include <ostream>
#include <string>
#include <vector>

namespace milldyn {

/// Runs one command (args without the program name). Never throws.
int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace milldyn
