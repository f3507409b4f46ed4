#include "core/color/color_pipeline.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace fraktal {

namespace fs = std::filesystem;

fs::path shippedOcioConfigPath() { return fs::path(FRAKTAL_SOURCE_DIR) / "config" / "ocio" / "config.ocio"; }

ColorPipeline::ColorPipeline(OCIO::ConstConfigRcPtr config, fs::path path)
    : config_(std::move(config)), path_(std::move(path)) {}

ColorPipeline ColorPipeline::fromEnvironment() {
    const char* env = std::getenv("OCIO");
    if (env && *env) return fromFile(env);
    return fromFile(shippedOcioConfigPath());
}

ColorPipeline ColorPipeline::fromFile(const fs::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw std::runtime_error("OCIO config " + name + ": no such file");
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(name.c_str());
        config->validate();
        return ColorPipeline(config, path);
    } catch (const OCIO::Exception& e) {
        throw std::runtime_error("OCIO config " + name + ": " + e.what());
    }
}

std::string ColorPipeline::resolveSpace(const std::string& nameOrRole) const {
    if (OCIO::ConstColorSpaceRcPtr cs = config_->getColorSpace(nameOrRole.c_str())) return cs->getName();
    std::string known;
    for (int i = 0; i < config_->getNumColorSpaces(); ++i)
        known += (known.empty() ? "" : ", ") + std::string(config_->getColorSpaceNameByIndex(i));
    throw std::runtime_error("OCIO config " + path_.string() + ": no colour space or role '" + nameOrRole +
                             "' (colour spaces: " + known + ")");
}

namespace {

void applyPixel(const OCIO::ConstCPUProcessorRcPtr& cpu, float rgb[3]) { cpu->applyRGB(rgb); }

// The config's linear Rec.709 space: the shipped name, else the scene_linear role of a config
// that calls itself Rec.709 (most studio configs name it so).
const char* linearRec709Name(const OCIO::ConstConfigRcPtr& config) {
    for (const char* name : {"Linear Rec.709 (sRGB)", "lin_rec709", "Utility - Linear - sRGB", "lin_srgb"})
        if (config->getColorSpace(name)) return name;
    return nullptr;
}

}  // namespace

vec3 ColorPipeline::fromLinearRec709(const vec3& rgb, const std::string& workingSpace) const {
    const char* source = linearRec709Name(config_);
    const std::string target = resolveSpace(workingSpace);
    if (!source || target == source) return rgb;
    float p[3] = {float(rgb.x), float(rgb.y), float(rgb.z)};
    applyPixel(config_->getProcessor(source, target.c_str())->getDefaultCPUProcessor(), p);
    return vec3(p[0], p[1], p[2]);
}

std::optional<Chromaticities> ColorPipeline::chromaticities(const std::string& space) const {
    // Spaces with published primaries and white (ITU-R BT.709; SMPTE ST 2065-1 and S-2014-004 for
    // AP0/AP1 with the ACES white). Measuring through the config's XYZ D65 role would give the
    // chromatically adapted (D65) values instead of the native white.
    const std::string name = resolveSpace(space);
    const vec2 d65(0.3127, 0.3290), aces(0.32168, 0.33767);
    if (name == "Linear Rec.709 (sRGB)" || name == "lin_rec709" || name == "lin_srgb")
        return Chromaticities{{vec2(0.64, 0.33), vec2(0.30, 0.60), vec2(0.15, 0.06), d65}};
    if (name == "ACEScg")
        return Chromaticities{{vec2(0.713, 0.293), vec2(0.165, 0.830), vec2(0.128, 0.044), aces}};
    if (name == "ACES2065-1")
        return Chromaticities{{vec2(0.7347, 0.2653), vec2(0.0, 1.0), vec2(0.0001, -0.077), aces}};
    const char* xyz = config_->getColorSpace("cie_xyz_d65_interchange") ? "cie_xyz_d65_interchange" : nullptr;
    if (!xyz) return std::nullopt;
    const std::string source = resolveSpace(space);
    OCIO::ConstCPUProcessorRcPtr cpu = config_->getProcessor(source.c_str(), xyz)->getDefaultCPUProcessor();
    Chromaticities c;
    const float inputs[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    for (int i = 0; i < 4; ++i) {
        float p[3] = {inputs[i][0], inputs[i][1], inputs[i][2]};
        applyPixel(cpu, p);
        const double sum = double(p[0]) + p[1] + p[2];
        if (!(std::abs(sum) > 1e-9)) return std::nullopt;
        c.xy[size_t(i)] = vec2(p[0] / sum, p[1] / sum);
    }
    return c;
}

void ColorPipeline::checkDisplayView(const std::string& display, const std::string& view) const {
    std::string displays;
    bool found = false;
    for (int i = 0; i < config_->getNumDisplays(); ++i) {
        const std::string d = config_->getDisplay(i);
        displays += (displays.empty() ? "" : ", ") + d;
        found = found || d == display;
    }
    if (!found)
        throw std::runtime_error("OCIO config " + path_.string() + ": no display '" + display + "' (displays: " +
                                 displays + ")");
    std::string views;
    for (int i = 0; i < config_->getNumViews(display.c_str()); ++i) {
        const std::string v = config_->getView(display.c_str(), i);
        if (v == view) return;
        views += (views.empty() ? "" : ", ") + v;
    }
    throw std::runtime_error("OCIO config " + path_.string() + ": display '" + display + "' has no view '" + view +
                             "' (views: " + views + ")");
}

DisplayTransform::DisplayTransform(const ColorPipeline& pipeline, const std::string& workingSpace,
                                   const std::string& display, const std::string& view, double exposure)
    : gain_(float(std::exp2(exposure))) {
    pipeline.checkDisplayView(display, view);
    const std::string source = pipeline.resolveSpace(workingSpace);
    try {
        OCIO::DisplayViewTransformRcPtr t = OCIO::DisplayViewTransform::Create();
        t->setSrc(source.c_str());
        t->setDisplay(display.c_str());
        t->setView(view.c_str());
        processor_ = pipeline.config()->getProcessor(t)->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
        throw std::runtime_error("OCIO config " + pipeline.configPath().string() + ": " + e.what());
    }
}

void DisplayTransform::apply(std::span<float> rgb) const {
    for (float& v : rgb) v *= gain_;
    if (rgb.size() < 3) return;
    OCIO::PackedImageDesc desc(rgb.data(), long(rgb.size() / 3), 1, 3);
    processor_->apply(desc);
}

void DisplayTransform::toDisplay8(std::span<const float> rgba, std::span<uint8_t> rgb8) const {
    const size_t pixels = rgba.size() / 4;
    std::vector<float> rgb(pixels * 3);
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = rgba[4 * i + c];
    apply(rgb);
    for (size_t i = 0; i < rgb.size() && i < rgb8.size(); ++i) {
        const float v = std::isfinite(rgb[i]) ? std::clamp(rgb[i], 0.0f, 1.0f) : 0.0f;
        rgb8[i] = uint8_t(std::lround(v * 255.0f));
    }
}

}  // namespace fraktal
