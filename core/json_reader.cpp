#include "core/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace fraktal {

using nlohmann::json;

PresetError::PresetError(std::string file, std::string field, std::string reason)
    : std::runtime_error(file + ": " + (field.empty() ? "" : field + ": ") + reason),
      file_(std::move(file)),
      field_(std::move(field)),
      reason_(std::move(reason)) {}

namespace {

// Follows the parser's events to find the first key that occurs twice in one object, and names
// it by its field path ("formula.nodes", "formula.nodes[2].params.limit").
class DuplicateKeyFinder {
   public:
    void see(json::parse_event_t event, const json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start:
            case json::parse_event_t::array_start:
                elementStarts();
                open_.push_back({event == json::parse_event_t::array_start, {}, {}, -1});
                break;
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                if (!open_.empty()) open_.pop_back();
                break;
            case json::parse_event_t::key:
                if (open_.empty()) break;
                open_.back().key = parsed.get<std::string>();
                if (!open_.back().keys.insert(open_.back().key).second && found_.empty()) found_ = currentPath();
                break;
            case json::parse_event_t::value: elementStarts(); break;
        }
    }
    const std::string& found() const { return found_; }

   private:
    struct Container {
        bool array;
        std::set<std::string> keys;  // objects: the keys seen so far
        std::string key;             // objects: the latest key
        long index;                  // arrays: the latest element
    };
    void elementStarts() {
        if (!open_.empty() && open_.back().array) ++open_.back().index;
    }
    // The path of the latest key or element of the innermost container.
    std::string currentPath() const {
        std::string path;
        for (const Container& c : open_) {
            if (c.array)
                path += "[" + std::to_string(c.index) + "]";
            else
                path += (path.empty() ? "" : ".") + c.key;
        }
        return path;
    }
    std::vector<Container> open_;
    std::string found_;
};

}  // namespace

json parseGuardedJson(std::string_view text, const std::string& file) {
    if (text.size() > kMaxDocumentBytes)
        throw PresetError(file, "",
                          "file is larger than " + std::to_string(kMaxDocumentBytes >> 20) + " MiB; not a preset");
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) throw PresetError(file, "", "file is empty");
    DuplicateKeyFinder duplicates;
    std::string tooDeep;
    auto callback = [&](int depth, json::parse_event_t event, json& parsed) {
        if (depth > kMaxJsonDepth && tooDeep.empty())
            tooDeep = "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels";
        duplicates.see(event, parsed);
        return tooDeep.empty();
    };
    json j;
    try {
        j = json::parse(text.begin(), text.end(), callback);
    } catch (const json::parse_error& e) {
        // Byte offset to line.
        const size_t at = std::min(e.byte, text.size());
        const size_t line = 1 + size_t(std::count(text.begin(), text.begin() + long(at ? at - 1 : 0), '\n'));
        std::string reason = e.what();
        if (auto p = reason.find("parse error"); p != std::string::npos) reason = reason.substr(p);
        if (!tooDeep.empty()) reason = tooDeep;
        throw PresetError(file, "", "invalid JSON at line " + std::to_string(line) + ": " + reason);
    } catch (const json::exception& e) {  // e.g. out_of_range 406: a number too large for a double
        std::string reason = e.what();
        if (auto p = reason.find("] "); p != std::string::npos) reason = reason.substr(p + 2);
        throw PresetError(file, "", "invalid JSON: " + reason);
    }
    if (!tooDeep.empty()) throw PresetError(file, "", "invalid preset: " + tooDeep);
    if (!duplicates.found().empty()) throw PresetError(file, duplicates.found(), "duplicated key");
    return j;
}

std::string readGuardedFile(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) throw PresetError(file, "", "no such file");
    if (std::filesystem::is_directory(status)) throw PresetError(file, "", "is a directory, not a preset file");
    if (!std::filesystem::is_regular_file(status)) throw PresetError(file, "", "is not a regular file");
    if (std::filesystem::file_size(path, ec) > kMaxDocumentBytes)
        throw PresetError(file, "",
                          "file is larger than " + std::to_string(kMaxDocumentBytes >> 20) + " MiB; not a preset");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw PresetError(file, "", "cannot be opened for reading");
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string pointerFromPath(const std::string& path) {
    if (path.empty()) return "";
    std::string pointer = "/";
    for (char c : path) {
        if (c == '.' || c == '[')
            pointer += '/';
        else if (c != ']')
            pointer += c;
    }
    return pointer;
}

