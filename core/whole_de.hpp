// Whole-DE estimators: a custom estimator whose GLSL is a complete set of global-scope
// declarations (functions, globals, #define lines) that defines `float DE(vec3)`, as an imported
// Fragmentarium frag brings it. Unlike a node-list custom block it may declare functions, loop
// and use the preprocessor; what keeps it from reaching outside its code is checked here, and
// the generated shader renames its names so that they cannot collide with fraktal's own.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/block.hpp"

namespace fraktal {

inline constexpr size_t kMaxWholeDEGlslBytes = 96 * 1024;
inline constexpr int kMaxWholeDELines = 9000;  // under kNodeLineStride: its #line range stays its own
inline constexpr int kMaxWholeDEParams = 48;
// Loop trips one DE call may run, all loops together: each loop condition also counts a shared
// trip counter, reset at every call, and fails once it passes this. Ten times the formula's own
// iteration cap (FRAKTAL_MAX_ITERATIONS): the frags' loops run their `Iterations` (at most a few
// hundred) times a handful of inner steps, and no preset can make a DE call run unbounded.
inline constexpr int kMaxWholeDELoopTrips = 10000;

// What the generator and the validation need to know of a whole DE's code.
struct WholeDEScan {
    std::vector<std::string> names;  // its top-level functions, globals, structs and #defines
    std::string deParameters;        // the parameter list of its `float DE(vec3 ...)`
    bool hasDE = false;
    bool hasInit = false;       // `void init()`: called before every DE call
    bool hasOrbitTrap = false;  // a global `orbitTrap`: reset to 10000 before every DE call, read as the trap
};

// The names a top-level declaration statement declares ("const float a = 1., b" -> a, b;
// "struct S { float x; }" -> S).
std::vector<std::string> declarationNames(std::string_view statement);

// Scans the code. Throws PresetError (file "estimator GLSL", "line N") for braces that do not balance.
WholeDEScan scanWholeDE(std::string_view glsl);

// Empty when the code is sound for a whole DE, else the reason, beginning with its line: no
// `uniform`, `buffer`, `layout`, `discard`, `main`, texture reads or `gl_` names; preprocessor
// lines limited to #define, #undef and conditionals; a `float DE(vec3 ...)`; `params` are the
// parameter names, which must not be declared again at the top level.
std::string wholeDEProblem(std::string_view glsl, std::span<const std::string> params);

// The code as the formula's shader compiles it: each top-level name N becomes `prefix + N`,
// each parameter P the result of `uniformOf(P)`, and every `for`/`while` condition also counts
// `tripCounter` up to kMaxWholeDELoopTrips. Comments and line breaks stay, so line numbers hold.
std::string wholeDEShaderCode(std::string_view glsl, const WholeDEScan& scan, std::string_view prefix,
                              const std::function<std::string(std::string_view)>& uniformOf,
                              std::span<const std::string> params, std::string_view tripCounter);

}  // namespace fraktal
