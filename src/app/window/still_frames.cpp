#include "app/window/still_frames.h"

#include <imgui.h>

#include <cstring>
#include <initializer_list>

#include "render/camera.h"

namespace app {
namespace {

// FNV-1a over 8-byte words (then the bytes left): a frame's UI is some 10^5 bytes.
class Look {
  public:
    void add(const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (; bytes >= 8; bytes -= 8, p += 8) {
            std::uint64_t word;
            std::memcpy(&word, p, 8);
            mix(word);
        }
        for (; bytes > 0; --bytes, ++p) mix(*p);
    }
    template <class T>
    void add(const T& value) { add(&value, sizeof value); }
    std::uint64_t value() const { return hash_; }

  private:
    void mix(std::uint64_t word) { hash_ = (hash_ ^ word) * 0x100000001b3ull; }
    std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace

void StillFrames::after(bool quiet, const ImDrawData& ui, const render::Camera& camera, std::uint64_t scene) {
    if (!quiet) {
        alike_ = 0;
        return;
    }
    Look look;
    look.add(scene);
    look.add(camera.target);
    for (const float angle : {camera.azimuth, camera.elevation, camera.distance, camera.fovY}) look.add(angle);
    look.add(ui.DisplaySize);
    for (int n = 0; n < ui.CmdListsCount; ++n) {
        const ImDrawList& list = *ui.CmdLists[n];
        look.add(list.VtxBuffer.Data, sizeof(ImDrawVert) * std::size_t(list.VtxBuffer.Size));
        look.add(list.IdxBuffer.Data, sizeof(ImDrawIdx) * std::size_t(list.IdxBuffer.Size));
        for (const ImDrawCmd& command : list.CmdBuffer) {
            look.add(command.ClipRect);
            look.add(command.TextureId);
            look.add(command.ElemCount);
        }
    }
    alike_ = look.value() == last_ ? alike_ + 1 : 0;
    last_ = look.value();
}

}  // namespace app