namespace {

// The identity of an array element: the first of these keys it has.
json elementIdentity(const json& element) {
    if (element.is_object())
        for (const char* key : {"block", "id", "name"})
            if (element.contains(key)) return json{{key, element[key]}};
    return nullptr;
}

bool matchesIdentity(const json& element, const json& identity) {
    if (identity.is_null()) return true;
    const auto only = identity.begin();  // identity holds one field
    return element.is_object() && element.contains(only.key()) && element[only.key()] == only.value();
}

}  // namespace

void KeptFields::keep(const json& document, const std::string& holderPath, const std::string& key, const json& value) {
    auto entry =
        std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.holderPath == holderPath; });
    if (entry == entries_.end()) {
        Entry e;
        e.holderPath = holderPath;
        if (const size_t bracket = holderPath.rfind('['); bracket != std::string::npos) {
            e.elementPointer = pointerFromPath(holderPath.substr(0, holderPath.find(']', bracket) + 1));
            const json::json_pointer element(e.elementPointer);
            if (document.contains(element)) e.identity = elementIdentity(document.at(element));
        }
        entries_.push_back(std::move(e));
        entry = entries_.end() - 1;
    }
    entry->fields[key] = value;
}

void KeptFields::writeBack(json& document) const {
    for (const Entry& e : entries_) {
        if (!e.elementPointer.empty()) {
            const json::json_pointer element(e.elementPointer);
            if (!document.contains(element) || !matchesIdentity(document.at(element), e.identity)) continue;
        }
        const json::json_pointer holder(pointerFromPath(e.holderPath));
        if (!document.contains(holder)) {
            // Only a section or a node's params object that the saver left out: its parent must
            // be there as an object.
            if (!document.contains(holder.parent_pointer()) || !document.at(holder.parent_pointer()).is_object())
                continue;
            document[holder] = json::object();
        }
        json& target = document.at(holder);
        if (!target.is_object()) continue;
        for (const auto& [key, value] : e.fields.items())
            if (!target.contains(key)) target[key] = value;
    }
}

std::vector<std::string> KeptFields::paths() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_)
        for (const auto& [key, value] : e.fields.items())
            out.push_back(e.holderPath.empty() ? key : e.holderPath + "." + key);
    return out;
}

FieldReader::FieldReader(const ReadContext& context, const json& object, std::string path)
    : context_(context), object_(object), path_(std::move(path)) {
    if (!object_.is_object()) fail("expected an object, found " + typeName(object_));
}

void FieldReader::fail(const std::string& reason, const std::string& key) const {
    throw PresetError(context_.file, key.empty() ? path_ : child(key), reason);
}

const json& FieldReader::at(const std::string& key) {
    seen_.insert(key);
    if (!object_.contains(key)) fail("missing required field", key);
    return object_.at(key);
}

bool FieldReader::has(const std::string& key) const {
    const bool present = object_.contains(key);
    if (!present && context_.log) note(key, FieldAsked::Kind::Optional, nullptr);
    return present;
}

void FieldReader::note(const std::string& key, FieldAsked::Kind kind, const json& value, double lo, double hi, int size,
                       std::vector<std::string> choices) const {
    FieldAsked f;
    f.path = child(key);
    f.kind = kind;
    f.value = value;
    f.present = object_.contains(key);
    f.lo = lo;
    f.hi = hi;
    f.size = size;
    f.choices = std::move(choices);
    context_.log->push_back(std::move(f));
}

void FieldReader::noteChoice(const std::string& key, const std::string& value, std::vector<std::string> names) const {
    if (!context_.log) return;
    const std::string path = child(key);
    std::erase_if(*context_.log, [&](const FieldAsked& f) { return f.path == path; });
    note(key, FieldAsked::Kind::Choice, value, 0.0, 0.0, 0, std::move(names));
}

