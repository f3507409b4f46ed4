// Streaming scanline EXR output with the AOVs a compositor expects: R G B A, Z, N.x N.y N.z,
// albedo.R albedo.G albedo.B, AO, steps. Colour and AOVs are half float by default (32-bit on
// request); Z and steps are always 32-bit (depth needs the range). Rows are written strip by strip
// in increasing y, so memory stays bounded for any image size.
#pragma once

#include <ImfOutputFile.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "core/color/color_pipeline.hpp"
#include "core/camera.hpp"
#include "core/render/image_strip.hpp"

namespace fraktal {

// Header attribute names (read back by `fraktal info` and `fraktal render OUT.exr`).
inline constexpr const char* kExrPresetAttribute = "fraktal.preset";
inline constexpr const char* kExrSppAttribute = "fraktal.spp";
inline constexpr const char* kExrWorkingSpaceAttribute = "fraktal.workingSpace";
inline constexpr const char* kExrFovAttribute = "fraktal.camera.fovY";

struct ExrMetadata {
    std::string presetJson;  // the whole preset, as written by serializePreset
    Camera camera;
    int spp = 1;
    std::string workingSpace;
    std::optional<Chromaticities> chromaticities;
};

class ExrStripWriter {
public:
    // Opens `path` for writing (the caller passes an AtomicFile's temporary path).
    ExrStripWriter(const std::filesystem::path& path, int width, int height, bool fullFloat, const ExrMetadata& meta);
    ~ExrStripWriter();
    // Strips must arrive in order, covering every row exactly once.
    void write(const ImageStrip& strip);
    // Flushes and closes the file; throws on failure.
    void close();

private:
    std::filesystem::path path_;
    int width_, height_;
    bool fullFloat_;
    int nextRow_ = 0;
    std::unique_ptr<Imf::OutputFile> file_;
};

// The preset embedded in an EXR written by fraktal; throws naming the file when there is none.
std::string readExrPreset(const std::filesystem::path& path);
// A human-readable listing of an EXR's size, channels and fraktal attributes.
std::string describeExr(const std::filesystem::path& path);

}  // namespace fraktal
