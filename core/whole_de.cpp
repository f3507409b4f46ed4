#include "core/whole_de.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "core/preset.hpp"

namespace fraktal {

namespace {

bool startsGlslName(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool continuesGlslName(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The end of the comment starting at i, or i when none starts there.
size_t commentEnd(std::string_view s, size_t i) {
    if (i + 1 >= s.size() || s[i] != '/') return i;
    if (s[i + 1] == '/') {
        const size_t end = s.find('\n', i);
        return end == std::string_view::npos ? s.size() : end;
    }
    if (s[i + 1] == '*') {
        const size_t end = s.find("*/", i + 2);
        return end == std::string_view::npos ? s.size() : end + 2;
    }
    return i;
}

// The end of the number starting at i (digits, '.', an exponent with its sign, a suffix).
size_t numberEnd(std::string_view s, size_t i) {
    while (i < s.size()) {
        const char c = s[i];
        if (continuesGlslName(c) || c == '.')
            ++i;
        else if ((c == '+' || c == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E'))
            ++i;
        else
            break;
    }
    return i;
}

// The index of the ')' matching the '(' at `open`, skipping comments; npos when none.
size_t matchingParen(std::string_view s, size_t open) {
    int depth = 0;
    for (size_t i = open; i < s.size(); ++i) {
        if (const size_t c = commentEnd(s, i); c != i) {
            i = c - 1;
            continue;
        }
        if (s[i] == '(') ++depth;
        if (s[i] == ')' && --depth == 0) return i;
    }
    return std::string_view::npos;
}

}  // namespace

std::vector<std::string> declarationNames(std::string_view text) {
    static const std::set<std::string, std::less<>> qualifiers{
        "const", "highp", "mediump", "lowp", "precise", "invariant", "flat", "smooth", "noperspective"};
    std::vector<std::string> words;
    std::vector<std::string> names;
    size_t i = 0;
    auto nextWord = [&]() -> std::string {
        while (i < text.size() && !startsGlslName(text[i])) ++i;
        const size_t from = i;
        while (i < text.size() && continuesGlslName(text[i])) ++i;
        return std::string(text.substr(from, i - from));
    };
    std::string word = nextWord();
    while (qualifiers.count(word)) word = nextWord();
    if (word == "struct") {
        names.push_back(nextWord());
        return names;
    }
    // `word` is the type; then declarators separated by commas at depth 0, each starting with
    // its name.
    bool expectName = true;
    int depth = 0;
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '(' || c == '[' || c == '{') ++depth;
        if (c == ')' || c == ']' || c == '}') --depth;
        if (c == ',' && depth == 0) expectName = true;
        if (expectName && depth == 0 && startsGlslName(c)) {
            const size_t from = i;
            while (i < text.size() && continuesGlslName(text[i])) ++i;
            names.emplace_back(text.substr(from, i - from));
            expectName = false;
            --i;
        }
    }
    return names;
}

namespace {

// GLSL's texture and image functions and types (texture2D, texelFetch, sampler2D, imageLoad,
// ...): a prefix followed by nothing, a digit or a capital, so that a name such as textured stays.
bool isTextureWord(std::string_view word) {
    for (std::string_view prefix :
         {"texture", "texel", "sampler", "isampler", "usampler", "image", "iimage", "uimage"}) {
        if (!word.starts_with(prefix)) continue;
        if (word.size() == prefix.size()) return true;
        const char next = word[prefix.size()];
        if (std::isdigit(static_cast<unsigned char>(next)) || std::isupper(static_cast<unsigned char>(next)))
            return true;
    }
    return false;
}

std::string lineAt(std::string_view s, size_t pos) {
    return "line " + std::to_string(1 + std::count(s.begin(), s.begin() + std::min(pos, s.size()), '\n'));
}

}  // namespace

WholeDEScan scanWholeDE(std::string_view glsl) {
    // A tokenizer over the top level, not a GLSL parser: statements at brace depth 0 are
    // declarations, a `type name(...)` followed by a body or ';' is a function. #define names
    // count whatever #if they sit under (renaming an inactive one changes nothing).
    WholeDEScan scan;
    std::set<std::string> seen;
    auto add = [&](std::string name) {
        if (!name.empty() && seen.insert(name).second) scan.names.push_back(std::move(name));
    };
    std::vector<std::string> statement;  // the tokens of the top-level statement so far
    std::string text;                    // and its text
    int line = 1;
    bool lineStart = true;
    // The function a statement declares: its name's index, or -1 (`T name ( ... )`).
    auto functionName = [&]() -> int {
        for (size_t k = 1; k + 1 < statement.size(); ++k)
            if (statement[k + 1] == "(" && startsGlslName(statement[k][0]) && startsGlslName(statement[k - 1][0]) &&
                statement.back() == ")" && statement[0] != "struct")
                return int(k);
        return -1;
    };
    auto recordFunction = [&](int k, bool definition) {
        const std::string name = statement[size_t(k)];
        add(name);
        std::string returnType;
        for (int i = 0; i < k; ++i) returnType += (i ? " " : "") + statement[size_t(i)];
        const size_t open = text.find('(');
        std::string parameters = text.substr(open + 1, text.rfind(')') - open - 1);
        parameters.erase(0, parameters.find_first_not_of(" \t\n"));
        parameters.erase(parameters.find_last_not_of(" \t\n") + 1);
        if (!definition) return;
        if (name == "init" && returnType == "void" && (parameters.empty() || parameters == "void")) scan.hasInit = true;
        if (name == "DE" && returnType.ends_with("float") && parameters.starts_with("vec3")) {
            scan.hasDE = true;
            scan.deParameters = parameters;
        }
    };
    for (size_t i = 0; i < glsl.size();) {
        if (const size_t c = commentEnd(glsl, i); c != i) {
            line += int(std::count(glsl.begin() + i, glsl.begin() + c, '\n'));
            i = c;
            continue;
        }
        const char ch = glsl[i];
        if (ch == '\n') {
            ++line;
            lineStart = true;
            ++i;
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(ch))) {
            ++i;
            continue;
        }
        if (ch == '#' && lineStart) {
            size_t end = i;
            while (end < glsl.size() && glsl[end] != '\n') end += glsl[end] == '\\' ? 2 : 1;
            std::string_view directive = glsl.substr(i + 1, end - i - 1);
            directive.remove_prefix(std::min(directive.find_first_not_of(" \t"), directive.size()));
            if (directive.starts_with("define")) {
                directive.remove_prefix(6);
                directive.remove_prefix(std::min(directive.find_first_not_of(" \t"), directive.size()));
                size_t n = 0;
                while (n < directive.size() && continuesGlslName(directive[n])) ++n;
                add(std::string(directive.substr(0, n)));
            }
            line += int(std::count(glsl.begin() + i, glsl.begin() + end, '\n'));
            i = end;
            continue;
        }
        lineStart = false;
        if (ch == '{' && !statement.empty() && functionName() >= 0) {
            recordFunction(functionName(), true);
            int depth = 0;
            for (; i < glsl.size(); ++i) {
                if (const size_t c = commentEnd(glsl, i); c != i) {
                    line += int(std::count(glsl.begin() + i, glsl.begin() + c, '\n'));
                    i = c - 1;
                    continue;
                }
                if (glsl[i] == '\n') ++line;
                if (glsl[i] == '{') ++depth;
                if (glsl[i] == '}' && --depth == 0) break;
            }
            if (depth != 0)
                throw PresetError("estimator GLSL", "line " + std::to_string(line), "a '{' that is never closed");
            ++i;
            statement.clear();
            text.clear();
            continue;
        }
        if (ch == '}' &&
            std::count(statement.begin(), statement.end(), "{") <= std::count(statement.begin(), statement.end(), "}"))
            throw PresetError("estimator GLSL", "line " + std::to_string(line), "a '}' without a '{' before it");
        if (ch == ';' && std::count(statement.begin(), statement.end(), "{") ==
                             std::count(statement.begin(), statement.end(), "}")) {
            if (const int k = functionName(); k >= 0)
                recordFunction(k, false);
            else if (!statement.empty())
                for (std::string& name : declarationNames(text)) {
                    if (name == "orbitTrap") scan.hasOrbitTrap = true;
                    add(std::move(name));
                }
            statement.clear();
            text.clear();
            ++i;
            continue;
        }
        size_t j = i + 1;
        if (startsGlslName(ch) || std::isdigit(static_cast<unsigned char>(ch)))
            while (j < glsl.size() && (continuesGlslName(glsl[j]) || glsl[j] == '.')) ++j;
        statement.emplace_back(glsl.substr(i, j - i));
        text += (text.empty() ? "" : " ") + std::string(glsl.substr(i, j - i));
        i = j;
    }
    if (std::count(statement.begin(), statement.end(), "{") != std::count(statement.begin(), statement.end(), "}"))
        throw PresetError("estimator GLSL", "line " + std::to_string(line), "a '{' that is never closed");
    return scan;
}

std::string wholeDEProblem(std::string_view glsl, std::span<const std::string> params) {
    static const std::set<std::string, std::less<>> forbidden{
        "uniform", "buffer", "layout", "shared", "discard", "main", "varying", "attribute", "barrier", "subroutine"};
    static const std::set<std::string, std::less<>> directives{"define", "undef", "if",   "ifdef",
                                                               "ifndef", "elif",  "else", "endif"};
    bool lineStart = true;
    for (size_t i = 0; i < glsl.size();) {
        if (const size_t c = commentEnd(glsl, i); c != i) {
            i = c;
            continue;
        }
        const char ch = glsl[i];
        if (ch == '\n') lineStart = true;
        if (ch == '#') {
            if (!lineStart) return lineAt(glsl, i) + ": '#' is allowed only at the start of a preprocessor line";
            size_t j = i + 1;
            while (j < glsl.size() && (glsl[j] == ' ' || glsl[j] == '\t')) ++j;
            size_t k = j;
            while (k < glsl.size() && continuesGlslName(glsl[k])) ++k;
            const std::string_view word = glsl.substr(j, k - j);
            if (!directives.count(word))
                return lineAt(glsl, i) + ": '#" + std::string(word) +
                       "' is not allowed in a whole DE (only #define, #undef and "
                       "#if/#ifdef/#ifndef/#elif/#else/#endif)";
            i = k;
            lineStart = false;
            continue;
        }
        if (!std::isspace(static_cast<unsigned char>(ch))) lineStart = false;
        if (std::isdigit(static_cast<unsigned char>(ch))) {
            i = numberEnd(glsl, i);
            continue;
        }
        if (startsGlslName(ch)) {
            size_t j = i;
            while (j < glsl.size() && continuesGlslName(glsl[j])) ++j;
            const std::string_view word = glsl.substr(i, j - i);
            if (forbidden.count(word))
                return lineAt(glsl, i) + ": '" + std::string(word) + "' is not allowed in a whole DE";
            if (word.starts_with("gl_") || word.starts_with("fraktal"))
                return lineAt(glsl, i) + ": '" + std::string(word) +
                       "' is not allowed in a whole DE (names beginning with gl_ or fraktal are reserved)";
            if (isTextureWord(word))
                return lineAt(glsl, i) + ": '" + std::string(word) +
                       "': a whole DE cannot read textures or images (the distance is a function of the point alone)";
            i = j;
            continue;
        }
        ++i;
    }
    WholeDEScan scan;
    try {
        scan = scanWholeDE(glsl);
    } catch (const PresetError& e) {
        return e.field() + ": " + e.reason();
    }
    if (!scan.hasDE) return "no function `float DE(vec3 ...)` defines the distance";
    for (const std::string& p : params)
        if (std::find(scan.names.begin(), scan.names.end(), p) != scan.names.end())
            return "'" + p + "' is a parameter and is declared again in the code";
    return {};
}

std::string wholeDEShaderCode(std::string_view glsl, const WholeDEScan& scan, std::string_view prefix,
                              const std::function<std::string(std::string_view)>& uniformOf,
                              std::span<const std::string> params, std::string_view tripCounter) {
    const std::set<std::string, std::less<>> names(scan.names.begin(), scan.names.end());
    const std::set<std::string, std::less<>> paramNames(params.begin(), params.end());
    const std::string bound = "++" + std::string(tripCounter) + " < " + std::to_string(kMaxWholeDELoopTrips);

    // Renames and bounds the text from..to; recursive for loop headers.
    std::function<std::string(std::string_view)> rewrite = [&](std::string_view s) {
        std::string out;
        out.reserve(s.size() + s.size() / 8);
        char previous = 0;  // the last character that is not a space, for member selection (`.x`)
        for (size_t i = 0; i < s.size();) {
            if (const size_t c = commentEnd(s, i); c != i) {
                out.append(s.substr(i, c - i));
                i = c;
                continue;
            }
            const char ch = s[i];
            if (std::isdigit(static_cast<unsigned char>(ch)) ||
                (ch == '.' && i + 1 < s.size() && std::isdigit(s[i + 1]))) {
                const size_t end = numberEnd(s, i);
                out.append(s.substr(i, end - i));
                previous = s[end - 1];
                i = end;
                continue;
            }
            if (!startsGlslName(ch)) {
                out.push_back(ch);
                if (!std::isspace(static_cast<unsigned char>(ch))) previous = ch;
                ++i;
                continue;
            }
            size_t j = i;
            while (j < s.size() && continuesGlslName(s[j])) ++j;
            const std::string_view word = s.substr(i, j - i);
            if (previous != '.' && (word == "for" || word == "while")) {
                size_t open = j;
                while (open < s.size() && std::isspace(static_cast<unsigned char>(s[open]))) ++open;
                const size_t close =
                    open < s.size() && s[open] == '(' ? matchingParen(s, open) : std::string_view::npos;
                if (close != std::string_view::npos) {
                    out.append(s.substr(i, open + 1 - i));
                    const std::string inner = rewrite(s.substr(open + 1, close - open - 1));
                    if (word == "while") {
                        out += "(" + inner + ") && " + bound;
                    } else {
                        // for (init; condition; step): the condition is between the first two
                        // semicolons outside parentheses.
                        size_t first = std::string::npos, second = std::string::npos;
                        int depth = 0;
                        for (size_t k = 0; k < inner.size(); ++k) {
                            if (inner[k] == '(') ++depth;
                            if (inner[k] == ')') --depth;
                            if (inner[k] == ';' && depth == 0) {
                                if (first == std::string::npos)
                                    first = k;
                                else if (second == std::string::npos)
                                    second = k;
                            }
                        }
                        if (second == std::string::npos) {
                            out += inner;  // not a for header GLSL accepts: the compiler says so
                        } else {
                            const std::string condition = inner.substr(first + 1, second - first - 1);
                            const bool empty = std::all_of(condition.begin(), condition.end(), [](char c) {
                                return std::isspace(static_cast<unsigned char>(c));
                            });
                            out += inner.substr(0, first + 1) + " " +
                                   (empty ? bound : "(" + condition + ") && " + bound) + inner.substr(second);
                        }
                    }
                    out.push_back(')');
                    previous = ')';
                    i = close + 1;
                    continue;
                }
            }
            if (previous != '.' && paramNames.count(word))
                out += uniformOf(word);
            else if (previous != '.' && names.count(word))
                out += std::string(prefix) + std::string(word);
            else
                out.append(word);
            previous = 'a';
            i = j;
        }
        return out;
    };
    return rewrite(glsl);
}

}  // namespace fraktal
