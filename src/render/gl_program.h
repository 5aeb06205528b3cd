#pragma once
// A linked GLSL program built from embedded sources, and the uniform lookups
// every pass needs. Requires a current GL 3.3 core context with glad loaded.
#include <glad/gl.h>

#include <string>
#include <string_view>

namespace render {

class GlProgram {
  public:
    GlProgram() = default;
    ~GlProgram();
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;

    // Compiles and links; on failure returns the compiler's log prefixed by `label`.
    std::string build(std::string_view label, std::string_view vertexSource,
                      std::string_view fragmentSource);
    void destroy();

    GLuint id() const { return program_; }
    GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

  private:
    GLuint program_ = 0;
};

}  // namespace render
