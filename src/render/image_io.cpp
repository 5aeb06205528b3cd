#include "render/image_io.h"

#include <cassert>
#include <string>

// Debian's libstb compiles the implementations: only the declarations here.
#include <stb_image.h>
#include <stb_image_write.h>

#include "platform/whole_file.h"

namespace render {

glm::u8vec4 Image::pixel(int x, int y) const {
    assert(x >= 0 && y >= 0 && x < width && y < height);
    const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                           static_cast<std::size_t>(x)) *
                          4;
    return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

bool writePng(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& rgba) {
    if (width <= 0 || height <= 0 ||
        rgba.size() < static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
        return false;
    }
    // Encoded in memory, then written whole or not at all: stb's own file writer does not
    // check its writes.
    std::string png;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
    };
    if (stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4) == 0) return false;
    return platform::writeWholeFile(path, png);
}

bool readPng(const std::string& path, Image* image) {
    *image = Image{};
    int width = 0;
    int height = 0;
    int channels = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 4);
    if (!pixels) return false;
    image->width = width;
    image->height = height;
    image->rgba.assign(pixels, pixels + static_cast<std::size_t>(width) * height * 4);
    stbi_image_free(pixels);
    return true;
}

}  // namespace render
