#pragma once
// `--set k=v` pairs for an in-process `runCli` call, as a user types them.

#include <string>
#include <vector>

namespace milldyn::testing_helpers {

/// {"a=1", "b=2 m"} -> {"--set", "a=1", "--set", "b=2 m"}.
inline std::vector<std::string> setArgs(const std::vector<std::string>& sets) {
    std::vector<std::string> args;
    for (const auto& s : sets) {
        args.push_back("--set");
        args.push_back(s);
    }
    return args;
}

}  // namespace milldyn::testing_helpers
