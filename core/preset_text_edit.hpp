// Edits one number of a preset file's text in place, so that a tool that changes one value
// (`fraktal check --apply` writing the measured step factor) leaves the rest of the file as the
// artist wrote it: key order, spacing, line breaks and number spellings.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace fraktal {

// `text` with the top-level object's `section`.`key` set to `value`: the number there replaced
// (only its characters), or, when the section has no such key, `"key": value, ` inserted as its
// first member. The result is parsed again and must equal the original with that one value
// changed; otherwise (no such section, the key holds something other than a number, a file that is
// not a JSON object) it throws std::runtime_error naming `file`, the field and the reason.
std::string withNumberInPlace(const std::string& text, const std::string& section, const std::string& key, double value,
                              const std::string& file);

// The same for a string value (the step factor's tag, formula.deFactorMeasuredFor).
std::string withStringInPlace(const std::string& text, const std::string& section, const std::string& key,
                              const std::string& value, const std::string& file);

// `text` with the last element of the top-level object's `section`.`key` array replaced by
// `value`, written on one line (`fraktal check --fit --apply` writing the fitted estimator, which
// closes formula.nodes). Checked and refused as withNumberInPlace is: the array must exist and
// hold at least one element.
std::string withLastElementInPlace(const std::string& text, const std::string& section, const std::string& key,
                                   const nlohmann::json& value, const std::string& file);

}  // namespace fraktal
