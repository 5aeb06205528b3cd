#include "ui/imgui_gl_renderer.h"

#include <imgui.h>

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <optional>

#include "render/gl_program.h"
#include "render/shader_sources.h"

namespace ui {
namespace {

constexpr const char* kBackendName = "spheres_imgui_gl";
constexpr GLenum kIndexType = sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;
// The panel layer costs a copy of the panel each frame on top of what it draws again: when
// most of the panel changes (a line more or less moves all below it, a scroll moves all
// of it), the panel is drawn straight in instead, for a third of a second at 60 frames/s.
constexpr float kMostRedrawnShare = 0.5f;
constexpr int kStraightFramesAfterChange = 20;

// The GL state render() changes, captured before and put back after, so that
// drawing the UI never disturbs the scene renderer or the app.
struct GlStateBackup {
    GLint activeTexture, program, texture, sampler, arrayBuffer, vertexArray, drawFramebuffer, readFramebuffer;
    GLfloat clearColor[4];
    GLint polygonMode[2], viewport[4], scissorBox[4];
    GLint blendSrcRgb, blendDstRgb, blendSrcAlpha, blendDstAlpha, blendEqRgb, blendEqAlpha;
    GLboolean blend, cullFace, depthTest, stencilTest, scissorTest;

    void capture() {
        glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture);
        glActiveTexture(GL_TEXTURE0);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
        glGetIntegerv(GL_SAMPLER_BINDING, &sampler);
        glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
        glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColor);
        glGetIntegerv(GL_POLYGON_MODE, polygonMode);
        glGetIntegerv(GL_VIEWPORT, viewport);
        glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
        glGetIntegerv(GL_BLEND_SRC_RGB, &blendSrcRgb);
        glGetIntegerv(GL_BLEND_DST_RGB, &blendDstRgb);
        glGetIntegerv(GL_BLEND_SRC_ALPHA, &blendSrcAlpha);
        glGetIntegerv(GL_BLEND_DST_ALPHA, &blendDstAlpha);
        glGetIntegerv(GL_BLEND_EQUATION_RGB, &blendEqRgb);
        glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blendEqAlpha);
        blend = glIsEnabled(GL_BLEND);
        cullFace = glIsEnabled(GL_CULL_FACE);
        depthTest = glIsEnabled(GL_DEPTH_TEST);
        stencilTest = glIsEnabled(GL_STENCIL_TEST);
        scissorTest = glIsEnabled(GL_SCISSOR_TEST);
    }

    static void setEnabled(GLenum capability, GLboolean on) {
        if (on) {
            glEnable(capability);
        } else {
            glDisable(capability);
        }
    }

    void restore() const {
        glUseProgram(static_cast<GLuint>(program));
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture));
        glBindSampler(0, static_cast<GLuint>(sampler));
        glActiveTexture(static_cast<GLenum>(activeTexture));
        glBindVertexArray(static_cast<GLuint>(vertexArray));
        glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(arrayBuffer));
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer));
        glClearColor(clearColor[0], clearColor[1], clearColor[2], clearColor[3]);
        glBlendEquationSeparate(static_cast<GLenum>(blendEqRgb), static_cast<GLenum>(blendEqAlpha));
        glBlendFuncSeparate(static_cast<GLenum>(blendSrcRgb), static_cast<GLenum>(blendDstRgb),
                            static_cast<GLenum>(blendSrcAlpha), static_cast<GLenum>(blendDstAlpha));
        setEnabled(GL_BLEND, blend);
        setEnabled(GL_CULL_FACE, cullFace);
        setEnabled(GL_DEPTH_TEST, depthTest);
        setEnabled(GL_STENCIL_TEST, stencilTest);
        setEnabled(GL_SCISSOR_TEST, scissorTest);
        // Core profile: front and back share one polygon mode.
        glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygonMode[0]));
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
        glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
    }
};

