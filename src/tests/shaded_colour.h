#pragma once
// Image tests: is a pixel a sphere's colour under some shading?
#include <algorithm>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

// The pixel is the colour under some lighting: a multiple k of it (shading),
// with little of any other hue mixed in.
inline void expectShadedVersionOf(glm::u8vec4 pixel, glm::u8vec4 colour) {
    const glm::vec3 p(pixel.x, pixel.y, pixel.z);
    const glm::vec3 c(colour.x, colour.y, colour.z);
    const float k = glm::dot(p, c) / glm::dot(c, c);
    EXPECT_GT(k, 0.45f) << "too dark";
    EXPECT_LT(k, 1.35f) << "too bright";
    const glm::vec3 residual = glm::abs(p - k * c);
    EXPECT_LT(std::max({residual.x, residual.y, residual.z}), 45.0f)
        << "pixel (" << p.x << ", " << p.y << ", " << p.z << ") vs colour (" << c.x << ", " << c.y
        << ", " << c.z << ")";
}
