// Never overwrite an input (issue 56): every output is compared, before any work, with every
// file the command reads and with its other outputs, and every output is written whole or not
// at all. A refused run exits 1 with one line naming both options and the path, prints nothing
// else, and leaves every file byte-identical.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "cli_fixture.h"

namespace vissort {
namespace {

// Every file of the folder with its bytes: what a refused run must leave as it was.
std::map<std::string, std::string> snapshot(const fs::path& folder) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().filename() != "tool.stdout" &&
            entry.path().filename() != "tool.stderr")
            files[entry.path().string()] = readFile(entry.path());
    return files;
}

class InputOutput : public Cli {
protected:
    void SetUp() override {
        Cli::SetUp();
        fs::create_directory(path("meshes"));
        fs::copy_file(dataPath("meshes/crabs.obj"), path("meshes/crabs.obj"));
        fs::copy_file(dataPath("meshes/crabs.mtl"), path("meshes/crabs.mtl"));
        fs::create_directory(path("scenes"));
        fs::copy_file(dataPath("scenes/crabs.json"), path("scenes/crabs.json"));
        fs::copy_file(dataPath("grids/tetgen_two_tets.node"), path("two_tets.node"));
        fs::copy_file(dataPath("grids/tetgen_two_tets.ele"), path("two_tets.ele"));
        fs::copy_file(dataPath("grids/medit_all_cells.mesh"), path("cells.mesh"));
        fs::copy_file(dataPath("grids/medit_all_cells.sol"), path("cells.sol"));
        fs::copy_file(dataPath("grids/vtu_mixed_ascii.vtu"), path("grid.vtu"));
        std::ofstream(path("tf.json"))
            << R"({"points": [[0, 0, 0, 1, 1], [1, 1, 0, 0, 2]]})" << '\n';
        std::ofstream(path("script.txt")) << "0 key ESCAPE\n";
    }

    // A refused run: exit 1, one line naming every needle, nothing on stdout, every file as it
    // was and no file added.
    void expectRefused(const std::vector<std::string>& args,
                       const std::vector<std::string>& needles) {
        SCOPED_TRACE(args[0] + " ... " + args.back());
        const auto before = snapshot(dir_);
        expectError(args, kFailure, needles);
        const RunResult r = run(args);
        EXPECT_TRUE(r.out.empty()) << "refused before any work" << r;
        EXPECT_EQ(snapshot(dir_), before) << "a refused run changed or added a file";
    }

    fs::path obj() const { return dir_ / "meshes/crabs.obj"; }
};

TEST_F(InputOutput, EveryOutputOptionRefusesTheSceneFile) {
    const std::string mesh = path("meshes/crabs.obj");
    std::vector<std::vector<std::string>> cases = {
        {"order", mesh, "--json", mesh},
        {"order", mesh, "--csv", mesh},
        {"order", mesh, "--dump-primitives", mesh},
        {"info", mesh, "--json", mesh},
        {"collide", mesh, "--json", mesh},
        {"collide", mesh, "--csv", mesh},
        {"collide", mesh, "--pairs-out", mesh},
        {"collide", mesh, "--dump-primitives", mesh},
    };
#if VISSORT_WITH_GL
    for (std::vector<std::string> gl_case : std::vector<std::vector<std::string>>{
             {"render", mesh, "-o", mesh},
             {"render", mesh, "-o", path("ok.png"), "--json", mesh},
             {"render", mesh, "-o", path("ok.png"), "--csv", mesh},
             {"render", mesh, "-o", path("ok.png"), "--reference", "linked-list", "--error-map",
              mesh},
             {"view", mesh, "--frames", "1", "--screenshot", mesh}})
        cases.push_back(gl_case);
#endif
    for (const auto& args : cases)
        expectRefused(args,
                      {args[args.size() - 2] + " '" + mesh + "' is the scene file '" + mesh + "'",
                       "never overwrites an input"});
}

TEST_F(InputOutput, EveryVolumeOutputRefusesTheGridFiles) {
    const std::string vtu = path("grid.vtu");
    for (const std::string option : {"-o", "--json", "--error-map"}) {
        std::vector<std::string> args = {"volume",      vtu,       "-o",   path("ok.png"),
                                         "--reference", "raycast", option, vtu};
        if (option == "-o")
            args = {"volume", vtu, "-o", vtu};
        expectRefused(args, {option + " '" + vtu + "' is the grid file"});
    }
    // tetgen's pair, either named: the other file is read too; Medit's .sol beside the .mesh.
    expectRefused(
        {"volume", path("two_tets.node"), "-o", path("ok.png"), "--json", path("two_tets.ele")},
        {"--json '" + path("two_tets.ele") + "' is the grid file"});
    expectRefused({"info", path("two_tets.ele"), "--json", path("two_tets.node")},
                  {"--json '" + path("two_tets.node") + "' is the grid file"});
    expectRefused({"volume", path("cells.mesh"), "-o", path("ok.png"), "--json", path("cells.sol")},
                  {"--json '" + path("cells.sol") + "' is the grid file"});
}

