#include "app/views/window_layout.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace app {
namespace {

constexpr float kBottomDockShare = 0.42f;  // of the height under the readouts' line: the dock at the bottom
constexpr float kExplainerShare = 0.6f;    // of the dock, for the explainer beside other windows

// The height of the largest box of aspect `aspect` (width / height) in w x h px.
float boxHeightIn(float w, float h, float aspect) { return std::max(std::min(w / aspect, h), 0.0f); }

glm::ivec4 toPixels(const Rect& r, glm::vec2 ppu, int framebufferHeight) {
    const int x0 = int(std::lround(r.min.x * ppu.x)), x1 = int(std::lround(r.max().x * ppu.x));
    const int top = int(std::lround(r.min.y * ppu.y)), bottom = int(std::lround(r.max().y * ppu.y));
    return {x0, framebufferHeight - bottom, std::max(x1 - x0, 1), std::max(bottom - top, 1)};
}

Rect toUnits(const glm::ivec4& px, glm::vec2 ppu, int framebufferHeight) {
    return {{float(px.x) / ppu.x, float(framebufferHeight - (px.y + px.w)) / ppu.y},
            {float(px.z) / ppu.x, float(px.w) / ppu.y}};
}

// The views and labels of `scene` for the request (layout.scene set).
float arrange(const LayoutRequest& q, WindowLayout& layout) {
    ViewLayout& v = layout.views;
    v.framebuffer = glm::max(glm::ivec2(glm::round(q.window * q.pixelsPerUnit)), glm::ivec2(1));
    v.pixelsPerUnit = q.pixelsPerUnit;
    v.count = std::clamp(q.views, 1, kMostViews);
    const bool labelled = v.count > 1 && q.labelWidth > 0.0f && q.labelHeight;
    const int labelWidth = labelled ? int(std::ceil(q.labelWidth * q.pixelsPerUnit.x)) : 0;
    const LabelHeight labelHeight = [&](int width) {
        return int(std::ceil(q.labelHeight(float(width) / q.pixelsPerUnit.x) * q.pixelsPerUnit.y));
    };
    glm::ivec4 labels[kMostViews]{};
    const float height = arrangeViews(toPixels(layout.scene, q.pixelsPerUnit, v.framebuffer.y), v.count, q.gap,
                                      labelWidth, labelled ? labelHeight : LabelHeight(), q.boxAspect, v.views, labels);
    for (int k = 0; k < kMostViews; ++k) {
        layout.labels[k] = k < v.count && labelled ? toUnits(labels[k], q.pixelsPerUnit, v.framebuffer.y) : Rect{};
    }
    return height;
}

// The dock's windows, top to bottom in a column, left to right in a strip.
void fillDock(const LayoutRequest& q, WindowLayout& layout) {
    const Rect& d = layout.dock;
    const bool sharesWithInspector = q.explainer || q.readouts;
    if (!layout.dockAtBottom) {
        const float inspector = q.inspectorHeight > 0.0f
                                    ? std::min(q.inspectorHeight, (sharesWithInspector ? 0.5f : 1.0f) * d.size.y)
                                    : 0.0f;
        if (inspector > 0.0f) layout.inspector = {d.min, {d.size.x, inspector}};
        const float rest = d.size.y - inspector, top = d.min.y + inspector;
        const float explainer = q.explainer ? (q.readouts ? kExplainerShare * rest : rest) : 0.0f;
        if (q.explainer) layout.explainer = {{d.min.x, top}, {d.size.x, explainer}};
        if (q.readouts) layout.readouts = {{d.min.x, top + explainer}, {d.size.x, rest - explainer}};
        return;
    }
    float inspector = q.inspectorHeight > 0.0f ? kInspectorFonts * q.font : 0.0f;
    float readouts = q.readouts ? kReadoutsFonts * q.font : 0.0f;
    if (!q.explainer) {  // the last one takes the rest
        if (q.readouts) readouts = std::max(d.size.x - inspector, 0.0f);
        else inspector = d.size.x;
    }
    // The explanation is what the class reads: at least kExplainerShare of the strip.
    const float room = q.explainer ? (1.0f - kExplainerShare) * d.size.x : d.size.x;
    const float fixed = inspector + readouts;
    if (fixed > room) {  // a narrow window: the others shrink alike
        inspector *= room / fixed;
        readouts *= room / fixed;
    }
    const float explainer = q.explainer ? std::max(d.size.x - inspector - readouts, 0.0f) : 0.0f;
    if (inspector > 0.0f) layout.inspector = {d.min, {inspector, d.size.y}};
    if (q.explainer) layout.explainer = {{d.min.x + inspector, d.min.y}, {explainer, d.size.y}};
    if (q.readouts) layout.readouts = {{d.min.x + inspector + explainer, d.min.y}, {readouts, d.size.y}};
}

}  // namespace

