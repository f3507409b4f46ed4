// libFuzzer target for the preset loaders (3D, and 2D for text with "dimension": 2), the
// Mandelbulber2 importer (text that starts with '#') and the Fragmentarium parser (text that
// starts with '/', as a frag's opening comment does): any byte string must either parse or raise a
// PresetError; anything else (a crash, a sanitizer report, another exception) is a bug. What the
// importer builds must be a preset that saves and parses again. Both go through the same guarded reader and migration
// (core/json_reader.hpp, core/preset_migrate.hpp). Built and run by scripts/fuzz.sh (clang,
// -fsanitize=fuzzer,address,undefined).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/import/fract_import.hpp"
#include "core/import/frag_file.hpp"
#include "core/plane/plane_preset.hpp"
#include "core/preset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        // What parses must save and parse again.
        if (text.starts_with("#")) {
            const fraktal::mb2::FractImport r =
                fraktal::mb2::importFract(fraktal::mb2::parseFractFile(text, "fuzz.fract"));
            fraktal::parsePreset(fraktal::serializePreset(r.preset), "fuzz-imported.json");
        } else if (text.starts_with("/")) {
            fraktal::frag::parseFragFile(text, "fuzz.frag");
        } else if (fraktal::isPlanePresetText(text)) {
            const fraktal::PlanePreset p = fraktal::parsePlanePreset(text, "fuzz.json");
            fraktal::parsePlanePreset(fraktal::serializePlanePreset(p), "fuzz-saved.json");
        } else {
            const fraktal::Preset p = fraktal::parsePreset(text, "fuzz.json");
            fraktal::parsePreset(fraktal::serializePreset(p), "fuzz-saved.json");
        }
    } catch (const fraktal::PresetError&) {
    }
    return 0;
}
