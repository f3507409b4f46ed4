// Small widgets for the Render and Shading tabs: doubles, ints, colours and directions of the
// preset's settings structs (core/render_settings.hpp), each with its range and help text.
#pragma once

#include "core/vec.hpp"

namespace fraktal::editor {

bool dragDouble(const char* label, double& value, double lo, double hi, float speed, const char* format,
                const char* help);
bool dragInt(const char* label, int& value, int lo, int hi, float speed, const char* help);
// A linear Rec.709 colour; components may exceed 1 (light intensities), HDR picker.
bool colorEdit(const char* label, vec3& rgb, const char* help);
// A direction (never the zero vector: such an edit is refused).
bool directionEdit(const char* label, vec3& direction, const char* help);

// Cosine palettes a + b cos(2 pi (c t + d)) (3D orbit traps, 2D smooth iteration counts): a
// combo of named starting points, and the four terms' widgets.
bool paletteChoice(vec3& a, vec3& b, vec3& c, vec3& d);
bool paletteTerms(vec3& a, vec3& b, vec3& c, vec3& d);

}  // namespace fraktal::editor
