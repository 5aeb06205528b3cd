#pragma once
// Scene-file tests: what the loader says about a broken file.
#include <initializer_list>
#include <string>

#include <gtest/gtest.h>

#include "scenes/scene_json.h"

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The message parseScene throws for `text`, or "" when it loads.
inline std::string errorOf(const std::string& text) {
    try {
        scenes::parseScene(text, "bad.json");
    } catch (const scenes::SceneError& e) {
        return e.what();
    }
    return "";
}

// One line that starts with "bad.json:<line>:<column>:" and names the problem.
inline void expectError(const std::string& text, const std::string& location,
                        std::initializer_list<const char*> words) {
    const std::string message = errorOf(text);
    SCOPED_TRACE(message);
    EXPECT_EQ(message.rfind("bad.json:" + location + ": ", 0), 0u);
    EXPECT_EQ(message.find('\n'), std::string::npos);
    for (const char* word : words) EXPECT_TRUE(contains(message, word)) << word;
}