GLuint toGl(ImTextureID id) { return static_cast<GLuint>(reinterpret_cast<std::intptr_t>(id)); }
ImTextureID toImGui(GLuint id) {
    return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(id));
}

// A list's drawn box (x, y, width, height in framebuffer px from the top left): its
// triangles, each cut by its command's clip rectangle (ImGui leaves clipped text's
// vertices in the list); nullopt when it draws nothing.
std::optional<glm::vec4> drawnRectangle(const ImDrawList& list, const ImDrawData& drawData) {
    ImVec2 lo(1e30f, 1e30f), hi(-1e30f, -1e30f);
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
        if (cmd.UserCallback || cmd.ElemCount == 0) continue;
        ImVec2 a(1e30f, 1e30f), b(-1e30f, -1e30f);
        for (unsigned int e = 0; e < cmd.ElemCount; ++e) {
            const ImDrawVert& v = list.VtxBuffer[int(cmd.VtxOffset + list.IdxBuffer[int(cmd.IdxOffset + e)])];
            a = ImVec2(std::min(a.x, v.pos.x), std::min(a.y, v.pos.y));
            b = ImVec2(std::max(b.x, v.pos.x), std::max(b.y, v.pos.y));
        }
        a = ImVec2(std::max(a.x, cmd.ClipRect.x), std::max(a.y, cmd.ClipRect.y));
        b = ImVec2(std::min(b.x, cmd.ClipRect.z), std::min(b.y, cmd.ClipRect.w));
        if (a.x >= b.x || a.y >= b.y) continue;
        lo = ImVec2(std::min(lo.x, a.x), std::min(lo.y, a.y));
        hi = ImVec2(std::max(hi.x, b.x), std::max(hi.y, b.y));
    }
    if (lo.x >= hi.x) return std::nullopt;
    const ImVec2 scale = drawData.FramebufferScale, origin = drawData.DisplayPos;
    return glm::vec4((lo.x - origin.x) * scale.x, (lo.y - origin.y) * scale.y, (hi.x - lo.x) * scale.x,
                     (hi.y - lo.y) * scale.y);
}

// Whole pixels around `area` (x0, y0, x1, y1 px from the top left), one more on each
// side for antialiased edges, within the framebuffer.
glm::vec4 pixelsAround(const glm::vec4& area, int width, int height) {
    const auto clampTo = [](float v, int most) { return std::clamp(v, 0.0f, float(most)); };
    return {clampTo(std::floor(area.x) - 1.0f, width), clampTo(std::floor(area.y) - 1.0f, height),
            clampTo(std::ceil(area.z) + 1.0f, width), clampTo(std::ceil(area.w) + 1.0f, height)};
}

// `box` (x0, y0, x1, y1 in ImGui units) in framebuffer px from the top left.
glm::vec4 inPixels(const ImVec4& box, const ImDrawData& drawData) {
    const ImVec2 origin = drawData.DisplayPos, scale = drawData.FramebufferScale;
    return {(box.x - origin.x) * scale.x, (box.y - origin.y) * scale.y, (box.z - origin.x) * scale.x,
            (box.w - origin.y) * scale.y};
}

// GL's scissor (rows from the bottom) for x0, y0, x1, y1 px from the top left.
void scissorTo(const glm::vec4& area, int framebufferHeight) {
    glScissor(GLint(area.x), GLint(float(framebufferHeight) - area.w), GLsizei(area.z - area.x),
              GLsizei(area.w - area.y));
}

void vertexAttribute(GLuint location, GLint size, GLenum type, GLboolean normalized,
                     std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, type, normalized, sizeof(ImDrawVert),
                          reinterpret_cast<const void*>(offset));
}

}  // namespace

ImGuiGlRenderer::ImGuiGlRenderer() = default;
ImGuiGlRenderer::~ImGuiGlRenderer() { shutdown(); }

