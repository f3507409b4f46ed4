// Atomic output: write to a temporary file in the destination's folder, then rename over the
// destination (rename(2) within one file system is atomic). An existing file is replaced only by
// a complete new one; a failed or cancelled write leaves nothing behind.
#pragma once

#include <filesystem>
#include <string_view>

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
    // Flushes the temporary file to disk, then renames it over the destination (and flushes the
    // folder), so that after a crash or power loss the destination is the complete old or the
    // complete new file. With keepBackup, the old file is kept as "<destination>.bak" first
    // (by a hard link, so the destination never goes missing). Throws on failure.
    void commit(bool keepBackup = false);
    // Renames the temporary file over the destination without flushing anything to disk: readers
    // see the complete old or the complete new file, and a crash may lose the new one. For files
    // that mirror live state many times a second (the editor's --state-file), where two flushes a
    // write cost more than the write. Throws on failure.
    void commitForReaders();

   private:
    std::filesystem::path destination_, temp_;
    bool committed_ = false;
};

// Writes `text` to `destination` through an AtomicFile.
void writeFileAtomically(const std::filesystem::path& destination, std::string_view text, bool keepBackup = false);
// The same, committed for readers only (AtomicFile::commitForReaders: nothing flushed to disk).
void replaceFileForReaders(const std::filesystem::path& destination, std::string_view text);

}  // namespace fraktal
