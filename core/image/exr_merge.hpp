// `fraktal merge`: joins the parts of a still rendered with `fraktal render --part i/n` into one
// EXR equal to a whole render: the same pixels in every channel (copied in their stored type) and
// the same header (the first part's, with the whole image as data window and no part attribute).
#pragma once

#include <filesystem>
#include <vector>

namespace fraktal {

// Throws std::runtime_error naming the file and what is wrong (not a part, parts of different
// images, rows missing or given twice); writes `output` atomically, nothing on error.
void mergeExrParts(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output);

}  // namespace fraktal
