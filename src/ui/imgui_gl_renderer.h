#pragma once
// Renders Dear ImGui's draw data with OpenGL 3.3 core through glad: one shader,
// one vertex array, the font atlas as an RGBA8 texture, a scissor rectangle and a
// texture per draw command. Works the same in a GLFW window and in a headless
// (OSMesa / EGL) context. Call order per frame: newFrame(), ImGui::NewFrame(),
// ...widgets..., ImGui::Render(), render(ImGui::GetDrawData()).
#include <glad/gl.h>

#include <glm/vec4.hpp>

#include <memory>
#include <string>
#include <vector>

struct ImDrawData;
struct ImDrawList;

namespace render {
class GlProgram;
}

namespace ui {

// What ImGui drew: the bounding box of each window's draw list, x, y, width, height
// in framebuffer px from the top left (tests check that no panel covers a view).
std::vector<glm::vec4> drawnRectangles(const ImDrawData& drawData);

class ImGuiGlRenderer {
  public:
    ImGuiGlRenderer();
    ~ImGuiGlRenderer();
    ImGuiGlRenderer(const ImGuiGlRenderer&) = delete;
    ImGuiGlRenderer& operator=(const ImGuiGlRenderer&) = delete;

    // Registers itself as the renderer backend of the current ImGui context.
    // Returns "" on success, else why not (no ImGui context).
    std::string init();
    // Creates the shader, buffers and font texture when missing; needs a current
    // GL context. On failure error() says why and render() draws nothing.
    void newFrame();
    // Draws into the bound framebuffer, whose size must be DisplaySize times
    // FramebufferScale. Saves and restores every piece of GL state it changes.
    void render(const ImDrawData* drawData);
    // Rebuilds the font texture at the next newFrame (after fonts were changed,
    // e.g. for a new content scale).
    void invalidateFontTexture();
    // Deletes the GL objects (needs the context current) and unregisters itself.
    void shutdown();

    const std::string& error() const { return error_; }

  private:
    bool createDeviceObjects();
    void createFontTexture();
    void destroyDeviceObjects();
    void setupRenderState(const ImDrawData& drawData, int framebufferWidth, int framebufferHeight);
    void renderList(const ImDrawList& list, const ImDrawData& drawData, int framebufferWidth,
                    int framebufferHeight);

    bool initialised_ = false;
    std::string error_;
    std::unique_ptr<render::GlProgram> program_;
    GLint projection_ = -1;
    GLint texture_ = -1;
    GLuint vertexArray_ = 0;
    GLuint vertexBuffer_ = 0;
    GLuint indexBuffer_ = 0;
    GLuint fontTexture_ = 0;
};

}  // namespace ui
