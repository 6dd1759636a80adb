#pragma once
// Splits a simple polygon into triangles (ear clipping), for the OpenGL layer, which fills the
// void cells as triangles: a void cell's polygon runs through grain centres and is often not
// convex, so a fan from one vertex would spill over its neighbours. Pure function, any thread.

#include <array>
#include <vector>

#include <QPolygonF>

namespace grainlab::ui {

/// Triangles (vertex index triples into `polygon`) whose union is the polygon, n - 2 of them
/// for n >= 3 vertices, in either orientation. The polygon is taken as closed (the last vertex
/// joins the first). When no ear is left (a self-touching or degenerate polygon) the rest is
/// closed as a fan, so the count stays n - 2.
std::vector<std::array<int, 3>> triangulatePolygon(const QPolygonF& polygon);

} // namespace grainlab::ui
