// The editor's GLSL block editor (users write their own blocks): what the dialog edits,
// as plain data owned by EditorState. The definition it produces goes through
// upsertCustomBlock (formula_edits.hpp), which validates it like a preset's block.
#pragma once

#include <filesystem>
#include <string>

#include "core/custom_block.hpp"

namespace fraktal::editor {

struct CustomBlockEditor {
    bool open = false;
    CustomBlock::Definition definition;
    std::string error;              // why the last Apply was refused (empty: applied, or not tried)
    std::filesystem::path library;  // block library file for Save / Load
    std::string libraryMessage;
};

// A starting point for a new block: a transform with one parameter and a body that uses it.
CustomBlock::Definition newBlockTemplate();

}  // namespace fraktal::editor