std::string ImGuiGlRenderer::init() {
    if (ImGui::GetCurrentContext() == nullptr) return "imgui renderer: no ImGui context";
    ImGuiIO& io = ImGui::GetIO();
    io.BackendRendererName = kBackendName;
    // 16-bit indices with a per-command vertex offset: meshes above 64K vertices.
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    initialised_ = true;
    error_.clear();
    return {};
}

void ImGuiGlRenderer::newFrame() {
    if (!initialised_) return;
    if (!program_ && !createDeviceObjects()) return;
    if (fontTexture_ == 0) createFontTexture();
}

bool ImGuiGlRenderer::createDeviceObjects() {
    program_ = std::make_unique<render::GlProgram>();
    error_ = program_->build("imgui", render::shaders::kImguiVert, render::shaders::kImguiFrag);
    if (!error_.empty()) {
        program_.reset();
        return false;
    }
    projection_ = program_->uniform("uProjection");
    texture_ = program_->uniform("uTexture");

    GLint previousArrayBuffer = 0;
    GLint previousVertexArray = 0;
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &previousArrayBuffer);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &previousVertexArray);
    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &vertexBuffer_);
    glGenBuffers(1, &indexBuffer_);
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);  // recorded in the vertex array
    vertexAttribute(0, 2, GL_FLOAT, GL_FALSE, offsetof(ImDrawVert, pos));
    vertexAttribute(1, 2, GL_FLOAT, GL_FALSE, offsetof(ImDrawVert, uv));
    vertexAttribute(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(ImDrawVert, col));
    glBindVertexArray(static_cast<GLuint>(previousVertexArray));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(previousArrayBuffer));
    return true;
}

void ImGuiGlRenderer::createFontTexture() {
    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int width = 0;
    int height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // builds the atlas if needed

    GLint previousTexture = 0;
    GLint previousAlignment = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previousTexture);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &previousAlignment);
    glGenTextures(1, &fontTexture_);
    glBindTexture(GL_TEXTURE_2D, fontTexture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);  // RGBA8 rows are always 4-byte aligned
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, previousAlignment);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previousTexture));
    io.Fonts->SetTexID(toImGui(fontTexture_));
}

void ImGuiGlRenderer::invalidateFontTexture() {
    forgetLayer();  // drawn with the old glyphs
    if (fontTexture_ != 0) glDeleteTextures(1, &fontTexture_);
    fontTexture_ = 0;
    if (ImGui::GetCurrentContext() != nullptr) ImGui::GetIO().Fonts->SetTexID(nullptr);
}

void ImGuiGlRenderer::destroyDeviceObjects() {
    invalidateFontTexture();
    if (vertexArray_ != 0) {
        glDeleteBuffers(1, &vertexBuffer_);
        glDeleteBuffers(1, &indexBuffer_);
        glDeleteVertexArrays(1, &vertexArray_);
    }
    vertexArray_ = vertexBuffer_ = indexBuffer_ = 0;
    if (layerFramebuffer_ != 0) glDeleteFramebuffers(1, &layerFramebuffer_);
    if (layerTexture_ != 0) glDeleteTextures(1, &layerTexture_);
    layerFramebuffer_ = layerTexture_ = 0;
    layerSize_ = glm::ivec2(0);
    program_.reset();
}

void ImGuiGlRenderer::shutdown() {
    if (!initialised_) return;
    destroyDeviceObjects();
    if (ImGui::GetCurrentContext() != nullptr) {
        ImGuiIO& io = ImGui::GetIO();
        io.BackendRendererName = nullptr;
        io.BackendFlags &= ~ImGuiBackendFlags_RendererHasVtxOffset;
    }
    initialised_ = false;
}

