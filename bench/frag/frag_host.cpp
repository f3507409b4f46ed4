// A minimal host for a Fragmentarium / FragM frag: runs the frag's own raytracer GLSL as written
// (its includes resolved, uniforms from their annotations' defaults and then the preset, 3D.frag's
// camera from its own #vertex code) for one sample per pixel, and writes the hit mask the frag's
// raytracer decides, with the DE evaluations it made per pixel. bench/frag/run.sh compares the
// mask with fraktal's render of the imported frag; bench/frag/README.md says what it measures.
//
// How the hit is observed without changing the raytracer: the frag's `trace()` (every FragM
// raytracer has one) is renamed and wrapped; the wrapper records the first call's verdict, which
// DE-Raytracer.frag gives as a non-zero `hitNormal` (zeroed on a miss) and the path tracers as
// their bool result. The user's `float DE(vec3)` is wrapped likewise to count its calls, and
// `main()` to write both to a float target after the frag's own main has run. A frag whose
// raytracer has no such trace() is reported, not guessed at.
//
// Frags are written on NVIDIA's compiler, which accepts what Mesa refuses by default; Mesa's own
// driconf switches for those are turned on (an #extension line after code, variables read before
// they are written, which read 0 there as on NVIDIA), as an artist's machine would run the frag.
//
// Usage: bench_frag_host FRAG [--include-dir DIR]... [--preset NAME] [--size WxH] [-o MASK.png]
//        [--colour IMAGE.png] (the frag's own colours, through its Exposure, ToneMapping and Gamma)
//        [--set NAME=V[,V...]]... (a uniform's value after the preset's)
//        [--dump-glsl FILE] (the vertex and the instrumented fragment GLSL, for reading)
// FRAKTAL_HOST_VERBOSE=1 prints each uniform's value and location on stderr.
// Prints one line: `KIND ok HIT_PIXELS DE_PER_PIXEL` (DE_PER_PIXEL "-" where the DE could not be
// wrapped), or `KIND fail REASON` (exit 1). KIND: `de` (a 3D camera and a `float DE(vec3)`),
// `inside` (a Brute-Raytracer `bool inside(vec3)` frag), `3d` (a 3D camera, neither), `2d` (no 3D
// camera), `?` (not read). The mask: RGBA, alpha 255 where the raytracer hit.
#include <epoxy/gl.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/gl/context.hpp"
#include "core/import/frag_builtins.hpp"
#include "core/import/frag_file.hpp"

