// How a 2D image is coloured: the preset's "colouring" section. Colours are linear Rec.709 as in
// the 3D shading section; the renderer converts them to the working space.
#pragma once

#include "core/vec.hpp"

namespace fraktal {

struct PlaneColouring {
    // Cosine palette a + b cos(2 pi (c t + d)) over t = frequency * smooth iterations + offset.
    vec3 paletteA{0.5, 0.5, 0.5};
    vec3 paletteB{0.5, 0.5, 0.5};
    vec3 paletteC{1.0, 1.0, 1.0};
    vec3 paletteD{0.0, 0.1, 0.2};
    double frequency = 0.05;
    double offset = 0.0;
    vec3 interior{0.0, 0.0, 0.0};
    double edgeWidth = 1.5;  // distance-estimate shading width in pixels (0: off)

    bool operator==(const PlaneColouring&) const = default;
};

}  // namespace fraktal
