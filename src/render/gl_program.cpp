#include "render/gl_program.h"

#include <vector>

namespace render {
namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.data();
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.data();
}

// Returns 0 and fills *error when the stage does not compile.
GLuint compile(GLenum stage, std::string_view source, std::string* error) {
    GLuint shader = glCreateShader(stage);
    const char* text = source.data();
    const GLint length = static_cast<GLint>(source.size());
    glShaderSource(shader, 1, &text, &length);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok == GL_TRUE) return shader;
    *error =
        (stage == GL_VERTEX_SHADER ? "vertex shader: " : "fragment shader: ") + shaderLog(shader);
    glDeleteShader(shader);
    return 0;
}

}  // namespace

GlProgram::~GlProgram() { destroy(); }

void GlProgram::destroy() {
    if (program_ != 0) glDeleteProgram(program_);
    program_ = 0;
}

std::string GlProgram::build(std::string_view label, std::string_view vertexSource,
                             std::string_view fragmentSource) {
    destroy();
    std::string error;
    GLuint vertex = compile(GL_VERTEX_SHADER, vertexSource, &error);
    GLuint fragment = vertex ? compile(GL_FRAGMENT_SHADER, fragmentSource, &error) : 0;
    if (vertex && fragment) {
        program_ = glCreateProgram();
        glAttachShader(program_, vertex);
        glAttachShader(program_, fragment);
        glLinkProgram(program_);
        GLint ok = GL_FALSE;
        glGetProgramiv(program_, GL_LINK_STATUS, &ok);
        if (ok != GL_TRUE) {
            error = "link: " + programLog(program_);
            destroy();
        }
    }
    if (vertex) glDeleteShader(vertex);
    if (fragment) glDeleteShader(fragment);
    return error.empty() ? std::string() : std::string(label) + " program, " + error;
}

}  // namespace render
