// OSMesa: Mesa's off-screen API. It renders with llvmpipe on the CPU and needs
// neither a display nor a GPU, so it is the first choice for tests and capture.
#include <glad/gl.h>
// After glad: osmesa.h includes GL/gl.h, which glad's include guard turns off.
#include <GL/osmesa.h>

#include <array>
#include <vector>

#include "platform/driver_crash_guard.h"
#include "platform/headless_backends.h"

namespace platform::detail {
namespace {

// OSMesa needs a colour buffer to make a context current; drawing goes to FBOs,
// so a tiny one is enough (pixels).
constexpr int kBufferSize = 4;

class OsMesaContext final : public HeadlessContext {
  public:
    explicit OsMesaContext(OSMesaContext context)
        : context_(context), buffer_(kBufferSize * kBufferSize * 4) {}
    ~OsMesaContext() override { OSMesaDestroyContext(context_); }
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;

    const char* name() const override { return "osmesa"; }

    bool makeCurrent() override {
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSize,
                               kBufferSize)) {
            return false;
        }
        return gladLoadGL(OSMesaGetProcAddress) != 0;
    }

  private:
    OSMesaContext context_;
    std::vector<unsigned char> buffer_;  // RGBA8, kBufferSize x kBufferSize
};

}  // namespace

std::unique_ptr<HeadlessContext> createOsMesaContext(std::string* error) {
    const std::array<int, 13> attributes = {OSMESA_FORMAT,
                                            OSMESA_RGBA,
                                            OSMESA_DEPTH_BITS,
                                            0,  // depth lives in the FBO's renderbuffer
                                            OSMESA_STENCIL_BITS,
                                            0,
                                            OSMESA_PROFILE,
                                            OSMESA_CORE_PROFILE,
                                            OSMESA_CONTEXT_MAJOR_VERSION,
                                            3,
                                            OSMESA_CONTEXT_MINOR_VERSION,
                                            3,
                                            0};
    const DriverCrashGuard guard("OSMesa created its context");
    OSMesaContext raw = OSMesaCreateContextAttribs(attributes.data(), nullptr);
    if (!raw) {
        if (error) *error = "osmesa: OSMesaCreateContextAttribs failed (no GL 3.3 core profile?)";
        return nullptr;
    }
    auto context = std::make_unique<OsMesaContext>(raw);
    if (!context->makeCurrent()) {
        if (error) *error = "osmesa: could not make the context current or load GL with glad";
        return nullptr;
    }
    return context;
}

}  // namespace platform::detail
