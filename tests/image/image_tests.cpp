// Images, without OpenGL: the one conversion to 8 bits, the comparison (RMSE, PSNR, largest
// channel error), the error map and PNG output.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "vissort/image.h"

namespace vissort {
namespace {

TEST(Image, ToRgba8ClampsRoundsAndZeroesNaN) {
    Image image;
    image.width = 2;
    image.height = 1;
    image.rgba = {-0.5f,         0.0f,
                  0.5f,          1.0f,
                  2.0f,          1.0f / 255 * 0.49f,
                  std::nanf(""), std::numeric_limits<float>::infinity()};
    EXPECT_EQ(image.toRgba8(), (std::vector<uint8_t>{0, 0, 128, 255, 255, 0, 0, 255}));
}

TEST(Image, ComparisonCountsRgbOnly) {
    const std::vector<uint8_t> a{10, 20, 30, 255, 0, 0, 0, 255};
    std::vector<uint8_t> b = a;
    const ImageError same = compareImages(a, b);
    EXPECT_EQ(same.max_abs, 0);
    EXPECT_EQ(same.rmse, 0.0);
    EXPECT_TRUE(std::isinf(same.psnr));
    b[3] = 0;  // alpha is not compared
    b[1] = 21; // one channel off by one
    b[6] = 6;  // one off by six
    const ImageError off = compareImages(a, b);
    EXPECT_EQ(off.max_abs, 6);
    EXPECT_EQ(off.pixels_over_one, 1u);
    EXPECT_DOUBLE_EQ(off.rmse, std::sqrt((1.0 + 36.0) / 6.0));
    EXPECT_DOUBLE_EQ(off.psnr, 20 * std::log10(255 / off.rmse));
    // Images of different sizes are as different as can be.
    EXPECT_EQ(compareImages(a, std::vector<uint8_t>(4, 0)).max_abs, 255);
}

TEST(Image, ErrorMapFadesAgreementAndColoursDifferences) {
    const std::vector<uint8_t> reference{0, 0, 0, 255, 100, 100, 100, 255, 50, 50, 50, 255};
    const std::vector<uint8_t> image{1, 0, 0, 255, 102, 100, 100, 255, 50, 150, 50, 255};
    const std::vector<uint8_t> map = errorMap(image, reference);
    ASSERT_EQ(map.size(), reference.size());
    EXPECT_EQ(map[0], map[1]); // within 1/255: grey
    EXPECT_GE(map[0], 192);    // faded
    EXPECT_EQ(map[4], 255);    // 2/255: yellow
    EXPECT_EQ(map[5], 220);
    EXPECT_EQ(map[6], 0);
    EXPECT_EQ(map[8], 255); // 100/255: red
    EXPECT_EQ(map[9], 0);
    for (std::size_t i = 3; i < map.size(); i += 4)
        EXPECT_EQ(map[i], 255);
}

TEST(Image, PngIsWrittenOrTheFailureNamed) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "vissort_image_test.png";
    const std::vector<uint8_t> pixels(2 * 3 * 4, 200);
    EXPECT_EQ(writePng(path.string(), 2, 3, pixels).error, "");
    EXPECT_GT(std::filesystem::file_size(path), 8u);
    std::filesystem::remove(path);
    const std::string missing = writePng("/nonexistent-folder/x.png", 2, 3, pixels).error;
    EXPECT_NE(missing.find("/nonexistent-folder/x.png"), std::string::npos) << missing;
    EXPECT_NE(writePng(path.string(), 3, 3, pixels).error, ""); // the wrong size
}

} // namespace
} // namespace vissort
