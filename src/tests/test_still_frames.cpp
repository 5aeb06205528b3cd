// The paused window's wait for input (app/window/still_frames.h): when it starts and stops.
#include <gtest/gtest.h>
#include <imgui.h>

#include "app/window/still_frames.h"
#include "render/camera.h"

namespace {

// A UI of one list holding one vertex at (x, 0).
struct OneVertexUi {
    ImDrawList list{nullptr};
    ImDrawList* lists[1] = {&list};
    ImDrawData data;

    explicit OneVertexUi(float x) {
        ImDrawVert vertex{};
        vertex.pos = ImVec2(x, 0.0f);
        list.VtxBuffer.push_back(vertex);
        data.CmdLists = lists;
        data.CmdListsCount = 1;
    }
};

}  // namespace

TEST(StillFrames, APausedWindowWaitsOnceItDrewTheSameFrameThreeTimes) {
    app::StillFrames still;
    const OneVertexUi ui(1.0f);
    const render::Camera camera;
    for (int frame = 0; frame < app::StillFrames::kAlikeBeforeWaiting; ++frame) {
        EXPECT_FALSE(still.waits()) << frame;
        still.after(true, ui.data, camera, 7);
    }
    EXPECT_FALSE(still.waits()) << "the first frame has none to be like";
    still.after(true, ui.data, camera, 7);
    EXPECT_TRUE(still.waits());
    still.woken();
    EXPECT_FALSE(still.waits()) << "input draws a few frames again";
}

TEST(StillFrames, AnyChangeOrAStepOrHeldKeyDrawsOn) {
    const OneVertexUi ui(1.0f), moved(2.0f);
    const render::Camera camera;
    render::Camera turned;
    turned.azimuth += 0.01f;
    const auto waitingThen = [&](auto change) {
        app::StillFrames still;
        for (int frame = 0; frame <= app::StillFrames::kAlikeBeforeWaiting; ++frame) still.after(true, ui.data, camera, 7);
        EXPECT_TRUE(still.waits());
        change(still);
        return still.waits();
    };
    EXPECT_FALSE(waitingThen([&](app::StillFrames& s) { s.after(true, moved.data, camera, 7); })) << "the UI changed";
    EXPECT_FALSE(waitingThen([&](app::StillFrames& s) { s.after(true, ui.data, turned, 7); })) << "the camera turned";
    EXPECT_FALSE(waitingThen([&](app::StillFrames& s) { s.after(true, ui.data, camera, 8); })) << "the scene changed";
    EXPECT_FALSE(waitingThen([&](app::StillFrames& s) { s.after(false, ui.data, camera, 7); })) << "not quiet";
    EXPECT_TRUE(waitingThen([&](app::StillFrames& s) { s.after(true, ui.data, camera, 7); })) << "the same again";
}
