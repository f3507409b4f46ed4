// The name the editor shows for a block parameter, from its declaration (core/block.hpp): the
// panels' widgets and the undo history's labels ("Undo change of packing") say the same words.
#pragma once

#include <algorithm>
#include <string>

#include "core/block.hpp"

namespace fraktal {

// The declaration's label, else its name with underscores as spaces and a capital ("box_size":
// "Box size"). Presets keep using ParamDecl::name.
inline std::string paramLabel(const ParamDecl& d) {
    if (!d.label.empty()) return std::string(d.label);
    std::string label(d.name);
    std::replace(label.begin(), label.end(), '_', ' ');
    if (!label.empty() && label[0] >= 'a' && label[0] <= 'z') label[0] = char(label[0] - 'a' + 'A');
    return label;
}

}  // namespace fraktal
