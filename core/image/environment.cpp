#include "core/image/environment.hpp"

#include <ImfRgbaFile.h>
#include <ImfTestFile.h>

#include <algorithm>
#include <cmath>

#include "core/json_reader.hpp"

namespace fraktal {

namespace {
constexpr double kPi = 3.14159265358979323846;

double luminance(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

// The index i with cdf[i] <= u < cdf[i + 1] (cdf of n + 1 entries from 0 to 1).
int findInterval(const double* cdf, int n, double u) {
    const double* it = std::upper_bound(cdf, cdf + n + 1, u);
    return std::clamp(int(it - cdf) - 1, 0, n - 1);
}
}  // namespace

void EnvironmentMap::directionToUv(const vec3& d, double& u, double& v) const {
    const double phi = std::atan2(d.x, -d.z) - rotation;
    u = phi / (2.0 * kPi) + 0.5;
    u -= std::floor(u);
    v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
}

vec3 EnvironmentMap::uvToDirection(double u, double v) const {
    const double phi = (u - 0.5) * 2.0 * kPi + rotation;
    const double theta = v * kPi;
    return vec3(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
}

vec3 EnvironmentMap::radiance(const vec3& d) const {
    if (empty()) return vec3(0.0);
    double u, v;
    directionToUv(d, u, v);
    const int x = std::min(int(u * width), width - 1), y = std::min(int(v * height), height - 1);
    const float* p = &rgb[(size_t(y) * width + x) * 3];
    return vec3(p[0], p[1], p[2]);
}

void buildEnvironmentDistribution(EnvironmentMap& map) {
    const int w = map.width, h = map.height;
    map.marginal.assign(size_t(h) + 1, 0.0);
    map.conditional.assign(size_t(h) * (w + 1), 0.0);
    std::vector<double> rowWeight(h, 0.0);
    for (int y = 0; y < h; ++y) {
        const double sinTheta = std::sin(kPi * (y + 0.5) / h);
        double* c = &map.conditional[size_t(y) * (w + 1)];
        for (int x = 0; x < w; ++x) c[x + 1] = c[x] + luminance(&map.rgb[(size_t(y) * w + x) * 3]) * sinTheta;
        rowWeight[y] = c[w];
        for (int x = 1; x <= w; ++x) c[x] = c[w] > 0.0 ? c[x] / c[w] : double(x) / w;
        map.marginal[y + 1] = map.marginal[y] + rowWeight[y];
    }
    map.total = map.marginal[h];
    for (int y = 1; y <= h; ++y) map.marginal[y] = map.total > 0.0 ? map.marginal[y] / map.total : double(y) / h;
}

vec3 EnvironmentMap::sample(double u1, double u2, double& pdfOut) const {
    const int y = findInterval(marginal.data(), height, u1);
    const double* c = &conditional[size_t(y) * (width + 1)];
    const int x = findInterval(c, width, u2);
    // Uniform within the chosen texel.
    const double dv = (u1 - marginal[y]) / std::max(marginal[y + 1] - marginal[y], 1e-300);
    const double du = (u2 - c[x]) / std::max(c[x + 1] - c[x], 1e-300);
    const vec3 d = uvToDirection((x + std::clamp(du, 0.0, 1.0)) / width, (y + std::clamp(dv, 0.0, 1.0)) / height);
    pdfOut = pdf(d);
    return d;
}

double EnvironmentMap::pdf(const vec3& d) const {
    if (empty() || total <= 0.0) return 0.0;
    double u, v;
    directionToUv(d, u, v);
    const int x = std::min(int(u * width), width - 1), y = std::min(int(v * height), height - 1);
    const double sinTheta = std::sin(kPi * (y + 0.5) / height);
    if (sinTheta <= 0.0) return 0.0;
    const double weight = luminance(&rgb[(size_t(y) * width + x) * 3]) * sinTheta;
    // Texel probability over its (u, v) area 1/(w h), then d(omega) = 2 pi^2 sin(theta) du dv.
    return weight / total * double(width) * double(height) / (2.0 * kPi * kPi * sinTheta);
}

std::filesystem::path resolveEnvironmentPath(const std::string& map, const std::string& presetFile) {
    std::filesystem::path p(map);
    if (p.is_relative()) p = std::filesystem::path(presetFile).parent_path() / p;
    return p;
}

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path, const EnvironmentSettings& settings,
                                  const ColorPipeline& colors, const std::string& workingSpace,
                                  const std::string& presetFile) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw PresetError(presetFile, "environment.map", "'" + path.string() + "' does not exist or is not a file");
    if (!Imf::isOpenExrFile(path.string().c_str()))
        throw PresetError(presetFile, "environment.map", "'" + path.string() + "' is not an OpenEXR file");
    EnvironmentMap map;
    try {
        Imf::RgbaInputFile in(path.string().c_str());
        const Imath::Box2i dw = in.dataWindow();
        map.width = dw.max.x - dw.min.x + 1;
        map.height = dw.max.y - dw.min.y + 1;
        if (map.width < 2 || map.height < 1 || size_t(map.width) * map.height > (size_t(1) << 26))
            throw PresetError(presetFile, "environment.map", "'" + path.string() + "' has an unusable size");
        std::vector<Imf::Rgba> pixels(size_t(map.width) * map.height);
        in.setFrameBuffer(pixels.data() - dw.min.x - size_t(dw.min.y) * map.width, 1, map.width);
        in.readPixels(dw.min.y, dw.max.y);
        map.rgb.resize(pixels.size() * 3);
        for (size_t i = 0; i < pixels.size(); ++i) {
            map.rgb[i * 3] = std::max(0.0f, float(pixels[i].r));
            map.rgb[i * 3 + 1] = std::max(0.0f, float(pixels[i].g));
            map.rgb[i * 3 + 2] = std::max(0.0f, float(pixels[i].b));
        }
    } catch (const PresetError&) {
        throw;
    } catch (const std::exception& e) {
        throw PresetError(presetFile, "environment.map", "cannot read '" + path.string() + "': " + e.what());
    }
    try {
        const std::string from = colors.resolveSpace(settings.colorSpace);
        const std::string to = colors.resolveSpace(workingSpace);
        if (from != to) {
            auto processor = colors.config()->getProcessor(from.c_str(), to.c_str())->getDefaultCPUProcessor();
            OCIO::PackedImageDesc desc(map.rgb.data(), long(map.width), long(map.height), 3);
            processor->apply(desc);
        }
    } catch (const std::exception& e) {
        throw PresetError(presetFile, "environment.colorSpace", e.what());
    }
    for (float& v : map.rgb) v = std::max(0.0f, float(v * settings.intensity));
    map.rotation = settings.rotation * kPi / 180.0;
    buildEnvironmentDistribution(map);
    return map;
}

}  // namespace fraktal
