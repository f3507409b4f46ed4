// Fragmentarium / FragM shader files (.frag), read as FragM reads them: parsing alone, apart from
// what a frag means for a fraktal scene (the importer builds on this).
//
// A frag is GLSL with FragM's own directives on lines of their own: `#include "X"` (text
// inclusion), `#donotrun` (an include-only file), `#info TEXT`, `#camera NAME`, `#group NAME`
// (the panel of the uniforms after it), `#buffer FORMAT`, `#buffershader "X"` (a second pass),
// `#vertex` .. `#endvertex` (vertex-shader code), `#preset NAME` .. `#endpreset` (blocks of
// `key = value` lines), `#replace "a" "b"`, `#TexParameter`. A uniform declared on one line with an
// annotation after it (`uniform float X; slider[0,1,2]`) is a parameter of the GUI; the
// annotation is stripped from the GLSL. Everything else (`#define`, `#ifdef`, functions) is GLSL
// and stays in the text.
// Reference: ../shared/reference/fragmentarium-frag.md. FragM's Parser/Preprocessor.* defines the
// grammar; this is an independent implementation of it.
//
// Where this differs from FragM on purpose: directives and annotations inside /* */ comments are
// ignored (FragM reads lines regardless of comments); a malformed annotation, a missing
// #endpreset / #endvertex and an include that cannot be found are errors (FragM warns and goes
// on, and the shader then fails to compile or misses its parameter).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace fraktal::frag {

// One line of a source file: the index of the file in FragFile::files and its 1-based line.
struct SourceLine {
    int file = 0;
    int line = 0;
};

struct SourceFile {
    std::string name;            // for messages: the path as found, or "built-in NAME"
    std::filesystem::path path;  // empty for a built-in include
    bool builtin = false;
    std::string includeName;  // as written in the #include that brought it ("" for the main file)
};

// FragM's lock words. None: no word written (FragM's default, NotLocked).
enum class Lock { None, Locked, NotLocked, NotLockable, AlwaysLocked };
const char* lockName(Lock lock);  // "Locked", ...; "" for None

enum class UniformKind {
    Plain,       // no annotation: `uniform float time;` (host-supplied in FragM)
    Slider,      // slider[min,default,max], for float/double/int/vecN/dvecN (tuples `(a,b,c)` for vectors)
    Checkbox,    // checkbox[true|false], bool
    Color,       // color[r,g,b], vec3
    FloatColor,  // color[min,default,max,r,g,b], vec4: a colour and an intensity (xyz colour, w intensity)
    Menu,        // menu[default, item;item;...], int
    File,        // file[path] or file[path, channel], sampler2D / samplerCube / ...
};
const char* uniformKindName(UniformKind kind);

struct FragUniform {
    std::string type;  // as declared: "float", "int", "bool", "vec3", "dvec3", "sampler2D", ...
    std::string name;
    std::string arraySize;  // "[3]" for `uniform float a[3];`, else ""
    UniformKind kind = UniformKind::Plain;
    // Slider: one value per component (1 for float/int, N for vecN). FloatColor: the intensity
    // (one value each). Color: `value` holds r,g,b and minimum/maximum are empty.
    std::vector<double> minimum, value, maximum;
    std::vector<double> colour;  // FloatColor's r,g,b
    bool checked = false;        // Checkbox
    int menuDefault = 0;         // Menu
    std::vector<std::string> menuItems;
    std::string file;         // File: the path as written (not resolved)
    std::string fileChannel;  // File: the optional second argument
    Lock lock = Lock::None;
    bool logarithmic = false;  // slider's `Logarithmic`
    std::string tooltip;       // the `//` comment line just before the declaration (FragM shows the last one)
    std::string group;         // the #group in force ("" before any, and after an include ends, as in FragM)
    bool inVertex = false;     // declared inside #vertex .. #endvertex
    SourceLine where;
};

// A preset line `Key = value [Lock] [Logarithmic]`.
struct PresetValue {
    std::string key;
    std::string raw;   // the value as written, suffix included
    std::string text;  // the value without the lock and slider words
    Lock lock = Lock::None;
    bool logarithmic = false;
    std::vector<double> numbers;  // when `text` is numbers separated by commas ("1", "0.5,1,-2")
    std::optional<bool> boolean;  // when `text` is true/false (any case)
    SourceLine where;
};

struct FragPreset {
    std::string name;                                     // as written after #preset, trimmed
    std::vector<PresetValue> values;                      // in file order; FragM lets a later line of a key win
    std::vector<std::string> easing;                      // FragM's easing-curve lines (12 ':'-separated fields)
    SourceLine where;                                     // the #preset line
    bool keyFrame() const;                                // a "KeyFrame.NNN" preset of an animation
    const PresetValue* find(std::string_view key) const;  // the last line of `key`
};

struct FragDefine {
    std::string name, value;  // `#define NAME VALUE` (value "" when none; a macro's "(a,b) ..." is in value)
    SourceLine where;
};