TEST_F(InputOutput, TheFilesOptionsReadAreRefusedToo) {
    expectRefused({"volume", "builtin:cube?n=2", "--tf", path("tf.json"), "-o", path("ok.png"),
                   "--json", path("tf.json")},
                  {"--json '" + path("tf.json") + "' is the --tf file"});
#if VISSORT_WITH_GL
    expectRefused({"view", "builtin:cube?n=2", "--tf", path("tf.json"), "--frames", "1",
                   "--screenshot", path("tf.json")},
                  {"--screenshot '" + path("tf.json") + "' is the --tf file"});
    expectRefused({"view", "builtin:bunnies?n=2", "--script", path("script.txt"), "--frames", "1",
                   "--screenshot", path("script.txt")},
                  {"--screenshot '" + path("script.txt") + "' is the --script file"});
#endif
    // A preset's name is no file: an output of that name is fine (refused for its extension only
    // later, by the image writer's own check, not as an input).
    const RunResult r = run({"volume", "builtin:cube?n=2", "--size", "16x16", "--tf", "fire", "-o",
                             path("fire.png"), "--json", path("fire")});
    EXPECT_EQ(r.code, 0) << r;
}

TEST_F(InputOutput, FilesTheSceneReadsAreRefusedOnceKnown) {
    // A JSON scene's meshes and an OBJ's material library: known once the scene is read, and
    // refused before any ordering, rendering or writing.
    const std::string json_scene = path("scenes/crabs.json"), mtl = path("meshes/crabs.mtl");
    expectRefused({"order", json_scene, "--json", path("meshes/crabs.obj")},
                  {"--json '" + path("meshes/crabs.obj") + "' is a file the scene reads"});
    expectRefused({"collide", json_scene, "--pairs-out", path("scenes/../meshes/crabs.mtl")},
                  {"--pairs-out", "is a file the scene reads", "crabs.mtl"});
    expectRefused({"order", path("meshes/crabs.obj"), "--csv", mtl},
                  {"--csv '" + mtl + "' is a file the scene reads"});
    expectRefused({"order", json_scene, "--json", json_scene},
                  {"--json '" + json_scene + "' is the scene file"});
}

TEST_F(InputOutput, ALinkOrAnotherSpellingOfTheInputIsTheInput) {
    const std::string mesh = path("meshes/crabs.obj");
    fs::create_symlink(obj(), path("link.obj"));
    fs::create_hard_link(obj(), path("hard.obj"));
    fs::create_directory(path("sub"));
    for (const std::string& output :
         {path("link.obj"), path("hard.obj"), path("sub/../meshes/crabs.obj"),
          std::string("./meshes/../meshes/crabs.obj"), std::string("meshes/crabs.obj")})
        expectRefused({"order", mesh, "--json", output},
                      {"--json '" + output + "' is the scene file '" + mesh + "'"});
    // The link given as the scene: its file is the input.
    expectRefused({"order", path("link.obj"), "--json", mesh},
                  {"--json '" + mesh + "' is the scene file '" + path("link.obj") + "'"});
}

TEST_F(InputOutput, TwoOutputsOnOnePathAreRefused) {
    const std::string out = path("out.txt");
    std::ofstream(out) << "kept\n";
    std::vector<std::vector<std::string>> cases = {
        {"order", "builtin:bunnies?n=2", "--json", out, "--csv", out},
        {"order", "builtin:bunnies?n=2", "--csv", out, "--dump-primitives", path("./out.txt")},
        {"collide", "builtin:bunnies?n=2", "--csv", out, "--pairs-out", out},
        {"collide", "builtin:bunnies?n=2", "--json", out, "--dump-primitives", out},
        {"volume", "builtin:cube?n=2", "-o", path("x.png"), "--reference", "raycast", "--error-map",
         path("x.png")},
        {"bench", "collision", "--json", out, "--plot", out},
    };
#if VISSORT_WITH_GL
    cases.push_back(
        {"render", "builtin:bunnies?n=2", "-o", path("x.png"), "--json", path("x.png")});
    cases.push_back({"render", "builtin:bunnies?n=2", "-o", path("x.png"), "--reference",
                     "linked-list", "--error-map", path("x.png")});
#endif
    for (const auto& args : cases)
        expectRefused(args, {"are one file", "give each output its own path"});
    // bench paper's files in --out are outputs too.
    fs::create_directory(path("paper"));
    expectRefused(
        {"bench", "paper", "--quick", "--out", path("paper"), "--json", path("paper/paper.csv")},
        {"--json '" + path("paper/paper.csv") + "' and --out '", "are one file"});
}

