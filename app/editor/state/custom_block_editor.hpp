// The editor's GLSL block editor (users write their own blocks): what the dialog edits,
// as plain data owned by EditorState. The definition it produces goes through
// upsertCustomBlock (formula_edits.hpp), which validates it like a preset's block.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/editor/widgets/source_editor.hpp"
#include "core/custom_block.hpp"
#include "core/glsl_log.hpp"

namespace fraktal::editor {

struct CustomBlockEditor {
    bool open = false;
    CustomBlock::Definition definition;
    std::string error;              // why the last Apply was refused (empty: applied, or not tried)
    std::filesystem::path library;  // block library file for Save / Load
    std::string libraryMessage;
    SourceEditorState source;  // the GLSL's cursor and scroll
};

// The errors the window lists and marks on the GLSL's lines: the refusal of the last Apply
// (CustomBlock::validate) where it concerns the GLSL, else the viewport's compile errors in the
// block being edited (`compileError` as ShaderSource::explainLog wrote it).
std::vector<SourceError> blockEditorErrors(const CustomBlockEditor& e, const std::string& compileError);

// A starting point for a new block: a transform with one parameter and a body that uses it.
CustomBlock::Definition newBlockTemplate();

}  // namespace fraktal::editor