int ViewLayout::viewAt(glm::vec2 mouse) const {
    const glm::vec2 pixel(mouse.x * pixelsPerUnit.x, float(framebuffer.y) - mouse.y * pixelsPerUnit.y);  // GL's origin
    for (int k = 0; k < count; ++k) {
        const glm::ivec4& v = views[k];
        if (pixel.x >= float(v.x) && pixel.x < float(v.x + v.z) && pixel.y >= float(v.y) && pixel.y < float(v.y + v.w)) {
            return k;
        }
    }
    return -1;
}

glm::vec2 ViewLayout::pixelIn(int view, glm::vec2 mouse) const {
    const glm::ivec4& v = views[view >= 0 && view < count ? view : 0];
    const float top = float(framebuffer.y - (v.y + v.w));  // the view's top row, from the framebuffer's top
    return {mouse.x * pixelsPerUnit.x - float(v.x), mouse.y * pixelsPerUnit.y - top};
}

render::Ray ViewLayout::ray(const render::Camera& camera, int view, glm::vec2 mouse) const {
    const glm::ivec4& v = views[view >= 0 && view < count ? view : 0];
    return camera.rayThroughPixel(pixelIn(view, mouse), glm::vec2(v.z, v.w));
}

float ViewLayout::aspect() const { return views[0].w > 0 ? float(views[0].z) / float(views[0].w) : 1.0f; }

Rect ViewLayout::rect(int view) const { return toUnits(views[view >= 0 && view < count ? view : 0], pixelsPerUnit, framebuffer.y); }

float arrangeViews(glm::ivec4 area, int count, int gap, int labelWidth, const LabelHeight& labelHeight,
                   float boxAspect, glm::ivec4 views[kMostViews], glm::ivec4 labels[kMostViews]) {
    count = std::clamp(count, 1, kMostViews);
    boxAspect = boxAspect > 0.0f ? boxAspect : 1.0f;
    const bool labelled = count > 1 && labelWidth > 0 && labelHeight;
    // Above a view the label is as wide as the view (a longer line wraps); beside it, its own width.
    const auto above = [&](int width) { return std::min(labelHeight(std::min(width, labelWidth)), area.w); };
    const int besideHeight = labelled ? labelHeight(labelWidth) : 0;  // px, a label at its own width
    int bestColumns = 1;
    bool bestAbove = true;  // each label above its view, else left of it
    float best = -1.0f;
    for (int columns = 1; columns <= count; ++columns) {
        const int rows = (count + columns - 1) / columns;
        const float w = float(area.z - (columns - 1) * gap) / float(columns);
        const float h = float(area.w - (rows - 1) * gap) / float(rows);
        const float top = labelled ? boxHeightIn(w, h - float(above(int(w))), boxAspect) : boxHeightIn(w, h, boxAspect);
        // Beside its view a label is as tall as its lines at its own width: where they need
        // more than the row, they were cut (18's "✗ break-away" in half at 1280 x 768).
        const bool fitsBeside = labelled && besideHeight <= int(h);
        const float left = fitsBeside ? boxHeightIn(w - float(labelWidth), h, boxAspect) : -1.0f;
        if (std::max(top, left) > best) {  // ties: fewer columns, labels above
            best = std::max(top, left);
            bestColumns = columns;
            bestAbove = top >= left;
        }
    }
    const int rows = (count + bestColumns - 1) / bestColumns;
    const int width = std::max((area.z - (bestColumns - 1) * gap) / bestColumns, 1);
    const int height = std::max((area.w - (rows - 1) * gap) / rows, 1);
    for (int k = 0; k < count; ++k) {
        const int column = k % bestColumns, row = k / bestColumns;  // row 0 at the top
        const int x = area.x + column * (width + gap);
        const int w = column == bestColumns - 1 ? area.x + area.z - x : width;  // the last column to the edge
        const int top = area.y + area.w - row * (height + gap);
        const int h = row == rows - 1 ? top - area.y : height;  // the last row to the bottom
        glm::ivec4 cell{x, top - h, std::max(w, 1), std::max(h, 1)};
        labels[k] = {cell.x, cell.y, 0, 0};
        if (labelled && bestAbove) {
            const int label = std::min(above(width), cell.w - 1);  // one height for every view: they stay alike
            labels[k] = {cell.x, cell.y + cell.w - label, cell.z, label};
            cell.w -= label;
        } else if (labelled) {
            const int label = std::min(labelWidth, cell.z - 1);
            labels[k] = {cell.x, cell.y, label, cell.w};
            cell.x += label;
            cell.z -= label;
        }
        views[k] = cell;
    }
    return best;
}

