// The animation timeline along the bottom of the viewport, the key markers beside keyable
// parameter widgets, and the camera path drawn over the viewport (timeline_edits.hpp holds the
// logic they share).
#pragma once

#include <string>
#include <vector>

#include "app/editor/state/editor_state.hpp"

namespace fraktal::editor {

// Space (play / pause, while the viewport or the timeline is hovered) and Delete (the selected
// key, while the timeline is hovered): handled before the other shortcuts, which then do not see
// them. Call at the start of a frame.
void handleTimelineShortcuts(EditorState& s);  // timeline_panel.cpp

// Advances playback, writes the animation at the current frame into the document when the frame
// or the animation changed, and draws the panel below the viewport, whose height it takes from
// s.layout (call after the viewport's rectangle is laid out, before the viewport draws).
void drawTimelinePanel(EditorState& s);  // timeline_panel.cpp

// A diamond before a keyable value's widget: hollow grey when the value has no track, hollow
// when keyed, filled when a key is on the current frame, orange when the value differs from what
// its track gives here (edited since). A click keys the value at the current frame (or removes
// the key there when the value is the key's); a right click offers the same and the track's
// interpolation. Call before the widget, which follows on the same line.
void keyMarker(EditorState& s, const std::string& target, const std::vector<double>& value);  // timeline_panel.cpp

// The camera position track projected into the viewport (a polyline, the keys as dots) when the
// camera is keyed and View > Camera path is on. Call after the viewport's image is drawn.
void drawCameraPathOverlay(const EditorState& s);  // camera_path_overlay.cpp

}  // namespace fraktal::editor
