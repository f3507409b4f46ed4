#include "core/import/frag_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "core/json_reader.hpp"

namespace fraktal::frag {

namespace {

constexpr int kMaxIncludeDepth = 32;
constexpr size_t kMaxExpandedBytes = 16 << 20;

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    return s;
}

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

bool equalsNoCase(std::string_view a, std::string_view b) { return a.size() == b.size() && lower(a) == lower(b); }

std::string lineField(int line) { return "line " + std::to_string(line); }

// Splits on \r\n, \r and \n, as FragM does.
std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n' || text[i] == '\r') {
            lines.push_back(text.substr(start, i - start));
            if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
            start = i + 1;
        }
    }
    if (start < text.size()) lines.push_back(text.substr(start));
    return lines;
}

// The line with its comments blanked out (same length, so offsets match the line), continuing
// a /* comment from the line before when `inBlock` is set; leaves `inBlock` set when a /* stays
// open at the end of the line. Text in "quotes" is kept as it is.
std::string blankComments(std::string_view line, bool& inBlock) {
    std::string code(line);
    bool inString = false;
    for (size_t i = 0; i < code.size(); ++i) {
        if (inBlock) {
            if (code[i] == '*' && i + 1 < code.size() && code[i + 1] == '/') {
                code[i] = code[i + 1] = ' ';
                ++i;
                inBlock = false;
            } else {
                code[i] = ' ';
            }
        } else if (inString) {
            if (code[i] == '"') inString = false;
        } else if (code[i] == '"') {
            inString = true;
        } else if (code[i] == '/' && i + 1 < code.size() && code[i + 1] == '/') {
            std::fill(code.begin() + long(i), code.end(), ' ');
            break;
        } else if (code[i] == '/' && i + 1 < code.size() && code[i + 1] == '*') {
            code[i] = code[i + 1] = ' ';
            ++i;
            inBlock = true;
        }
    }
    return code;
}

// "#word rest": the directive word (as written) and the rest, for a line whose code starts with '#'.
struct Directive {
    std::string word;
    std::string_view rest;
};

std::optional<Directive> directiveOf(std::string_view code) {
    code = trim(code);
    if (code.empty() || code.front() != '#') return std::nullopt;
    size_t i = 1;
    while (i < code.size() && (code[i] == ' ' || code[i] == '\t')) ++i;
    size_t start = i;
    while (i < code.size() && isIdentChar(code[i])) ++i;
    return Directive{std::string(code.substr(start, i - start)), trim(code.substr(i))};
}

// `"name"` -> name; nothing when the text is not one quoted string.
std::optional<std::string> quoted(std::string_view text) {
    text = trim(text);
    if (text.size() < 2 || text.front() != '"') return std::nullopt;
    const size_t close = text.find('"', 1);
    if (close == std::string_view::npos || !trim(text.substr(close + 1)).empty()) return std::nullopt;
    return std::string(text.substr(1, close - 1));
}

std::optional<Lock> lockOf(std::string_view word) {
    if (word == "Locked") return Lock::Locked;
    if (word == "NotLocked") return Lock::NotLocked;
    if (word == "NotLockable") return Lock::NotLockable;
    if (word == "AlwaysLocked") return Lock::AlwaysLocked;
    return std::nullopt;
}

std::vector<std::string_view> splitOn(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i) {
        if (i == text.size() || text[i] == separator) {
            parts.push_back(trim(text.substr(start, i - start)));
            start = i + 1;
        }
    }
    return parts;
}

std::optional<std::vector<double>> numberList(std::string_view text, size_t count) {
    const auto parts = splitOn(text, ',');
    if (parts.size() != count) return std::nullopt;
    std::vector<double> values;
    for (auto part : parts) {
        const auto v = parseFragNumber(part);
        if (!v) return std::nullopt;
        values.push_back(*v);
    }
    return values;
}

std::optional<int> parseInteger(std::string_view text) {
    text = trim(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

// `(a,b,c),(d,e,f),(g,h,i)`: `tuples` tuples of `size` numbers each.
std::optional<std::vector<std::vector<double>>> tupleList(std::string_view text, size_t tuples, size_t size) {
    std::vector<std::vector<double>> out;
    text = trim(text);
    while (!text.empty()) {
        if (text.front() != '(') return std::nullopt;
        const size_t close = text.find(')');
        if (close == std::string_view::npos) return std::nullopt;
        auto values = numberList(text.substr(1, close - 1), size);
        if (!values) return std::nullopt;
        out.push_back(std::move(*values));
        text = trim(text.substr(close + 1));
        if (text.empty()) break;
        if (text.front() != ',') return std::nullopt;
        text = trim(text.substr(1));
        if (text.empty()) return std::nullopt;
    }
    if (out.size() != tuples) return std::nullopt;
    return out;
}

int vectorSize(std::string_view type) {
    if (type == "float" || type == "double" || type == "int") return 1;
    if (type.size() == 4 && type.starts_with("vec") && type[3] >= '2' && type[3] <= '4') return type[3] - '0';
    if (type.size() == 5 && type.starts_with("dvec") && type[4] >= '2' && type[4] <= '4') return type[4] - '0';
    return 0;
}

// Whether `s` is well-formed UTF-8 (no overlong forms, surrogates or code points past U+10FFFF).
bool validUtf8(std::string_view s) {
    for (size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        const int more = c < 0x80                 ? 0
                         : c >= 0xC2 && c <= 0xDF ? 1
                         : (c & 0xF0) == 0xE0     ? 2
                         : c >= 0xF0 && c <= 0xF4 ? 3
                                                  : -1;
        if (more < 0 || i + size_t(more) >= s.size() + (more == 0 ? 1 : 0)) return false;
        for (int k = 1; k <= more; ++k)
            if ((static_cast<unsigned char>(s[i + size_t(k)]) & 0xC0) != 0x80) return false;
        if (more >= 2) {
            const auto next = static_cast<unsigned char>(s[i + 1]);
            if ((c == 0xE0 && next < 0xA0) || (c == 0xED && next >= 0xA0) || (c == 0xF0 && next < 0x90) ||
                (c == 0xF4 && next >= 0x90))
                return false;
        }
        i += size_t(more) + 1;
    }
    return true;
}

// Frags are UTF-8 or, as many artists' editors saved them, Latin-1: a text that is not UTF-8 is read
// as Latin-1, so that the names, tooltips and code a preset carries are UTF-8, as JSON must be (six
// community frags failed the import's JSON writer on a Latin-1 byte in a comment).
std::string asUtf8(std::string_view text) {
    if (validUtf8(text)) return std::string(text);
    std::string out;
    out.reserve(text.size() + text.size() / 8);
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x80) {
            out += ch;
        } else {
            out += char(0xC0 | (c >> 6));
            out += char(0x80 | (c & 0x3F));
        }
    }
    return out;
}

