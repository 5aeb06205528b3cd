// EGL on Mesa's surfaceless platform: a GL context with no window and no
// surface at all (EGL_KHR_surfaceless_context). The fallback when OSMesa is absent.
#include <glad/gl.h>
// After glad, so that EGL's headers do not pull in a second GL header.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "platform/driver_crash_guard.h"
#include "platform/headless_backends.h"

namespace platform::detail {
namespace {

class EglContext final : public HeadlessContext {
  public:
    EglContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
    // The display is left initialised: EGL hands every caller the same surfaceless
    // display, and terminating it would break any other context still alive.
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
    }
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    const char* name() const override { return "egl"; }

    bool makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) return false;
        return gladLoadGL(eglGetProcAddress) != 0;
    }

  private:
    EGLDisplay display_;
    EGLContext context_;
};

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const std::size_t length = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name)) {
        const bool starts = p == list || p[-1] == ' ';
        const bool ends = p[length] == ' ' || p[length] == '\0';
        if (starts && ends) return true;
    }
    return false;
}

std::string fail(const char* step) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
    return std::string("egl: ") + step + " failed (EGL error " + code + ")";
}

EGLDisplay openSurfacelessDisplay(std::string* error) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        if (error) *error = "egl: EGL_MESA_platform_surfaceless is not supported";
        return EGL_NO_DISPLAY;
    }
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) {
        if (error) *error = "egl: eglGetPlatformDisplayEXT is missing";
        return EGL_NO_DISPLAY;
    }
    EGLDisplay display =
        getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) {
        if (error) *error = fail("eglGetPlatformDisplayEXT");
        return EGL_NO_DISPLAY;
    }
    EGLint major = 0;
    EGLint minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        if (error) *error = fail("eglInitialize");
        return EGL_NO_DISPLAY;
    }
    return display;
}

EGLContext createCoreContext(EGLDisplay display, std::string* error) {
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
        if (error) *error = "egl: EGL_KHR_surfaceless_context is not supported";
        return EGL_NO_CONTEXT;
    }
    // Surfaceless displays offer pbuffer configs only; the default (window) would match none.
    const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                       EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, configAttributes, &config, 1, &count) || count < 1) {
        if (error) *error = fail("eglChooseConfig (desktop GL config)");
        return EGL_NO_CONTEXT;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        if (error) *error = fail("eglBindAPI(EGL_OPENGL_API)");
        return EGL_NO_CONTEXT;
    }
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                        3,
                                        EGL_CONTEXT_MINOR_VERSION,
                                        3,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context == EGL_NO_CONTEXT && error) *error = fail("eglCreateContext (GL 3.3 core)");
    return context;
}

}  // namespace

std::unique_ptr<HeadlessContext> createEglContext(std::string* error) {
    const DriverCrashGuard guard("EGL created its context");
    EGLDisplay display = openSurfacelessDisplay(error);
    if (display == EGL_NO_DISPLAY) return nullptr;
    EGLContext raw = createCoreContext(display, error);
    if (raw == EGL_NO_CONTEXT) return nullptr;
    auto context = std::make_unique<EglContext>(display, raw);
    if (!context->makeCurrent()) {
        if (error) *error = "egl: could not make the context current or load GL with glad";
        return nullptr;
    }
    return context;
}

}  // namespace platform::detail
