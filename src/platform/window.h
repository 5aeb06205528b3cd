#pragma once
// The interactive window: GLFW with an OpenGL 3.3 core context, glad loaded.
// Input stays with the app, which reads it through handle().
#include <glm/vec2.hpp>
#include <memory>
#include <string>

struct GLFWwindow;

namespace platform {

struct WindowOptions {
    int width = 1280;  // screen coordinates (scaled by the monitor's content scale); at most the screen's work area
    int height = 720;  // screen coordinates
    // The size above is the least: on a larger screen the window opens at kScreenShare of its
    // work area, in its middle (a teacher's 1920x1080 projector had it small in a corner).
    bool growToScreen = false;
    std::string title = "Rigid Spheres";
    bool vsync = true;
    // MSAA samples of the default framebuffer, 0 for none: the app's views blend the
    // spheres' outlines themselves, and the panel needs none.
    int samples = 0;
};

// One window per process: it initialises GLFW and terminates it when destroyed.
class Window {
  public:
    // Returns nullptr and fills *error (when given) if there is no display or no GL 3.3.
    static std::unique_ptr<Window> create(const WindowOptions& options, std::string* error);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    bool shouldClose() const;
    void requestClose();
    void pollEvents();
    void waitEvents(double timeoutSeconds);  // until an event comes, or the timeout (s)
    void swapBuffers();
    void setTitle(const std::string& title);
    void setVsync(bool on);

    glm::ivec2 windowSize() const;       // screen coordinates: what mouse positions use
    glm::ivec2 framebufferSize() const;  // pixels: what glViewport uses
    glm::vec2 contentScale() const;  // 1 on a normal screen, 2 on a HiDPI one: scale fonts by it
    // framebufferSize / windowSize: for ImGui's DisplayFramebufferScale (1 when minimised).
    glm::vec2 framebufferScale() const;
    double time() const;  // s since GLFW was initialised
    // Frames a second the primary display shows (its video mode's refresh rate; 60 where it
    // says none).
    double refreshRate() const;

    GLFWwindow* handle() const { return window_; }

  private:
    explicit Window(GLFWwindow* window) : window_(window) {}
    GLFWwindow* window_ = nullptr;
};

}  // namespace platform
