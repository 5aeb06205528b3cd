#pragma once
// While a GL driver starts (creates its context, loads GL), a crash inside it ends the
// program with one line that names the driver and what to try, instead of "Segmentation
// fault" and nothing else: Debian 12's OSMesa dereferences a null screen when
// GALLIUM_DRIVER names a driver it does not have. Only around the driver's own start-up: a
// crash anywhere else is a bug of ours and keeps its core dump.
namespace platform {

class DriverCrashGuard {
public:
    // `starting`: what the driver is doing, e.g. "OSMesa creating its context".
    explicit DriverCrashGuard(const char* starting);
    ~DriverCrashGuard();
    DriverCrashGuard(const DriverCrashGuard&) = delete;
    DriverCrashGuard& operator=(const DriverCrashGuard&) = delete;
};

}  // namespace platform
