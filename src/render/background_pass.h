#pragma once
// Internal to spheres_render: the gradient behind everything.
#include <string>

#include "render/frame_context.h"
#include "render/gl_program.h"

namespace render {

class BackgroundPass {
  public:
    std::string init();
    void destroy();
    void draw(const FrameContext& frame);

  private:
    GlProgram program_;
    GLuint vertexArray_ = 0;  // empty: core profile draws need one bound
    GLint top_ = -1;
    GLint bottom_ = -1;
};

}  // namespace render
