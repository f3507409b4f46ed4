// An equirectangular HDR environment map, loaded for rendering: pixels converted from the map's
// declared colour space into the working space through OpenColorIO, scaled by the intensity, and
// a luminance CDF for importance sampling (pbrt-v4 12.5.2: a piecewise-constant 2D distribution
// over (u, v) weighted by sin(theta), so directions are drawn in proportion to the light they
// bring; a small bright sun gets most samples and casts clean shadows).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/color/color_pipeline.hpp"
#include "core/lighting.hpp"
#include "core/vec.hpp"

namespace fraktal {

struct EnvironmentMap {
    int width = 0, height = 0;
    std::vector<float> rgb;           // working space, times intensity, rows from the top (+y)
    std::vector<double> marginal;     // CDF over rows, height + 1 entries
    std::vector<double> conditional;  // CDF over columns of each row, height * (width + 1)
    double rotation = 0.0;            // radians about +y
    double total = 0.0;               // sum of the sampling weights (0: a black map)

    bool empty() const { return width == 0; }
    // Radiance arriving from direction `d` (unit vector), nearest texel.
    vec3 radiance(const vec3& d) const;
    // A direction drawn with probability proportional to weight, from two uniform numbers; its
    // solid-angle pdf in `pdf`.
    vec3 sample(double u1, double u2, double& pdf) const;
    double pdf(const vec3& d) const;
    // Map coordinates of a direction and back (u along longitude, v from the top, both 0..1).
    void directionToUv(const vec3& d, double& u, double& v) const;
    vec3 uvToDirection(double u, double v) const;
};

// Reads `path` (an RGBA or RGB OpenEXR). Throws PresetError naming `presetFile` and the field
// "environment.map" when the file is missing or not a readable EXR, and "environment.colorSpace"
// when the config has no such space.
EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path, const EnvironmentSettings& settings,
                                  const ColorPipeline& colors, const std::string& workingSpace,
                                  const std::string& presetFile);
// Builds the CDFs of pixels already in `map.rgb` (tests build maps by hand).
void buildEnvironmentDistribution(EnvironmentMap& map);
// The environment settings' map resolved against the preset file's directory.
std::filesystem::path resolveEnvironmentPath(const std::string& map, const std::string& presetFile);

}  // namespace fraktal