WindowLayout layoutWindow(const LayoutRequest& q) {
    const glm::vec2 w = glm::max(q.window, glm::vec2(1.0f));
    WindowLayout base;
    const float panel = std::clamp(q.panelWidth, 0.0f, w.x - 1.0f);
    base.panel = {{0.0f, 0.0f}, {panel, w.y}};
    const float right = w.x - panel;
    const float bar = std::clamp(q.barHeight, 0.0f, 0.5f * w.y);
    const float line = std::clamp(q.readoutsLine, 0.0f, 0.25f * w.y);
    base.timeline = bar > 0.0f ? Rect{{panel, w.y - bar}, {right, bar}} : Rect{};
    base.readoutsLine = line > 0.0f ? Rect{{panel, 0.0f}, {right, line}} : Rect{};
    const Rect middle{{panel, line}, {right, w.y - bar - line}};
    base.scene = middle;
    if (q.inspectorHeight <= 0.0f && !q.explainer && !q.readouts) {
        arrange(q, base);
        return base;
    }
    // The dock on the right, then at the bottom: the one whose views hold the larger box.
    WindowLayout side = base, bottom = base;
    float column = 0.0f;
    if (q.inspectorHeight > 0.0f) column = std::max(column, kInspectorFonts * q.font);
    if (q.explainer) column = std::max(column, kExplainerFonts * q.font);
    if (q.readouts) column = std::max(column, kReadoutsFonts * q.font);
    column = std::min(column, 0.5f * middle.size.x);
    side.dock = {{middle.max().x - column, middle.min.y}, {column, middle.size.y}};
    side.scene = {middle.min, {middle.size.x - column, middle.size.y}};
    const float strip = q.explainer || q.readouts ? kBottomDockShare * middle.size.y
                                                   : std::min(q.inspectorHeight, 0.5f * middle.size.y);
    bottom.dockAtBottom = true;
    bottom.dock = {{middle.min.x, middle.max().y - strip}, {middle.size.x, strip}};
    bottom.scene = {middle.min, {middle.size.x, middle.size.y - strip}};
    WindowLayout& chosen = arrange(q, side) >= arrange(q, bottom) ? side : bottom;
    fillDock(q, chosen);
    return chosen;
}

float boxAspectOnScreen(const render::Camera& camera, glm::vec3 lo, glm::vec3 hi) {
    const glm::vec3 f = camera.forward();
    const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0.0f, 0.0f, 1.0f)));
    const glm::vec3 up = glm::cross(right, f);
    glm::vec2 least(1e30f), most(-1e30f);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
        const glm::vec2 s(glm::dot(p, right), glm::dot(p, up));
        least = glm::min(least, s);
        most = glm::max(most, s);
    }
    const glm::vec2 extent = most - least;
    return extent.y > 0.0f && extent.x > 0.0f ? extent.x / extent.y : 1.0f;
}

}  // namespace app