double FieldReader::number(const std::string& key, double fallback, double lo, double hi) {
    const double d = object_.contains(key) ? checkNumber(at(key), child(key), lo, hi) : fallback;
    if (context_.log) note(key, FieldAsked::Kind::Number, d, lo, hi);
    return d;
}

int FieldReader::integer(const std::string& key, int fallback, int lo, int hi) {
    int n = fallback;
    if (object_.contains(key)) {
        const json& v = at(key);
        const double d = checkNumber(v, child(key), lo, hi);
        if (d != std::floor(d)) fail("expected a whole number, found " + v.dump(), key);
        n = int(d);
    }
    if (context_.log) note(key, FieldAsked::Kind::Integer, n, lo, hi);
    return n;
}

bool FieldReader::boolean(const std::string& key, bool fallback) {
    bool b = fallback;
    if (object_.contains(key)) {
        const json& v = at(key);
        if (!v.is_boolean()) fail("expected true or false, found " + typeName(v), key);
        b = v.get<bool>();
    }
    if (context_.log) note(key, FieldAsked::Kind::Boolean, b);
    return b;
}

bool FieldReader::toggle(const std::string& key, bool fallback) {
    bool b = fallback;
    if (object_.contains(key)) {
        const json& v = at(key);
        if (v.is_boolean())
            b = v.get<bool>();
        else if (v.is_number() && (v.get<double>() == 0.0 || v.get<double>() == 1.0))
            b = v.get<double>() == 1.0;
        else
            fail("expected true or false (or 0 or 1), found " + v.dump(), key);
    }
    if (context_.log) note(key, FieldAsked::Kind::Boolean, b);
    return b;
}

std::string FieldReader::string(const std::string& key, const std::string& fallback, size_t maxLength) {
    std::string s = fallback;
    if (object_.contains(key)) {
        const json& v = at(key);
        if (!v.is_string()) fail("expected a string, found " + typeName(v), key);
        s = v.get<std::string>();
        if (s.size() > maxLength) fail("string longer than " + std::to_string(maxLength) + " bytes", key);
    }
    if (context_.log) note(key, FieldAsked::Kind::String, s, 0.0, double(maxLength));
    return s;
}

int FieldReader::choice(const std::string& key, std::span<const std::string_view> names, int fallback,
                        const std::string& what, const std::string& prefix) {
    const std::string name = string(key, std::string(names[size_t(fallback)]));
    if (context_.log) {  // a choice, not the free string string() noted
        context_.log->back().kind = FieldAsked::Kind::Choice;
        context_.log->back().choices.assign(names.begin(), names.end());
    }
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return int(i);
    std::string expected;
    for (size_t i = 0; i < names.size(); ++i)
        expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(names[i]);
    fail(prefix + "unknown " + what + " \"" + name + "\" (expected " + expected + ")", key);
}

void FieldReader::finish(const std::string& reason) const {
    for (const auto& [key, value] : object_.items()) {
        if (seen_.count(key)) continue;
        if (!context_.keepUnknown || !context_.document) fail(reason, key);
        context_.keepUnknown->keep(*context_.document, path_, key, value);
    }
}

double FieldReader::checkNumber(const json& v, const std::string& path, double lo, double hi) const {
    if (!v.is_number()) throw PresetError(context_.file, path, "expected a number, found " + typeName(v));
    const double d = v.get<double>();
    if (!std::isfinite(d)) throw PresetError(context_.file, path, "number is not finite");
    if (d < lo || d > hi)
        throw PresetError(
            context_.file, path,
            "value " + v.dump() + " is outside the range [" + formatNumber(lo) + ", " + formatNumber(hi) + "]");
    return d;
}

std::string FieldReader::typeName(const json& v) {
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_array()) return "an array";
    if (v.is_object()) return "an object";
    if (v.is_boolean()) return "a boolean";
    if (v.is_null()) return "null";
    return v.type_name();
}

std::string FieldReader::formatNumber(double d) {
    std::ostringstream s;
    s << d;
    return s.str();
}

}  // namespace fraktal
