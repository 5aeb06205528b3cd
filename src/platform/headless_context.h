#pragma once
// A GL 3.3 core context without a window, for image tests and frame capture.
// There is no default framebuffer worth drawing into: render into an
// render::OffscreenTarget (an FBO) and read it back from there.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace platform {

// Auto tries OSMesa first (works everywhere Mesa is), then EGL surfaceless.
enum class HeadlessBackend { Auto, OSMesa, EGL };

class HeadlessContext {
  public:
    virtual ~HeadlessContext() = default;
    virtual const char* name() const = 0;  // "osmesa" or "egl"
    // Makes the context current on this thread and (re)loads glad for it.
    virtual bool makeCurrent() = 0;
};

// Creates the context, makes it current and loads glad. Returns nullptr and
// fills *error (when given) with the reason of every backend that was tried.
std::unique_ptr<HeadlessContext> createHeadless(HeadlessBackend backend, std::string* error);

// Whether the backend was compiled in (its package was found at configure time).
bool headlessBackendCompiled(HeadlessBackend backend);

const char* toString(HeadlessBackend backend);  // "auto", "osmesa", "egl"
std::optional<HeadlessBackend> parseHeadlessBackend(std::string_view text);

}  // namespace platform
