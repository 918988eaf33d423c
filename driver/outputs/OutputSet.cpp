#include "driver/outputs/OutputSet.h"

#include "driver/outputs/AtomicFile.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace milldyn {
namespace {

// The registry the signal handler reads: fixed slots, no allocation, each
// slot claimed by one thread with an atomic flag.
constexpr int kSlots = 128;
constexpr std::size_t kPathMax = 4096;
struct Slot {
    std::atomic<int> state{0};  // 0 free, 1 being written, 2 holds a path
    char path[kPathMax];
};
Slot g_slots[kSlots];
std::atomic<pid_t> g_child{0};

/// Removes the files directly in `dir`, then `dir`: with system calls only
/// (open, getdents64, unlinkat), which are safe in a signal handler.
void removeFlatDirectory(const char* dir) {
    const int fd = ::open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    alignas(8) char buf[4096];
    for (;;) {
        const long n = ::syscall(SYS_getdents64, fd, buf, sizeof buf);
        if (n <= 0) break;
        for (long off = 0; off < n;) {
            // struct linux_dirent64: ino (8), off (8), reclen (2), type (1), name
            unsigned short reclen;
            std::memcpy(&reclen, buf + off + 16, sizeof reclen);
            const char* name = buf + off + 19;
            if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0) ::unlinkat(fd, name, 0);
            off += reclen;
        }
    }
    ::close(fd);
    ::rmdir(dir);
}

void onSignal(int sig) {
    const pid_t child = g_child.load();
    if (child > 0) ::kill(child, SIGTERM);
    // Temporary files, then staging directories with what they hold.
    for (int pass = 0; pass < 2; ++pass)
        for (auto& slot : g_slots)
            if (slot.state.load() == 2) {
                if (pass == 0) ::unlink(slot.path);
                else removeFlatDirectory(slot.path);
            }
    std::signal(sig, SIG_DFL);
    ::raise(sig);
}

const std::string kSetList = ".milldyn-outputs";

}  // namespace

void installSignalCleanup() {
    static std::atomic<bool> installed{false};
    if (installed.exchange(true)) return;
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    ::sigaction(SIGINT, &sa, nullptr);
    ::sigaction(SIGTERM, &sa, nullptr);
}

void registerTemporary(const std::string& path) {
    if (path.size() >= kPathMax) return;
    for (auto& slot : g_slots) {
        int expected = 0;
        if (slot.state.compare_exchange_strong(expected, 1)) {
            std::memcpy(slot.path, path.c_str(), path.size() + 1);
            slot.state.store(2);
            return;
        }
    }
    // All slots taken (more than kSlots temporaries at once): this one is
    // not removed on a signal; its name (*.tmp.PID.N) still says what it is.
}

void forgetTemporary(const std::string& path) {
    for (auto& slot : g_slots) {
        int expected = 2;
        if (slot.state.load() == 2 && path == slot.path && slot.state.compare_exchange_strong(expected, 1)) {
            slot.state.store(0);
            return;
        }
    }
}

