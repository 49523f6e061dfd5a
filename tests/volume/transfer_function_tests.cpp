// Transfer functions: evaluation, presets, the JSON form and its errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "vissort/transfer_function.h"

namespace vissort {
namespace {

TEST(TransferFunction, IsPiecewiseLinearAndConstantBeyondItsEnds) {
    const TransferFunction tf{{{0.0, 0, 0, 0, 0}, {0.5, 1, 0.5, 0, 2}, {1.0, 1, 1, 1, 4}}, true};
    const TransferPoint quarter = tf.at(0.25);
    EXPECT_DOUBLE_EQ(quarter.r, 0.5);
    EXPECT_DOUBLE_EQ(quarter.g, 0.25);
    EXPECT_DOUBLE_EQ(quarter.extinction, 1.0);
    EXPECT_DOUBLE_EQ(tf.at(0.75).extinction, 3.0);
    EXPECT_DOUBLE_EQ(tf.at(-3).extinction, 0.0);
    EXPECT_DOUBLE_EQ(tf.at(7).b, 1.0);
    EXPECT_DOUBLE_EQ(tf.at(0.5).g, 0.5);
}

TEST(TransferFunction, PresetsAreValidAndNamed) {
    ASSERT_GE(transferPresets().size(), 4u);
    for (const TransferPreset& preset : transferPresets()) {
        Result<TransferFunction> tf = loadTransferFunction(preset.name);
        ASSERT_TRUE(tf) << preset.name << ": " << tf.error;
        EXPECT_TRUE(validateTransferFunction(*tf.value)) << preset.name;
    }
    EXPECT_EQ(loadTransferFunction("fier").error,
              "'fier' is neither a transfer function preset (did you mean 'fire'?) nor a file; the "
              "presets are "
              "cool-warm, fire, grey, bands");
}

TEST(TransferFunction, JsonRoundTripsAndFilesLoad) {
    const TransferFunction tf{{{-2.0, 0.1, 0.2, 0.3, 0.0}, {5.0, 1, 1, 1, 2.5}}, false};
    Result<TransferFunction> again = parseTransferFunction(transferFunctionJson(tf));
    ASSERT_TRUE(again) << again.error;
    EXPECT_EQ(*again.value, tf);
    const std::string path =
        (std::filesystem::temp_directory_path() / "vissort_tf_test.json").string();
    std::ofstream(path) << R"({"points": [[0, 0, 0, 0, 0], [1, 1, 0, 0, 3]]})";
    Result<TransferFunction> loaded = loadTransferFunction(path);
    ASSERT_TRUE(loaded) << loaded.error;
    EXPECT_TRUE(loaded.value->normalized);
    EXPECT_EQ(loaded.value->points.size(), 2u);
    std::ofstream(path) << R"({"points": [[0, 0, 0, 0, 0], [0, 1, 0, 0, 3]]})";
    EXPECT_EQ(loadTransferFunction(path).error,
              path + ": the transfer function's point 1's scalar is not above the one before it "
                     "(scalars must increase)");
}

TEST(TransferFunction, BadJsonIsNamed) {
    EXPECT_EQ(parseTransferFunction("[").error, "not valid JSON");
    EXPECT_EQ(parseTransferFunction("{}").error,
              "\"points\" must be a list of [scalar, r, g, b, extinction]");
    EXPECT_EQ(parseTransferFunction(R"({"points": [[0, 1, 1]]})").error,
              "\"points\"[0] must be [scalar, r, g, b, extinction], 5 numbers");
    EXPECT_EQ(parseTransferFunction(R"({"points": [[0, 1, 1, 2, 0]]})").error,
              "the transfer function's point 0 has a colour outside [0, 1]");
    EXPECT_EQ(parseTransferFunction(R"({"points": [[0, 1, 1, 1, -1]]})").error,
              "the transfer function's point 0 has a negative extinction");
    EXPECT_EQ(parseTransferFunction(R"({"points": [], "range": "log"})").error,
              "\"range\" is \"normalized\" or \"absolute\", not \"log\"");
    EXPECT_EQ(parseTransferFunction(R"({"points": [], "colour": 1})").error,
              "unknown key \"colour\" (a transfer function has \"range\" and \"points\")");
    EXPECT_EQ(parseTransferFunction(R"({"points": []})").error,
              "the transfer function has no points");
}

} // namespace
} // namespace vissort
