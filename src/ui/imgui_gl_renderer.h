#pragma once
// Renders Dear ImGui's draw data with OpenGL 3.3 core through glad: one shader,
// one vertex array, the font atlas as an RGBA8 texture, a scissor rectangle and a
// texture per draw command. Works the same in a GLFW window and in a headless
// (OSMesa / EGL) context. Call order per frame: newFrame(), ImGui::NewFrame(),
// ...widgets..., ImGui::Render(), render(ImGui::GetDrawData()).
#include <glad/gl.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/draw_list_changes.h"

struct ImDrawData;
struct ImDrawList;

namespace render {
class GlProgram;
}

namespace ui {

// What ImGui drew: the bounding box of each window's draw list, x, y, width, height
// in framebuffer px from the top left (tests check that no panel covers a view).
std::vector<glm::vec4> drawnRectangles(const ImDrawData& drawData);

// What lies beneath the first window ImGui draws (the control panel), vouched for by the
// caller: a flat `colour`, and the scene's `drawn` rectangles (x, y, width, height in
// framebuffer px from the top left) around it. Then that window is kept drawn in a
// texture and copied each frame, drawn again only where it changed, while it overlaps
// none of `drawn`.
struct Backdrop {
    glm::vec3 colour{0.0f};
    std::vector<glm::vec4> drawn;
};

// How the last render() drew the first window.
struct PanelLayerStats {
    bool copied = false;     // from the texture (else drawn straight in)
    glm::vec4 redrawn{0.0f};  // the part drawn again into the texture (x, y, width, height px)
};

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
    // With `beneath`, the first window is drawn from its texture when it can be.
    void render(const ImDrawData* drawData, const Backdrop* beneath = nullptr);
    // Rebuilds the font texture at the next newFrame (after fonts were changed,
    // e.g. for a new content scale).
    void invalidateFontTexture();
    // Deletes the GL objects (needs the context current) and unregisters itself.
    void shutdown();

    const std::string& error() const { return error_; }
    const PanelLayerStats& panelLayerStats() const { return layerStats_; }

  private:
    bool createDeviceObjects();
    void createFontTexture();
    void destroyDeviceObjects();
    void setupRenderState(const ImDrawData& drawData, int framebufferWidth, int framebufferHeight);
    // Draws the list, cut to `limit` (framebuffer px from the top left: x0, y0, x1, y1).
    void renderList(const ImDrawList& list, const ImDrawData& drawData, int framebufferWidth,
                    int framebufferHeight, glm::vec4 limit);
    // The first list from the panel layer; false when it cannot be (then draw it straight).
    bool drawFromLayer(const ImDrawData& drawData, const Backdrop& beneath, int framebufferWidth,
                       int framebufferHeight);
    // The part of the layer to draw again (px from the top left: x0, y0, x1, y1); keeps
    // the list's triangles in drawnList_.
    glm::vec4 staleArea(const ImDrawList& list, const ImDrawData& drawData, const Backdrop& beneath,
                        int framebufferWidth, int framebufferHeight);
    struct LayerCopy {
        glm::vec4 area{0.0f};      // px from the top left: x0, y0, x1, y1
        float straightFrom = 0.0f;  // px: right of this the list is drawn straight in
    };
    std::optional<LayerCopy> layerCopy(const ImDrawList& list, const ImDrawData& drawData, const Backdrop& beneath,
                                       int framebufferWidth, int framebufferHeight) const;
    bool resizeLayer(int width, int height);
    void forgetLayer();

    bool initialised_ = false;
    std::string error_;
    std::unique_ptr<render::GlProgram> program_;
    GLint projection_ = -1;
    GLint texture_ = -1;
    GLuint vertexArray_ = 0;
    GLuint vertexBuffer_ = 0;
    GLuint indexBuffer_ = 0;
    GLuint fontTexture_ = 0;

    // The panel layer: the first window drawn over its backdrop, as it was last frame.
    GLuint layerTexture_ = 0;
    GLuint layerFramebuffer_ = 0;
    glm::ivec2 layerSize_{0};
    bool layerComplete_ = false;  // its framebuffer at layerSize_
    DrawListCopy layerList_;     // what the layer holds
    DrawListCopy drawnList_;     // this frame's, compared with it
    glm::vec3 layerBackdrop_{-1.0f};
    glm::vec4 layerDisplay_{0.0f};  // DisplayPos, FramebufferScale it was drawn with
    PanelLayerStats layerStats_;
    int straightFrames_ = 0;  // frames left to draw the panel straight in, after most of it changed
};

}  // namespace ui
