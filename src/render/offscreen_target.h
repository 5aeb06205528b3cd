#pragma once
// An offscreen framebuffer (colour RGBA8 + depth 24), optionally multisampled,
// for headless rendering and for reading frames back.
#include <glad/gl.h>

#include <cstdint>
#include <string>
#include <vector>

#include "render/image_io.h"

namespace render {

class OffscreenTarget {
  public:
    OffscreenTarget() = default;
    ~OffscreenTarget();
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;

    // (Re)creates the buffers in pixels; samples 0 = no MSAA. "" on success.
    std::string resize(int width, int height, int samples = 0);
    // Binds it for drawing and reading, and sets the viewport to all of it.
    void bind() const;
    // Resolves MSAA if needed and returns the pixels, rows top-down. Leaves it bound.
    Image read() const;
    void destroy();

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }
    GLuint framebuffer() const { return framebuffer_; }

  private:
    int width_ = 0;
    int height_ = 0;
    int samples_ = 0;
    GLuint framebuffer_ = 0;  // drawn into
    GLuint colorBuffer_ = 0;
    GLuint depthBuffer_ = 0;
    GLuint resolveFramebuffer_ = 0;  // single-sampled copy, only with MSAA
    GLuint resolveColor_ = 0;
};

// Reads width x height RGBA8 pixels at (0, 0) of the bound read framebuffer,
// rows top-down (GL's are bottom-up).
std::vector<std::uint8_t> readPixelsRGBA(int width, int height);

}  // namespace render
