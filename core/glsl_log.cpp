#include "core/glsl_log.hpp"

#include <algorithm>
#include <cctype>
#include <regex>

namespace fraktal {

namespace {

std::string lowerCase(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// One line of a log as a message, or false when it is in no known form.
bool parseLogLine(const std::string& line, ShaderLogMessage& message) {
    // Mesa: "0:10003(5): error: ...", and without the column "0:10003: error: ...".
    static const std::regex mesa(R"(^\s*\d+:(\d+)(?:\(\d+\))?:\s*(.*)$)");
    // NVIDIA: "0(10003) : error C1008: ...".
    static const std::regex nvidia(R"(^\s*\d+\((\d+)\)\s*:\s*(.*)$)");
    // glslang, AMD: "ERROR: 0:10003: ..." (severity before the place).
    static const std::regex glslang(R"(^\s*(ERROR|WARNING|error|warning):\s*\d+:(\d+):\s*(.*)$)");
    std::smatch m;
    if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia)) {
        message.line = std::stoi(m[1]);
        message.text = m[2];
        return true;
    }
    if (std::regex_match(line, m, glslang)) {
        message.line = std::stoi(m[2]);
        message.text = lowerCase(m[1]) + ": " + std::string(m[3]);
        return true;
    }
    return false;
}

template <class Each>
void forEachLine(std::string_view text, const Each& each) {
    size_t from = 0;
    while (from < text.size()) {
        size_t end = text.find('\n', from);
        if (end == std::string_view::npos) end = text.size();
        std::string line(text.substr(from, end - from));
        if (!line.empty() && line.back() == '\r') line.pop_back();
        each(line);
        from = end + 1;
    }
}

}  // namespace

std::vector<ShaderLogMessage> parseShaderLog(std::string_view log) {
    std::vector<ShaderLogMessage> messages;
    forEachLine(log, [&](const std::string& line) {
        ShaderLogMessage m;
        if (parseLogLine(line, m)) messages.push_back(std::move(m));
    });
    return messages;
}

std::vector<SourceError> blockErrorsInExplainedLog(std::string_view explainedLog, std::string_view blockId) {
    // explainLog names a block's line as `"Label" (id), GLSL line N: ` (core/glsl_gen.cpp).
    static const std::regex where(R"(\(([A-Za-z0-9_]+)\), GLSL line (\d+):\s*(.*)$)");
    std::vector<SourceError> errors;
    forEachLine(explainedLog, [&](const std::string& line) {
        std::smatch m;
        if (!std::regex_search(line, m, where) || m[1].str() != blockId) return;
        SourceError e{std::stoi(m[2]), m[3]};
        // Warnings are no reason the code failed, and some are about what the shader adds to it
        // (Mesa: a whole DE's loop trip counter "used uninitialized").
        if (lowerCase(e.message).starts_with("warning")) return;
        if (std::find(errors.begin(), errors.end(), e) == errors.end()) errors.push_back(std::move(e));
    });
    return errors;
}

std::vector<SourceError> validationSourceErrors(std::string_view refusal) {
    constexpr std::string_view field = "glsl: ";
    if (!refusal.starts_with(field)) return {};
    const std::string rest(refusal.substr(field.size()));
    static const std::regex atLine(R"(^line (\d+): (.*)$)");
    std::smatch m;
    if (std::regex_match(rest, m, atLine)) return {SourceError{std::stoi(m[1]), m[2]}};
    return {SourceError{0, rest}};
}

}  // namespace fraktal