void ImGuiGlRenderer::setupRenderState(const ImDrawData& drawData, int framebufferWidth,
                                       int framebufferHeight) {
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_SCISSOR_TEST);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glViewport(0, 0, framebufferWidth, framebufferHeight);

    // Display rectangle (ImGui units, y down) to clip space.
    const float left = drawData.DisplayPos.x;
    const float right = left + drawData.DisplaySize.x;
    const float top = drawData.DisplayPos.y;
    const float bottom = top + drawData.DisplaySize.y;
    const float projection[16] = {2.0f / (right - left),
                                  0.0f,
                                  0.0f,
                                  0.0f,
                                  0.0f,
                                  2.0f / (top - bottom),
                                  0.0f,
                                  0.0f,
                                  0.0f,
                                  0.0f,
                                  -1.0f,
                                  0.0f,
                                  (right + left) / (left - right),
                                  (top + bottom) / (bottom - top),
                                  0.0f,
                                  1.0f};
    glUseProgram(program_->id());
    glUniformMatrix4fv(projection_, 1, GL_FALSE, projection);
    glUniform1i(texture_, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindSampler(0, 0);
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
}

void ImGuiGlRenderer::renderList(const ImDrawList& list, const ImDrawData& drawData,
                                 int framebufferWidth, int framebufferHeight, glm::vec4 limit) {
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.VtxBuffer.Size) * sizeof(ImDrawVert),
                 list.VtxBuffer.Data, GL_STREAM_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(list.IdxBuffer.Size) * sizeof(ImDrawIdx),
                 list.IdxBuffer.Data, GL_STREAM_DRAW);
    const ImVec2 origin = drawData.DisplayPos;
    const ImVec2 scale = drawData.FramebufferScale;
    for (const ImDrawCmd& command : list.CmdBuffer) {
        if (command.UserCallback == ImDrawCallback_ResetRenderState) {
            setupRenderState(drawData, framebufferWidth, framebufferHeight);
            continue;
        }
        if (command.UserCallback != nullptr) {
            command.UserCallback(&list, &command);
            continue;
        }
        // Clip rectangle in whole framebuffer pixels, GL's rows from the bottom (the same
        // pixels whatever the limit, at any scale), then cut to the limit.
        const float x0 = (command.ClipRect.x - origin.x) * scale.x;
        const float y0 = (command.ClipRect.y - origin.y) * scale.y;
        const float x1 = (command.ClipRect.z - origin.x) * scale.x;
        const float y1 = (command.ClipRect.w - origin.y) * scale.y;
        if (x1 <= x0 || y1 <= y0) continue;
        const GLint left = std::max(GLint(x0), GLint(limit.x));
        const GLint right = std::min(GLint(x0) + GLint(x1 - x0), GLint(limit.z));
        const GLint bottom = std::max(GLint(float(framebufferHeight) - y1), framebufferHeight - GLint(limit.w));
        const GLint top = std::min(GLint(float(framebufferHeight) - y1) + GLint(y1 - y0), framebufferHeight - GLint(limit.y));
        if (right <= left || top <= bottom) continue;
        glScissor(left, bottom, right - left, top - bottom);
        glBindTexture(GL_TEXTURE_2D, toGl(command.GetTexID()));
        glDrawElementsBaseVertex(
            GL_TRIANGLES, static_cast<GLsizei>(command.ElemCount), kIndexType,
            reinterpret_cast<const void*>(command.IdxOffset * sizeof(ImDrawIdx)),
            static_cast<GLint>(command.VtxOffset));
    }
}

void ImGuiGlRenderer::render(const ImDrawData* drawData, const Backdrop* beneath) {
    layerStats_ = {};
    if (drawData == nullptr || !program_) return;
    const int framebufferWidth =
        static_cast<int>(drawData->DisplaySize.x * drawData->FramebufferScale.x);
    const int framebufferHeight =
        static_cast<int>(drawData->DisplaySize.y * drawData->FramebufferScale.y);
    if (framebufferWidth <= 0 || framebufferHeight <= 0) return;  // minimised

    GlStateBackup backup{};
    backup.capture();
    setupRenderState(*drawData, framebufferWidth, framebufferHeight);
    int first = 0;
    if (beneath != nullptr && drawData->CmdListsCount > 0) {
        first = drawFromLayer(*drawData, *beneath, framebufferWidth, framebufferHeight) ? 1 : 0;
    }
    const glm::vec4 everything(0.0f, 0.0f, float(framebufferWidth), float(framebufferHeight));
    for (int i = first; i < drawData->CmdListsCount; ++i) {
        renderList(*drawData->CmdLists[i], *drawData, framebufferWidth, framebufferHeight, everything);
    }
    backup.restore();
}

