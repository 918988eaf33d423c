#include "driver/CpodesMessages.h"

#include "driver/Simulation.h"

#include <algorithm>
#include <unistd.h>

namespace milldyn {
namespace {

thread_local std::string t_cpodesText;
/// This thread has made a CPodes integrator (and integrates with it: an
/// integrator lives on the thread that made it). Simbody's Integrator has
/// no virtual destructor, so the end of one cannot be counted.
thread_local bool t_makesCpodes = false;

ssize_t writeToSink(void*, const char* buffer, size_t size) {
    if (t_makesCpodes) {
        if (t_cpodesText.size() < 4096)
            t_cpodesText.append(buffer, std::min<size_t>(size, 4096 - t_cpodesText.size()));
        return static_cast<ssize_t>(size);
    }
    // Not CPodes: another thread wrote to `stderr` while it pointed here.
    size_t done = 0;
    while (done < size) {
        const ssize_t n = ::write(STDERR_FILENO, buffer + done, size - done);
        if (n <= 0) break;
        done += static_cast<size_t>(n);
    }
    return static_cast<ssize_t>(size);
}

}  // namespace

std::mutex& cpodesStderrLock() {
    static std::mutex lock;
    return lock;
}

FILE* cpodesMessageSink() {
    static FILE* const sink = [] {
        cookie_io_functions_t io{nullptr, writeToSink, nullptr, nullptr};
        FILE* f = fopencookie(nullptr, "w", io);
        if (f) setvbuf(f, nullptr, _IONBF, 0);
        return f;
    }();
    return sink;
}

std::unique_ptr<SimTK::Integrator> makeCpodesIntegrator(const SimTK::System& system,
                                                        SimTK::CPodes::LinearMultistepMethod method,
                                                        SimTK::CPodes::NonlinearSystemIterationType iteration) {
    FILE* const sink = cpodesMessageSink();
    const std::lock_guard<std::mutex> lock(cpodesStderrLock());
    struct Restore {
        FILE* saved = stderr;
        ~Restore() { stderr = saved; }
    } restore;
    if (sink) stderr = sink;
    t_makesCpodes = true;
    return std::make_unique<SimTK::CPodesIntegrator>(system, method, iteration);
}

std::string takeCpodesError() {
    std::string text;
    text.swap(t_cpodesText);
    const auto at = text.rfind("ERROR]");
    if (at == std::string::npos) return "";
    const auto body = text.find('\n', at);
    return body == std::string::npos ? "" : simbodyMessage(text.substr(body + 1));
}

}  // namespace milldyn
