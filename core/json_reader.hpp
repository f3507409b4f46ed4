// Guarded reading of JSON documents, shared by the 3D preset reader (core/preset.cpp) and the 2D
// one (core/plane/plane_preset.cpp): the text's guards (size, depth, duplicate keys), typed field
// access whose errors name the file, the field's JSON path and the reason, and the keeping of
// fields that a newer format version added (written back at their place on save).
#pragma once

#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fraktal {

// Limits on any document we read: bad input gets an error, never an out-of-memory or a stack
// overflow in the parser.
inline constexpr size_t kMaxDocumentBytes = 4 << 20;
inline constexpr int kMaxJsonDepth = 32;
inline constexpr size_t kMaxStringBytes = 4096;  // the default limit of FieldReader::string

// A document that cannot be used: says which file, which field (a JSON path such as
// formula.nodes[2].params.limit; empty for the file as a whole) and why.
class PresetError : public std::runtime_error {
   public:
    PresetError(std::string file, std::string field, std::string reason);
    const std::string& file() const { return file_; }
    const std::string& field() const { return field_; }
    const std::string& reason() const { return reason_; }

   private:
    std::string file_, field_, reason_;
};

// Parses JSON text, refusing empty text, text over kMaxDocumentBytes, nesting deeper than
// kMaxJsonDepth and duplicate keys (nlohmann keeps the last duplicate silently; a document with
// two values for one field is ambiguous). Syntax errors give the line.
nlohmann::json parseGuardedJson(std::string_view text, const std::string& file);

// The whole content of a file, after checking that it exists, is a regular file (not a
// directory) and is at most kMaxDocumentBytes.
std::string readGuardedFile(const std::filesystem::path& path);

// "formula.nodes[2].params" -> "/formula/nodes/2/params" (a JSON Pointer, RFC 6901). Field
// paths are built from known keys, which never hold '.', '[', '/' or '~'.
std::string pointerFromPath(const std::string& path);

// Fields a newer format version added inside sections this version knows, kept so that saving
// writes them back at their place (a user's file must not lose what a newer fraktal put in it).
// Each field is kept with the path of the object that held it. Where that object is, or sits
// in, an element of an array (a node, a custom block, a parameter), the element's identity
// (its "block", "id" or "name") is kept too: if the list was edited and that element now holds
// something else, the fields are dropped rather than written onto the wrong element.
class KeptFields {
   public:
    // `document` is the whole document being read; `holderPath` the field path of the object
    // that held `key`.
    void keep(const nlohmann::json& document, const std::string& holderPath, const std::string& key,
              const nlohmann::json& value);
    // Writes every kept field back into `document` (the saved form) at its place, creating the
    // holding object where the saver left it out (all its known fields at their defaults);
    // never overwrites a field the saver wrote.
    void writeBack(nlohmann::json& document) const;
    bool empty() const { return entries_.empty(); }
    // The kept fields' paths ("formula.glow"), for reports such as `fraktal check`.
    std::vector<std::string> paths() const;

   private:
    struct Entry {
        std::string holderPath;
        std::string elementPointer;  // the innermost array element on the way ("" when none)
        nlohmann::json identity;     // that element's {"block": ...} (or id, name); null when none
        nlohmann::json fields = nlohmann::json::object();
    };
    std::vector<Entry> entries_;
};

// Every field the readers asked about while reading one document, present or not, with what
// they accept: the format's own enumeration of itself. Tests walk it to reach every field a
// preset can hold without a list of their own (tests/scene_change_test.cpp); nothing else reads
// it.
struct FieldAsked {
    enum class Kind {
        Number,    // lo..hi
        Integer,   // whole numbers in lo..hi
        Boolean,   // true or false
        String,    // any string (up to hi bytes)
        Choice,    // one of `choices`
        Vector,    // `size` numbers, each in lo..hi
        Optional,  // an object, list or field that is absent and was only asked about (has())
    };
    std::string path;  // formula.nodes[2].params.scale
    Kind kind = Kind::Optional;
    nlohmann::json value;  // as read: the document's value, or the reader's default when absent
    bool present = false;
    double lo = 0.0, hi = 0.0;
    int size = 0;
    std::vector<std::string> choices;
};
using FieldLog = std::vector<FieldAsked>;

