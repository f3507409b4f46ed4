// Mandelbulber2 settings files (.fract), read as Mandelbulber2 2.20 reads them: parsing alone,
// apart from what the settings mean for a fraktal scene (core/import/fract_import.hpp).
//
// The v2 format: "# Mandelbulber settings file", "# version 2.NN", then sections "[description]"
// (free text), "[main_parameters]", "[fractal_1]" .. "[fractal_9]" (one per formula slot) and the
// animation tables "[frames]" and "[keyframes]". A parameter line is `name value;`: the value runs
// from the first space to the first ';'. Only parameters that differ from Mandelbulber2's
// defaults are written (core/import/mb2_defaults.inc holds the defaults). Numbers use the saving
// locale's decimal separator ("0,7" and "0.7" both occur), vectors are space separated, colours
// 16-bit hex triples ("e800 9500 4200"), booleans true/false (or 1/0).
// Reference: ../shared/reference/mandelbulber2-fract.md, Notes 1.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec.hpp"

namespace fraktal::mb2 {

struct FractEntry {
    std::string value;
    int line = 0;  // 1-based, for messages
};

struct FractFile {
    std::string source;   // the file, for messages
    std::string version;  // as written in "# version", e.g. "2.15"
    double versionNumber = 0.0;
    std::string description;  // the [description] section's text
    // Parameter sections by name ("main_parameters", "fractal_1", ...): name -> entry.
    std::map<std::string, std::map<std::string, FractEntry>> sections;
    // The animation tables' sections present ("frames", "keyframes") and their data rows.
    std::map<std::string, int> animationRows;

    const FractEntry* find(const std::string& section, const std::string& key) const;
};

// Parses a settings file's text. Throws PresetError naming `source`, the line and the reason: a
// Mandelbulber 1.x file (a different format), a file without the v2 header, a line that is not
// `name value;`, a parameter given twice in a section.
FractFile parseFractFile(std::string_view text, const std::string& source);
FractFile loadFractFile(const std::filesystem::path& path);

// Whether `path` names a Mandelbulber settings file by its extension (.fract, any case).
bool isFractPath(const std::filesystem::path& path);

// Values as Mandelbulber2 writes them. Each returns nothing for text it cannot read; the caller
// names the parameter in its error.
std::optional<double> parseNumber(std::string_view text);
std::optional<vec3> parseVector(std::string_view text);         // 3 numbers (a 4th is refused)
std::optional<glm::dvec4> parseVector4(std::string_view text);  // 4 numbers (the 4D transforms')
std::optional<bool> parseBoolean(std::string_view text);
std::optional<vec3> parseColour(std::string_view text);  // 16-bit hex triple -> 0..1 (display-referred)

// A parameter's default in Mandelbulber2 2.20: `main` for [main_parameters] (slot settings carry
// their slot's suffix, "formula_1"), else a formula parameter (no suffix). Null for a name 2.20
// does not have.
const char* defaultValue(std::string_view key, bool main);

}  // namespace fraktal::mb2