struct FragDirective {
    std::string argument;  // what follows the directive word, trimmed (quotes removed for file names)
    SourceLine where;
};

// A top-level function of the fragment GLSL, found by a tokenizer that skips comments and
// preprocessor lines and balances braces (not a GLSL parser).
struct FragFunction {
    std::string returnType;  // the tokens before the name ("float", "vec3", "highp float")
    std::string name;
    std::string parameters;  // between the parentheses, whitespace collapsed ("vec3 pos", "inout vec3 z, float r")
    bool definition = true;  // false for a prototype (`void init();`)
    // Byte range in FragFile::glsl from the return type to the closing brace (or the ';').
    size_t begin = 0, end = 0;
    // 0-based lines of FragFile::glsl (glslLines maps them to the sources).
    int firstLine = 0, lastLine = 0;
};

// A top-level declaration statement other than a function (`mat3 rot;`, `const float k = 2.;`,
// `uniform float time;`, `varying vec3 from;`, `struct S {..};`).
struct FragGlobal {
    std::string text;  // whitespace collapsed, without the ';'
    size_t begin = 0, end = 0;
    int firstLine = 0;
};

struct FragWarning {
    SourceLine where;
    std::string message;
};

struct FragFile {
    std::vector<SourceFile> files;  // [0] the file parsed; then each include in the order it was met
    // The fragment shader's GLSL after preprocessing: includes expanded; presets and vertex
    // code taken out; FragM's directive lines kept as `// #directive ...` comments; annotations
    // stripped from uniform declarations. glslLines[i] is the source of line i (0-based).
    std::string glsl;
    std::vector<SourceLine> glslLines;
    std::string vertex;  // the #vertex .. #endvertex code of every file, in order
    std::vector<SourceLine> vertexLines;

    bool doNotRun = false;  // the parsed file itself says #donotrun
    std::vector<FragDirective> info, camera, buffer, bufferShaders, texParameters, groups;
    std::vector<std::pair<std::string, std::string>> replacements;  // #replace "from" "to", in order
    std::vector<FragDefine> defines;                                // active #define lines of the fragment GLSL
    std::set<std::string> provides;  // the `provides*` names #defined (providesInit, providesColor, ...)
    std::vector<FragUniform> uniforms;
    std::vector<FragPreset> presets;      // every #preset block, in file order (includes' too)
    std::vector<FragFunction> functions;  // top-level functions of the active fragment GLSL, in order
    std::vector<FragGlobal> globals;
    std::vector<FragWarning>
        warnings;  // what FragM would warn about and go on (a preset line that is not key = value, ...)

    std::string where(SourceLine line) const;   // "path/file.frag:12"
    SourceLine glslSource(int glslLine) const;  // the source of a 0-based line of `glsl`
    const FragUniform* findUniform(std::string_view name) const;
    const FragFunction* findFunction(std::string_view name) const;  // the first definition
    // `float DE(vec3 ...)`: the first definition named DE returning float whose first parameter
    // is a vec3 (the Slicer raytracer's DE(vec3 pos, int type) included). Null when none.
    const FragFunction* deFunction() const;
    std::string functionSource(const FragFunction& f) const { return glsl.substr(f.begin, f.end - f.begin); }
    // The preset FragM applies on load: among the preset names in sorted order (a later block of
    // a name replaces an earlier one), the first that contains "default" in any case. Null when none.
    const FragPreset* defaultPreset() const;
    const FragPreset* findPreset(std::string_view name) const;  // the last block of that name
};

struct FragOptions {
    // Searched, in order, for an `#include "X"` that is not next to the including file.
    std::vector<std::filesystem::path> includeDirs;
    // Then these: include name as written ("MathUtils.frag") -> its text.
    std::map<std::string, std::string, std::less<>> builtinIncludes;
    // Take a built-in include before any folder: fraktal's stand-ins for FragM's standard
    // includes then replace the files of a FragM install in an include folder.
    bool preferBuiltins = false;
    // The GLSL version `#if __VERSION__ ...` is evaluated at when the function finder picks
    // the active branches; 0: the frag's own #version, else 110 (GLSL's default without one).
    int glslVersion = 0;
};

// Parses a frag's text; `path` names it in messages and its folder is searched first for its
// includes. Throws PresetError naming the file (the included one where the fault is), "line N"
// and the reason: an include not found, an include cycle, an unterminated /* comment, a #preset
// without #endpreset, a #vertex without #endvertex, a malformed annotation, braces that do not
// balance, a file over the size limits.
FragFile parseFragFile(std::string_view text, const std::filesystem::path& path, const FragOptions& options = {});
FragFile loadFragFile(const std::filesystem::path& path, const FragOptions& options = {});

// Whether `path` names a Fragmentarium file by its extension (.frag, any case).
bool isFragPath(const std::filesystem::path& path);

// A number as FragM writes it ("1", "-0.5", ".5", "1e-3", "+2"); nothing for anything else.
std::optional<double> parseFragNumber(std::string_view text);

}  // namespace fraktal::frag
