#pragma once
// Image tests: how many pixels of two images of one size differ (any channel, alpha too).
#include "render/image_io.h"

inline int differingPixels(const render::Image& a, const render::Image& b) {
    int differ = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) differ += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
    }
    return differ;
}