bool isSamplerType(std::string_view type) {
    return type == "sampler2D" || type == "samplerCube" || type == "isampler2D" || type == "usampler2D";
}

// Tokens joined with a space between words and after commas ("inout vec3 z, float r").
struct Token {
    std::string text;
    size_t pos = 0;
    int line = 0;
};

bool isWordToken(const std::string& t) { return !t.empty() && (isIdentChar(t.front()) || t.front() == '.'); }

std::string joinTokens(const std::vector<Token>& tokens, size_t from, size_t to) {
    std::string out;
    for (size_t i = from; i < to; ++i) {
        const std::string& t = tokens[i].text;
        if (!out.empty()) {
            const std::string& prev = tokens[i - 1].text;
            if ((isWordToken(prev) && isWordToken(t)) || prev == "," || prev == "=" || t == "=") out += ' ';
        }
        out += t;
    }
    return out;
}

bool isKeyword(const std::string& word) {
    static const std::set<std::string> keywords = {"if", "for", "while", "switch", "return", "else", "do"};
    return keywords.count(word) > 0;
}

class Preprocessor {
   public:
    Preprocessor(FragFile& out, const FragOptions& options) : out_(out), options_(options) {}

    void run(std::string_view text, const std::filesystem::path& path) {
        SourceFile main;
        main.path = path;
        main.name = path.string();
        out_.files.push_back(main);
        identities_[identity(path)] = 0;
        stack_.push_back(identity(path));
        readFile(text, 0, 0);
    }

   private:
    static std::string identity(const std::filesystem::path& path) {
        std::error_code ec;
        const auto canonical = std::filesystem::weakly_canonical(path, ec);
        return "file:" + (ec ? path.lexically_normal().string() : canonical.string());
    }

    [[noreturn]] void fail(int file, int line, const std::string& reason) const {
        throw PresetError(out_.files[size_t(file)].name, lineField(line), reason);
    }

    void emit(std::string_view text, SourceLine where) {
        expanded_ += text.size() + 1;
        if (expanded_ > kMaxExpandedBytes)
            fail(where.file, where.line,
                 "the frag expands to more than " + std::to_string(kMaxExpandedBytes >> 20) + " MiB with its includes");
        std::string& target = inVertex_ ? out_.vertex : out_.glsl;
        target.append(text);
        target.push_back('\n');
        (inVertex_ ? out_.vertexLines : out_.glslLines).push_back(where);
    }

    void emitDirectiveComment(std::string_view line, SourceLine where) { emit("// " + std::string(trim(line)), where); }

