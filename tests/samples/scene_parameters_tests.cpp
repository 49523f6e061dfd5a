#include "scenes/scene_parameters.h"

#include <gtest/gtest.h>

namespace vissort::detail {
namespace {

// Whether text contains part; the message is printed on failure.
::testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

TEST(SceneParameters, AbsentKeysGiveDefaults) {
    const SceneParameters none;
    ParameterReader reader("builtin:test", none);
    EXPECT_EQ(reader.integer("n", 18, 1, 100), 18);
    EXPECT_EQ(reader.seed("seed", 7u), 7u);
    EXPECT_EQ(reader.error(), "");
}

TEST(SceneParameters, ReadsValuesAtTheEndsOfTheRange) {
    const SceneParameters parameters = {{"n", "1"}, {"m", "100"}, {"seed", "18446744073709551615"}};
    ParameterReader reader("builtin:test", parameters);
    EXPECT_EQ(reader.integer("n", 18, 1, 100), 1);
    EXPECT_EQ(reader.integer("m", 18, 1, 100), 100);
    EXPECT_EQ(reader.seed("seed", 1), 18446744073709551615u);
    EXPECT_EQ(reader.error(), "");
}

TEST(SceneParameters, RejectsWhatIsNotAnInteger) {
    for (const char* text : {"", "abc", "1.5", "12x", " 3", "3 ", "+3", "0x10", "1e3"}) {
        const SceneParameters parameters = {{"n", text}};
        ParameterReader reader("builtin:test", parameters);
        EXPECT_EQ(reader.integer("n", 18, 1, 100000), 18) << text;
        const std::string error = reader.error();
        EXPECT_TRUE(contains(error, "builtin:test")) << text;
        EXPECT_TRUE(contains(error, "parameter n=")) << text;
        EXPECT_TRUE(contains(error, "not an integer")) << text;
        EXPECT_EQ(error.find('\n'), std::string::npos);
    }
}

TEST(SceneParameters, RejectsOutOfRangeValues) {
    for (const char* text : {"0", "-3", "101", "99999999999999999999", "-99999999999999999999"}) {
        const SceneParameters parameters = {{"layers", text}};
        ParameterReader reader("builtin:test", parameters);
        reader.integer("layers", 8, 1, 100);
        EXPECT_TRUE(contains(reader.error(), "parameter layers=" + std::string(text) +
                                                 " is out of range (allowed 1 to 100)"));
    }
}

TEST(SceneParameters, SeedsMustBeUnsigned64BitIntegers) {
    for (const char* text : {"-1", "seven", "1.0"}) {
        const SceneParameters parameters = {{"seed", text}};
        ParameterReader reader("builtin:test", parameters);
        reader.seed("seed", 1);
        EXPECT_TRUE(contains(reader.error(), "not a non-negative integer")) << text;
    }
    const SceneParameters too_big = {{"seed", "18446744073709551616"}};
    ParameterReader reader("builtin:test", too_big);
    reader.seed("seed", 1);
    EXPECT_TRUE(contains(reader.error(), "seed=18446744073709551616 is out of range"));
}

TEST(SceneParameters, UnknownKeysAreNamedWithTheAcceptedOnes) {
    const SceneParameters parameters = {{"n", "3"}, {"colour", "red"}};
    ParameterReader reader("builtin:test", parameters);
    EXPECT_EQ(reader.integer("n", 18, 1, 100), 3);
    reader.seed("seed", 1);
    EXPECT_EQ(reader.error(), "builtin:test: unknown parameter 'colour' (accepted: n, seed)");
}

TEST(SceneParameters, TheFirstProblemIsReported) {
    const SceneParameters parameters = {{"a", "x"}, {"b", "0"}, {"zzz", "1"}};
    ParameterReader reader("builtin:test", parameters);
    reader.integer("a", 1, 1, 9);
    reader.integer("b", 1, 1, 9);
    EXPECT_TRUE(contains(reader.error(), "parameter a='x' is not an integer"));
}

} // namespace
} // namespace vissort::detail
