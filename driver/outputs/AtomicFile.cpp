#include "driver/outputs/AtomicFile.h"

#include "driver/outputs/OutputSet.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fcntl.h>
#include <unistd.h>

namespace milldyn {

std::string temporaryNameBeside(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    std::string name = path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    registerTemporary(name);  // removed on SIGINT/SIGTERM
    return name;
}

void discardTemporary(const std::string& path) {
    std::remove(path.c_str());
    forgetTemporary(path);
}

void commitFile(const std::string& from, const std::string& to) {
    if (std::rename(from.c_str(), to.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        discardTemporary(from);
        throw OutputError("cannot write " + to + ": " + reason);
    }
    forgetTemporary(from);
}

namespace {

/// Writes `content` to a new temporary name beside `path`, flushed to disk;
/// returns that name. Throws OutputError (and leaves no temporary).
std::string writeTemporary(const std::string& path, const std::string& content) {
    const std::string tmp = temporaryNameBeside(path);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw OutputError("cannot write " + path + ": " + std::strerror(errno));
    const char* data = content.data();
    std::size_t left = content.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string reason = std::strerror(errno);
            ::close(fd);
            discardTemporary(tmp);
            throw OutputError("cannot write " + path + ": " + reason);
        }
        data += n;
        left -= static_cast<std::size_t>(n);
    }
    // The data must be on disk before the name points at it.
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        const std::string reason = std::strerror(errno);
        discardTemporary(tmp);
        throw OutputError("cannot write " + path + ": " + reason);
    }
    return tmp;
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
    commitFile(writeTemporary(path, content), path);
}

bool createFileExclusively(const std::string& path, const std::string& content) {
    const std::string tmp = writeTemporary(path, content);
    // link() fails with EEXIST if the name exists: of two processes racing
    // for the name, exactly one gets it, and it gets the whole content.
    const int rc = ::link(tmp.c_str(), path.c_str());
    const int err = errno;
    discardTemporary(tmp);
    if (rc == 0) return true;
    if (err == EEXIST) return false;
    throw OutputError("cannot write " + path + ": " + std::strerror(err));
}

void ensureDirectory(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw OutputError("cannot create output directory " + dir + ": " + ec.message());
    if (::access(dir.c_str(), W_OK) != 0)
        throw OutputError("output directory " + dir + " is not writable: " + std::strerror(errno));
}

}  // namespace milldyn
