#pragma once
// A run's output files as one set: all new or the old set untouched
// (issue 16, item 5). Files are written into a staging directory inside the
// output directory and moved into place only once every one of them is
// complete; the previous run's files that the new set does not replace are
// removed then (DIR/.milldyn-outputs lists the set). SIGINT and SIGTERM end
// the run non-zero and remove every temporary file and staging directory;
// they are held off only while a set is being moved into place.

#include <string>
#include <vector>

namespace milldyn {

/// Installs the SIGINT/SIGTERM handlers (once): they kill a running helper
/// tool, remove registered temporaries, and re-raise the signal, so the
/// process ends as killed by it (exit status 130/143 in a shell).
void installSignalCleanup();

/// Registers `path` (a file or an empty-able staging directory) for removal
/// on SIGINT/SIGTERM; forgetTemporary when it is committed or removed.
void registerTemporary(const std::string& path);
void forgetTemporary(const std::string& path);

/// Runs a helper program (gnuplot, rsvg-convert) without a shell, its
/// standard error discarded, in the working directory `cwd` (empty: this
/// process's); true if it exited 0. SIGINT/SIGTERM reach this process while
/// it runs (std::system would ignore SIGINT).
bool runTool(const std::vector<std::string>& argv, const std::string& cwd = "");

/// Removes the staging directories `.milldyn-staging.PID.N` and temporary
/// files `NAME.tmp.PID.N` in `dir` whose process PID no longer runs
/// (SIGKILL leaves them: no handler runs), and returns their names. A live
/// process's are left alone.
std::vector<std::string> removeStaleStaging(const std::string& dir);

/// True if `path` holds a whole PNG: the signature and the closing IEND
/// chunk (a tool that exits 0 on a full disk leaves a truncated file).
bool isCompletePng(const std::string& path);

class OutputSet {
public:
    /// Creates DIR (if needed) and a fresh staging directory inside it;
    /// first removes the staging directories of dead processes there
    /// (removeStaleStaging). Throws OutputError.
    explicit OutputSet(std::string dir);
    /// Removes the staging directory and whatever is in it, unless committed.
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    /// Where the writers put the files.
    const std::string& staging() const { return m_staging; }
    /// Moves the staged files (paths under staging()) into DIR, removes the
    /// previous set's other files, records the new set; returns the final
    /// paths in the same order. Throws OutputError (the old set then stays).
    std::vector<std::string> commit(const std::vector<std::string>& staged);

private:
    std::string m_dir, m_staging;
    bool m_committed = false;
};

}  // namespace milldyn
