#pragma once
// Reading the PNGs the tool writes, for the end-to-end tests (stb_image, Debian's libstb).

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <stb/stb_image.h>

namespace vissort {

struct Png {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba; // 4 bytes a pixel, rows from the top
};

/// The image at path as RGBA; a failed test and an empty image when it cannot be read.
inline Png readPng(const std::string& path) {
    Png png;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 4);
    if (data == nullptr) {
        ADD_FAILURE() << "cannot read " << path << ": " << stbi_failure_reason();
        return png;
    }
    png.rgba.assign(data, data + std::size_t(png.width) * png.height * 4);
    stbi_image_free(data);
    return png;
}

} // namespace vissort
