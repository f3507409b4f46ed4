// Blocks written by users in GLSL (a function body over `p` and `c` with declared parameters),
// carried in a preset's "customBlocks" section or a block library file. They sit in the node
// list like built-in blocks and get uniforms and widgets from their declared parameters; they
// have no CPU body, so a formula using one is evaluated through the GL context (gl::DEProbe).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/block.hpp"

namespace fraktal {

// Limits on a user's snippet: bounded work per call, nothing that reaches outside its function.
inline constexpr size_t kMaxCustomGlslBytes = 16 * 1024;
inline constexpr int kMaxCustomParams = 16;
inline constexpr int kMaxCustomBlocks = 32;

class CustomBlock {
   public:
    struct Definition {
        std::string id, label, help;
        Category category = Category::Transform;
        Membership membership = Membership::Distance;  // estimators only
        struct Param {
            std::string name, help;
            ParamType type = ParamType::Float;
            vec3 defaultValue{0.0};
            double min = 0.0, max = 1.0;
            std::string group = {};  // the editor's panel for it ("" : the block's own); an imported frag's #group
        };
        std::vector<Param> params;
        std::string glsl;
        // The GLSL is a whole DE (core/whole_de.hpp): global-scope functions, globals and #define
        // lines defining `float DE(vec3)`, with loops allowed (bounded by a trip count). Only an
        // estimator, alone in its formula; its parameters are in scope everywhere in the code.
        bool wholeDE = false;
    };

    // Checks the definition; returns an empty string when it is sound, else the reason, with
    // the field it concerns first ("glsl: line 3: loops are not allowed ...").
    static std::string validate(const Definition& d);
    // The definition must validate.
    static std::shared_ptr<const CustomBlock> make(Definition d);

    const Definition& definition() const { return def_; }
    const BlockDesc& desc() const { return desc_; }

   private:
    explicit CustomBlock(Definition d);
    Definition def_;
    std::vector<ParamDecl> decls_;  // views into def_
    BlockDesc desc_;                // views into def_ and decls_
};

using CustomBlocks = std::vector<std::shared_ptr<const CustomBlock>>;

// JSON form, as in a preset's "customBlocks" array and a library's. `path` names the array
// element in errors; throws PresetError(file, path + ".field", reason).
std::shared_ptr<const CustomBlock> parseCustomBlock(const nlohmann::json& j, const std::string& file,
                                                    const std::string& path);
nlohmann::json customBlockToJson(const CustomBlock& block);

// A reusable block library: {"format": "fraktal-blocks", "version": 1, "customBlocks": [...]}.
CustomBlocks loadBlockLibrary(const std::string& path);
std::string serializeBlockLibrary(const CustomBlocks& blocks);

}  // namespace fraktal
