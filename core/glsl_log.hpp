// Reading a GLSL compiler's log: the messages with the line each names, whatever driver wrote
// it, and the lines of one block's own source they fall on. Pure text work (no GL), shared by
// ShaderSource::explainLog and the editor's GLSL block window, which marks those lines.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fraktal {

// One message of a compile log: the line of the assembled shader it names and what it says
// ("error: `foo' undeclared", severity first, lower case).
struct ShaderLogMessage {
    int line = 0;
    std::string text;
};

// The messages of a driver's or glslang's log, in order. Understands
//   Mesa:    0:10003(5): error: `foo' undeclared
//   NVIDIA:  0(10003) : error C1008: undefined variable "foo"
//   glslang and AMD: ERROR: 0:10003: 'foo' : undeclared identifier
// A line in none of these forms (a summary, a blank) is no message.
std::vector<ShaderLogMessage> parseShaderLog(std::string_view log);

// A message on a line of a block's own source, numbered from 1 as the block's text is.
struct SourceError {
    int line = 0;  // 0: the message names no line
    std::string message;
    bool operator==(const SourceError&) const = default;
};

// The messages a log that ShaderSource::explainLog rewrote places in the block `blockId`
// (`... "Label" (blockId), GLSL line N: error: ...`), once each even where several fractals use
// the block; what the editor's viewport keeps of a failed compile. Errors only: warnings are left
// out (a failed compile's log also carries the driver's warnings about the generated shader).
std::vector<SourceError> blockErrorsInExplainedLog(std::string_view explainedLog, std::string_view blockId);

// The line a refusal of CustomBlock::validate names in the block's GLSL ("glsl: line 3: loops
// ..." -> {3, "loops ..."}); a refusal of the GLSL that names no line is line 0, and a refusal of
// another field (an id, a parameter) is none: empty.
std::vector<SourceError> validationSourceErrors(std::string_view refusal);

}  // namespace fraktal