// What readers of one document share: the file name for errors, and what to do with fields
// they were not asked about.
struct ReadContext {
    std::string file;
    const nlohmann::json* document = nullptr;  // the whole document (for KeptFields)
    // Null: unknown fields are errors (a typo must not be ignored silently). Set (a document of
    // a newer format version): they are kept here instead.
    KeptFields* keepUnknown = nullptr;
    FieldLog* log = nullptr;  // set: every field asked about is noted there
};

// Reads the fields of one JSON object, with its path for error messages. Every field asked
// about is marked; finish() then refuses (or, for a newer version, keeps) the others.
class FieldReader {
   public:
    FieldReader(const ReadContext& context, const nlohmann::json& object, std::string path);

    [[noreturn]] void fail(const std::string& reason, const std::string& key = {}) const;
    std::string child(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    const std::string& path() const { return path_; }
    const ReadContext& context() const { return context_; }
    // Whether the field is there (an absent one is noted in the context's log as optional).
    bool has(const std::string& key) const;
    // A field that must be there.
    const nlohmann::json& at(const std::string& key);
    // A field read elsewhere (e.g. "format" and "version", by readPresetDocument).
    void skip(const std::string& key) { seen_.insert(key); }

    double number(const std::string& key, double fallback, double lo, double hi);
    int integer(const std::string& key, int fallback, int lo, int hi);
    bool boolean(const std::string& key, bool fallback);
    // An on/off parameter: true or false, or the number 0 or 1 that presets held before
    // parameters had an on/off kind. Anything else is refused, naming the value.
    bool toggle(const std::string& key, bool fallback);
    std::string string(const std::string& key, const std::string& fallback, size_t maxLength = kMaxStringBytes);
    // The index in `names` of the name at key (`fallback` when it is absent). Any other string
    // fails: "PREFIXunknown WHAT "x" (expected a, b or c)".
    int choice(const std::string& key, std::span<const std::string_view> names, int fallback, const std::string& what,
               const std::string& prefix = {});
    // A string the caller checks against `names` itself (block and object ids, light types),
    // read as `value`: noted in the log as a choice (it replaces a note string() made).
    void noteChoice(const std::string& key, const std::string& value, std::vector<std::string> names) const;
    template <int N>
    glm::vec<N, double> vector(const std::string& key, const glm::vec<N, double>& fallback, double lo, double hi) {
        const glm::vec<N, double> v = object_.contains(key) ? checkVector<N>(at(key), child(key), lo, hi) : fallback;
        if (context_.log) {
            nlohmann::json a = nlohmann::json::array();
            for (int i = 0; i < N; ++i) a.push_back(v[i]);
            note(key, FieldAsked::Kind::Vector, a, lo, hi, N);
        }
        return v;
    }
    template <int N>
    glm::vec<N, double> requiredVector(const std::string& key, double lo, double hi) {
        const glm::vec<N, double> v = checkVector<N>(at(key), child(key), lo, hi);
        if (context_.log) note(key, FieldAsked::Kind::Vector, at(key), lo, hi, N);
        return v;
    }

    // Fields present but never asked about: an error with `reason`, or kept (newer version).
    void finish(const std::string& reason = "unknown field") const;

    // Checks of a value at `path` (array elements, values read by hand).
    double checkNumber(const nlohmann::json& v, const std::string& path, double lo, double hi) const;
    template <int N>
    glm::vec<N, double> checkVector(const nlohmann::json& v, const std::string& path, double lo, double hi) const {
        if (!v.is_array() || v.size() != N)
            throw PresetError(context_.file, path,
                              "expected an array of " + std::to_string(N) + " numbers, found " + typeName(v) +
                                  (v.is_array() ? " of " + std::to_string(v.size()) : ""));
        glm::vec<N, double> r;
        for (int i = 0; i < N; ++i) r[i] = checkNumber(v[size_t(i)], path + "[" + std::to_string(i) + "]", lo, hi);
        return r;
    }

    static std::string typeName(const nlohmann::json& v);
    static std::string formatNumber(double d);

   private:
    void note(const std::string& key, FieldAsked::Kind kind, const nlohmann::json& value, double lo = 0.0,
              double hi = 0.0, int size = 0, std::vector<std::string> choices = {}) const;

    const ReadContext& context_;
    const nlohmann::json& object_;
    std::string path_;
    std::set<std::string> seen_;
};

}  // namespace fraktal
