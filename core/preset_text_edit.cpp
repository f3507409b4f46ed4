#include "core/preset_text_edit.hpp"

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

namespace fraktal {

namespace {

// A scanner over JSON text that knows where each value starts and ends; enough to find a member
// of a member of the top-level object. The text is assumed valid (it was parsed first).
struct Scanner {
    const std::string& text;
    size_t at = 0;

    void skipSpace() {
        while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '\n' || text[at] == '\r')) ++at;
    }
    std::string string() {  // at the opening quote; returns the raw contents (escapes left as they are)
        const size_t start = ++at;
        while (at < text.size() && text[at] != '"') at += text[at] == '\\' ? 2 : 1;
        return text.substr(start, at++ - start);
    }
    void skipValue() {
        skipSpace();
        if (text[at] == '"') {
            string();
        } else if (text[at] == '{' || text[at] == '[') {
            int depth = 0;
            do {
                if (text[at] == '"') {
                    string();
                    continue;
                }
                if (text[at] == '{' || text[at] == '[') ++depth;
                if (text[at] == '}' || text[at] == ']') --depth;
                ++at;
            } while (depth > 0 && at < text.size());
        } else {
            while (at < text.size() && text[at] != ',' && text[at] != '}' && text[at] != ']' && text[at] != ' ' &&
                   text[at] != '\n' && text[at] != '\r' && text[at] != '\t')
                ++at;
        }
    }
    // At an object's '{': calls found(key) at each member's value (the scanner just before it) until
    // it returns true; returns whether it did.
    template <typename Found>
    bool members(Found found) {
        ++at;  // '{'
        for (;;) {
            skipSpace();
            if (at >= text.size() || text[at] == '}') return false;
            if (text[at] == ',') {
                ++at;
                continue;
            }
            const std::string key = string();
            skipSpace();
            ++at;  // ':'
            skipSpace();
            if (found(key)) return true;
            skipValue();
        }
    }
};

std::string numberText(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    // The shortest spelling that reads back as the same double.
    for (int digits = 1; digits <= 17; ++digits) {
        char shorter[32];
        std::snprintf(shorter, sizeof shorter, "%.*g", digits, value);
        if (std::strtod(shorter, nullptr) == value) return shorter;
    }
    return buffer;
}

// value on one line, with a space after each ':' and ',' (as the shipped presets write nodes).
std::string oneLine(const nlohmann::json& value) {
    const std::string compact = value.dump();
    std::string out;
    bool inString = false;
    for (size_t i = 0; i < compact.size(); ++i) {
        const char c = compact[i];
        out += c;
        if (inString) {
            if (c == '\\')
                out += compact[++i];
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == ':' || c == ',') {
            out += ' ';
        }
    }
    return out;
}

nlohmann::json parsedForEdit(const std::string& text, const std::string& field, const std::string& file) {
    try {
        return nlohmann::json::parse(text);
    } catch (const std::exception& e) {
        throw std::runtime_error(file + ": not valid JSON, so " + field + " was not written: " + e.what());
    }
}

}  // namespace

std::string withLastElementInPlace(const std::string& text, const std::string& section, const std::string& key,
                                   const nlohmann::json& value, const std::string& file) {
    const std::string field = section + "." + key;
    const nlohmann::json original = parsedForEdit(text, field, file);
    if (!original.is_object() || !original.contains(section) || !original[section].is_object() ||
        !original[section].contains(key) || !original[section][key].is_array() || original[section][key].empty())
        throw std::runtime_error(file + ": the last element of " + field +
                                 " was not written: the file has no such array with an element");
    Scanner s{text};
    s.skipSpace();
    std::optional<std::string> edited;
    s.members([&](const std::string& name) {
        if (name != section) return false;
        return s.members([&](const std::string& member) {
            if (member != key) return false;
            size_t lastStart = 0, lastEnd = 0;
            ++s.at;  // '['
            for (;;) {
                s.skipSpace();
                if (s.at >= text.size() || text[s.at] == ']') break;
                if (text[s.at] == ',') {
                    ++s.at;
                    continue;
                }
                lastStart = s.at;
                s.skipValue();
                lastEnd = s.at;
            }
            edited = text.substr(0, lastStart) + oneLine(value) + text.substr(lastEnd);
            return true;
        });
    });
    nlohmann::json expected = original;
    expected[section][key].back() = value;
    if (!edited || nlohmann::json::parse(*edited) != expected)
        throw std::runtime_error(file + ": the last element of " + field + " could not be edited in place");
    return *edited;
}

namespace {

// withNumberInPlace and withStringInPlace: `value` a number or a string, written as JSON writes it
// (numbers in numberText's shortest spelling that reads back the same).
std::string withScalarInPlace(const std::string& text, const std::string& section, const std::string& key,
                              const nlohmann::json& value, const std::string& file) {
    const bool number = value.is_number();
    const std::string valueText = number ? numberText(value.get<double>()) : value.dump();
    const std::string field = section + "." + key;
    const nlohmann::json original = parsedForEdit(text, field, file);
    if (!original.is_object() || !original.contains(section) || !original[section].is_object())
        throw std::runtime_error(file + ": " + field + " was not written: the file has no " + section + " object");
    if (original[section].contains(key) && original[section][key].is_number() != number)
        throw std::runtime_error(file + ": " + field + " was not written: it holds " +
                                 original[section][key].type_name() + ", not a " + (number ? "number" : "string"));

    Scanner s{text};
    s.skipSpace();
    std::optional<std::string> edited;
    s.members([&](const std::string& name) {
        if (name != section) return false;
        const size_t open = s.at;  // the section's '{'
        const bool replaced = s.members([&](const std::string& member) {
            if (member != key) return false;
            const size_t start = s.at;
            s.skipValue();
            edited = text.substr(0, start) + valueText + text.substr(s.at);
            return true;
        });
        if (!replaced) {
            // As the section's first member, after the same white space as the member it goes before.
            Scanner first{text, open + 1};
            first.skipSpace();
            const std::string lead = text.substr(open + 1, first.at - (open + 1));
            const std::string member = "\"" + key + "\": " + valueText;
            const bool empty = first.at < text.size() && text[first.at] == '}';
            edited = text.substr(0, open + 1) + (empty ? member : lead + member + (lead.empty() ? ", " : ",")) +
                     text.substr(open + 1);
        }
        return true;
    });
    nlohmann::json expected = original;
    expected[section][key] = value;
    if (!edited || nlohmann::json::parse(*edited) != expected)
        throw std::runtime_error(file + ": " + field + " could not be edited in place");
    return *edited;
}

}  // namespace

std::string withNumberInPlace(const std::string& text, const std::string& section, const std::string& key, double value,
                              const std::string& file) {
    return withScalarInPlace(text, section, key, value, file);
}

std::string withStringInPlace(const std::string& text, const std::string& section, const std::string& key,
                              const std::string& value, const std::string& file) {
    return withScalarInPlace(text, section, key, value, file);
}

}  // namespace fraktal
