#include "platform/driver_crash_guard.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iterator>

#include <unistd.h>

namespace platform {
namespace {

constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT};  // virpipe aborts when it finds no server
constexpr int kRefusedExitCode = 2;  // as the command line's refusals

// Written before the driver runs: the handler may only write and exit.
char message[512];
std::size_t messageLength = 0;
struct sigaction previous[std::size(kSignals)];

extern "C" void sayWhyAndExit(int) {
    if (write(STDERR_FILENO, message, messageLength) < 0) {
        // nothing more can be said
    }
    _exit(kRefusedExitCode);
}

}  // namespace

DriverCrashGuard::DriverCrashGuard(const char* starting) {
    const char* named = std::getenv("GALLIUM_DRIVER");
    int length = 0;
    if (named && *named) {
        length = std::snprintf(message, sizeof message,
                               "spheres: the GL driver crashed while %s, with GALLIUM_DRIVER=%s: Mesa's software "
                               "drivers are llvmpipe and softpipe; unset it or name one of them\n",
                               starting, named);
    } else {
        length = std::snprintf(message, sizeof message,
                               "spheres: the GL driver crashed while %s; try the other headless GL (--gl osmesa or "
                               "--gl egl), or LIBGL_ALWAYS_SOFTWARE=1 for Mesa's llvmpipe\n",
                               starting);
    }
    messageLength = length > 0 ? std::min(std::size_t(length), sizeof message - 1) : 0;
    struct sigaction action {};
    action.sa_handler = sayWhyAndExit;
    sigemptyset(&action.sa_mask);
    for (std::size_t k = 0; k < std::size(kSignals); ++k) sigaction(kSignals[k], &action, &previous[k]);
}

DriverCrashGuard::~DriverCrashGuard() {
    for (std::size_t k = 0; k < std::size(kSignals); ++k) sigaction(kSignals[k], &previous[k], nullptr);
}

}  // namespace platform