namespace {

using namespace fraktal;
namespace fs = std::filesystem;

struct Edit {
    size_t at = 0, erase = 0;
    std::string insert;
};

// The parameter names of a parameter list "vec3 from, inout vec3 hitNormal".
std::vector<std::string> parameterNames(const std::string& parameters) {
    std::vector<std::string> names;
    static const std::regex last(R"((\w+)\s*(\[[^\]]*\])?\s*$)");
    size_t start = 0;
    while (start <= parameters.size()) {
        size_t comma = parameters.find(',', start);
        if (comma == std::string::npos) comma = parameters.size();
        const std::string one = parameters.substr(start, comma - start);
        std::smatch m;
        if (std::regex_search(one, m, last) && m[1] != "void") names.push_back(m[1]);
        start = comma + 1;
    }
    return names;
}

// Renames the function `f` (its name right before its '(') to `to`.
Edit renameFunction(const frag::FragFile& file, const frag::FragFunction& f, const std::string& to) {
    const std::string source = file.functionSource(f);
    const std::regex name("\\b" + f.name + "\\s*\\(");
    std::smatch m;
    if (!std::regex_search(source, m, name)) throw std::runtime_error("cannot find the name of " + f.name + "()");
    return {f.begin + size_t(m.position(0)), f.name.size(), to};
}

struct Program {
    std::string fragment;
    bool countsDe = false;
};

// The frag's fragment GLSL with trace(), DE() and main() wrapped (the header comment says why).
// With `ownColours`, the pixel stays the frag's own (3D.frag's accumulation (c w, w)): a program of
// its own, since the mask's leaves the frag's colour dead code for the compiler to drop (a skybox
// frag's samplerCube then never meets its sampler2D on one texture unit).
Program instrument(const frag::FragFile& file, bool ownColours = false) {
    std::vector<Edit> edits;
    const frag::FragFunction* trace = nullptr;
    const frag::FragFunction* mainFunction = nullptr;
    const frag::FragFunction* de = nullptr;
    for (const frag::FragFunction& f : file.functions) {
        if (!f.definition) continue;
        if (f.name == "trace" && !trace) trace = &f;
        if (f.name == "main") mainFunction = &f;
        // The one-vec3 DE the raytracers call; an `out` parameter or a second one is left alone.
        if (f.name == "DE" && f.returnType.ends_with("float") && !de &&
            std::regex_match(f.parameters, std::regex(R"((in\s+)?(highp\s+|mediump\s+)?vec3\s+\w+)")))
            de = &f;
    }
    if (!mainFunction) throw std::runtime_error("the frag has no main()");
    if (!trace) throw std::runtime_error("its raytracer has no trace() whose verdict the host can observe");
    const std::vector<std::string> names = parameterNames(trace->parameters);
    std::string verdict;
    if (trace->returnType.ends_with("bool"))
        verdict = "fraktalHostResult";
    else if (std::find(names.begin(), names.end(), "hitNormal") != names.end())
        verdict = "hitNormal != vec3(0.0)";
    else
        throw std::runtime_error("its trace(" + trace->parameters + ") gives no hit verdict (no hitNormal, not bool)");
    std::string call = "fraktalHostTrace(";
    for (size_t i = 0; i < names.size(); ++i) call += (i ? ", " : "") + names[i];
    call += ")";
    const bool isVoid = trace->returnType.ends_with("void");
    std::string wrapper = "\nbool fraktalHostTraced = false;\nbool fraktalHostHit = false;\n" + trace->returnType +
                          " trace(" + trace->parameters + ") {\n";
    wrapper += isVoid ? "\t" + call + ";\n" : "\t" + trace->returnType + " fraktalHostResult = " + call + ";\n";
    wrapper += "\tif (!fraktalHostTraced) { fraktalHostTraced = true; fraktalHostHit = " + verdict + "; }\n";
    wrapper += isVoid ? "}\n" : "\treturn fraktalHostResult;\n}\n";
    edits.push_back(renameFunction(file, *trace, "fraktalHostTrace"));
    edits.push_back({trace->end, 0, wrapper});
    edits.push_back(renameFunction(file, *mainFunction, "fraktalHostMain"));
    std::string tail = "\n";
    if (de) {
        // A prototype where the definition was: code after it may call DE without the raytracer's.
        edits.push_back({de->begin, 0, "float DE(vec3 fraktalHostP);\n"});
        edits.push_back(renameFunction(file, *de, "fraktalHostUserDE"));
        tail +=
            "int fraktalHostDeCount = 0;\nfloat DE(vec3 p) { fraktalHostDeCount++; return fraktalHostUserDE(p); }\n";
    }
    if (ownColours)
        tail += "void main() {\n\tfraktalHostMain();\n}\n";
    else
        tail += "void main() {\n\tfraktalHostMain();\n\tgl_FragColor = vec4(fraktalHostHit ? 1.0 : 0.0, " +
                std::string(de ? "float(fraktalHostDeCount)" : "-1.0") + ", fraktalHostTraced ? 1.0 : 0.0, 1.0);\n}\n";
    std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.at > b.at; });
    std::string glsl = file.glsl;
    for (const Edit& e : edits) glsl.replace(e.at, e.erase, e.insert);
    return {glsl + tail, de != nullptr};
}

// A shader's or program's info log (glGetShaderInfoLog / glGetProgramInfoLog).
template <class GetLog>
std::string infoLog(GLuint object, GetLog getLog) {
    std::string log(8192, '\0');
    getLog(object, GLsizei(log.size()), nullptr, log.data());
    log.resize(log.find('\0'));
    return log;
}

GLuint compile(GLenum kind, const std::string& source, const char* what) {
    const GLuint shader = glCreateShader(kind);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok)
        throw std::runtime_error(std::string(what) +
                                 " shader does not compile: " + infoLog(shader, glGetShaderInfoLog));
    return shader;
}

GLuint link(GLuint vertex, GLuint fragment) {
    const GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error("the program does not link: " + infoLog(program, glGetProgramInfoLog));
    return program;
}

