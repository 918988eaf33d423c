#pragma once
// The clocks of the bench programs: wall time and the process's CPU time,
// read together. On a shared machine the wall time of a single-threaded run
// counts the time other processes held the core; its CPU time does not
// (docs/benchmarks.md reports CPU time, with the wall time beside it).

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace bench {

/// Seconds of wall time and of the process's CPU time since construction.
class Stopwatch {
public:
    Stopwatch() : m_wall0(std::chrono::steady_clock::now()), m_cpu0(cpuNow()) {}
    double wall() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_wall0).count(); }
    double cpu() const { return cpuNow() - m_cpu0; }

private:
    static double cpuNow() {
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }
    std::chrono::steady_clock::time_point m_wall0;
    double m_cpu0;
};

/// The median of `v` (the upper one of an even count; 0 for none).
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace bench
