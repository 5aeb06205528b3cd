#include "platform/window.h"

#include <algorithm>

#include <glad/gl.h>
// After glad, so that GLFW does not pull in the system GL header.
#include <GLFW/glfw3.h>

#include "platform/driver_crash_guard.h"

namespace platform {
namespace {

// GLFW reports errors through a C callback; keep the last message so that
// create() can hand it back instead of crashing or printing to nowhere.
thread_local std::string lastGlfwError;

void onGlfwError(int code, const char* description) {
    lastGlfwError = "GLFW error " + std::to_string(code) + ": " + (description ? description : "");
}

std::string takeGlfwError(const char* fallback) {
    std::string message = lastGlfwError.empty() ? fallback : lastGlfwError;
    lastGlfwError.clear();
    return message;
}

void setError(std::string* error, const std::string& message) {
    if (error) *error = message;
}

void setContextHints(const WindowOptions& options) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);  // required on macOS
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, options.samples);
    // HiDPI: scale the window to the monitor on Windows/X11, full-resolution framebuffer on macOS.
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    glfwWindowHint(GLFW_COCOA_RETINA_FRAMEBUFFER, GLFW_TRUE);
}

// The size asked for, no larger than the primary monitor's work area (the screen less its
// panels): the default 1280 x 800 on a 1366 x 768 laptop put the timeline bar and the
// side-by-side field below the screen's edge. Screen coordinates, before the monitor's
// content scale, which GLFW_SCALE_TO_MONITOR applies on Windows and X11 (on macOS screen
// coordinates are points already, and the hint does nothing).
// With `grow`, at least kScreenShare of the work area.
constexpr float kScreenShare = 0.8f;

// The primary monitor's work area: its corner and size in screen coordinates, and the content
// scale GLFW multiplies a window's size by (1 on macOS); a size of 0 where it is unknown.
struct WorkArea {
    glm::ivec2 corner{0}, size{0};
    glm::vec2 scale{1.0f};
    glm::ivec2 room() const { return glm::ivec2(glm::vec2(size) / scale); }  // a window's size that fills it
};
WorkArea primaryWorkArea() {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (!monitor) return {};
    int x = 0, y = 0, w = 0, h = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
    float xscale = 1.0f, yscale = 1.0f;
#ifndef __APPLE__
    glfwGetMonitorContentScale(monitor, &xscale, &yscale);
#endif
    if (w <= 0 || h <= 0 || xscale <= 0.0f || yscale <= 0.0f) return {};
    return {{x, y}, {w, h}, {xscale, yscale}};
}

glm::ivec2 sizeThatFits(int width, int height, bool grow, const WorkArea& area) {
    if (area.size.x <= 0) return {width, height};
    const glm::ivec2 room = area.room();
    if (grow) {
        width = std::max(width, int(kScreenShare * float(room.x)));
        height = std::max(height, int(kScreenShare * float(room.y)));
    }
    return {std::min(width, room.x), std::min(height, room.y)};
}

}  // namespace

std::unique_ptr<Window> Window::create(const WindowOptions& options, std::string* error) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        setError(error, takeGlfwError("GLFW could not be initialised (is there a display?)"));
        return nullptr;
    }
    setContextHints(options);
    const DriverCrashGuard guard("GLFW opened the window");
    const WorkArea area = primaryWorkArea();
    const glm::ivec2 size = sizeThatFits(options.width, options.height, options.growToScreen, area);
    GLFWwindow* window = glfwCreateWindow(size.x, size.y, options.title.c_str(), nullptr, nullptr);
    if (!window) {
        setError(error, takeGlfwError("could not create an OpenGL 3.3 core window"));
        glfwTerminate();
        return nullptr;
    }
    if (options.growToScreen && area.room().x > size.x) {  // in the middle of a screen it does not fill
        const glm::ivec2 margin = (area.size - glm::ivec2(glm::vec2(size) * area.scale)) / 2;
        glfwSetWindowPos(window, area.corner.x + margin.x, area.corner.y + margin.y);
    }
    glfwMakeContextCurrent(window);
    if (!gladLoadGL(glfwGetProcAddress)) {
        setError(error, "glad could not load OpenGL 3.3 core through GLFW");
        glfwDestroyWindow(window);
        glfwTerminate();
        return nullptr;
    }
    glfwSwapInterval(options.vsync ? 1 : 0);
    return std::unique_ptr<Window>(new Window(window));
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }
void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::pollEvents() { glfwPollEvents(); }
void Window::waitEvents(double timeoutSeconds) { glfwWaitEventsTimeout(timeoutSeconds); }
void Window::swapBuffers() { glfwSwapBuffers(window_); }
void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

double Window::refreshRate() const {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    return mode && mode->refreshRate > 0 ? double(mode->refreshRate) : 60.0;
}

void Window::setVsync(bool on) {
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(on ? 1 : 0);
}

glm::ivec2 Window::windowSize() const {
    glm::ivec2 size{0};
    glfwGetWindowSize(window_, &size.x, &size.y);
    return size;
}

glm::ivec2 Window::framebufferSize() const {
    glm::ivec2 size{0};
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
}

glm::vec2 Window::contentScale() const {
    glm::vec2 scale{1.0f};
    glfwGetWindowContentScale(window_, &scale.x, &scale.y);
    return scale;
}

glm::vec2 Window::framebufferScale() const {
    const glm::ivec2 window = windowSize();
    const glm::ivec2 framebuffer = framebufferSize();
    if (window.x <= 0 || window.y <= 0) return glm::vec2{1.0f};
    return glm::vec2(framebuffer) / glm::vec2(window);
}

double Window::time() const { return glfwGetTime(); }

}  // namespace platform