// The value FragM gives a uniform: its annotation's default, then the preset's line (clamped to a
// slider's range, as FragM clamps). One number per component; a FloatColor is (r, g, b, intensity).
// Written apart from the importer's own (core/import/frag_import.cpp) on purpose: the bench proves
// the import, so it does not share the import's reading of the values.
std::vector<double> uniformValue(const frag::FragUniform& u, const frag::FragPreset* preset) {
    using K = frag::UniformKind;
    std::vector<double> v;
    switch (u.kind) {
        case K::Slider: v = u.value; break;
        case K::Checkbox: v = {u.checked ? 1.0 : 0.0}; break;
        case K::Color: v = u.value; break;
        case K::FloatColor: v = {u.colour.at(0), u.colour.at(1), u.colour.at(2), u.value.at(0)}; break;
        case K::Menu: v = {double(u.menuDefault)}; break;
        default: break;
    }
    const frag::PresetValue* line = preset ? preset->find(u.name) : nullptr;
    if (line) {
        if (line->boolean)
            v = {*line->boolean ? 1.0 : 0.0};
        else if (!line->numbers.empty())
            v = line->numbers;
    }
    // FragM's editor holds a slider's value in a spin box of the slider's range. A vec3 or vec4
    // slider declared with its minimum equal to its maximum (3D.frag's Up:
    // slider[(0,0,0),(0,1,0),(0,0,0)]) gets the range [-1, 1] in each component (GUI/FloatWidget.cpp);
    // a spin box whose minimum is above its maximum raises the maximum to the minimum (Qt).
    if (u.kind == K::Slider) {
        const bool direction = (u.type.ends_with("vec3") || u.type.ends_with("vec4")) && u.minimum == u.maximum;
        for (size_t i = 0; i < v.size() && i < u.minimum.size() && i < u.maximum.size(); ++i) {
            const double lo = direction ? -1.0 : u.minimum[i];
            const double hi = direction ? 1.0 : std::max(u.maximum[i], u.minimum[i]);
            v[i] = std::min(std::max(v[i], lo), hi);
        }
    }
    if (u.kind == K::FloatColor && v.size() == 4 && !u.minimum.empty() && !u.maximum.empty())
        v[3] = std::clamp(v[3], u.minimum[0], u.maximum[0]);
    return v;
}

void setUniform(GLuint program, const frag::FragUniform& u, const std::vector<double>& v) {
    const GLint at = glGetUniformLocation(program, u.name.c_str());
    if (at < 0 || v.empty()) return;  // optimised away, or a kind that has no value (a sampler)
    auto f = [&](size_t i) { return GLfloat(i < v.size() ? v[i] : 0.0); };
    auto n = [&](size_t i) { return GLint(std::lround(i < v.size() ? v[i] : 0.0)); };
    const std::string& t = u.type;
    if (t == "float" || t == "double")
        glUniform1f(at, f(0));
    else if (t == "vec2" || t == "dvec2")
        glUniform2f(at, f(0), f(1));
    else if (t == "vec3" || t == "dvec3")
        glUniform3f(at, f(0), f(1), f(2));
    else if (t == "vec4" || t == "dvec4")
        glUniform4f(at, f(0), f(1), f(2), f(3));
    else if (t == "int" || t == "bool")
        glUniform1i(at, n(0));
    else if (t == "ivec2")
        glUniform2i(at, n(0), n(1));
    else if (t == "ivec3")
        glUniform3i(at, n(0), n(1), n(2));
}

struct Options;
GLuint useProgram(const frag::FragFile& file, const Program& program, const Options& o, const frag::FragPreset* preset);
void writeOwnColours(const Options& o, const frag::FragFile& file, const frag::FragPreset* preset);

struct Options {
    fs::path frag, out, dump, colour;
    std::vector<fs::path> includeDirs;
    std::string preset;
    std::vector<std::pair<std::string, std::vector<double>>> set;  // --set NAME=V[,V...]: after the preset
    int width = 160, height = 120;
};

Options parseArguments(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
            return argv[++i];
        };
        if (a == "--include-dir")
            o.includeDirs.push_back(next());
        else if (a == "--preset")
            o.preset = next();
        else if (a == "-o")
            o.out = next();
        else if (a == "--colour")
            o.colour = next();
        else if (a == "--dump-glsl")
            o.dump = next();
        else if (a == "--set") {
            const std::string kv = next();
            const size_t eq = kv.find('=');
            if (eq == std::string::npos) throw std::runtime_error("--set wants NAME=VALUE[,VALUE...]");
            std::vector<double> v;
            for (size_t at = eq + 1; at <= kv.size();) {
                size_t comma = kv.find(',', at);
                if (comma == std::string::npos) comma = kv.size();
                v.push_back(std::stod(kv.substr(at, comma - at)));
                at = comma + 1;
            }
            o.set.emplace_back(kv.substr(0, eq), v);
        } else if (a == "--size") {
            if (std::sscanf(next().c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1)
                throw std::runtime_error("--size wants WxH");
        } else if (o.frag.empty())
            o.frag = a;
        else
            throw std::runtime_error("unexpected argument " + a);
    }
    if (o.frag.empty())
        throw std::runtime_error(
            "usage: bench_frag_host FRAG [--include-dir DIR]... [--preset NAME] [--size WxH] [-o MASK.png]");
    return o;
}

