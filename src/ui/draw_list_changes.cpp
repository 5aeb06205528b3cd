#include "ui/draw_list_changes.h"

#include <algorithm>

namespace ui {
namespace {

bool sameVertex(const ImDrawVert& a, const ImDrawVert& b) {
    return a.pos.x == b.pos.x && a.pos.y == b.pos.y && a.uv.x == b.uv.x && a.uv.y == b.uv.y && a.col == b.col;
}

bool sameTriangle(const DrawnTriangle& a, const DrawnTriangle& b) {
    return sameVertex(a.corner[0], b.corner[0]) && sameVertex(a.corner[1], b.corner[1]) &&
           sameVertex(a.corner[2], b.corner[2]) && a.clip.x == b.clip.x && a.clip.y == b.clip.y &&
           a.clip.z == b.clip.z && a.clip.w == b.clip.w && a.texture == b.texture;
}

// `area` grown to hold the triangles [first, last), each cut by its clip rectangle.
void include(ImVec4& area, const DrawnTriangle* first, const DrawnTriangle* last) {
    for (const DrawnTriangle* t = first; t != last; ++t) {
        ImVec4 box(1e30f, 1e30f, -1e30f, -1e30f);
        for (const ImDrawVert& v : t->corner) {
            box = ImVec4(std::min(box.x, v.pos.x), std::min(box.y, v.pos.y), std::max(box.z, v.pos.x),
                         std::max(box.w, v.pos.y));
        }
        box = ImVec4(std::max(box.x, t->clip.x), std::max(box.y, t->clip.y), std::min(box.z, t->clip.z),
                     std::min(box.w, t->clip.w));
        if (box.z <= box.x || box.w <= box.y) continue;
        area = ImVec4(std::min(area.x, box.x), std::min(area.y, box.y), std::max(area.z, box.z),
                      std::max(area.w, box.w));
    }
}

}  // namespace

void DrawListCopy::assign(const ImDrawList& list) {
    triangles.clear();
    for (const ImDrawCmd& command : list.CmdBuffer) {
        if (command.UserCallback != nullptr) continue;
        for (unsigned int e = 0; e + 2 < command.ElemCount; e += 3) {
            DrawnTriangle t;
            for (int k = 0; k < 3; ++k) {
                t.corner[k] = list.VtxBuffer[int(command.VtxOffset + list.IdxBuffer[int(command.IdxOffset + e + k)])];
            }
            t.clip = command.ClipRect;
            t.texture = command.GetTexID();
            triangles.push_back(t);
        }
    }
}

std::optional<ImVec4> changedArea(const DrawListCopy& before, const DrawListCopy& now) {
    if (before.empty()) return std::nullopt;
    const std::vector<DrawnTriangle>& a = before.triangles;
    const std::vector<DrawnTriangle>& b = now.triangles;
    const std::size_t shorter = std::min(a.size(), b.size());
    std::size_t start = 0;  // triangles alike from the first
    while (start < shorter && sameTriangle(a[start], b[start])) ++start;
    std::size_t end = 0;  // and from the last, not into the start
    while (end < shorter - start && sameTriangle(a[a.size() - 1 - end], b[b.size() - 1 - end])) ++end;
    ImVec4 area(1e30f, 1e30f, -1e30f, -1e30f);
    include(area, a.data() + start, a.data() + a.size() - end);
    include(area, b.data() + start, b.data() + b.size() - end);
    return area;
}

}  // namespace ui
