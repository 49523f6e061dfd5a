#pragma once
// Images of the renderer and the tools that judge them: the one conversion of a float frame to
// 8 bits, the comparison of two 8-bit images, an error map and PNG output. No OpenGL: tools that
// only compare or write images (and their tests) build without it.
//
// Layer: vissort::image (the package's `image` component; docs/architecture.md).

#include <cstdint>
#include <string>
#include <vector>

#include "vissort/geometry.h"
#include "vissort/result.h"

namespace vissort {

/// The background unless one is asked for: a dark slate grey, under which light and dark
/// surfaces both show, and the default grey (0.8) at alpha 0.5 is plainly lighter (white made
/// such surfaces nearly invisible: 0.9 against 1).
inline constexpr Rgba kDefaultBackground{0.3f, 0.32f, 0.36f, 1.0f};

/// A rendered frame: linear RGBA floats, row 0 at the top, 4 floats per pixel.
struct Image {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;

    /// Each channel clamped to [0, 1] and rounded to 8 bits: the one conversion of a frame.
    std::vector<uint8_t> toRgba8() const;
};

/// Differences between two 8-bit RGBA images of one size, in 8-bit units over the RGB channels.
struct ImageError {
    double rmse = 0;
    double psnr = 0;              // infinity when the images are identical
    int max_abs = 0;              // the largest channel difference, 0..255
    uint64_t pixels_over_one = 0; // pixels with some channel more than 1 apart
};
ImageError compareImages(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b);

/// Where two 8-bit images of one size differ, as an 8-bit RGBA picture: pixels within 1/255
/// show the reference faded to light grey, the others yellow (2/255) through red (64/255 and more).
std::vector<uint8_t> errorMap(const std::vector<uint8_t>& image,
                              const std::vector<uint8_t>& reference);

/// Writes 8-bit RGBA as PNG; on failure a one-line message naming the file.
Status writePng(const std::string& path, uint32_t width, uint32_t height,
                const std::vector<uint8_t>& rgba8);

enum class ImageFormat { png, jpeg };
/// The format a file name asks for by its extension: .png, or .jpg / .jpeg (any case); else a
/// one-line error naming the file and the extensions known (a PNG under a .jpg name misleads).
Result<ImageFormat> imageFormatOf(const std::string& path);
/// Writes 8-bit RGBA in the format of path's extension (imageFormatOf): PNG, or JPEG at quality
/// 95 without alpha (the renderer's images are opaque).
Status writeImage(const std::string& path, uint32_t width, uint32_t height,
                  const std::vector<uint8_t>& rgba8);

} // namespace vissort