// What kind of frag this is, for the bench's counts (printed first, also on a failure).
std::string fragKind = "?";

std::string kindOf(const frag::FragFile& file) {
    const bool camera3d = std::any_of(file.camera.begin(), file.camera.end(), [](const frag::FragDirective& d) {
        return d.argument.find("3D") != std::string::npos;
    });
    if (!camera3d) return "2d";
    if (file.deFunction()) return "de";
    if (file.findFunction("inside")) return "inside";
    return "3d";
}

// One frame of the program in use: FragM's full-screen quad, the projection matrix left the identity
// (no 2D zoom in 3D), read back as RGBA floats, rows from the bottom.
std::vector<float> drawFrame(int width, int height) {
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
    std::vector<float> pixels(size_t(width) * size_t(height) * 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, pixels.data());
    if (const GLenum e = glGetError(); e != GL_NO_ERROR) throw std::runtime_error("GL error " + std::to_string(e));
    return pixels;
}

// The frag's own picture, drawn a second time with the frag's gl_FragColor kept, to hold fraktal's
// look against (bench/frag/README.md, "Shading"). The backbuffer reads 0 (a black texture on
// unit 0), so a pixel is 3D.frag's (c w, w) and c its colour. BufferShader's pass is done here:
// Exposure, the tone curve (1 linear, 2 exponential, 3 filmic, the others as 4, Reinhard), then
// 1 / Gamma.
// Compiles and links the frag's vertex code and `program`, and sets every uniform as FragM would.
GLuint useProgram(const frag::FragFile& file, const Program& program, const Options& o,
                  const frag::FragPreset* preset) {
    const std::string vertex = file.vertex.empty() ? "void main() { gl_Position = gl_Vertex; }\n" : file.vertex;
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex, "the vertex");
    const GLuint fs = compile(GL_FRAGMENT_SHADER, program.fragment, "the fragment");
    const GLuint prog = link(vs, fs);
    glUseProgram(prog);
    for (const frag::FragUniform& u : file.uniforms) {
        std::vector<double> v = uniformValue(u, preset);
        for (const auto& [name, value] : o.set)
            if (name == u.name) v = value;
        if (std::getenv("FRAKTAL_HOST_VERBOSE")) {
            std::fprintf(stderr, "%s %s (%s):", u.type.c_str(), u.name.c_str(), frag::uniformKindName(u.kind));
            for (double x : v) std::fprintf(stderr, " %g", x);
            std::fprintf(stderr, " at %d\n", glGetUniformLocation(prog, u.name.c_str()));
        }
        setUniform(prog, u, v);
    }
    // What FragM itself sets: the pixel's size (1 / the viewport), a still's time, the first frame.
    if (GLint at = glGetUniformLocation(prog, "pixelSize"); at >= 0)
        glUniform2f(at, 1.0f / float(o.width), 1.0f / float(o.height));
    if (GLint at = glGetUniformLocation(prog, "time"); at >= 0) glUniform1f(at, 0.0f);
    if (GLint at = glGetUniformLocation(prog, "subframe"); at >= 0) glUniform1i(at, 1);
    return prog;
}

void writeOwnColours(const Options& o, const frag::FragFile& file, const frag::FragPreset* preset) {
    auto setting = [&](const char* name, double fallback) {
        const frag::FragUniform* u = file.findUniform(name);
        const std::vector<double> v = u ? uniformValue(*u, preset) : std::vector<double>{};
        return v.empty() ? fallback : v[0];
    };
    const double exposure = setting("Exposure", 1.0), gamma = std::max(setting("Gamma", 2.0), 0.1);
    const int tone = int(std::lround(setting("ToneMapping", 4.0)));
    GLuint black = 0;
    const float zero[4] = {0, 0, 0, 0};
    glGenTextures(1, &black);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, black);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, zero);
    useProgram(file, instrument(file, true), o, preset);
    const std::vector<float> pixels = drawFrame(o.width, o.height);
    std::vector<unsigned char> image(pixels.size());
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            const float* p = &pixels[(size_t(y) * size_t(o.width) + size_t(x)) * 4];
            unsigned char* q = &image[(size_t(o.height - 1 - y) * size_t(o.width) + size_t(x)) * 4];
            for (int k = 0; k < 3; ++k) {
                double c = p[3] > 0.0f ? double(p[k]) / double(p[3]) : 0.0;
                c = std::max(c, 0.0) * exposure;
                if (tone == 3) {  // filmic (Hejl, Burgess-Dawson), its own gamma of 2.2 raised back
                    const double x = std::max(c - 0.004, 0.0);
                    c = std::pow(x * (6.2 * x + 0.5) / (x * (6.2 * x + 1.7) + 0.06), 2.2);
                } else if (tone != 1) {
                    c = tone == 2 ? 1.0 - std::exp(-c) : c / (1.0 + c);
                }
                q[k] = (unsigned char)std::lround(255.0 * std::pow(std::clamp(c, 0.0, 1.0), 1.0 / gamma));
            }
            q[3] = 255;
        }
    if (!stbi_write_png(o.colour.c_str(), o.width, o.height, 4, image.data(), o.width * 4))
        throw std::runtime_error("cannot write " + o.colour.string());
}

}  // namespace

