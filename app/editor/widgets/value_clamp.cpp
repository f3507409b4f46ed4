#include "app/editor/widgets/value_clamp.hpp"

#include <algorithm>
#include <cstdio>

namespace fraktal::editor {

namespace {
std::string number(double v, bool integer) {
    char text[64];
    if (integer)
        std::snprintf(text, sizeof text, "%.0f", v);
    else
        std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}
}  // namespace

std::optional<ClampNotice> clampIntoRange(std::string_view param, std::span<double> values, double lo, double hi,
                                          bool integer) {
    if (lo > hi) return std::nullopt;
    std::optional<ClampNotice> notice;
    for (double& v : values) {
        const double in = std::clamp(v, lo, hi);
        if (in == v) continue;
        if (!notice) notice = ClampNotice{std::string(param), v, in, lo, hi, integer};
        v = in;
    }
    return notice;
}

std::string clampMessage(const ClampNotice& n) {
    return n.param + ": " + number(n.typed, n.integer) + " is outside " + number(n.lo, n.integer) + " .. " +
           number(n.hi, n.integer) + ", set to " + number(n.clamped, n.integer);
}

std::string_view visibleLabel(std::string_view label) { return label.substr(0, label.find("##")); }

void ClampReports::drawn(unsigned id, std::optional<ClampNotice> notice, bool changed, bool left) {
    if (notice) {
        pendingId_ = id;
        pending_ = std::move(notice);
    } else if (changed && pendingId_ == id) {
        pending_.reset();  // typed on into the range
    }
    if (left && pendingId_ == id && pending_) {
        ready_ = std::move(pending_);
        pending_.reset();
    }
}

std::optional<ClampNotice> ClampReports::take() {
    std::optional<ClampNotice> out = std::move(ready_);
    ready_.reset();
    return out;
}

}  // namespace fraktal::editor