    void readFile(std::string_view text, int file, int depth) {
        const auto lines = splitLines(text);
        bool inBlock = false;
        int blockLine = 0;
        constexpr size_t kNone = size_t(-1);
        size_t preset = kNone;  // index of the open #preset block
        int vertexLine = 0;     // the #vertex line, when this file opened one
        for (size_t n = 0; n < lines.size(); ++n) {
            const int lineNo = int(n) + 1;
            const SourceLine where{file, lineNo};
            std::string line(lines[n]);
            if (preset != kNone) {
                if (lower(trim(line)).starts_with("#endpreset")) {
                    preset = kNone;
                } else {
                    presetLine(out_.presets[preset], line, where);
                }
                continue;
            }
            if (!lower(trim(line)).starts_with("#replace")) applyReplacements(line);
            const bool blockAtStart = inBlock;
            const std::string code = blankComments(line, inBlock);
            if (!blockAtStart && inBlock) blockLine = lineNo;
            const auto directive = directiveOf(code);
            std::string comment;
            if (!blockAtStart && trim(line).starts_with("//")) {
                std::string_view c = trim(line);
                while (!c.empty() && c.front() == '/') c.remove_prefix(1);
                comment = std::string(trim(c));
            }
            if (directive) {
                const std::string word = lower(directive->word);
                const std::string_view rest = directive->rest;
                if (word == "include") {
                    const auto name = quoted(rest);
                    if (!name) fail(file, lineNo, "#include needs a file name in quotes: " + std::string(trim(line)));
                    include(*name, where, depth);
                } else if (word == "preset") {
                    FragPreset p;
                    p.name = std::string(rest);
                    p.where = where;
                    out_.presets.push_back(std::move(p));
                    preset = out_.presets.size() - 1;
                } else if (word == "endpreset") {
                    out_.warnings.push_back({where, "#endpreset without #preset"});
                } else if (word == "vertex") {
                    if (inVertex_) fail(file, lineNo, "#vertex inside a #vertex section");
                    inVertex_ = true;
                    vertexLine = lineNo;
                } else if (word == "endvertex") {
                    if (!inVertex_) fail(file, lineNo, "#endvertex without #vertex");
                    inVertex_ = false;
                    vertexLine = 0;
                } else if (word == "buffershader") {
                    const auto name = quoted(rest);
                    if (!name) fail(file, lineNo, "#buffershader needs a file name in quotes");
                    out_.bufferShaders.push_back({*name, where});
                    emitDirectiveComment(line, where);
                } else if (word == "buffer") {
                    out_.buffer.push_back({std::string(rest), where});
                    emitDirectiveComment(line, where);
                } else if (word == "group") {
                    group_ = std::string(rest);
                    out_.groups.push_back({group_, where});
                    emitDirectiveComment(line, where);
                } else if (word == "info") {
                    out_.info.push_back({std::string(rest), where});
                    emitDirectiveComment(line, where);
                } else if (word == "camera") {
                    out_.camera.push_back({std::string(rest), where});
                    emitDirectiveComment(line, where);
                } else if (word == "donotrun") {
                    if (file == 0) out_.doNotRun = true;
                    emitDirectiveComment(line, where);
                } else if (word == "texparameter") {
                    out_.texParameters.push_back({std::string(rest), where});
                    emitDirectiveComment(line, where);
                } else if (word == "replace") {
                    replaceRule(rest, where);
                    emitDirectiveComment(line, where);
                } else {
                    emit(line, where);  // GLSL's own: #define, #ifdef, #version, #extension, ...
                }
                lastComment_.clear();
                continue;
            }
            const std::string_view codeView = trim(code);
            if (codeView.starts_with("uniform") && codeView.size() > 7 && isSpace(codeView[7])) {
                emit(uniformLine(line, code, where), where);
            } else {
                emit(line, where);
            }
            lastComment_ = comment;
        }
        if (inBlock) fail(file, blockLine, "a /* comment that is never closed");
        if (preset != kNone)
            fail(file, out_.presets[preset].where.line,
                 "#preset " + out_.presets[preset].name + " has no #endpreset before the end of the file");
        if (vertexLine != 0 && inVertex_)
            fail(file, vertexLine, "#vertex has no #endvertex before the end of the file");
        // FragM falls back to the default group after each file.
        group_.clear();
        lastComment_.clear();
    }

    void include(const std::string& name, SourceLine where, int depth) {
        if (depth + 1 > kMaxIncludeDepth)
            fail(where.file, where.line, "includes nest deeper than " + std::to_string(kMaxIncludeDepth));
        const SourceFile& from = out_.files[size_t(where.file)];
        std::vector<std::filesystem::path> looked;
        std::optional<std::filesystem::path> found;
        auto tryDir = [&](const std::filesystem::path& dir) {
            looked.push_back(dir.empty() ? std::filesystem::path(".") : dir);
            std::error_code ec;
            if (std::filesystem::is_regular_file(dir / name, ec)) found = dir / name;
        };
        const bool builtinFirst = options_.preferBuiltins && options_.builtinIncludes.count(name) > 0;
        if (!builtinFirst && !from.builtin && !from.path.empty()) tryDir(from.path.parent_path());
        for (size_t i = 0; !builtinFirst && !found && i < options_.includeDirs.size(); ++i)
            tryDir(options_.includeDirs[i]);
        std::string key, text;
        SourceFile source;
        source.includeName = name;
        if (found) {
            key = identity(*found);
            source.path = *found;
            source.name = found->string();
        } else if (const auto builtin = options_.builtinIncludes.find(name);
                   builtin != options_.builtinIncludes.end()) {
            key = "builtin:" + name;
            source.builtin = true;
            source.name = "built-in " + name;
            text = builtin->second;
        } else {
            std::string places;
            for (const auto& dir : looked) places += (places.empty() ? "" : ", ") + dir.string();
            fail(where.file, where.line,
                 "#include \"" + name + "\" not found (looked in " + (places.empty() ? "no folder" : places) +
                     (options_.builtinIncludes.empty() ? "" : ", and among the built-in includes") + ")");
        }
        if (std::find(stack_.begin(), stack_.end(), key) != stack_.end()) {
            std::string chain;
            bool on = false;
            for (size_t i = 0; i < stack_.size(); ++i) {
                if (stack_[i] == key) on = true;
                if (on) chain += out_.files[size_t(identities_.at(stack_[i]))].name + " -> ";
            }
            fail(where.file, where.line, "include cycle: " + chain + source.name);
        }
        if (found) text = asUtf8(readGuardedFile(*found));
        int index;
        if (const auto known = identities_.find(key); known != identities_.end()) {
            index = known->second;
        } else {
            index = int(out_.files.size());
            out_.files.push_back(source);
            identities_[key] = index;
        }
        stack_.push_back(key);
        readFile(text, index, depth + 1);
        stack_.pop_back();
    }

    void applyReplacements(std::string& line) const {
        for (const auto& [from, to] : out_.replacements) {
            if (from.empty()) continue;
            for (size_t at = line.find(from); at != std::string::npos; at = line.find(from, at + to.size()))
                line.replace(at, from.size(), to);
        }
    }

    void replaceRule(std::string_view rest, SourceLine where) {
        // "from" "to"
        rest = trim(rest);
        const size_t q1 = rest.find('"');
        const size_t q2 = q1 == std::string_view::npos ? q1 : rest.find('"', q1 + 1);
        const size_t q3 = q2 == std::string_view::npos ? q2 : rest.find('"', q2 + 1);
        const size_t q4 = q3 == std::string_view::npos ? q3 : rest.find('"', q3 + 1);
        if (q1 != 0 || q4 == std::string_view::npos || !trim(rest.substr(q4 + 1)).empty() ||
            !trim(rest.substr(q2 + 1, q3 - q2 - 1)).empty() || q2 == q1 + 1)
            fail(where.file, where.line, "#replace needs two strings in quotes: #replace \"from\" \"to\"");
        out_.replacements.emplace_back(std::string(rest.substr(q1 + 1, q2 - q1 - 1)),
                                       std::string(rest.substr(q3 + 1, q4 - q3 - 1)));
    }

