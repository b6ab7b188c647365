// Resizable panel layout: a draggable bar between two regions whose position is a fraction of
// the available size, kept in the persisted layout so it survives window resizes and restarts.
#pragma once

namespace polarform::studio {

// The first region's size for `fraction` of `length` (less the bar), leaving both regions at
// least `min_size` pixels.
float split_size(float fraction, float length, float min_size);

// The draggable bar between the regions (after SameLine(0, 0) for a vertical bar); dragging it
// moves `fraction` by the mouse movement over `length`.
void vertical_splitter(const char* id, float& fraction, float length);
void horizontal_splitter(const char* id, float& fraction, float length);

}  // namespace polarform::studio
