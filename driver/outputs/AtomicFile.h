#pragma once
// Output files are written completely or not at all: the content goes to a
// temporary name in the same directory, is flushed, and is renamed over the
// final name (rename is atomic within one file system).

#include <stdexcept>
#include <string>

namespace milldyn {

/// A file could not be written; the driver exits 1. No partial file is left.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Writes `content` to `path` atomically. Throws OutputError.
void writeFileAtomically(const std::string& path, const std::string& content);

/// Creates `path` with `content` (complete, as writeFileAtomically) only if
/// no file of that name exists; false if one does. Throws OutputError.
bool createFileExclusively(const std::string& path, const std::string& content);

/// A temporary name beside `path` (same directory, unique to this process
/// and call), for tools that write files themselves (gnuplot). It is
/// removed if SIGINT or SIGTERM ends the process (OutputSet.h).
std::string temporaryNameBeside(const std::string& path);

/// Removes a temporary made by temporaryNameBeside (if it exists).
void discardTemporary(const std::string& path);

/// Renames `from` over `to`; removes `from` and throws OutputError on failure.
void commitFile(const std::string& from, const std::string& to);

/// Creates the directory (and parents) if needed. Throws OutputError.
void ensureDirectory(const std::string& dir);

}  // namespace milldyn
