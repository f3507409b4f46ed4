// Atomic output (core/atomic_file.hpp): a file is replaced only by a complete new one, with or
// without the flushes to disk, and nothing temporary stays behind.
#include "core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fraktal {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The folder's entries, for checking that no temporary file was left in it.
int entries(const fs::path& folder) {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(folder)) ++n;
    return n;
}

struct TempFolder {
    fs::path path = fs::temp_directory_path() / ("fraktal-atomic-" + std::to_string(::getpid()));
    TempFolder() { fs::create_directories(path); }
    ~TempFolder() { fs::remove_all(path); }
};

TEST(AtomicFile, BothWritesReplaceAFileWholeAndLeaveNothingBehind) {
    TempFolder folder;
    const fs::path file = folder.path / "state.json";
    for (const bool forReaders : {false, true}) {
        const auto write = [&](const std::string& text) {
            forReaders ? replaceFileForReaders(file, text) : writeFileAtomically(file, text);
        };
        write("a longer first version\n");
        write("second\n");
        EXPECT_EQ(contents(file), "second\n") << (forReaders ? "for readers" : "flushed");
        EXPECT_EQ(entries(folder.path), 1) << "a temporary file stayed beside the destination";
    }
}

TEST(AtomicFile, AMissingFolderIsAnErrorNamingThePath) {
    TempFolder folder;
    const fs::path file = folder.path / "missing" / "state.json";
    for (const bool forReaders : {false, true}) {
        try {
            forReaders ? replaceFileForReaders(file, "x") : writeFileAtomically(file, "x");
            ADD_FAILURE() << "no error for a file in a missing folder";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("state.json"), std::string::npos) << e.what();
        }
        EXPECT_FALSE(fs::exists(file));
    }
}

}  // namespace
}  // namespace fraktal
