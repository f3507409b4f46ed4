#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace fraktal {

namespace fs = std::filesystem;

namespace {
// Distinguishes several temporaries of one process (e.g. EXR and PNG written side by side).
std::atomic<unsigned> temporaryCounter{0};
}  // namespace

AtomicFile::AtomicFile(fs::path destination) : destination_(std::move(destination)) {
    const std::string name = destination_.string();
    if (destination_.filename().empty()) throw std::runtime_error(name + ": not a file name");
    fs::path folder = destination_.parent_path();
    if (folder.empty()) folder = ".";
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw std::runtime_error(name + ": folder " + folder.string() + " does not exist");
    if (fs::is_directory(destination_, ec)) throw std::runtime_error(name + ": is a directory");
    if (::access(folder.c_str(), W_OK) != 0)
        throw std::runtime_error(name + ": cannot write to folder " + folder.string() + " (" + std::strerror(errno) +
                                 ")");
    if (fs::exists(destination_, ec) && ::access(destination_.c_str(), W_OK) != 0)
        throw std::runtime_error(name + ": existing file is not writable (" + std::strerror(errno) + ")");
    temp_ = folder / ("." + destination_.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                      std::to_string(temporaryCounter++) + destination_.extension().string());
}

AtomicFile::~AtomicFile() {
    if (!committed_) {
        std::error_code ec;
        fs::remove(temp_, ec);
    }
}

namespace {

void syncPath(const fs::path& path, int flags) {
    const int fd = ::open(path.c_str(), flags);
    if (fd < 0) throw std::runtime_error(path.string() + ": cannot open to flush (" + std::strerror(errno) + ")");
    const int result = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (result != 0) throw std::runtime_error(path.string() + ": cannot flush to disk (" + std::strerror(err) + ")");
}

}  // namespace

void AtomicFile::commit(bool keepBackup) {
    syncPath(temp_, O_RDONLY);
    std::error_code ec;
    if (keepBackup && fs::exists(destination_, ec)) {
        // link + rename: "<name>.bak" is replaced atomically, and the destination stays in place.
        const fs::path backup = destination_.string() + ".bak";
        const fs::path backupTemp = temp_.string() + ".bak";
        fs::remove(backupTemp, ec);
        fs::create_hard_link(destination_, backupTemp, ec);
        if (!ec) fs::rename(backupTemp, backup, ec);
        if (ec) {
            fs::remove(backupTemp, ec);
            throw std::runtime_error(backup.string() + ": cannot keep the previous version: " + ec.message());
        }
    }
    fs::rename(temp_, destination_, ec);
    if (ec) throw std::runtime_error(destination_.string() + ": cannot replace with the new file: " + ec.message());
    committed_ = true;
    fs::path folder = destination_.parent_path();
    syncPath(folder.empty() ? fs::path(".") : folder, O_RDONLY | O_DIRECTORY);
}

void AtomicFile::commitForReaders() {
    std::error_code ec;
    fs::rename(temp_, destination_, ec);
    if (ec) throw std::runtime_error(destination_.string() + ": cannot replace with the new file: " + ec.message());
    committed_ = true;
}

namespace {

void writeTemporary(const AtomicFile& file, std::string_view text) {
    FILE* out = std::fopen(file.tempPath().c_str(), "wb");
    if (!out) throw std::runtime_error(file.destination().string() + ": cannot write (" + std::strerror(errno) + ")");
    const bool ok = std::fwrite(text.data(), 1, text.size(), out) == text.size();
    const int err = errno;
    if (std::fclose(out) != 0 || !ok)
        throw std::runtime_error(file.destination().string() + ": cannot write (" + std::strerror(err) + ")");
}

}  // namespace

void writeFileAtomically(const fs::path& destination, std::string_view text, bool keepBackup) {
    AtomicFile file(destination);
    writeTemporary(file, text);
    file.commit(keepBackup);
}

void replaceFileForReaders(const fs::path& destination, std::string_view text) {
    AtomicFile file(destination);
    writeTemporary(file, text);
    file.commitForReaders();
}

}  // namespace fraktal
