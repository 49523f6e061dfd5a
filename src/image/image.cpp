// Image conversion, comparison and PNG output (image.h).

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>

#include <stb/stb_image_write.h>

#include "vissort/image.h"

#include "vissort/atomic_file.h"

namespace vissort {
namespace {

// The largest difference between the RGB channels of pixel p (its first byte) of a and b.
int largestChannelDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b,
                             std::size_t p) {
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(int(a[p + c]) - int(b[p + c])));
    return worst;
}

// ": the system's reason" for a write that failed, when the system gave one.
std::string systemReason() {
    return errno == 0 ? std::string() : ": " + std::string(std::strerror(errno));
}

} // namespace

std::vector<uint8_t> Image::toRgba8() const {
    std::vector<uint8_t> out(rgba.size());
    for (std::size_t i = 0; i < rgba.size(); ++i) {
        const float v = std::isnan(rgba[i]) ? 0.0f : std::fmin(std::fmax(rgba[i], 0.0f), 1.0f);
        out[i] = uint8_t(std::lround(v * 255.0f));
    }
    return out;
}

ImageError compareImages(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    ImageError error;
    if (a.size() != b.size() || a.empty()) {
        error.rmse = error.max_abs = 255;
        return error;
    }
    double sum = 0;
    for (std::size_t p = 0; p < a.size(); p += 4) {
        for (std::size_t c = 0; c < 3; ++c) {
            const int d = int(a[p + c]) - int(b[p + c]);
            sum += double(d) * d;
        }
        const int worst = largestChannelDifference(a, b, p);
        error.max_abs = std::max(error.max_abs, worst);
        if (worst > 1)
            ++error.pixels_over_one;
    }
    error.rmse = std::sqrt(sum / double(a.size() / 4 * 3));
    error.psnr = error.rmse > 0 ? 20.0 * std::log10(255.0 / error.rmse)
                                : std::numeric_limits<double>::infinity();
    return error;
}

std::vector<uint8_t> errorMap(const std::vector<uint8_t>& image,
                              const std::vector<uint8_t>& reference) {
    std::vector<uint8_t> map(reference.size(), 255);
    if (image.size() != reference.size())
        return map;
    for (std::size_t p = 0; p < reference.size(); p += 4) {
        const int worst = largestChannelDifference(image, reference, p);
        if (worst <= 1) {
            // Within rounding: the reference, faded, so the map shows where errors are.
            const int luma =
                (int(reference[p]) * 3 + int(reference[p + 1]) * 6 + reference[p + 2]) / 10;
            const uint8_t faded = uint8_t(192 + luma / 4);
            map[p] = map[p + 1] = map[p + 2] = faded;
        } else {
            // Yellow for 2/255, through orange, to red at 64/255 and beyond.
            const double t = std::min(1.0, double(worst - 2) / 62.0);
            map[p] = 255;
            map[p + 1] = uint8_t(std::lround(220.0 * (1.0 - t)));
            map[p + 2] = 0;
        }
        map[p + 3] = 255;
    }
    return map;
}

Status writePng(const std::string& path, uint32_t width, uint32_t height,
                const std::vector<uint8_t>& rgba8) {
    if (rgba8.size() != std::size_t(width) * height * 4 || width == 0 || height == 0)
        return Status::failure("no image to write to " + path);
    // Whole or not at all (atomic_file.h): a killed run leaves no truncated picture.
    return writeFileAtomically(path, [&](const std::string& write_path) {
        errno = 0;
        if (!stbi_write_png(write_path.c_str(), int(width), int(height), 4, rgba8.data(),
                            int(width) * 4))
            return Status::failure("cannot write " + path + systemReason());
        return Status::ok();
    });
}

Result<ImageFormat> imageFormatOf(const std::string& path) {
    const std::size_t dot = path.find_last_of("./");
    std::string extension = dot == std::string::npos || path[dot] == '/' ? "" : path.substr(dot);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".png")
        return {ImageFormat::png, ""};
    if (extension == ".jpg" || extension == ".jpeg")
        return {ImageFormat::jpeg, ""};
    return Result<ImageFormat>::failure("cannot tell the image format of '" + path +
                                        "' from its extension: use .png or .jpg");
}

Status writeImage(const std::string& path, uint32_t width, uint32_t height,
                  const std::vector<uint8_t>& rgba8) {
    const Result<ImageFormat> format = imageFormatOf(path);
    if (!format)
        return Status::failure(format.error);
    if (*format.value == ImageFormat::png)
        return writePng(path, width, height, rgba8);
    if (rgba8.size() != std::size_t(width) * height * 4 || width == 0 || height == 0)
        return Status::failure("no image to write to " + path);
    return writeFileAtomically(path, [&](const std::string& write_path) {
        errno = 0;
        if (!stbi_write_jpg(write_path.c_str(), int(width), int(height), 4, rgba8.data(), 95))
            return Status::failure("cannot write " + path + systemReason());
        return Status::ok();
    });
}

} // namespace vissort