bool runTool(const std::vector<std::string>& argv, const std::string& cwd) {
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
    pid_t pid = 0;
    const int rc = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) return false;
    g_child.store(pid);
    int status = 0;
    pid_t w;
    while ((w = ::waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
    }
    g_child.store(0);
    return w == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

bool isCompletePng(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return false;
    const std::streamoff size = in.tellg();
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static const unsigned char kEnd[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    if (size < 8 + 12) return false;
    char head[8], tail[12];
    in.seekg(0);
    in.read(head, 8);
    in.seekg(size - 12);
    in.read(tail, 12);
    return in && std::memcmp(head, kSignature, 8) == 0 && std::memcmp(tail, kEnd, 12) == 0;
}

namespace {

/// The process id in "PID.N" at the end of `rest` (all digits, a dot, all
/// digits), or 0.
pid_t pidOf(const std::string& rest) {
    const auto dot = rest.find('.');
    auto digits = [](const std::string& t) {
        return !t.empty() && t.size() <= 9 && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (dot == std::string::npos || !digits(rest.substr(0, dot)) || !digits(rest.substr(dot + 1))) return 0;
    return static_cast<pid_t>(std::stol(rest.substr(0, dot)));
}

/// No process of that id exists (kill(pid, 0): ESRCH; EPERM means one of
/// another user runs, whose files may be in use).
bool deadProcess(pid_t pid) { return pid > 0 && pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH; }

}  // namespace

std::vector<std::string> removeStaleStaging(const std::string& dir) {
    std::vector<std::string> removed;
    std::error_code ec;
    const std::string staging = ".milldyn-staging.", temporary = ".tmp.";
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        pid_t pid = 0;
        if (name.compare(0, staging.size(), staging) == 0) {
            pid = pidOf(name.substr(staging.size()));  // .milldyn-staging.PID.N
        } else {
            // NAME.tmp.PID.N: a ".tmp." followed by PID.N and nothing else.
            for (auto k = name.find(temporary); k != std::string::npos && !pid; k = name.find(temporary, k + 1))
                pid = pidOf(name.substr(k + temporary.size()));
        }
        if (!deadProcess(pid)) continue;
        std::error_code rm;
        std::filesystem::remove_all(it->path(), rm);
        if (!rm) removed.push_back(name);
    }
    return removed;
}

OutputSet::OutputSet(std::string dir) : m_dir(std::move(dir)) {
    installSignalCleanup();
    ensureDirectory(m_dir);
    removeStaleStaging(m_dir);  // what a SIGKILLed run left (issue 26 item 8)
    static std::atomic<unsigned> counter{0};
    m_staging = m_dir + "/.milldyn-staging." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    std::error_code ec;
    std::filesystem::remove_all(m_staging, ec);
    if (!std::filesystem::create_directory(m_staging, ec) || ec)
        throw OutputError("cannot create " + m_staging + ": " + ec.message());
    registerTemporary(m_staging);
}

OutputSet::~OutputSet() {
    if (m_committed) return;
    std::error_code ec;
    std::filesystem::remove_all(m_staging, ec);
    forgetTemporary(m_staging);
}

std::vector<std::string> OutputSet::commit(const std::vector<std::string>& staged) {
    std::vector<std::string> names, finals;
    for (const auto& path : staged) {
        names.push_back(std::filesystem::path(path).filename().string());
        finals.push_back(m_dir + "/" + names.back());
    }
    // The previous set, by the list it left.
    std::set<std::string> previous;
    {
        std::ifstream in(m_dir + "/" + kSetList);
        for (std::string line; std::getline(in, line);)
            if (!line.empty() && line.find('/') == std::string::npos) previous.insert(line);
    }
    std::string list;
    for (const auto& n : names) list += n + "\n";
    // Held off while the set moves into place: a signal now would leave
    // half of each set.
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    // The old files move aside into the staging directory first, so that a
    // rename failing half way can put them all back: the old set untouched.
    std::string failure;
    const std::string aside = m_staging + "/.previous";
    std::vector<std::string> movedAside, placed;
    std::set<std::string> involved(previous.begin(), previous.end());
    involved.insert(names.begin(), names.end());
    try {
        std::error_code ec;
        std::filesystem::create_directory(aside, ec);
        if (ec) throw OutputError("cannot create " + aside + ": " + ec.message());
        std::remove((m_dir + "/" + kSetList).c_str());  // no list: the files are not known to be one set
        for (const auto& n : involved) {
            const std::string final = m_dir + "/" + n;
            if (!std::filesystem::exists(std::filesystem::symlink_status(final, ec))) continue;
            if (std::rename(final.c_str(), (aside + "/" + n).c_str()) != 0)
                throw OutputError("cannot replace " + final + ": " + std::strerror(errno));
            movedAside.push_back(n);
        }
        for (std::size_t i = 0; i < staged.size(); ++i) {
            if (std::rename(staged[i].c_str(), finals[i].c_str()) != 0)
                throw OutputError("cannot write " + finals[i] + ": " + std::strerror(errno));
            placed.push_back(finals[i]);
        }
        writeFileAtomically(m_dir + "/" + kSetList, list);
    } catch (const std::exception& e) {
        failure = e.what();
        for (const auto& f : placed) std::remove(f.c_str());
        for (const auto& n : movedAside) std::rename((aside + "/" + n).c_str(), (m_dir + "/" + n).c_str());
        if (!previous.empty()) {
            std::string oldList;
            for (const auto& n : previous) oldList += n + "\n";
            try {
                writeFileAtomically(m_dir + "/" + kSetList, oldList);
            } catch (const std::exception&) {
            }
        }
    }
    std::error_code ec;
    std::filesystem::remove_all(m_staging, ec);
    forgetTemporary(m_staging);
    m_committed = true;
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
    if (!failure.empty()) throw OutputError(failure);
    return finals;
}

}  // namespace milldyn