#if VISSORT_WITH_GL
TEST_F(InputOutput, FramePatternsAreCheckedFrameByFrameAndByShape) {
    // An input named like the pattern's frame 2 of 3; frame 3 of the pattern does not exist.
    fs::copy_file(obj(), path("frame_0002.obj"));
    expectRefused({"render", path("frame_0002.obj"), "--frames", "3", "-o", path("frame_%04d.obj")},
                  {"-o '" + path("frame_%04d.obj") + "' (frame 2: '" + path("frame_0002.obj") +
                   "') is the scene file"});
    // Frames 0 to 1 do not reach it: no clash (the run then fails for the image's extension,
    // later, as any .obj picture would).
    EXPECT_EQ(run({"render", path("frame_0002.obj"), "--frames", "2", "-o", path("frame_%04d.obj")})
                  .err.find("is the scene file"),
              std::string::npos);
    // The padding counts: frame_2.obj is not a frame of frame_%04d.
    fs::copy_file(obj(), path("frame_2.obj"));
    EXPECT_EQ(run({"render", path("frame_2.obj"), "--frames", "3", "-o", path("frame_%04d.obj")})
                  .err.find("is the scene file"),
              std::string::npos);
    // Two patterns of 100,000 frames, and a plain output among them: refused at once, nothing
    // listed or written.
    expectRefused({"render", "builtin:bunnies?n=2", "--frames", "100000", "-o", path("f_%06d.png"),
                   "--json", path("f_099999.png")},
                  {"(frame 99999: '" + path("f_099999.png") + "')", "are one file"});
    // A frame file that is a link to the input, up to 4,096 frames.
    fs::create_symlink(obj(), path("shot_01.obj"));
    expectRefused(
        {"render", path("meshes/crabs.obj"), "--frames", "5", "-o", path("./shot_%02d.obj")},
        {"(frame 1: '", "is the scene file"});
}
#endif

TEST_F(InputOutput, VolumeFramePatternsAreCheckedToo) {
    expectRefused({"volume", "builtin:cube?n=2", "--frames", "100000", "-o", path("v_%d.png"),
                   "--reference", "raycast", "--error-map", path("./v_%d.png")},
                  {"-o '" + path("v_%d.png") + "' (frame 0", "are one file"});
    fs::copy_file(dataPath("grids/vtu_mixed_ascii.vtu"), path("v_7.vtu"));
    expectRefused(
        {"volume", path("v_7.vtu"), "--frames", "8", "-o", path("v_%d.vtu")},
        {"-o '" + path("v_%d.vtu") + "' (frame 7: '" + path("v_7.vtu") + "') is the grid file"});
    // A frame file that is a hard link to the input, named unlike it.
    fs::create_hard_link(path("grid.vtu"), path("h_2.vtu"));
    expectRefused({"volume", path("grid.vtu"), "--frames", "4", "-o", path("h_%d.vtu")},
                  {"-o '" + path("h_%d.vtu") + "' (frame 2: '" + path("h_2.vtu") +
                   "') is the grid file '" + path("grid.vtu") + "'"});
    // A plain copy is another file.
    fs::copy_file(path("grid.vtu"), path("c_2.vtu"));
    EXPECT_EQ(run({"volume", path("grid.vtu"), "--frames", "4", "-o", path("c_%d.vtu")})
                  .err.find("is the grid file"),
              std::string::npos);
}

TEST_F(InputOutput, StandardOutputAndDevNullAreNotFiles) {
    const RunResult r = run({"order", "builtin:bunnies?n=2", "--quiet", "--json", "/dev/null",
                             "--csv", "/dev/null", "--dump-primitives", "/dev/null"});
    EXPECT_EQ(r.code, 0) << r;
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
    EXPECT_EQ(run({"order", "builtin:bunnies?n=2", "--quiet", "--json", "-"}).code, 0);
}