    void presetLine(FragPreset& preset, std::string_view raw, SourceLine where) {
        const std::string_view s = trim(raw);
        if (s.empty() || s.starts_with("#")) return;
        if (std::count(s.begin(), s.end(), ':') == 11) {  // an easing curve: 12 fields
            preset.easing.emplace_back(s);
            return;
        }
        if (s.starts_with("//")) return;
        const auto parts = splitOn(s, '=');
        if (parts.size() != 2 || parts[0].empty()) {
            out_.warnings.push_back({where, "preset " + preset.name + ": not a `key = value` line: " + std::string(s)});
            return;
        }
        PresetValue v;
        v.key = std::string(parts[0]);
        v.raw = std::string(parts[1]);
        v.where = where;
        // Trailing words: the lock and the slider type, in either order.
        std::string_view text = trim(parts[1]);
        if (!text.empty() && text.back() == ';') text = trim(text.substr(0, text.size() - 1));
        for (;;) {
            const size_t space = text.find_last_of(" \t");
            if (space == std::string_view::npos) break;  // one word: the value itself
            const std::string_view last = text.substr(space + 1);
            if (const auto lock = lockOf(last))
                v.lock = *lock;
            else if (last == "Logarithmic")
                v.logarithmic = true;
            else if (last != "Linear")
                break;
            text = trim(text.substr(0, space));
        }
        v.text = std::string(trim(text));
        if (equalsNoCase(v.text, "true")) v.boolean = true;
        if (equalsNoCase(v.text, "false")) v.boolean = false;
        if (!v.text.empty()) {
            const auto parts2 = splitOn(v.text, ',');
            if (auto numbers = numberList(v.text, parts2.size())) v.numbers = std::move(*numbers);
        }
        preset.values.push_back(std::move(v));
    }

