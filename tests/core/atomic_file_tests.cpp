// Files written whole or not at all (atomic_file.h): the target holds the old file or the new
// one, never part of one, and no temporary file is left behind by a write that ends.

#include "vissort/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "scratch_folder.h"

namespace vissort {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public testing::Test {
protected:
    void SetUp() override {
        ASSERT_FALSE(scratch_.path().empty());
        dir_ = scratch_.path();
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    static std::string read(const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
    static void put(const fs::path& file, const std::string& text) {
        std::ofstream(file, std::ios::binary) << text;
    }
    // The folder's entries besides the ones named.
    std::size_t entries() const {
        return std::size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
    }
    static Status writeText(const std::string& path, const std::string& text) {
        return writeFileAtomically(path, [&](const std::string& write_path) {
            put(write_path, text);
            return Status::ok();
        });
    }

    ScratchFolder scratch_;
    fs::path dir_; // scratch_'s path
};

TEST_F(AtomicFileTest, WritesANewFileAndLeavesNothingElse) {
    ASSERT_TRUE(writeText(path("out.txt"), "new"));
    EXPECT_EQ(read(path("out.txt")), "new");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, TheWriterWritesAnotherFileThanTheTarget) {
    put(path("out.txt"), "old");
    std::string seen_path, seen_target_during_write;
    ASSERT_TRUE(writeFileAtomically(path("out.txt"), [&](const std::string& write_path) {
        seen_path = write_path;
        put(write_path, "new");
        seen_target_during_write = read(path("out.txt"));
        return Status::ok();
    }));
    EXPECT_NE(seen_path, path("out.txt"));
    EXPECT_EQ(fs::path(seen_path).parent_path(), dir_); // renamed within one file system
    EXPECT_EQ(seen_target_during_write, "old");         // a reader saw the old file whole
    EXPECT_EQ(read(path("out.txt")), "new");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, AFailedWriteLeavesTheOldFileAndNoTemporaryFile) {
    put(path("out.txt"), "old contents");
    const Status failed = writeFileAtomically(path("out.txt"), [&](const std::string& write_path) {
        put(write_path, "half");
        return Status::failure("disk full, say");
    });
    EXPECT_FALSE(failed);
    EXPECT_EQ(failed.error, "disk full, say");
    EXPECT_EQ(read(path("out.txt")), "old contents");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, AnUncommittedFileIsRemovedAndTheTargetUntouched) {
    put(path("pairs.txt"), "old");
    {
        Result<AtomicFile> file = AtomicFile::begin(path("pairs.txt"));
        ASSERT_TRUE(file) << file.error;
        put(file.value->writePath(), "partial frames");
        EXPECT_EQ(entries(), 2u);
    }
    EXPECT_EQ(read(path("pairs.txt")), "old");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, CommitReplacesOnceAndRefusesASecondCommit) {
    Result<AtomicFile> file = AtomicFile::begin(path("pairs.txt"));
    ASSERT_TRUE(file) << file.error;
    put(file.value->writePath(), "all frames");
    ASSERT_TRUE(file.value->commit());
    EXPECT_EQ(read(path("pairs.txt")), "all frames");
    EXPECT_FALSE(file.value->commit());
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, ASymbolicLinkStaysALinkToTheReplacedFile) {
    put(path("real.txt"), "old");
    fs::create_symlink("real.txt", path("link.txt"));
    ASSERT_TRUE(writeText(path("link.txt"), "new"));
    EXPECT_TRUE(fs::is_symlink(path("link.txt")));
    EXPECT_EQ(read(path("real.txt")), "new");
    EXPECT_EQ(entries(), 2u);
}

TEST_F(AtomicFileTest, AnExistingFileKeepsItsPermissions) {
    put(path("out.txt"), "old");
    const fs::perms kept = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read;
    fs::permissions(path("out.txt"), kept);
    ASSERT_TRUE(writeText(path("out.txt"), "new"));
    EXPECT_EQ(fs::status(path("out.txt")).permissions() & fs::perms::mask, kept);
}

TEST_F(AtomicFileTest, ANewFileGetsTheUsualPermissions) {
    ASSERT_TRUE(writeText(path("out.txt"), "new"));
    // Not the 0600 of a private temporary file: what any new file gets under this umask.
    put(path("plain.txt"), "plain");
    EXPECT_EQ(fs::status(path("out.txt")).permissions(),
              fs::status(path("plain.txt")).permissions());
}

TEST_F(AtomicFileTest, SpecialFilesAreWrittenInPlace) {
    std::string seen;
    ASSERT_TRUE(writeFileAtomically("/dev/null", [&](const std::string& write_path) {
        seen = write_path;
        return Status::ok();
    }));
    EXPECT_EQ(seen, "/dev/null");
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST_F(AtomicFileTest, AMissingFolderIsOneLineNamingThePath) {
    const Status failed = writeText(path("no/such/folder/out.txt"), "x");
    EXPECT_FALSE(failed);
    EXPECT_NE(failed.error.find("no/such/folder/out.txt"), std::string::npos) << failed.error;
    EXPECT_EQ(failed.error.find('\n'), std::string::npos);
}

TEST_F(AtomicFileTest, ASignalsCleanUpRemovesTheWritesInProgress) {
    put(path("out.txt"), "old");
    Result<AtomicFile> file = AtomicFile::begin(path("out.txt"));
    ASSERT_TRUE(file) << file.error;
    put(file.value->writePath(), "partial");
    ASSERT_TRUE(fs::exists(file.value->writePath()));
    removeTemporaryFilesOfWritesInProgress();
    EXPECT_FALSE(fs::exists(file.value->writePath()));
    EXPECT_EQ(read(path("out.txt")), "old");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, TheHookSeesTheWholeTemporaryFileBeforeTheRename) {
    put(path("out.txt"), "old");
    std::string held, target_then;
    setBeforeRenameHook([&](const std::string& temporary) {
        held = read(temporary);
        target_then = read(path("out.txt"));
    });
    const Status written = writeText(path("out.txt"), "new");
    setBeforeRenameHook({});
    ASSERT_TRUE(written);
    EXPECT_EQ(held, "new");
    EXPECT_EQ(target_then, "old");
    EXPECT_EQ(read(path("out.txt")), "new");
}

TEST_F(AtomicFileTest, ALongNameStillGetsATemporaryFile) {
    const std::string name(250, 'n');
    ASSERT_TRUE(writeText(path(name), "new"));
    EXPECT_EQ(read(path(name)), "new");
    EXPECT_EQ(entries(), 1u);
}

} // namespace
} // namespace vissort
