#include "app/editor/input/pointer_input.hpp"

#include <algorithm>
#include <cmath>

namespace fraktal::editor {

DragMotion consumePointerEvents(ViewportDrag& drag, const std::vector<PointerEvent>& events,
                                const ViewportRect& viewport, bool uiOwnsMouse) {
    DragMotion m;
    m.held = drag.button >= 0;
    for (const PointerEvent& e : events) {
        const vec2 at(e.x, e.y);
        switch (e.kind) {
            case PointerEvent::Kind::Press:
                if (drag.button >= 0) break;  // a second button during a drag changes nothing
                drag.focused = !uiOwnsMouse && viewport.contains(e.x, e.y);
                if (!drag.focused) break;
                drag.button = e.button;
                drag.pressAt = drag.last = at;
                drag.pressMods = e.mods;
                drag.dragging = false;
                m.held = true;
                break;
            case PointerEvent::Kind::Release:
                if (e.button != drag.button) break;
                if (!drag.dragging) m.clicks.push_back({e.button, drag.pressAt, drag.pressMods});
                drag.button = -1;
                break;
            case PointerEvent::Kind::Move: {
                if (drag.button < 0) break;
                if (!drag.dragging) {
                    if (length(at - drag.pressAt) <= drag.thresholdPixels) break;
                    drag.dragging = true;
                }
                const vec2 delta = at - drag.last;
                drag.last = at;
                (drag.button == 0 ? m.rotate : m.pan) += delta;
                break;
            }
        }
    }
    return m;
}

void flyKeyEvent(FlyKeys& keys, FlyKey key, bool pressed, double time) {
    const size_t k = size_t(key);
    if (pressed) {
        if (!keys.down[k]) keys.downSince[k] = time;
        keys.down[k] = true;
    } else if (keys.down[k]) {
        keys.heldSeconds[k] += std::max(time - keys.downSince[k], keys.minTapSeconds);
        keys.down[k] = false;
    }
}

std::array<double, kFlyKeys> takeFlyKeySeconds(FlyKeys& keys, double now, bool accept) {
    std::array<double, kFlyKeys> seconds{};
    for (size_t k = 0; k < seconds.size(); ++k) {
        seconds[k] = keys.heldSeconds[k];
        if (keys.down[k]) {
            seconds[k] += std::max(now - keys.downSince[k], 0.0);
            keys.downSince[k] = now;
        }
        keys.heldSeconds[k] = 0.0;
        if (!accept) seconds[k] = 0.0;
    }
    return seconds;
}

void flyMotion(const std::array<double, kFlyKeys>& seconds, vec3& direction, double& duration) {
    direction = vec3(seconds[FlyRight] - seconds[FlyLeft], seconds[FlyUp] - seconds[FlyDown],
                     seconds[FlyForward] - seconds[FlyBack]);
    duration = std::max({std::abs(direction.x), std::abs(direction.y), std::abs(direction.z)});
}

}  // namespace fraktal::editor