    // A line whose code starts with `uniform `: records the uniform(s) and returns the GLSL to
    // keep (the declaration without its annotation).
    std::string uniformLine(const std::string& line, const std::string& code, SourceLine where) {
        auto bad = [&](const std::string& reason) { fail(where.file, where.line, reason); };
        size_t i = code.find("uniform") + 7;
        auto skipSpace = [&] {
            while (i < code.size() && isSpace(code[i])) ++i;
        };
        auto identifier = [&] {
            skipSpace();
            const size_t start = i;
            if (i < code.size() && isIdentStart(code[i]))
                while (i < code.size() && isIdentChar(code[i])) ++i;
            return code.substr(start, i - start);
        };
        std::string type = identifier();
        while (type == "highp" || type == "mediump" || type == "lowp") type = identifier();
        if (type.empty()) return line;  // not a declaration this layer reads; GLSL will say
        std::vector<FragUniform> declared;
        for (;;) {
            FragUniform u;
            u.type = type;
            u.name = identifier();
            if (u.name.empty()) return line;  // e.g. an interface block `uniform Name {`: left to GLSL
            skipSpace();
            if (i < code.size() && code[i] == '[') {
                const size_t close = code.find(']', i);
                if (close == std::string::npos) return line;
                u.arraySize = code.substr(i, close - i + 1);
                i = close + 1;
                skipSpace();
            }
            u.group = group_;
            u.tooltip = lastComment_;
            u.inVertex = inVertex_;
            u.where = where;
            declared.push_back(std::move(u));
            if (i < code.size() && code[i] == '=') {  // an initialiser: plain
                const size_t semicolon = code.find(';', i);
                if (semicolon == std::string::npos) return line;
                i = semicolon;
            }
            if (i < code.size() && code[i] == ',') {
                ++i;
                continue;
            }
            break;
        }
        if (i >= code.size() || code[i] != ';') {
            const size_t bracket = code.find('[', i);
            if (bracket != std::string::npos) {
                for (const char* word : {"slider", "checkbox", "color", "menu", "file"})
                    if (trim(std::string_view(code).substr(i, bracket - i)) == word)
                        bad("a ';' is missing between " + declared.back().name + " and its " + word + "[...]");
            }
            for (auto& u : declared) out_.uniforms.push_back(std::move(u));
            return line;  // a declaration over several lines: plain
        }
        const size_t semicolon = i;
        ++i;
        skipSpace();
        // An annotation: word '[' ... ']' after the ';'.
        const std::string word = identifier();
        skipSpace();
        if (word.empty() || i >= code.size() || code[i] != '[') {
            for (auto& u : declared) out_.uniforms.push_back(std::move(u));
            return line;  // no annotation: GLSL after the ';' stays as written
        }
        if (declared.size() != 1 || !declared[0].arraySize.empty())
            bad("an annotation needs a single uniform, not a list or an array");
        FragUniform& u = declared[0];
        const size_t close = code.find(']', i);
        if (close == std::string::npos) bad("the " + word + "[ annotation of " + u.name + " has no closing ]");
        const std::string_view args = trim(std::string_view(code).substr(i + 1, close - i - 1));
        // After the ']': an optional slider type and lock word, and one stray character (FragM
        // accepts a trailing ';').
        std::string_view tail = trim(std::string_view(code).substr(close + 1));
        if (!tail.empty() && tail.back() == ';') tail = trim(tail.substr(0, tail.size() - 1));
        for (const auto w : splitOn(tail, ' ')) {
            if (w.empty()) continue;
            if (const auto lock = lockOf(w)) {
                u.lock = *lock;
            } else if (w == "Logarithmic" && word == "slider") {
                u.logarithmic = true;
            } else if (w == "Linear" && word == "slider") {
            } else {
                bad("unexpected '" + std::string(w) + "' after the " + word + "[...] of " + u.name +
                    " (expected Locked, NotLocked, NotLockable or AlwaysLocked)");
            }
        }
        const std::string what = word + "[" + std::string(args) + "] of " + u.type + " " + u.name;
        if (word == "slider") {
            const int size = vectorSize(u.type);
            if (size == 0) bad("a slider on a " + u.type + " uniform (" + u.name + ")");
            u.kind = UniformKind::Slider;
            if (u.type == "int") {
                const auto parts = splitOn(args, ',');
                std::vector<int> ints;
                for (auto p : parts)
                    if (auto v = parseInteger(p)) ints.push_back(*v);
                if (parts.size() != 3 || ints.size() != 3)
                    bad("bad " + what + ": an int slider needs three whole numbers [min,default,max]");
                u.minimum = {double(ints[0])};
                u.value = {double(ints[1])};
                u.maximum = {double(ints[2])};
            } else if (size == 1) {
                const auto values = numberList(args, 3);
                if (!values) bad("bad " + what + ": a slider needs three numbers [min,default,max]");
                u.minimum = {(*values)[0]};
                u.value = {(*values)[1]};
                u.maximum = {(*values)[2]};
            } else {
                const auto tuples = tupleList(args, 3, size_t(size));
                if (!tuples)
                    bad("bad " + what + ": a " + u.type + " slider needs three tuples of " + std::to_string(size) +
                        " numbers [(min),(default),(max)]");
                u.minimum = (*tuples)[0];
                u.value = (*tuples)[1];
                u.maximum = (*tuples)[2];
            }
        } else if (word == "checkbox") {
            if (u.type != "bool") bad("a checkbox on a " + u.type + " uniform (" + u.name + ")");
            u.kind = UniformKind::Checkbox;
            if (equalsNoCase(args, "true"))
                u.checked = true;
            else if (equalsNoCase(args, "false"))
                u.checked = false;
            else
                bad("bad " + what + ": a checkbox is true or false");
        } else if (word == "color") {
            const int size = vectorSize(u.type);
            if (size == 3) {
                const auto values = numberList(args, 3);
                if (!values) bad("bad " + what + ": a colour needs three numbers [r,g,b]");
                u.kind = UniformKind::Color;
                u.value = *values;
            } else if (size == 4) {
                const auto values = numberList(args, 6);
                if (!values) bad("bad " + what + ": a vec4 colour needs six numbers [min,default,max,r,g,b]");
                u.kind = UniformKind::FloatColor;
                u.minimum = {(*values)[0]};
                u.value = {(*values)[1]};
                u.maximum = {(*values)[2]};
                u.colour = {(*values)[3], (*values)[4], (*values)[5]};
            } else {
                bad("a colour on a " + u.type + " uniform (" + u.name + "): it needs a vec3 or a vec4");
            }
        } else if (word == "menu") {
            if (u.type != "int") bad("a menu on a " + u.type + " uniform (" + u.name + ")");
            const size_t comma = args.find(',');
            const auto def = comma == std::string_view::npos ? std::nullopt : parseInteger(args.substr(0, comma));
            if (!def) bad("bad " + what + ": a menu is [default, item;item;...]");
            u.kind = UniformKind::Menu;
            u.menuDefault = *def;
            for (const auto item : splitOn(args.substr(comma + 1), ';')) u.menuItems.emplace_back(item);
            if (u.menuItems.size() < 2 && u.menuItems[0].empty()) bad("bad " + what + ": the menu has no items");
        } else if (word == "file") {
            if (!isSamplerType(u.type)) bad("a file[] on a " + u.type + " uniform (" + u.name + ")");
            if (args.empty()) bad("bad " + what + ": no file name");
            u.kind = UniformKind::File;
            const size_t comma = args.find(',');
            u.file = std::string(trim(args.substr(0, comma)));
            if (comma != std::string_view::npos) u.fileChannel = std::string(trim(args.substr(comma + 1)));
        } else {
            bad("unknown annotation '" + word + "[' on " + u.name +
                " (FragM knows slider, checkbox, color, menu and file)");
        }
        out_.uniforms.push_back(u);
        return line.substr(0, semicolon + 1);
    }

    FragFile& out_;
    const FragOptions& options_;
    std::map<std::string, int> identities_;  // identity -> index in files
    std::vector<std::string> stack_;         // the identities of the files being read
    std::string group_;
    std::string lastComment_;
    bool inVertex_ = false;
    size_t expanded_ = 0;
};

// The top-level functions and declarations of the preprocessed GLSL, and its active #defines.
class Scanner {
   public:
    Scanner(FragFile& out, int version) : out_(out), text_(out.glsl) {
        // __VERSION__: the caller's, else the frag's own #version, else GLSL's default (110).
        version_ = version;
        if (version_ == 0) {
            // A view of the first line: the directive's words are views into it.
            const std::string_view firstLine = std::string_view(out.glsl).substr(0, out.glsl.find('\n'));
            const auto d = directiveOf(firstLine);
            if (d && d->word == "version") version_ = parseInteger(firstWord(d->rest)).value_or(110);
        }
        if (version_ == 0) version_ = 110;
    }

