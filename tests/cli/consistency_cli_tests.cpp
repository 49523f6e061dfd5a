// Small consistencies a user meets (issue 35): a mistyped scene, parameter or method gets a
// "did you mean"; every command's --frames has the same limit and words; counts agree with
// their nouns.

#include <string>

#include "cli_fixture.h"

namespace vissort {
namespace {

TEST_F(Cli, MistypedScenesParametersAndMethodsGetADidYouMean) {
    expectError({"order", "builtin:bunny"}, kInput,
                {"unknown built-in scene 'builtin:bunny'", "did you mean 'builtin:bunnies'?"});
    expectError({"order", "builtin:slabs?layer=4"}, kInput,
                {"unknown parameter 'layer'", "did you mean 'layers'?"});
    expectError({"order", "builtin:bunnies", "--level", "objct"}, kUsage,
                {"did you mean 'object'?"});
#if VISSORT_WITH_GL
    expectError({"render", "builtin:bunnies", "--method", "al", "-o", path("x.png")}, kUsage,
                {"unknown method 'al'", "did you mean 'all'?", "; or all"});
    expectError({"render", "builtin:bunnies", "--method", "linked-lst", "-o", path("x.png")},
                kUsage, {"did you mean 'linked-list'?"});
#endif
}

TEST_F(Cli, EveryCommandsFramesHasTheSameLimitAndWords) {
    for (const char* command : {"order", "collide"}) {
        SCOPED_TRACE(command);
        for (const char* frames : {"0", "100001"})
            expectError({command, "builtin:bunnies", "--frames", frames}, kUsage,
                        {"--frames must be between 1 and 100000"});
    }
#if VISSORT_WITH_GL
    expectError({"render", "builtin:bunnies", "--frames", "0", "-o", path("f%d.png")}, kUsage,
                {"--frames must be between 1 and 100000"});
#endif
}

#if VISSORT_WITH_GL
// `render --method all` says "1 pass" for a method of one pass (vissort on the slabs).
TEST_F(Cli, CountsAgreeWithTheirNouns) {
    const RunResult r = run({"render", "builtin:slabs?layers=3", "--size", "48x32", "--method",
                             "all", "-o", path("all.png")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find(" 1 pass, "), std::string::npos) << r;
    EXPECT_EQ(r.out.find(" 1 passes"), std::string::npos) << r;
}
#endif

} // namespace
} // namespace vissort
