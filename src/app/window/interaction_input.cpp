#include "app/window/interaction_input.h"

#include <cstdarg>
#include <cstdio>

#include <imgui.h>
#include <glm/geometric.hpp>

namespace app {

void InteractionInput::say(double now, const char* format, ...) {
    char text[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof text, format, args);
    va_end(args);
    tools_.message = text;
    messageTime_ = now;
    messageSeconds_ = kMessageSeconds;
}

void InteractionInput::sayBriefly(double now, const std::string& text) {
    tools_.message = text;
    messageTime_ = now;
    messageSeconds_ = kBriefMessageSeconds;
}

void InteractionInput::expireMessage(double now) {
    if (!tools_.message.empty() && now - messageTime_ > messageSeconds_) tools_.message.clear();
}

bool InteractionInput::takeFoldReadouts() {
    const bool fold = foldReadouts_;
    foldReadouts_ = false;
    return fold;
}

bool InteractionInput::handleMouse(const ViewLayout& views, const render::Camera& camera, double now) {
    const ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 mouse(io.MousePos.x, io.MousePos.y);
    if (session_.dragging()) {
        if (io.MouseDown[ImGuiMouseButton_Left]) {
            session_.dragTo(views.ray(camera, dragView_, mouse), now);
        } else {
            const glm::dvec3 v = session_.endDrag();
            say(now, "sphere #%d thrown at %.2f m/s", session_.selected(), glm::length(v));
        }
        return true;
    }
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        pressInScene_ = !io.WantCaptureMouse;
        const int view = pressInScene_ ? views.viewAt(mouse) : -1;
        if (io.KeyCtrl && view >= 0) {
            const render::Ray ray = views.ray(camera, view, mouse);
            const int hit = pickSphere(session_.run(view).world(), ray);
            if (hit >= 0 && session_.beginDrag(view, static_cast<std::size_t>(hit), ray, camera.forward(), now)) {
                dragView_ = view;
                return true;
            }
        }
    }
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && pressInScene_ &&
        io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < kClickPixels * kClickPixels) {
        if (const int view = views.viewAt(mouse); view >= 0) {
            const int hit = pickSphere(session_.run(view).world(), views.ray(camera, view, mouse));
            if (hit < 0 && tools_.explainer && session_.selected() >= 0) {
                // A click that misses a moving sphere must not lose the contact being explained.
                say(now, "no sphere there: the explanation of #%d stays (Deselect or Esc closes it)",
                    session_.selected());
            } else {
                session_.select(hit, view);
            }
        }
    }
    return false;
}

void InteractionInput::shoot(const ViewLayout& views, const render::Camera& camera, bool throughMouse, double now) {
    const ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 mouse(io.MousePos.x, io.MousePos.y);
    const int view = throughMouse && !io.WantCaptureMouse ? views.viewAt(mouse) : -1;
    const render::Ray aim = view >= 0 ? views.ray(camera, view, mouse) : render::Ray{camera.position(), camera.forward()};
    const std::string refusal = session_.shoot(aim, tools_.shootSpeed);
    if (refusal.empty()) {
        say(now, "shot sphere #%d at %.0f m/s", session_.selected(), double(tools_.shootSpeed));
    } else {
        say(now, "%s", refusal.c_str());
    }
}

std::string InteractionInput::startComparison(const std::vector<std::string>& lists) {
    tools_.compareText = joinedOverrides(lists);
    const std::string error = session_.startComparison(lists);
    foldReadouts_ = error.empty();
    comparingSuggestion_ = false;
    return error;
}

std::string InteractionInput::openFirstScene(const std::vector<std::string>& asked) {
    if (!asked.empty()) return startComparison(asked);
    sceneChanged();
    const std::vector<std::string>& own = session_.run(0).scene().compare;
    if (!own.empty() && !session_.comparison()) return session_.startComparison(own);  // why the scene's own is refused
    return "";
}

// Side by side with the last scene's offer, the next scene's offer replaces it: its overrides
// could change nothing there (the cradle's order=index,reversed on 13's one sphere: two views
// of one run). Overrides the user wrote stay, and a scene's own "compare" comes first.
void InteractionInput::sceneChanged() {
    const bool followOffer = session_.comparison() && comparingSuggestion_ && tools_.compareText == suggested_;
    if (followOffer) session_.stopComparison();
    session_.sceneChanged();
    suggestOverrides();
    const std::vector<std::string>& asked = session_.run(0).scene().compare;
    if (!asked.empty() && session_.comparison()) {
        tools_.compareText = joinedOverrides(asked);
        foldReadouts_ = true;
        comparingSuggestion_ = false;
        return;
    }
    comparingSuggestion_ = followOffer && !suggested_.empty() && session_.startComparison({suggested_}).empty();
    if (comparingSuggestion_) foldReadouts_ = true;
}

void InteractionInput::suggestOverrides() {
    const std::string next = suggestedOverrides(session_.run(0).scene());
    if (tools_.compareText == suggested_) tools_.compareText = next;  // else the user's own stay
    suggested_ = next;
}

bool InteractionInput::toggleCompare(double now) {
    if (session_.comparison()) {
        session_.stopComparison();
        comparingSuggestion_ = false;
        say(now, "side by side: off");
        return true;
    }
    return applyCompare(now);
}

bool InteractionInput::applyCompare(double now) {
    if (const std::string error = session_.startComparison({tools_.compareText}); !error.empty()) {
        say(now, "cannot compare: %s", error.c_str());
        return false;
    }
    comparingSuggestion_ = tools_.compareText == suggested_;
    const Comparison& comparison = *session_.comparison();
    const std::string primary = comparison.primaryLabel(session_.run(0).scene());
    if (comparison.changesNothing(session_.run(0).scene())) {
        const bool two = comparison.count() == 1;
        say(now, "side by side: %s in %s: the overrides change nothing, so the %s are the same", primary.c_str(),
            two ? "both views" : "every view", two ? "two views" : "views");
    } else {
        std::string others;
        for (int k = 0; k < comparison.count(); ++k) others += (k == 0 ? "" : " and ") + comparison.label(k);
        say(now, "side by side: %s against %s, all restarted from the scene's initial state", primary.c_str(),
            others.c_str());
    }
    foldReadouts_ = true;
    return true;
}

void InteractionInput::toggleExplainer(double now) {
    if (session_.selected() >= 0 || tools_.explainer) {
        tools_.explainer = !tools_.explainer;
        return;
    }
    say(now, "E explains a sphere's contact: click a sphere first");  // nothing happened, and nothing said why
}

bool InteractionInput::backOut() {
    if (tools_.explainer) {
        tools_.explainer = false;
        return true;
    }
    if (session_.selected() < 0) return false;
    session_.select(-1);
    return true;
}

bool InteractionInput::apply(const ToolActions& a, const ViewLayout& views, const render::Camera& camera, double now) {
    if (a.deselect) session_.select(-1);
    if (a.edited) {
        tools_.inspectorRefusal = session_.editSelected(a.fields);
        tools_.refusedSphere = session_.selected();
    }
    if (a.shoot) shoot(views, camera, false, now);
    if (a.toggleExplainer) tools_.explainer = !tools_.explainer;
    if (a.scrub) session_.scrubTo(a.scrubTo);
    if (a.applyCompare) return applyCompare(now);
    return a.toggleCompare && toggleCompare(now);
}

}  // namespace app