    void run() {
        size_t i = 0;
        bool lineStart = true;
        std::vector<Token> statement;
        bool inFunction = false;
        std::optional<Token> functionOpen;  // the '{' of the block at depth 1
        size_t functionIndex = 0;
        int depth = 0;
        while (i < text_.size()) {
            const char c = text_[i];
            if (c == '\n') {
                ++line_;
                lineStart = true;
                ++i;
                continue;
            }
            if (isSpace(c)) {
                ++i;
                continue;
            }
            if (c == '/' && i + 1 < text_.size() && text_[i + 1] == '/') {
                while (i < text_.size() && text_[i] != '\n') ++i;
                continue;
            }
            if (c == '/' && i + 1 < text_.size() && text_[i + 1] == '*') {
                const int startLine = line_;
                const size_t end = text_.find("*/", i + 2);
                if (end == std::string::npos) fail(startLine, "a /* comment that is never closed");
                for (size_t k = i; k < end; ++k)
                    if (text_[k] == '\n') ++line_;
                i = end + 2;
                continue;
            }
            if (c == '#' && lineStart) {
                i = preprocessorLine(i);
                continue;
            }
            lineStart = false;
            if (!active()) {
                ++i;
                continue;
            }
            if (c == '"') {
                ++i;
                while (i < text_.size() && text_[i] != '"' && text_[i] != '\n') ++i;
                if (i < text_.size() && text_[i] == '"') ++i;
                continue;
            }
            Token t;
            t.pos = i;
            t.line = line_;
            if (isIdentChar(c) || (c == '.' && i + 1 < text_.size() && std::isdigit((unsigned char)text_[i + 1]))) {
                size_t k = i;
                while (k < text_.size() && (isIdentChar(text_[k]) || text_[k] == '.')) ++k;
                t.text = text_.substr(i, k - i);
                i = k;
            } else {
                t.text = std::string(1, c);
                ++i;
            }
            if (t.text == "{") {
                if (depth == 0) {
                    functionOpen = t;
                    inFunction = functionShape(statement).has_value();
                    if (inFunction) {
                        const auto shape = *functionShape(statement);
                        FragFunction f;
                        f.returnType = joinTokens(statement, 0, shape.name);
                        f.name = statement[shape.name].text;
                        f.parameters = joinTokens(statement, shape.open + 1, statement.size() - 1);
                        f.begin = statement.front().pos;
                        f.firstLine = statement.front().line;
                        functionIndex = out_.functions.size();
                        out_.functions.push_back(f);
                    }
                }
                ++depth;
                if (!inFunction) statement.push_back(t);
                continue;
            }
            if (t.text == "}") {
                if (depth == 0) fail(t.line, "a '}' without a '{' before it");
                --depth;
                if (depth == 0 && inFunction) {
                    out_.functions[functionIndex].end = i;
                    out_.functions[functionIndex].lastLine = t.line;
                    inFunction = false;
                    functionOpen.reset();
                    statement.clear();
                    continue;
                }
                if (depth == 0) functionOpen.reset();
                if (!inFunction) statement.push_back(t);
                continue;
            }
            if (inFunction) continue;
            if (t.text == ";" && depth == 0) {
                if (!statement.empty()) {
                    if (const auto shape = functionShape(statement)) {
                        FragFunction f;
                        f.returnType = joinTokens(statement, 0, shape->name);
                        f.name = statement[shape->name].text;
                        f.parameters = joinTokens(statement, shape->open + 1, statement.size() - 1);
                        f.definition = false;
                        f.begin = statement.front().pos;
                        f.end = i;
                        f.firstLine = statement.front().line;
                        f.lastLine = t.line;
                        out_.functions.push_back(f);
                    } else {
                        FragGlobal g;
                        g.text = joinTokens(statement, 0, statement.size());
                        g.begin = statement.front().pos;
                        g.end = i;
                        g.firstLine = statement.front().line;
                        out_.globals.push_back(g);
                    }
                }
                statement.clear();
                continue;
            }
            statement.push_back(t);
        }
        if (depth > 0 && functionOpen) {
            std::string what = "a '{'";
            if (inFunction) what = "the '{' of " + out_.functions[functionIndex].name + "()";
            fail(functionOpen->line, what + " that is never closed");
        }
        if (!conditions_.empty())
            out_.warnings.push_back({out_.glslSource(conditions_.back().line), "an #if without #endif"});
    }

   private:
    struct Condition {
        bool parentActive;
        bool active;
        bool taken;  // a branch of this #if was taken already
        int line;
    };
    struct Shape {
        size_t name, open;
    };

    [[noreturn]] void fail(int glslLine, const std::string& reason) const {
        const SourceLine s = out_.glslSource(glslLine);
        throw PresetError(s.file < int(out_.files.size()) ? out_.files[size_t(s.file)].name : "", lineField(s.line),
                          reason);
    }

    bool active() const { return conditions_.empty() || conditions_.back().active; }

    // `[qualifiers] type name ( ... )` at the end of a top-level statement.
    static std::optional<Shape> functionShape(const std::vector<Token>& s) {
        if (s.size() < 4 || s.back().text != ")") return std::nullopt;
        int level = 0;
        size_t open = s.size();
        for (size_t k = s.size(); k-- > 0;) {
            if (s[k].text == ")") ++level;
            if (s[k].text == "(" && --level == 0) {
                open = k;
                break;
            }
        }
        if (open == s.size() || open < 2) return std::nullopt;
        const Token& name = s[open - 1];
        const Token& type = s[open - 2];
        if (!isIdentStart(name.text.front()) || isKeyword(name.text)) return std::nullopt;
        if (!(isIdentStart(type.text.front()) || type.text == "]") || isKeyword(type.text)) return std::nullopt;
        for (size_t k = 0; k + 2 < open; ++k)
            if (!isIdentStart(s[k].text.front())) return std::nullopt;  // `x = f(...)`, not a declaration
        if (s.front().text == "struct" || s.front().text == "uniform" || s.front().text == "layout")
            return std::nullopt;
        return Shape{open - 1, open};
    }

