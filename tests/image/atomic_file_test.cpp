#include "candela/core/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "image/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using testing::TempDir;
using testing::read_test_file;
using testing::write_test_file;

TEST(AtomicFile, WritesNewFile) {
    TempDir dir;
    write_contents_atomically(dir / "a.txt", "hello");
    EXPECT_EQ(read_test_file(dir / "a.txt"), "hello");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, ReplacesExistingFile) {
    TempDir dir;
    write_test_file(dir / "a.txt", "an old and longer content");
    write_contents_atomically(dir / "a.txt", "new");
    EXPECT_EQ(read_test_file(dir / "a.txt"), "new");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, WritesBinaryBytesIncludingZeros) {
    TempDir dir;
    const std::string bytes("a\0b\n\r\xff", 6);
    write_contents_atomically(dir / "b.bin", bytes);
    EXPECT_EQ(read_test_file(dir / "b.bin"), bytes);
}

TEST(AtomicFile, MissingFolderThrowsNamingDestination) {
    TempDir dir;
    const auto destination = dir / "no_such_folder" / "a.txt";
    try {
        write_contents_atomically(destination, "x");
        FAIL() << "expected SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file, destination.string());
        EXPECT_NE(e.message().find("does not exist"), std::string::npos) << e.message();
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, FailingWriterLeavesOldFileAndNoTemporary) {
    TempDir dir;
    write_test_file(dir / "a.txt", "old");
    std::filesystem::path seen;
    try {
        write_file_atomically(dir / "a.txt", [&](const std::filesystem::path& temporary) {
            seen = temporary;
            write_test_file(temporary, "half");
            throw std::runtime_error("disk on fire");
        });
        FAIL() << "expected SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file, (dir / "a.txt").string());
        EXPECT_NE(e.message().find("disk on fire"), std::string::npos) << e.message();
    }
    EXPECT_EQ(seen.parent_path(), dir.path());  // same folder, so the rename is atomic
    EXPECT_EQ(seen.filename().string().rfind(".a.txt.tmp.", 0), 0u) << seen;
    EXPECT_EQ(read_test_file(dir / "a.txt"), "old");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, RenderErrorFromWriterPassesThroughAfterCleanup) {
    TempDir dir;
    EXPECT_THROW(write_file_atomically(dir / "a.txt",
                                       [](const std::filesystem::path& temporary) {
                                           write_test_file(temporary, "x");
                                           throw RenderError("bug");
                                       }),
                 RenderError);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, WriterThatCreatesNothingIsAnError) {
    TempDir dir;
    EXPECT_THROW(write_file_atomically(dir / "a.txt", [](const std::filesystem::path&) {}), SceneError);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, DestinationThatIsAFolderIsAnError) {
    TempDir dir;
    std::filesystem::create_directory(dir / "sub");
    EXPECT_THROW(write_contents_atomically(dir / "sub", "x"), SceneError);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"sub"});
    EXPECT_TRUE(std::filesystem::is_empty(dir / "sub"));
}

TEST(AtomicFile, TemporaryNamesAreUnique) {
    TempDir dir;
    std::vector<std::filesystem::path> names;
    for (int i = 0; i < 3; ++i)
        write_file_atomically(dir / "a.txt", [&](const std::filesystem::path& temporary) {
            names.push_back(temporary);
            write_test_file(temporary, std::to_string(i));
        });
    EXPECT_NE(names[0], names[1]);
    EXPECT_NE(names[1], names[2]);
    EXPECT_EQ(read_test_file(dir / "a.txt"), "2");
}

}  // namespace
}  // namespace candela
