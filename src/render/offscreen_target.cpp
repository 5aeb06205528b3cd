#include "render/offscreen_target.h"

#include <algorithm>
#include <utility>

namespace render {
namespace {

GLuint makeRenderbuffer(GLenum format, int width, int height, int samples) {
    GLuint buffer = 0;
    glGenRenderbuffers(1, &buffer);
    glBindRenderbuffer(GL_RENDERBUFFER, buffer);
    if (samples > 0) {
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
        glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
    return buffer;
}

GLuint makeFramebuffer(GLuint color, GLuint depth) {
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    if (depth != 0) {
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    }
    return framebuffer;
}

}  // namespace

OffscreenTarget::~OffscreenTarget() { destroy(); }

void OffscreenTarget::destroy() {
    const GLuint framebuffers[] = {framebuffer_, resolveFramebuffer_};
    const GLuint renderbuffers[] = {colorBuffer_, depthBuffer_, resolveColor_};
    if (framebuffer_ != 0) {
        glDeleteFramebuffers(2, framebuffers);
        glDeleteRenderbuffers(3, renderbuffers);
    }
    framebuffer_ = colorBuffer_ = depthBuffer_ = resolveFramebuffer_ = resolveColor_ = 0;
    width_ = height_ = samples_ = 0;
}

std::string OffscreenTarget::resize(int width, int height, int samples) {
    destroy();
    if (width <= 0 || height <= 0) return "offscreen target: size must be positive";
    GLint maxSamples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    samples_ = std::clamp(samples, 0, static_cast<int>(maxSamples));
    width_ = width;
    height_ = height;
    colorBuffer_ = makeRenderbuffer(GL_RGBA8, width, height, samples_);
    if (samples_ > 0) {  // the GL may give more than asked (3 -> 4): what the image has
        GLint given = samples_;
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &given);
        samples_ = given;
    }
    depthBuffer_ = makeRenderbuffer(GL_DEPTH_COMPONENT24, width, height, samples_);
    framebuffer_ = makeFramebuffer(colorBuffer_, depthBuffer_);
    bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (samples_ > 0) {
        resolveColor_ = makeRenderbuffer(GL_RGBA8, width, height, 0);
        resolveFramebuffer_ = makeFramebuffer(resolveColor_, 0);
        complete = complete && glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
    bind();
    if (complete) return {};
    destroy();
    return "offscreen target: framebuffer incomplete";
}

void OffscreenTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width_, height_);
}

Image OffscreenTarget::read() const {
    Image image;
    image.width = width_;
    image.height = height_;
    if (samples_ > 0) {
        // Multisampled pixels cannot be read directly: average them into the copy.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFramebuffer_);
        glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, resolveFramebuffer_);
    } else {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    }
    image.rgba = readPixelsRGBA(width_, height_);
    bind();
    return image;
}

std::vector<std::uint8_t> readPixelsRGBA(int width, int height) {
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
    std::vector<std::uint8_t> bottomUp(rowBytes * static_cast<std::size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    std::vector<std::uint8_t> topDown(bottomUp.size());
    for (int row = 0; row < height; ++row) {
        const auto source = bottomUp.begin() + static_cast<std::ptrdiff_t>(rowBytes) * row;
        std::copy(source, source + static_cast<std::ptrdiff_t>(rowBytes),
                  topDown.begin() + static_cast<std::ptrdiff_t>(rowBytes) * (height - 1 - row));
    }
    return topDown;
}

}  // namespace render