    // An #if / #elif expression as the GLSL preprocessor reads it: integers, macros (an unknown
    // name is 0), defined(X), __VERSION__, ! ( ) * / % + - < > <= >= == != && ||. An expression it
    // cannot read is taken as true, with a warning.
    bool evaluate(std::string_view expression, int line) {
        ExpressionReader reader{expression, 0, defined_, version_, 0};
        const auto value = reader.read();
        if (!value) {
            out_.warnings.push_back({out_.glslSource(line), "cannot evaluate #if " + std::string(trim(expression)) +
                                                                "; its first branch is taken as active"});
            return true;
        }
        return *value != 0;
    }

    struct ExpressionReader {
        std::string_view text;
        size_t at;
        const std::map<std::string, std::string>& macros;
        long version;
        int depth;

        std::optional<long> read() {
            auto v = binary(0);
            skip();
            if (!v || at != text.size()) return std::nullopt;
            return v;
        }
        void skip() {
            while (at < text.size() && isSpace(text[at])) ++at;
        }
        bool take(std::string_view op) {
            skip();
            if (text.substr(at).starts_with(op)) {
                at += op.size();
                return true;
            }
            return false;
        }
        std::string identifier() {
            skip();
            const size_t start = at;
            if (at < text.size() && isIdentStart(text[at]))
                while (at < text.size() && isIdentChar(text[at])) ++at;
            return std::string(text.substr(start, at - start));
        }
        // Precedence climbing over the binary operators, lowest level first.
        std::optional<long> binary(int level) {
            static const std::vector<std::vector<std::string_view>> levels = {
                {"||"}, {"&&"}, {"==", "!="}, {"<=", ">=", "<", ">"}, {"+", "-"}, {"*", "/", "%"}};
            if (level == int(levels.size())) return unary();
            auto left = binary(level + 1);
            for (;;) {
                if (!left) return std::nullopt;
                std::string_view op;
                for (auto candidate : levels[size_t(level)]) {
                    skip();
                    // '<' must not take the '<' of '<=', '|' and '&' are not operators here.
                    if (text.substr(at).starts_with(candidate)) {
                        op = candidate;
                        break;
                    }
                }
                if (op.empty()) return left;
                at += op.size();
                const auto right = binary(level + 1);
                if (!right) return std::nullopt;
                const long l = *left, r = *right;
                if (op == "||") left = long(l || r);
                if (op == "&&") left = long(l && r);
                if (op == "==") left = long(l == r);
                if (op == "!=") left = long(l != r);
                if (op == "<=") left = long(l <= r);
                if (op == ">=") left = long(l >= r);
                if (op == "<") left = long(l < r);
                if (op == ">") left = long(l > r);
                if (op == "+") left = l + r;
                if (op == "-") left = l - r;
                if (op == "*") left = l * r;
                if ((op == "/" || op == "%") && r == 0) return std::nullopt;
                if (op == "/") left = l / r;
                if (op == "%") left = l % r;
            }
        }
        std::optional<long> unary() {
            struct Nesting {
                int& depth;
                ~Nesting() { --depth; }
            } nesting{++depth};
            if (depth > 64) return std::nullopt;
            skip();
            if (take("!")) {
                const auto v = unary();
                return v ? std::optional<long>(!*v) : std::nullopt;
            }
            if (take("-")) {
                const auto v = unary();
                return v ? std::optional<long>(-*v) : std::nullopt;
            }
            if (take("(")) {
                const auto v = binary(0);
                if (!v || !take(")")) return std::nullopt;
                return v;
            }
            skip();
            if (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) {
                const size_t start = at;
                while (at < text.size() && isIdentChar(text[at])) ++at;
                return parseInteger(text.substr(start, at - start));
            }
            const std::string name = identifier();
            if (name.empty()) return std::nullopt;
            if (name == "defined") {
                const bool paren = take("(");
                const std::string macro = identifier();
                if (macro.empty() || (paren && !take(")"))) return std::nullopt;
                return long(macros.count(macro) > 0 || macro == "__VERSION__");
            }
            if (name == "__VERSION__") return version;
            const auto macro = macros.find(name);
            if (macro == macros.end()) return 0;  // an unknown name is 0, as in C
            if (macro->second.empty()) return std::nullopt;
            ExpressionReader inner{macro->second, 0, macros, version, depth};
            return inner.read();
        }
    };

    // Reads a preprocessor line (with its \ continuations) from `i`; returns the position after it.
    size_t preprocessorLine(size_t i) {
        const int startLine = line_;
        std::string text;
        while (i < text_.size() && text_[i] != '\n') {
            if (text_[i] == '\\' && i + 1 < text_.size() && text_[i + 1] == '\n') {
                ++line_;
                i += 2;
                continue;
            }
            text.push_back(text_[i++]);
        }
        bool inBlock = false;
        const std::string code = blankComments(text, inBlock);
        if (inBlock) {  // a /* that runs on past the line: continue in the main loop at its end
            const size_t end = text_.find("*/", i);
            if (end == std::string::npos) fail(startLine, "a /* comment that is never closed");
            for (size_t k = i; k < end; ++k)
                if (text_[k] == '\n') ++line_;
            i = end + 2;
        }
        const auto d = directiveOf(code);
        if (!d) return i;
        const std::string& w = d->word;
        const std::string_view rest = d->rest;
        if (w == "ifdef" || w == "ifndef" || w == "if") {
            const bool parent = active();
            bool value = true;
            if (parent) {
                if (w == "if")
                    value = evaluate(rest, startLine);
                else
                    value = (defined_.count(std::string(firstWord(rest))) > 0) == (w == "ifdef");
            }
            conditions_.push_back({parent, parent && value, parent && value, startLine});
        } else if (w == "elif") {
            if (conditions_.empty()) {
                out_.warnings.push_back({out_.glslSource(startLine), "#elif without #if"});
                return i;
            }
            Condition& c = conditions_.back();
            if (c.taken || !c.parentActive) {
                c.active = false;
            } else {
                c.active = evaluate(rest, startLine);
                c.taken = c.active;
            }
        } else if (w == "else") {
            if (conditions_.empty()) {
                out_.warnings.push_back({out_.glslSource(startLine), "#else without #if"});
                return i;
            }
            Condition& c = conditions_.back();
            c.active = c.parentActive && !c.taken;
            c.taken = true;
        } else if (w == "endif") {
            if (conditions_.empty())
                out_.warnings.push_back({out_.glslSource(startLine), "#endif without #if"});
            else
                conditions_.pop_back();
        } else if (!active()) {
        } else if (w == "define") {
            const std::string_view name = firstWord(rest);
            if (name.empty()) return i;
            std::string_view value = rest.substr(name.size());
            if (!value.empty() && value.front() != '(') value = trim(value);
            out_.defines.push_back({std::string(name), std::string(trim(value)), out_.glslSource(startLine)});
            defined_[std::string(name)] = std::string(trim(value));
            if (name.starts_with("provides")) out_.provides.insert(std::string(name));
        } else if (w == "undef") {
            defined_.erase(std::string(firstWord(rest)));
        }
        return i;
    }