// The layer holds the first list drawn over the backdrop's colour, exactly as it would be
// drawn straight in (the same blending onto the same colour), so copying it changes no
// pixel. What changed since it was drawn is drawn again first: cleared to the backdrop and
// drawn again within that area.
bool ImGuiGlRenderer::drawFromLayer(const ImDrawData& drawData, const Backdrop& beneath, int framebufferWidth,
                                    int framebufferHeight) {
    const ImDrawList& list = *drawData.CmdLists[0];
    const std::optional<LayerCopy> copy = layerCopy(list, drawData, beneath, framebufferWidth, framebufferHeight);
    GLint multisampled = 0;  // a blit into a multisampled frame would fail
    glGetIntegerv(GL_SAMPLE_BUFFERS, &multisampled);
    if (straightFrames_ > 0 || multisampled != 0 || !copy || !resizeLayer(framebufferWidth, framebufferHeight)) {
        straightFrames_ = std::max(straightFrames_ - 1, 0);
        forgetLayer();
        return false;
    }
    const bool held = !layerList_.empty();
    const glm::vec4 stale = staleArea(list, drawData, beneath, framebufferWidth, framebufferHeight);
    const auto size = [](const glm::vec4& a) { return std::max(a.z - a.x, 0.0f) * std::max(a.w - a.y, 0.0f); };
    if (held && size(stale) > kMostRedrawnShare * size(copy->area)) {  // most of it changes: straight in
        straightFrames_ = kStraightFramesAfterChange;
        forgetLayer();
        return false;
    }
    GLint target = 0;  // where the frame is drawn
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    if (stale.z > stale.x && stale.w > stale.y) {
        glBindFramebuffer(GL_FRAMEBUFFER, layerFramebuffer_);
        scissorTo(stale, framebufferHeight);
        glClearColor(beneath.colour.x, beneath.colour.y, beneath.colour.z, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        renderList(list, drawData, framebufferWidth, framebufferHeight, stale);
        layerStats_.redrawn = glm::vec4(stale.x, stale.y, stale.z - stale.x, stale.w - stale.y);
    }
    std::swap(layerList_, drawnList_);
    layerBackdrop_ = beneath.colour;
    layerDisplay_ = glm::vec4(drawData.DisplayPos.x, drawData.DisplayPos.y, drawData.FramebufferScale.x,
                              drawData.FramebufferScale.y);
    const glm::vec4& area = copy->area;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, layerFramebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
    scissorTo(area, framebufferHeight);
    const GLint x0 = GLint(area.x), x1 = GLint(area.z), y0 = framebufferHeight - GLint(area.w),
                y1 = framebufferHeight - GLint(area.y);
    glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    if (copy->straightFrom < float(framebufferWidth)) {  // its edge over a view
        renderList(list, drawData, framebufferWidth, framebufferHeight,
                   glm::vec4(copy->straightFrom, 0.0f, float(framebufferWidth), float(framebufferHeight)));
    }
    layerStats_.copied = true;
    return true;
}

// The layer is copied where only the backdrop lies beneath it: the list's drawn box in
// whole pixels, up to the first view on its right (the panel's border reaches a pixel
// into the view beside it), and the rest is drawn straight in. nullopt when the box
// reaches into a view elsewhere, or the list draws with another texture than the font
// atlas (its pixels may change while the list stays the same).
std::optional<ImGuiGlRenderer::LayerCopy> ImGuiGlRenderer::layerCopy(const ImDrawList& list, const ImDrawData& drawData,
                                                                      const Backdrop& beneath, int framebufferWidth,
                                                                      int framebufferHeight) const {
    const bool fontOnly = std::all_of(list.CmdBuffer.begin(), list.CmdBuffer.end(), [&](const ImDrawCmd& c) {
        return c.UserCallback == nullptr && (c.ElemCount == 0 || toGl(c.GetTexID()) == fontTexture_);
    });
    const std::optional<glm::vec4> box = drawnRectangle(list, drawData);
    if (!fontOnly || !box) return std::nullopt;
    const auto clampTo = [](float v, int most) { return std::clamp(v, 0.0f, float(most)); };
    LayerCopy copy;
    copy.area = glm::vec4(clampTo(std::floor(box->x), framebufferWidth), clampTo(std::floor(box->y), framebufferHeight),
                          clampTo(std::ceil(box->x + box->z), framebufferWidth),
                          clampTo(std::ceil(box->y + box->w), framebufferHeight));
    const auto reaches = [&](const glm::vec4& view) {  // x, y, width, height
        return copy.area.x < view.x + view.z && view.x < copy.area.z && copy.area.y < view.y + view.w &&
               view.y < copy.area.w;
    };
    for (const glm::vec4& view : beneath.drawn) {
        if (reaches(view) && view.x > copy.area.x) copy.area.z = std::min(copy.area.z, std::floor(view.x));
    }
    if (std::any_of(beneath.drawn.begin(), beneath.drawn.end(), reaches)) return std::nullopt;
    copy.straightFrom = copy.area.z < std::ceil(box->x + box->z) ? copy.area.z : float(framebufferWidth);
    return copy;
}

glm::vec4 ImGuiGlRenderer::staleArea(const ImDrawList& list, const ImDrawData& drawData, const Backdrop& beneath,
                                     int framebufferWidth, int framebufferHeight) {
    drawnList_.assign(list);
    const glm::vec4 everything(0.0f, 0.0f, float(framebufferWidth), float(framebufferHeight));
    const glm::vec4 display(drawData.DisplayPos.x, drawData.DisplayPos.y, drawData.FramebufferScale.x,
                            drawData.FramebufferScale.y);
    if (beneath.colour != layerBackdrop_ || display != layerDisplay_) return everything;
    const std::optional<ImVec4> changed = changedArea(layerList_, drawnList_);
    if (!changed) return everything;
    if (changed->z <= changed->x) return glm::vec4(0.0f);
    return pixelsAround(inPixels(*changed, drawData), framebufferWidth, framebufferHeight);
}

bool ImGuiGlRenderer::resizeLayer(int width, int height) {
    if (layerFramebuffer_ != 0 && layerSize_ == glm::ivec2(width, height)) return layerComplete_;
    forgetLayer();
    GLint previousTexture = 0, previousFramebuffer = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previousTexture);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    if (layerTexture_ == 0) glGenTextures(1, &layerTexture_);
    if (layerFramebuffer_ == 0) glGenFramebuffers(1, &layerFramebuffer_);
    glBindTexture(GL_TEXTURE_2D, layerTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, layerFramebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, layerTexture_, 0);
    const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previousTexture));
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
    layerSize_ = glm::ivec2(width, height);  // not tried again at this size when incomplete
    layerComplete_ = complete;
    return complete;
}

void ImGuiGlRenderer::forgetLayer() {
    layerList_.clear();
    layerBackdrop_ = glm::vec3(-1.0f);
}

std::vector<glm::vec4> drawnRectangles(const ImDrawData& drawData) {
    std::vector<glm::vec4> boxes;
    for (int n = 0; n < drawData.CmdListsCount; ++n) {
        if (const std::optional<glm::vec4> box = drawnRectangle(*drawData.CmdLists[n], drawData)) boxes.push_back(*box);
    }
    return boxes;
}

}  // namespace ui
