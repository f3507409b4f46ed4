#include "core/image/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
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
    if (!fs::is_directory(folder, ec)) throw std::runtime_error(name + ": folder " + folder.string() + " does not exist");
    if (fs::is_directory(destination_, ec)) throw std::runtime_error(name + ": is a directory");
    if (::access(folder.c_str(), W_OK) != 0)
        throw std::runtime_error(name + ": cannot write to folder " + folder.string() + " (" + std::strerror(errno) + ")");
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

void AtomicFile::commit() {
    std::error_code ec;
    fs::rename(temp_, destination_, ec);
    if (ec) throw std::runtime_error(destination_.string() + ": cannot replace with the new file: " + ec.message());
    committed_ = true;
}

}  // namespace fraktal