    static std::string_view firstWord(std::string_view s) {
        s = trim(s);
        size_t k = 0;
        while (k < s.size() && isIdentChar(s[k])) ++k;
        return s.substr(0, k);
    }

    FragFile& out_;
    const std::string& text_;
    int line_ = 0;
    std::vector<Condition> conditions_;
    std::map<std::string, std::string> defined_;
    long version_ = 110;
};

}  // namespace

const char* lockName(Lock lock) {
    switch (lock) {
        case Lock::None: return "";
        case Lock::Locked: return "Locked";
        case Lock::NotLocked: return "NotLocked";
        case Lock::NotLockable: return "NotLockable";
        case Lock::AlwaysLocked: return "AlwaysLocked";
    }
    return "";
}

const char* uniformKindName(UniformKind kind) {
    switch (kind) {
        case UniformKind::Plain: return "plain";
        case UniformKind::Slider: return "slider";
        case UniformKind::Checkbox: return "checkbox";
        case UniformKind::Color: return "color";
        case UniformKind::FloatColor: return "floatcolor";
        case UniformKind::Menu: return "menu";
        case UniformKind::File: return "file";
    }
    return "";
}

bool FragPreset::keyFrame() const {
    const size_t at = name.find("KeyFrame.");
    return at != std::string::npos && at + 9 < name.size() && std::isdigit((unsigned char)name[at + 9]);
}

const PresetValue* FragPreset::find(std::string_view key) const {
    for (size_t k = values.size(); k-- > 0;)
        if (values[k].key == key) return &values[k];
    return nullptr;
}

std::string FragFile::where(SourceLine line) const {
    const std::string name = line.file >= 0 && size_t(line.file) < files.size() ? files[size_t(line.file)].name : "?";
    return name + ":" + std::to_string(line.line);
}

SourceLine FragFile::glslSource(int glslLine) const {
    if (glslLines.empty()) return {0, 0};
    const size_t k = std::min(size_t(std::max(glslLine, 0)), glslLines.size() - 1);
    return glslLines[k];
}

const FragUniform* FragFile::findUniform(std::string_view name) const {
    for (const auto& u : uniforms)
        if (u.name == name) return &u;
    return nullptr;
}

const FragFunction* FragFile::findFunction(std::string_view name) const {
    for (const auto& f : functions)
        if (f.definition && f.name == name) return &f;
    return nullptr;
}

const FragFunction* FragFile::deFunction() const {
    for (const auto& f : functions) {
        if (!f.definition || f.name != "DE") continue;
        const std::string type = f.returnType.substr(f.returnType.find_last_of(' ') + 1);
        const std::string first = f.parameters.substr(0, f.parameters.find(','));
        bool vec3 = false;
        for (size_t at = first.find("vec3"); at != std::string::npos; at = first.find("vec3", at + 1)) {
            const bool startOk = at == 0 || first[at - 1] == ' ';
            const bool endOk = at + 4 == first.size() || first[at + 4] == ' ';
            vec3 = vec3 || (startOk && endOk);
        }
        if (type == "float" && vec3) return &f;
    }
    return nullptr;
}

const FragPreset* FragFile::findPreset(std::string_view name) const {
    for (size_t k = presets.size(); k-- > 0;)
        if (presets[k].name == name) return &presets[k];
    return nullptr;
}

const FragPreset* FragFile::defaultPreset() const {
    std::map<std::string, size_t> byName;  // sorted as FragM's preset map; a later block replaces
    for (size_t k = 0; k < presets.size(); ++k) byName[presets[k].name] = k;
    for (const auto& [name, index] : byName)
        if (lower(name).find("default") != std::string::npos) return &presets[index];
    return nullptr;
}

std::optional<double> parseFragNumber(std::string_view text) {
    text = trim(text);
    if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
    if (text.empty()) return std::nullopt;
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

FragFile parseFragFile(std::string_view text, const std::filesystem::path& path, const FragOptions& options) {
    FragFile file;
    if (text.size() > kMaxDocumentBytes)
        throw PresetError(path.string(), "",
                          "file is larger than " + std::to_string(kMaxDocumentBytes >> 20) + " MiB; not a frag");
    const std::string utf8 = asUtf8(text);
    Preprocessor(file, options).run(utf8, path);
    Scanner(file, options.glslVersion).run();
    return file;
}

FragFile loadFragFile(const std::filesystem::path& path, const FragOptions& options) {
    return parseFragFile(readGuardedFile(path), path, options);
}

bool isFragPath(const std::filesystem::path& path) { return lower(path.extension().string()) == ".frag"; }

}  // namespace fraktal::frag
