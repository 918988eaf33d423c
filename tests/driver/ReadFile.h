#pragma once
// A whole file as a string (empty if it cannot be read), for tests that
// check what was written.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace milldyn::test {

inline std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace milldyn::test
