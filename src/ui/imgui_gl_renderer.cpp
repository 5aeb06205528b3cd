#include "ui/imgui_gl_renderer.h"

#include <imgui.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "render/gl_program.h"
#include "render/shader_sources.h"

namespace ui {
namespace {

constexpr const char* kBackendName = "spheres_imgui_gl";
constexpr GLenum kIndexType = sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;

// The GL state render() changes, captured before and put back after, so that
// drawing the UI never disturbs the scene renderer or the app.
struct GlStateBackup {
    GLint activeTexture, program, texture, sampler, arrayBuffer, vertexArray;
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
                                 int framebufferWidth, int framebufferHeight) {
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
        // Clip rectangle in framebuffer pixels; GL's scissor counts rows from the bottom.
        const float x0 = (command.ClipRect.x - origin.x) * scale.x;
        const float y0 = (command.ClipRect.y - origin.y) * scale.y;
        const float x1 = (command.ClipRect.z - origin.x) * scale.x;
        const float y1 = (command.ClipRect.w - origin.y) * scale.y;
        if (x1 <= x0 || y1 <= y0) continue;
        glScissor(static_cast<GLint>(x0), static_cast<GLint>(framebufferHeight - y1),
                  static_cast<GLsizei>(x1 - x0), static_cast<GLsizei>(y1 - y0));
        glBindTexture(GL_TEXTURE_2D, toGl(command.GetTexID()));
        glDrawElementsBaseVertex(
            GL_TRIANGLES, static_cast<GLsizei>(command.ElemCount), kIndexType,
            reinterpret_cast<const void*>(command.IdxOffset * sizeof(ImDrawIdx)),
            static_cast<GLint>(command.VtxOffset));
    }
}

void ImGuiGlRenderer::render(const ImDrawData* drawData) {
    if (drawData == nullptr || !program_) return;
    const int framebufferWidth =
        static_cast<int>(drawData->DisplaySize.x * drawData->FramebufferScale.x);
    const int framebufferHeight =
        static_cast<int>(drawData->DisplaySize.y * drawData->FramebufferScale.y);
    if (framebufferWidth <= 0 || framebufferHeight <= 0) return;  // minimised

    GlStateBackup backup{};
    backup.capture();
    setupRenderState(*drawData, framebufferWidth, framebufferHeight);
    for (int i = 0; i < drawData->CmdListsCount; ++i) {
        renderList(*drawData->CmdLists[i], *drawData, framebufferWidth, framebufferHeight);
    }
    backup.restore();
}

std::vector<glm::vec4> drawnRectangles(const ImDrawData& drawData) {
    std::vector<glm::vec4> boxes;
    for (int n = 0; n < drawData.CmdListsCount; ++n) {
        const ImDrawList& list = *drawData.CmdLists[n];
        ImVec2 lo(1e30f, 1e30f), hi(-1e30f, -1e30f);
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            if (cmd.UserCallback || cmd.ElemCount == 0) continue;
            // What a command covers: its triangles, cut by its scissor rectangle (ImGui
            // leaves clipped text's vertices in the list).
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
        if (lo.x >= hi.x) continue;
        const ImVec2 scale = drawData.FramebufferScale, origin = drawData.DisplayPos;
        boxes.emplace_back((lo.x - origin.x) * scale.x, (lo.y - origin.y) * scale.y, (hi.x - lo.x) * scale.x,
                           (hi.y - lo.y) * scale.y);
    }
    return boxes;
}

}  // namespace ui
