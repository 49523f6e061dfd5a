#pragma once
// The fixture of `vissort view`'s end-to-end tests: the viewer under Xvfb (xvfb-run, Debian's
// xvfb) with --hide-ui and a screenshot, and `vissort render` of the same frames to compare with.

#include <cstdlib>
#include <string>
#include <vector>

#include "cli_fixture.h"
#include "png_reading.h"
#include "vissort/image.h"

namespace vissort {

// A server per run (-a), large enough for every window here, with 24-bit colour.
inline const std::string kXvfb = "xvfb-run -a -s '-screen 0 1280x1024x24'";

// The largest colour channel difference; -1 when the sizes differ.
inline int maxDifference(const Png& a, const Png& b) {
    if (a.width != b.width || a.height != b.height)
        return -1;
    return compareImages(a.rgba, b.rgba).max_abs;
}

class View : public Cli {
protected:
    void SetUp() override {
        Cli::SetUp();
        ASSERT_EQ(std::system("command -v xvfb-run >/dev/null"), 0)
            << "the viewer's tests need xvfb-run (Debian's xvfb, scripts/install-deps.sh)";
    }
    // `view` under Xvfb, --hide-ui, a screenshot of the last of `frames` frames.
    RunResult view(std::vector<std::string> args, int frames, const std::string& screenshot) {
        args.insert(args.begin(), "view");
        for (std::string a : {std::string("--hide-ui"), std::string("--frames"),
                              std::to_string(frames), std::string("--screenshot"), screenshot})
            args.push_back(a);
        return run(args, 120, kXvfb);
    }
    // `render` of the same frames; the last frame's picture.
    Png render(std::vector<std::string> args, int frames) {
        args.insert(args.begin(), "render");
        const std::string output = frames > 1 ? "render_%d.png" : "render.png";
        for (std::string a :
             {std::string("--frames"), std::to_string(frames), std::string("-o"), path(output)})
            args.push_back(a);
        const RunResult r = run(args, 120);
        EXPECT_EQ(r.code, 0) << r;
        return readPng(path(frames > 1 ? "render_" + std::to_string(frames - 1) + ".png" : output));
    }
};

} // namespace vissort