int main(int argc, char** argv) try {
    const Options o = parseArguments(argc, argv);
    // FragM's own includes come from the folders given; fraktal's stand-ins only fill in for an
    // include none of them has (the tests' frags, run without a FragM install).
    frag::FragOptions parse;
    parse.includeDirs = o.includeDirs;
    parse.builtinIncludes = frag::builtinIncludes();
    const frag::FragFile file = frag::loadFragFile(o.frag, parse);
    fragKind = kindOf(file);
    if (file.doNotRun) throw std::runtime_error("an include-only file (#donotrun)");
    if (fragKind == "2d") throw std::runtime_error("a 2D frag");
    const frag::FragPreset* preset = o.preset.empty() ? file.defaultPreset() : file.findPreset(o.preset);
    if (!o.preset.empty() && !preset) throw std::runtime_error("no preset named " + o.preset);
    if (!preset)  // as the import chooses: FragM's "default", else the first that is not a key frame
        for (const frag::FragPreset& p : file.presets)
            if (!p.keyFrame()) {
                preset = &p;
                break;
            }
    const Program program = instrument(file);
    if (!o.dump.empty()) {
        std::FILE* out = std::fopen(o.dump.c_str(), "w");
        if (!out) throw std::runtime_error("cannot write " + o.dump.string());
        std::fprintf(out, "// vertex\n%s\n// fragment\n%s", file.vertex.c_str(), program.fragment.c_str());
        std::fclose(out);
    }

    setenv("allow_glsl_extension_directive_midshader", "true", 0);
    setenv("glsl_zero_init", "true", 0);
    setenv("force_glsl_version", "130", 0);
    setenv("allow_glsl_builtin_variable_redeclaration", "true", 0);
    const auto context = gl::HeadlessContext::create(gl::HeadlessContext::Profile::Compatibility);
    useProgram(file, program, o, preset);

    GLuint texture = 0, fbo = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, o.width, o.height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glViewport(0, 0, o.width, o.height);
    glDisable(GL_DEPTH_TEST);
    glClearColor(0, 0, 0, 0);
    const std::vector<float> pixels = drawFrame(o.width, o.height);

    long hits = 0, traced = 0;
    double deCalls = 0;
    std::vector<unsigned char> mask(size_t(o.width) * size_t(o.height) * 4, 0);
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            const float* p = &pixels[(size_t(y) * size_t(o.width) + size_t(x)) * 4];
            const bool hit = p[0] >= 0.5f;
            hits += hit, traced += p[2] >= 0.5f, deCalls += std::max(0.0f, p[1]);
            // GL's rows start at the bottom; the mask's at the top, as fraktal's images.
            unsigned char* m = &mask[(size_t(o.height - 1 - y) * size_t(o.width) + size_t(x)) * 4];
            m[0] = m[1] = m[2] = m[3] = hit ? 255 : 0;
        }
    if (traced == 0) throw std::runtime_error("its main() never called trace()");
    if (!o.colour.empty()) writeOwnColours(o, file, preset);
    if (!o.out.empty() && !stbi_write_png(o.out.c_str(), o.width, o.height, 4, mask.data(), o.width * 4))
        throw std::runtime_error("cannot write " + o.out.string());
    const double pixelCount = double(o.width) * double(o.height);
    if (program.countsDe)
        std::printf("%s ok %ld %.2f\n", fragKind.c_str(), hits, deCalls / pixelCount);
    else
        std::printf("%s ok %ld -\n", fragKind.c_str(), hits);
    return 0;
} catch (const std::exception& e) {
    std::string why = e.what();
    std::replace(why.begin(), why.end(), '\n', ' ');
    std::replace(why.begin(), why.end(), '\t', ' ');
    std::printf("%s fail %s\n", fragKind.c_str(), why.c_str());
    return 1;
}