TEST_F(InputOutput, DistinctFilesAreFineAndNothingIsLeftBeside) {
    const RunResult r =
        run({"order", path("scenes/crabs.json"), "--quiet", "--json", path("out.json"), "--csv",
             path("out.csv"), "--dump-primitives", path("out.obj")});
    EXPECT_EQ(r.code, 0) << r;
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos)
            << "left behind: " << entry.path();
    EXPECT_TRUE(json::accept(readFile(path("out.json"))));
}

// A run stopped while it writes: the test hook holds each written temporary file before its
// rename (VISSORT_TEST_PAUSE_BEFORE_RENAME, atomic_file.cpp) and says so on stderr; the test
// then kills the run there. The target keeps its old bytes; SIGTERM and Ctrl-C also take the
// temporary file away.
class KilledWrite : public InputOutput {
protected:
    // Starts the tool held before its first rename and waits until it is there.
    pid_t startHeld(const std::vector<std::string>& args) {
        const std::string err = path("held.stderr");
        fs::remove(err); // the last run's line must not be taken for this one's
        const pid_t pid = fork();
        if (pid == 0) {
            if (chdir(dir_.c_str()) != 0)
                _exit(127);
            setenv("VISSORT_TEST_PAUSE_BEFORE_RENAME", "60", 1);
            if (!freopen(err.c_str(), "w", stderr) || !freopen("/dev/null", "w", stdout))
                _exit(127);
            std::vector<char*> argv{const_cast<char*>(kTool.c_str())};
            for (const std::string& a : args)
                argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            execv(kTool.c_str(), argv.data());
            _exit(127);
        }
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (readFile(err).find("test pause before renaming") == std::string::npos) {
            if (std::chrono::steady_clock::now() > deadline ||
                waitpid(pid, nullptr, WNOHANG) != 0) {
                ADD_FAILURE() << "the run never reached its rename: " << readFile(err);
                kill(pid, SIGKILL);
                waitpid(pid, nullptr, 0);
                return -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return pid;
    }
    std::vector<std::string> partials() const {
        std::vector<std::string> found;
        for (const auto& entry : fs::directory_iterator(dir_))
            if (entry.path().string().find(".partial") != std::string::npos)
                found.push_back(entry.path().string());
        return found;
    }
    void killDuringWrite(const std::vector<std::string>& args, const std::string& target,
                         int signal_number) {
        SCOPED_TRACE(args[0] + " " + target + " signal " + std::to_string(signal_number));
        const std::string old = "the old file's bytes\n";
        std::ofstream(target) << old;
        const pid_t pid = startHeld(args);
        if (pid < 0)
            return;
        // The new file is whole, and not yet where the old one is.
        EXPECT_EQ(partials().size(), 1u);
        for (const std::string& partial : partials())
            EXPECT_GT(fs::file_size(partial), 0u);
        EXPECT_EQ(readFile(target), old);
        kill(pid, signal_number);
        int status = 0;
        waitpid(pid, &status, 0);
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number);
        EXPECT_EQ(readFile(target), old);
        if (signal_number == SIGKILL) {
            // Nothing can clean up after SIGKILL: the whole new file stays, named apart.
            EXPECT_EQ(partials().size(), 1u);
            for (const std::string& partial : partials())
                fs::remove(partial);
        } else {
            EXPECT_TRUE(partials().empty()) << "the temporary file was left behind";
        }
    }
};

TEST_F(KilledWrite, LeavesTheOldFileWholeForEveryKindOfWriter) {
    for (int signal_number : {SIGKILL, SIGTERM, SIGINT}) {
        killDuringWrite({"order", "builtin:bunnies?n=2", "--quiet", "--json", path("out.json")},
                        path("out.json"), signal_number);
        killDuringWrite({"collide", "builtin:bunnies?n=3", "--frames", "3", "--quiet",
                         "--pairs-out", path("pairs.txt")},
                        path("pairs.txt"), signal_number);
        killDuringWrite(
            {"volume", "builtin:cube?n=2", "--size", "16x16", "--quiet", "-o", path("cube.png")},
            path("cube.png"), signal_number);
    }
    // Not held: the new files replace the old ones.
    EXPECT_EQ(run({"order", "builtin:bunnies?n=2", "--quiet", "--json", path("out.json")}).code, 0);
    EXPECT_TRUE(json::accept(readFile(path("out.json"))));
    EXPECT_TRUE(partials().empty());
}

} // namespace
} // namespace vissort
