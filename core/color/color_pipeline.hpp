// Colour management through OpenColorIO: which config (the user's $OCIO, else the shipped
// config/ocio/config.ocio), the scene-linear working space, and the display/view transform the
// PNG preview (and later the viewport) goes through. Data stays scene-linear everywhere else
// (tev style: exposure and display transforms only at display).
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "core/vec.hpp"

namespace fraktal {

namespace OCIO = OCIO_NAMESPACE;

// CIE xy of the red, green, blue primaries and the white point (what an EXR header stores).
struct Chromaticities {
    std::array<vec2, 4> xy;  // red, green, blue, white
};

// The project's config: FRAKTAL_SOURCE_DIR/config/ocio/config.ocio.
std::filesystem::path shippedOcioConfigPath();

class ColorPipeline {
public:
    // $OCIO when set (and not empty), else the shipped config. Throws std::runtime_error naming
    // the config file and what is wrong with it.
    static ColorPipeline fromEnvironment();
    static ColorPipeline fromFile(const std::filesystem::path& config);

    const std::filesystem::path& configPath() const { return path_; }
    // A colour space name, or a role such as "scene_linear", resolved to the colour space name.
    // Throws, listing the known spaces, when the config has no such space.
    std::string resolveSpace(const std::string& nameOrRole) const;
    // Linear Rec.709 (the preset's colour convention) into `workingSpace`. When the config has no
    // linear Rec.709 space to convert from, colours pass through unchanged.
    vec3 fromLinearRec709(const vec3& rgb, const std::string& workingSpace) const;
    // The primaries and white of a space: published values for the shipped spaces, else measured
    // through the config's CIE XYZ D65 role (then the white is D65-adapted); empty
    // when the config does not define that role.
    std::optional<Chromaticities> chromaticities(const std::string& space) const;
    // Checks display and view exist; throws listing the ones that do.
    void checkDisplayView(const std::string& display, const std::string& view) const;

    OCIO::ConstConfigRcPtr config() const { return config_; }

private:
    ColorPipeline(OCIO::ConstConfigRcPtr config, std::filesystem::path path);
    OCIO::ConstConfigRcPtr config_;
    std::filesystem::path path_;
};

// working space -> display/view, with exposure in stops applied in scene-linear first.
class DisplayTransform {
public:
    DisplayTransform(const ColorPipeline& pipeline, const std::string& workingSpace, const std::string& display,
                     const std::string& view, double exposure);
    // In place on packed RGB floats (scene-linear in, display-encoded out).
    void apply(std::span<float> rgb) const;
    // Scene-linear RGBA rows to 8-bit display RGB (alpha is ignored: the preview is opaque).
    void toDisplay8(std::span<const float> rgba, std::span<uint8_t> rgb8) const;

private:
    OCIO::ConstCPUProcessorRcPtr processor_;
    float gain_ = 1.0f;
};

}  // namespace fraktal
