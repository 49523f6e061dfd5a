// "Did you mean": edit distances computed by hand, and the suggestions the errors make.

#include "vissort/closest_name.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "vissort/transparency_renderer.h" // the method names (header-only without GL)

namespace vissort {
namespace {

TEST(ClosestName, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("order", "order"), 0u);
    EXPECT_EQ(editDistance("ordr", "order"), 1u);      // one insertion
    EXPECT_EQ(editDistance("color", "colour"), 1u);    // one insertion
    EXPECT_EQ(editDistance("--levle", "--level"), 1u); // one swap
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("abc", ""), 3u);
}

TEST(ClosestName, SuggestsOnlyNamesNearEnough) {
    const std::vector<std::string> commands = {"order", "info", "render", "collide", "bench"};
    EXPECT_EQ(closestName("ordr", commands), "order");
    EXPECT_EQ(closestName("rendr", commands), "render");
    EXPECT_EQ(closestName("xyzzy", commands), "");
    EXPECT_EQ(closestName("order", commands), ""); // not a mistake
    EXPECT_EQ(didYouMean("infp", commands), " (did you mean 'info'?)");
    EXPECT_EQ(didYouMean("zzzz", commands), "");
}

// A name that begins as the text does, for most of it, is suggested when no name is a few edits
// away: a singular for a plural. Short or mostly different beginnings are not.
TEST(ClosestName, SuggestsANameThatBeginsAsTheTextDoes) {
    const std::vector<std::string> scenes = {"bunnies", "plant", "powerplant", "slabs", "soup"};
    EXPECT_EQ(closestName("bunny", scenes), "bunnies");    // 'bunn': 4 of 5 letters
    EXPECT_EQ(closestName("power", scenes), "powerplant"); // 5 of 5
    EXPECT_EQ(closestName("plants", scenes), "plant");     // one edit: the nearest name
    EXPECT_EQ(closestName("bunker", scenes), "");          // 'bun': under 4 letters
    EXPECT_EQ(closestName("bunnyhop", scenes), "");        // 'bunn': half of 8 letters
}

TEST(ClosestName, EnumErrorsSuggestTheNearestName) {
    const Result<BlendMethod> typo = parseBlendMethod("vissrot");
    ASSERT_FALSE(typo);
    EXPECT_NE(typo.error.find("unknown method 'vissrot' (did you mean 'vissort'? expected "),
              std::string::npos)
        << typo.error;
    const Result<BlendMethod> far = parseBlendMethod("quantum");
    ASSERT_FALSE(far);
    EXPECT_EQ(far.error.find("did you mean"), std::string::npos) << far.error;
}

} // namespace
} // namespace vissort
