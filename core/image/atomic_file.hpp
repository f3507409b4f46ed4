// Atomic output: write to a temporary file in the destination's folder, then rename over the
// destination (rename(2) within one file system is atomic). An existing file is replaced only by
// a complete new one; a failed or cancelled write leaves nothing behind.
#pragma once

#include <filesystem>

namespace fraktal {

class AtomicFile {
public:
    // Checks that the destination's folder exists and is writable; throws std::runtime_error
    // naming the path and the reason otherwise. Nothing is created yet.
    explicit AtomicFile(std::filesystem::path destination);
    ~AtomicFile();  // removes the temporary file unless committed
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // Where to write: "<folder>/.<name>.tmp-<pid>-<n><extension>", keeping the extension so that
    // libraries that choose the format by it still work.
    const std::filesystem::path& tempPath() const { return temp_; }
    const std::filesystem::path& destination() const { return destination_; }
    // Renames the temporary file over the destination; throws on failure.
    void commit();

private:
    std::filesystem::path destination_, temp_;
    bool committed_ = false;
};

}  // namespace fraktal
