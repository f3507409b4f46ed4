#include "app/editor/state/custom_block_editor.hpp"

namespace fraktal::editor {

std::vector<SourceError> blockEditorErrors(const CustomBlockEditor& e, const std::string& compileError) {
    // A refused Apply left the formula's block as it was: a compile error would be about that one.
    if (!e.error.empty()) return validationSourceErrors(e.error);
    return blockErrorsInExplainedLog(compileError, e.definition.id);
}

}  // namespace fraktal::editor
