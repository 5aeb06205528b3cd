#pragma once
// RGBA8 images in memory and as PNG files (stb_image / stb_image_write).
#include <cstdint>
#include <glm/gtc/type_precision.hpp>
#include <string>
#include <vector>

namespace render {

struct Image {
    int width = 0;                   // px
    int height = 0;                  // px
    std::vector<std::uint8_t> rgba;  // rows top-down, 4 bytes per pixel

    // (x, y) from the top-left; no bounds check beyond an assert.
    glm::u8vec4 pixel(int x, int y) const;
};

// Writes rows top-down. Returns false (nothing thrown) when the file cannot be written.
bool writePng(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& rgba);
// Reads any PNG as RGBA8. Returns false and leaves *image empty when it cannot.
bool readPng(const std::string& path, Image* image);

}  // namespace render
