#include "platform/headless_context.h"

#include "platform/headless_backends.h"

namespace platform {
namespace {

#ifdef SPHERES_HAVE_OSMESA
constexpr bool kHaveOsMesa = true;
#else
constexpr bool kHaveOsMesa = false;
#endif
#ifdef SPHERES_HAVE_EGL
constexpr bool kHaveEgl = true;
#else
constexpr bool kHaveEgl = false;
#endif

std::unique_ptr<HeadlessContext> tryOsMesa(std::string* error) {
#ifdef SPHERES_HAVE_OSMESA
    return detail::createOsMesaContext(error);
#else
    if (error) *error = "osmesa: not built (libosmesa6-dev was not found at configure time)";
    return nullptr;
#endif
}

std::unique_ptr<HeadlessContext> tryEgl(std::string* error) {
#ifdef SPHERES_HAVE_EGL
    return detail::createEglContext(error);
#else
    if (error) *error = "egl: not built (libegl-dev was not found at configure time)";
    return nullptr;
#endif
}

}  // namespace

std::unique_ptr<HeadlessContext> createHeadless(HeadlessBackend backend, std::string* error) {
    std::string osmesaError;
    std::string eglError;
    std::unique_ptr<HeadlessContext> context;
    if (backend == HeadlessBackend::OSMesa || backend == HeadlessBackend::Auto) {
        context = tryOsMesa(&osmesaError);
    }
    if (!context && (backend == HeadlessBackend::EGL || backend == HeadlessBackend::Auto)) {
        context = tryEgl(&eglError);
    }
    if (!context && error) {
        *error = osmesaError;
        if (!osmesaError.empty() && !eglError.empty()) *error += "; ";
        *error += eglError;
    }
    return context;
}

bool headlessBackendCompiled(HeadlessBackend backend) {
    switch (backend) {
        case HeadlessBackend::OSMesa:
            return kHaveOsMesa;
        case HeadlessBackend::EGL:
            return kHaveEgl;
        case HeadlessBackend::Auto:
            return kHaveOsMesa || kHaveEgl;
    }
    return false;
}

const char* toString(HeadlessBackend backend) {
    switch (backend) {
        case HeadlessBackend::Auto:
            return "auto";
        case HeadlessBackend::OSMesa:
            return "osmesa";
        case HeadlessBackend::EGL:
            return "egl";
    }
    return "auto";
}

std::optional<HeadlessBackend> parseHeadlessBackend(std::string_view text) {
    if (text == "auto") return HeadlessBackend::Auto;
    if (text == "osmesa") return HeadlessBackend::OSMesa;
    if (text == "egl") return HeadlessBackend::EGL;
    return std::nullopt;
}

}  // namespace platform
