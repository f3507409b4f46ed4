// libFuzzer target for the preset loader: any byte string must either parse or raise a
// PresetError; anything else (a crash, a sanitizer report, another exception) is a bug.
// Built and run by scripts/fuzz.sh (clang, -fsanitize=fuzzer,address,undefined).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/preset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const fraktal::Preset p = fraktal::parsePreset(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
        // What parses must save and parse again.
        fraktal::parsePreset(fraktal::serializePreset(p), "fuzz-saved.json");
    } catch (const fraktal::PresetError&) {
    }
    return 0;
}
